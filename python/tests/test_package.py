"""The package's surface: every public name has a docstring and a stub in __init__.pyi."""

import ast
import pathlib

import yinset

STUB = pathlib.Path(yinset.__file__).with_name("__init__.pyi")


def stubbed():
    """Module-level names and {class: method names} declared in the stub."""
    tree = ast.parse(STUB.read_text())
    names, classes = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names.add(node.name)
            inherited = set().union(*(classes.get(b.id, set()) for b in node.bases))
            own = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            classes[node.name] = own | inherited
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return names, classes


def public(cls):
    """The methods and properties a user calls: no private names, the operators included."""
    return {
        n
        for c in cls.__mro__[:-1]
        for n, v in vars(c).items()
        if (not n.startswith("_") or n.startswith("__") and n != "__init__" and callable(v))
        and n not in {"__module__", "__doc__", "__slots__", "__repr__", "__hash__"}
        and (callable(v) or isinstance(v, (property, classmethod)))
    } | {"__init__"}


def test_every_public_name_is_stubbed():
    names, classes = stubbed()
    assert set(yinset.__all__) <= names
    for cls in (yinset.Region, yinset.Solid):
        missing = public(cls) - classes[cls.__name__]
        assert not missing, f"{cls.__name__}: no stub for {sorted(missing)}"


def test_every_public_name_has_a_docstring():
    for cls in (yinset.Region, yinset.Solid):
        assert cls.__doc__
        for name in public(cls) - {"__init__"}:
            assert getattr(cls, name).__doc__, f"{cls.__name__}.{name}"
    assert yinset.YinsetError.__doc__ and issubclass(yinset.YinsetError, ValueError)
