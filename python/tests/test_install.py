"""The module installs with the library and imports from the installed tree."""
import os
import subprocess
import sys


def test_installed_package_imports_and_renders(tmp_path):
    build = os.environ["VELOCITY_BUILD_DIR"]
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], check=True, capture_output=True)
    site = prefix / os.environ["VELOCITY_PYTHON_INSTALL_DIR"]
    assert (site / "velocity" / "_velocity.pyi").exists() and (site / "velocity" / "py.typed").exists()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    code = ("import velocity, os; assert os.path.dirname(velocity.__file__).startswith(%r); "
            "s = velocity.Scene(); s.add(velocity.Mesh.cube()); "
            "s.add(velocity.PerspectiveCamera(1.0), pose=velocity.look_at([0, 0, 3], [0, 0, 0])); "
            "c, d = velocity.OffscreenRenderer(16, 16).render(s); assert d[8, 8] > 0" % str(site))
    subprocess.run([sys.executable, "-c", code], check=True, env=env, cwd=tmp_path)
    p = subprocess.run([str(prefix / "bin" / "velocity-batch"), "--help"], env=env, capture_output=True, text=True)
    assert p.returncode == 0 and "velocity-batch" in p.stdout
