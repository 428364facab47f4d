"""The type stub of the extension (orikin/_orikin.pyi) names what the extension has."""

import ast
import inspect
import os

import orikin
from orikin import _orikin


def stub() -> ast.Module:
    return ast.parse(open(os.path.join(os.path.dirname(orikin.__file__), "_orikin.pyi")).read())


def test_the_stub_declares_every_function_and_method_of_the_extension():
    tree = stub()
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {}
    for n in tree.body:
        if isinstance(n, ast.ClassDef):
            classes[n.name] = {m.name for m in n.body if isinstance(m, ast.FunctionDef)} | {
                m.target.id for m in n.body if isinstance(m, ast.AnnAssign)}
    for name, obj in vars(_orikin).items():
        if name.startswith("__"):
            continue
        if inspect.isclass(obj):
            assert name in classes, f"class {name} is not in the stub"
            for attr in dir(obj):
                if attr.startswith("_") or issubclass(obj, BaseException):
                    continue
                assert attr in classes[name], f"{name}.{attr} is not in the stub"
        elif callable(obj):
            assert name in functions, f"function {name} is not in the stub"
    assert {"Error", "InputError", "SolveError", "Cancelled"} <= set(classes)
