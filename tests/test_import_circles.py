"""No import circle in ``grader/``: no module imports, directly or through others, a module that imports it.

Every import counts, wherever it is written (at the top of a module or inside a function, where a circle hides from
Python's import machinery until the function runs, or in a package's table of names imported when first used), and
importing ``a.b.c`` imports the packages ``a`` and ``a.b``
first, so it counts as importing them too (but for the packages the importing module is inside of: they are being
imported already).  The test parses the files (``ast``); nothing is imported.
"""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: the table of a package's names that ``grader.lazy`` imports when first used: name -> submodule
LAZY = "_WHERE"


def modules_of(root: Path, package: str) -> dict[str, Path]:
    """Every module of the package folder ``root`` by its dotted name (``grader.sandbox.child``)."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        parts = list(path.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join([package, *parts])] = path
    return found


def imported(name: str, path: Path, known: dict[str, Path]) -> set[str]:
    """The modules of ``known`` that the module ``name`` (its file ``path``) imports anywhere, each with the
    packages above it."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    targets: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1])
                module = f"{base}.{node.module}" if node.module else base
            else:
                module = node.module or ""
            targets.add(module)
            targets |= {f"{module}.{alias.name}" for alias in node.names}  # a submodule, when it is one
        elif (isinstance(node, ast.Assign) and any(getattr(t, "id", "") == LAZY for t in node.targets)
              and isinstance(node.value, ast.Dict)):  # a package's names imported when first used (grader.lazy)
            targets |= {f"{package}.{v.value}" for v in node.value.values if isinstance(v, ast.Constant)}
    own = {".".join(name.split(".")[:i]) for i in range(1, name.count(".") + 1)}  # the packages it is inside of
    edges = set()
    for target in targets:
        parts = target.split(".")
        edges |= {".".join(parts[:i]) for i in range(1, len(parts) + 1)} & known.keys()
    return edges - own - {name}


def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of ``graph`` with more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in sorted(graph.get(node, ())):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def import_graph(root: Path, package: str) -> dict[str, set[str]]:
    known = modules_of(root, package)
    return {name: imported(name, path, known) for name, path in known.items()}


def test_no_import_circle_in_the_grader():
    graph = import_graph(ROOT / "grader", "grader")
    assert "grader.sandbox.child" in graph and "grader.runner" in graph["grader.cli"]
    found = circles(graph)
    described = ["; ".join(f"{a} -> {', '.join(sorted(graph[a] & set(c)))}" for a in c) for c in found]
    assert not found, "import circles in grader/:\n" + "\n".join(described)


@pytest.mark.parametrize("files, expected", [
    ({"__init__.py": "", "a.py": "from . import b\n", "b.py": "from .a import x\n"}, [["p.a", "p.b"]]),
    ({"__init__.py": "", "a.py": "def f():\n    from .b import y\n", "b.py": "import p.a\n"}, [["p.a", "p.b"]]),
    ({"__init__.py": "", "a.py": "from .sub.c import z\n", "sub/__init__.py": "from .. import a\n",
      "sub/c.py": ""}, [["p.a", "p.sub"]]),
    ({"__init__.py": "_WHERE = {'f': 'b'}\n", "a.py": "", "b.py": "from p import a\nimport p\n"}, []),
    ({"__init__.py": "", "a.py": "import p.sub\n", "sub/__init__.py": "_WHERE = {'g': 'c'}\n",
      "sub/c.py": "from ..a import x\n"}, [["p.a", "p.sub", "p.sub.c"]]),
    ({"__init__.py": "", "a.py": "from . import b\n", "b.py": "import json\n"}, []),
])
def test_a_circle_is_found_wherever_its_import_is_written(tmp_path, files, expected):
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    assert circles(import_graph(tmp_path, "p")) == expected
