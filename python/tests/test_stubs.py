"""The .pyi stubs describe what the extension has: every stubbed function, class and class member
exists in the module (so editors never complete a name that fails at run time), and every public
function and class of the module is stubbed."""

from __future__ import annotations

import ast
import importlib
import pathlib

import pytest

import voronav

STUB_DIR = pathlib.Path(voronav.__file__).parent
MODULES = ["io", "planning", "field", "voronoi", "topology", "mapping", "coordination", "netsim", "explore", "render"]
ALIASES = {"PoseLike", "Cell", "Point", "ColorLike", "_Grid"}  # typing aliases / stub-only bases


def stub_names(path: pathlib.Path) -> dict[str, set[str]]:
    tree = ast.parse(path.read_text())
    out: dict[str, set[str]] = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = set()
        elif isinstance(node, ast.ClassDef):
            members = set()
            for n in node.body:
                if isinstance(n, ast.FunctionDef) and not n.name.startswith("_"):
                    members.add(n.name)
                elif isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name):
                    members.add(n.target.id)
                elif isinstance(n, ast.Assign):
                    members.update(t.id for t in n.targets if isinstance(t, ast.Name))
            out[node.name] = members
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 1 and node.module != "":
            out.update({a.asname or a.name: set() for a in node.names if a.asname == a.name})  # re-exports
    return out


@pytest.mark.parametrize("name", ["__init__", *MODULES])
def test_stubs_match_module(name):
    module = voronav if name == "__init__" else importlib.import_module(f"voronav.{name}")
    stubs = stub_names(STUB_DIR / f"{name}.pyi")
    assert stubs, name
    for sym, members in stubs.items():
        if sym in ALIASES:
            continue
        assert hasattr(module, sym), f"{name}.pyi: {sym} is not in the module"
        obj = getattr(module, sym)
        for m in members:
            assert hasattr(obj, m), f"{name}.pyi: {sym}.{m} is not in the module"
    public = {n for n in dir(module) if not n.startswith("_") and callable(getattr(module, n))}
    missing = sorted(public - set(stubs))
    if name == "__init__":
        missing = [n for n in missing if n not in MODULES]
    assert not missing, f"{name}: not in the stubs: {missing}"
