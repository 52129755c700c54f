"""The type stubs describe the module as built: every public name and member, and nothing that does not exist."""
import ast
import builtins
import pathlib

import somicage
from somicage import _somicage

STUB = pathlib.Path(_somicage.__file__).with_name("_somicage.pyi")


def public(names):
    return {n for n in names if not n.startswith("_") or n == "__version__"}


def member_names(class_node):
    names = set()
    for node in class_node.body:
        if isinstance(node, ast.FunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return names


def test_stub_matches_module():
    tree = ast.parse(STUB.read_text())
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    functions = {node.name for node in tree.body if isinstance(node, ast.FunctionDef)}
    variables = {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}
    assert set(classes) | functions | variables == public(dir(_somicage)) == set(somicage.__all__)
    for name, node in classes.items():
        built = getattr(_somicage, name)
        if issubclass(built, Exception):  # the stub's base is the real one; attributes are set per instance
            assert all(issubclass(built, getattr(builtins, base.id)) for base in node.bases), name
            continue
        members = public(vars(built)) | {"__init__"}
        assert member_names(node) == members, f"{name}: {sorted(member_names(node) ^ members)} differ"
