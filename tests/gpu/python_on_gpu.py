"""The Python module's render, depth, mask and threads tests (python/tests) with every OffscreenRenderer
on the GPU backend: the same assertions, the default backend switched to "gpu".

  python3 tests/gpu/python_on_gpu.py TEST_FILE...   (PYTHONPATH: the built module)
"""
import sys

import pytest

import velocity

_init = velocity.OffscreenRenderer.__init__


def _on_gpu(self, *args, **kwargs):
    kwargs.setdefault("backend", "gpu")
    _init(self, *args, **kwargs)


velocity.OffscreenRenderer.__init__ = _on_gpu
probe = velocity.OffscreenRenderer(8, 8)  # fails here, clearly, when there is no GPU backend
sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
