"""The grading code as files: which files decide a problem's verdicts (the import closure of its checks, the
probes they call, the grader's machinery and the reference those probes reach), and one digest of a set of files.

Every question of the kind "has the code changed?" is a ``digest`` of the files it depends on:

* a problem's grader version (``grader_version``): the package version and a digest of ``verdict_sources`` and of
  the versions of the libraries that can change a verdict.  A batch grades a student again when it changed:
  editing the checks of problem 6 regrades problem 6 and nothing else, editing ``checks/_trees.py`` every tree
  problem;
* the answer key's fingerprint (``grader.oracle``): the check and probe modules, which decide which reference
  calls a check makes;
* the reference results cached on disk (``grader.oracle``): the reference and probe modules;
* the problem list of ``grade list`` (``grader.listing``): the check modules and the checking vocabulary.

Nothing here imports the files it reads: they are parsed (``ast``), so that a digest costs no import of numpy or
of the checks.  The same parsing serves the other questions asked of the code: which third-party modules a batch
slot's warm process imports (``grader.sandbox.zygote.warm_modules``) and which files a PrairieLearn question asks a
student to upload (``grader.prairielearn.problem_files``).
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
from functools import lru_cache
from pathlib import Path

from . import __version__

__all__ = [
    "PROJECT_PACKAGES",
    "module_file",
    "package_files",
    "digest",
    "parsed",
    "strings",
    "project_imports",
    "absolute_imports",
    "relative_imports",
    "named_modules",
    "verdict_sources",
    "grader_version",
]

#: the packages of the project whose files the analysis follows
PROJECT_PACKAGES = ("grader", "checks", "probes", "reference")
#: the grader's modules that run every check: the import graph from these reaches the rest of the machinery
MACHINERY = ("grader.runner", "grader.context", "grader.sandbox.worker", "grader.sandbox.forkserver")
#: third-party packages whose versions can change a verdict (random inputs, numerics)
VERDICT_DEPENDENCIES = ("numpy", "scipy", "sympy", "hypothesis", "mujoco")
#: strings shorter than this are read as possible names of modules
_NAME_LENGTH = 80


# ---------------------------------------------------------------------------------------------- files


def module_file(name: str) -> Path | None:
    """The source file of the module ``name`` (imported or not), or None when it has none."""
    import sys

    loaded = sys.modules.get(name)
    origin = getattr(loaded, "__file__", None) if loaded is not None else None
    if origin is None:
        origin = _found_origin(name)
    return Path(origin) if origin and origin.endswith(".py") else None


@lru_cache(maxsize=None)
def _found_origin(name: str) -> str | None:
    """Where the import system finds the module ``name`` that is not imported (asked once per process: every
    problem's ``verdict_sources`` asks for the same machinery)."""
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return None
    return spec.origin if spec else None


def package_files(*packages: str) -> list[Path]:
    """The modules (``*.py``) of each installed package of ``packages``, in order, found without importing them."""
    files = []
    for package in packages:
        spec = importlib.util.find_spec(package)
        if spec is None or not spec.submodule_search_locations:
            continue
        files += sorted(Path(list(spec.submodule_search_locations)[0]).glob("*.py"))
    return files


def _label(path: Path) -> str:
    """``package/name`` of a file: the nearest folder that names a package of the project (or the template)."""
    package = next((p for p in reversed(path.parts[:-1]) if p in (*PROJECT_PACKAGES, "student_template")),
                   path.parent.name)
    return f"{package}/{path.name}"


def digest(paths, prefix: bytes = b"") -> str:
    """One digest of ``paths`` (each file's ``package/name`` and a hash of its bytes, in the order given), after
    ``prefix``: a hexadecimal SHA-256."""
    hasher = hashlib.sha256(prefix)
    for path in paths:
        hasher.update(f"{_label(path)}\0".encode() + hashlib.sha256(path.read_bytes()).digest())
    return hasher.hexdigest()


# ---------------------------------------------------------------------------------------------- parsing


@lru_cache(maxsize=None)
def _tree(source: bytes) -> ast.Module:
    return ast.parse(source)


def parsed(path: Path) -> ast.Module:
    """The syntax tree of the file ``path`` (parsed once per content)."""
    return _tree(Path(path).read_bytes())


def strings(tree: ast.Module) -> set[str]:
    """The string constants of ``tree`` short enough to name a module."""
    return set(_strings(tree))


@lru_cache(maxsize=None)
def _strings(tree: ast.Module) -> frozenset[str]:
    """``strings`` of a tree, walked once per tree (``parsed`` gives one tree per content)."""
    return frozenset(node.value for node in ast.walk(tree)
                     if isinstance(node, ast.Constant) and isinstance(node.value, str)
                     and len(node.value) < _NAME_LENGTH)


def project_imports(tree: ast.Module, package: str) -> set[str]:
    """The modules of the project's packages that ``tree`` (a module of ``package``) imports, anywhere in the file:
    relative imports resolved, and for ``from X import y`` both ``X`` and ``X.y`` (``y`` may be a module)."""
    return set(_project_imports(tree, package))


@lru_cache(maxsize=None)
def _project_imports(tree: ast.Module, package: str) -> frozenset[str]:
    """``project_imports`` of a tree, walked once per tree and package: every problem's ``verdict_sources`` walks
    the same machinery's modules."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1])
                module = f"{base}.{node.module}" if node.module else base
            else:
                module = node.module or ""
            names.add(module)
            names.update(f"{module}.{alias.name}" for alias in node.names)
    return frozenset(n for n in names if n.split(".")[0] in PROJECT_PACKAGES)


def absolute_imports(tree: ast.Module) -> set[str]:
    """The absolute imports anywhere in ``tree`` (function bodies included)."""
    return set(_absolute_imports(tree))


@lru_cache(maxsize=None)
def _absolute_imports(tree: ast.Module) -> frozenset[str]:
    """``absolute_imports`` of a tree, walked once per tree."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and not node.level and node.module:
            names.add(node.module)
    return frozenset(names)


def relative_imports(tree: ast.Module) -> set[str]:
    """The sibling modules ``tree`` imports relatively (``from .rotations import R1``, ``from . import tree``)."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            found |= {node.module.split(".")[0]} if node.module else {alias.name for alias in node.names}
    return found


def named_modules(tree: ast.Module) -> set[str]:
    """The modules a probe module reaches by name: ``module(pkg, "rotations")``."""
    return {n.args[1].value for n in ast.walk(tree)
            if isinstance(n, ast.Call) and getattr(n.func, "id", None) == "module" and len(n.args) >= 2
            and isinstance(n.args[1], ast.Constant) and isinstance(n.args[1].value, str)}


# ---------------------------------------------------------------------------------------------- verdicts


def verdict_sources(problem: int) -> list[Path]:
    """Every file that decides a verdict of ``problem``: its check module and what it imports (the probe modules
    among them: a check names a probe by its function, ``from probes import problem_22 as p22``), the grader's
    machinery, the reference modules the probes reach (by import or by name, ``module(pkg, "tree")``), the
    matching student-template modules (laid under every submission) and the reference's answers."""
    from .problems import problem_module

    seeds = [problem_module(problem).__name__, *MACHINERY, "probes", "probes._codec", "reference"]
    seen: dict[str, Path] = {}
    queue = list(seeds)
    reference_names: set[str] = set()
    while queue:
        name = queue.pop()
        if name in seen:
            continue
        path = module_file(name)
        if path is None:
            continue
        seen[name] = path
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        tree = parsed(path)
        queue += sorted(project_imports(tree, package))
        top = name.split(".")[0]
        if top in ("probes", "checks"):
            reference_names |= {text for text in strings(tree) if text.isidentifier()}
        if top == "reference":
            reference_names.add(name.rpartition(".")[2])
    for text in sorted(reference_names):
        if module_file(f"reference.{text}") is not None:
            queue.append(f"reference.{text}")
    while queue:  # the reference modules named by probes, and their own imports
        name = queue.pop()
        if name in seen or (path := module_file(name)) is None:
            continue
        seen[name] = path
        queue += sorted(project_imports(parsed(path), name.rpartition(".")[0]))
    files = set(seen.values())
    for name, path in seen.items():
        if name.split(".")[0] == "reference":
            files.add(path.with_name("answers.toml"))
            template = module_file("student_template" + name.removeprefix("reference"))
            if template is not None:
                files.add(template)
    return sorted(p for p in files if p.is_file())


@lru_cache(maxsize=1)
def _runtime_versions() -> bytes:
    """Python's version and the versions of the libraries that can change a verdict, read once per process (reading
    a distribution's metadata parses it; the modules a process grades with are those it loaded, whatever is
    installed later)."""
    import importlib.metadata
    import sys

    parts = [f"python {sys.version_info[0]}.{sys.version_info[1]}\0"]
    for name in VERDICT_DEPENDENCIES:
        try:
            parts.append(f"{name} {importlib.metadata.version(name)}\0")
        except importlib.metadata.PackageNotFoundError:
            parts.append(f"{name} -\0")
    return "".join(parts).encode()


def grader_version(problem: int) -> str:
    """The package version and a digest of every file that decides the problem's verdicts
    (``verdict_sources``) and of the versions of the libraries that can change them: editing shared check or
    probe code regrades the problems that use it, and only those."""
    return f"{__version__}+{digest(verdict_sources(problem), _runtime_versions())[:12]}"
