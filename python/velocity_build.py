"""The PEP 517 build backend of `pip install .` (pyproject.toml): CMake builds the Python
module (`velocity_python`, the engine linked in) in a fresh folder, and the package
folder it makes (build/python/velocity) becomes the wheel, with the `velocity-batch`
command. Standard library only: pip's isolated build environment needs nothing
downloaded. Tools it runs: cmake, and ninja and ccache when they are there. CMAKE_ARGS
in the environment (space-separated, as scikit-build and conda read it) adds CMake
settings, e.g. CMAKE_ARGS="-DVELOCITY_NATIVE=ON" for a module for this processor only."""
from __future__ import annotations

import base64
import hashlib
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAME = "velocity"


def _version() -> str:
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(velocity VERSION ([0-9.]+)", f.read())
    if not m:
        raise RuntimeError("CMakeLists.txt: no 'project(velocity VERSION x.y.z' line")
    return m.group(1)


def _tag() -> str:
    interp = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interp}-{interp}-{platform}"


def _build(folder: str) -> str:
    """Builds the module in `folder`; returns the package folder it made."""
    # The module is built for the interpreter pip installs into, which must see numpy's
    # headers: CMake asks it, outside pip's isolated build environment (whose PYTHONPATH
    # hides the interpreter's own packages).
    configure = ["cmake", "-S", ROOT, "-B", folder, "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={sys.executable}", f"-DPYTHON_EXECUTABLE={sys.executable}",
                 "-DVELOCITY_BUILD_TESTS=OFF",
                 "-DVELOCITY_BUILD_GL=OFF", "-DVELOCITY_BUILD_REALTIME=OFF"]
    if shutil.which("ninja"):
        configure += ["-G", "Ninja"]
    if shutil.which("ccache"):
        configure += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
    configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
    jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONNOUSERSITE", "PYTHONHOME")}
    for cmd in (configure, ["cmake", "--build", folder, "--target", "velocity_python", "velocity_python_files",
                            "-j", jobs]):
        print("velocity_build:", " ".join(cmd), file=sys.stderr, flush=True)
        subprocess.run(cmd, check=True, stdout=sys.stderr, env=env)
    package = os.path.join(folder, "python", NAME)
    if not any(n.startswith("_velocity") and n.endswith(".so") for n in os.listdir(package)):
        raise RuntimeError(f"{package}: CMake built no _velocity module")
    return package


def _metadata(version: str) -> str:
    return (f"Metadata-Version: 2.1\nName: {NAME}\nVersion: {version}\n"
            "Summary: CPU rendering to numpy arrays, with pyrender's API (velocity.pyrender)\n"
            "Requires-Python: >=3.9\nRequires-Dist: numpy\nRequires-Dist: Pillow\nRequires-Dist: tqdm\n")


def _digest(data: bytes) -> str:
    return "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    info = f"{NAME}-{_version()}.dist-info"
    os.makedirs(os.path.join(metadata_directory, info), exist_ok=True)
    with open(os.path.join(metadata_directory, info, "METADATA"), "w", encoding="utf-8") as f:
        f.write(_metadata(_version()))
    return info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version, tag = _version(), _tag()
    info = f"{NAME}-{version}.dist-info"
    name = f"{NAME}-{version}-{tag}.whl"
    with tempfile.TemporaryDirectory(prefix="velocity-wheel-") as folder:
        package = _build(folder)
        records = []
        with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as whl:
            def add(arcname: str, data: bytes) -> None:
                whl.writestr(arcname, data)
                records.append(f"{arcname},{_digest(data)},{len(data)}")

            for entry in sorted(os.listdir(package)):
                path = os.path.join(package, entry)
                if os.path.isfile(path) and not entry.endswith(".pyc"):
                    with open(path, "rb") as f:
                        add(f"{NAME}/{entry}", f.read())
            add(f"{info}/METADATA", _metadata(version).encode())
            add(f"{info}/WHEEL", f"Wheel-Version: 1.0\nGenerator: velocity_build\nRoot-Is-Purelib: false\n"
                                 f"Tag: {tag}\n".encode())
            add(f"{info}/entry_points.txt", b"[console_scripts]\nvelocity-batch = velocity.batch:main\n")
            records.append(f"{info}/RECORD,,")
            whl.writestr(f"{info}/RECORD", "\n".join(records) + "\n")
    return name
