# Sourced by simd_targets.sh and scalar.sh: the CTest arguments that pick the tests whose
# result can change with the SIMD kernels, for the runs that repeat ./test.sh on another
# instruction set. Kept: the unit tests (raster, shading, SIMD, every render), the golden
# tests against Mesa, pGL's conformance programs against Mesa and the GLX vendor's
# programs, the CLI's renders, three.js's comparisons with Velocity's renders, the soak,
# the micro benchmarks' run and the fuzz corpora's replay.
# Left out (each already runs once, in ./test.sh), as they do not depend on the target:
#   python    the module and its processes: the same C++ renders, through the bindings
#   gpu       the GPU backend; its parity scenes compare with the CPU at the best target
#   realtime  the SDL programs' windows, input, sound, menus and replays (and rt_*, the
#             same programs' command lines), and GLUT's windows
#   three.js's own checks against the glTF spec and its renders of models (no Velocity in
#   them), the docs' and layout's checks, and the packaging tests (pkg-config, CMake's
#   find_package from a downstream project, pip install).
# The tests that run none of Velocity's code (three.js's own checks, the docs' and the
# layout's); scripts/sanitize.sh leaves them out too.
no_engine_tests='docs_references|layout_includes|threejs_(texcoords|srgb|lambert|lights|shadows|assimp_models|failures)'
kernel_tests=(
  -LE '^(python|gpu|realtime)$'
  -E "^(rt_.*|downstream_find_package|gl_pkg_config|python_pip_install|$no_engine_tests)\$"
)
