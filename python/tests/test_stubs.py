"""The type stubs (_velocity.pyi) name exactly what the compiled module has."""
import ast
import inspect
import os

import velocity
from velocity import _velocity


def stub_tree():
    path = os.path.join(os.path.dirname(velocity.__file__), "_velocity.pyi")
    return ast.parse(open(path).read())


def test_every_public_name_has_a_stub_and_back():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    actual = {n for n in dir(_velocity) if not n.startswith("__")}
    assert stubbed == actual, (stubbed ^ actual)
    for cls in (n for n in tree.body if isinstance(n, ast.ClassDef)):
        members = {m.name for m in cls.body if isinstance(m, ast.FunctionDef)} | \
                  {m.target.id for m in cls.body if isinstance(m, ast.AnnAssign)}
        real = getattr(_velocity, cls.name)
        for m in members:
            assert hasattr(real, m), f"{cls.name}.{m} is in the stub but not in the module"
        own = {k for k, v in vars(real).items() if not k.startswith("__")} if isinstance(real, type) else set()
        missing = own - members - {"_pybind11_conduit_v1_"}
        assert not missing, f"{cls.name}: {missing} missing from the stub"


def test_stub_arguments_match_the_signatures():
    # pybind11 writes each function's signature as the first line of its docstring.
    for cls in (n for n in stub_tree().body if isinstance(n, ast.ClassDef)):
        for fn in (m for m in cls.body if isinstance(m, ast.FunctionDef) and not any(
                isinstance(d, ast.Name) and d.id == "property" for d in m.decorator_list)):
            real = getattr(getattr(_velocity, cls.name), fn.name)
            names = [a.arg for a in fn.args.args if a.arg != "self"]
            if inspect.isfunction(real):  # written in Python (velocity/__init__.py)
                assert list(inspect.signature(real).parameters) == names, (cls.name, fn.name)
                continue
            doc = (real.__doc__ or "").split("\n")[0]
            for name in names:
                assert f"{name}:" in doc, f"{cls.name}.{fn.name}: argument {name!r} not in {doc!r}"


def test_public_api_has_docstrings():
    for name in velocity.__all__:
        obj = getattr(velocity, name)
        if inspect.isclass(obj) or inspect.isfunction(obj):
            assert (obj.__doc__ or "").strip(), name
