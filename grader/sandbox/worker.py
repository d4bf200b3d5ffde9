"""The child side of the grader: imports a submission and runs probes on it, one request at a time.

This file runs inside the sandbox with the untrusted submission and must stay importable on its own: standard
library only, plus ``protocol.py``, ``notebook.py``, ``confinement.py`` (and its ``seccomp.py``) and the ``probes``
package, which the grader copies next to it.  It never sees the reference, the checks or the scoring code: it
receives probe calls on a dedicated pipe and sends back plain data (see ``protocol`` for the messages).

    python -I -B worker.py REQUEST_FD REPLY_FD SUBMISSION CONFIG_JSON

Start-up, before any code of the submission runs: the confinement (``confinement.confine``: resource limits;
as root without bubblewrap, namespaces of its own and the switch to the unprivileged uid the grader claimed;
Landlock; a fresh session keyring and the system-call filter), then the imports of the dependencies (the probes
package, numpy).  Only then does the worker say ready: a failure up to that point is a fault of the installation,
never of the submission.  A batch slot's warm process forks workers that serve with this same loop
(``forkserver.py``), and so does the portable mode's worker (``portable_worker.py``).
"""

from __future__ import annotations

import importlib
import importlib.util
import json
import os
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    from . import confinement, notebook, protocol
except ImportError:  # run as a script from the runtime directory, next to protocol.py
    import confinement  # type: ignore[no-redef]
    import notebook  # type: ignore[no-redef]
    import protocol  # type: ignore[no-redef]

__all__ = ["serve", "import_dependencies", "seal", "setup_fault", "error_reply", "BlockTrustedPackages", "main",
           "PACKAGE", "RUNTIME", "BLOCKED"]

PACKAGE = "submission"
RUNTIME = os.path.dirname(os.path.abspath(__file__))
#: the grader's own packages: never importable here (the sandbox hides their files as well)
BLOCKED = ("reference", "checks", "grader", "tests", "student_template", "tools")

_codec = None  # probes._codec, imported at start-up
_probes = None  # probes (its ``lookup``), imported at start-up


# ---------------------------------------------------------------- replies


def _student_traceback(exc: BaseException) -> str:
    """The traceback restricted to frames of the submission."""
    root = os.environ.get("GRADER_SUBMISSION", "")
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if root and f.filename.startswith(root)]
    lines = traceback.format_list(frames[-8:])
    lines += traceback.format_exception_only(type(exc), exc)
    text = "".join(lines)
    if root:
        text = text.replace(root + os.sep, "")
    return text[-4000:]


def error_reply(req_id, kind: str, exc: BaseException, text: str | None = None) -> dict:
    return {
        "id": req_id,
        "ok": False,
        "kind": kind,
        "type": type(exc).__name__,
        "message": (str(exc) if text is None else text)[:2000],
        "traceback": _student_traceback(exc),
    }


def _raised_in_probes(exc: BaseException) -> bool:
    """True when the innermost frame of ``exc`` is the grader's probe code, not the submission's."""
    frames = traceback.extract_tb(exc.__traceback__)
    probes_dir = os.path.join(RUNTIME, "probes") + os.sep
    return bool(frames) and frames[-1].filename.startswith(probes_dir)


# ---------------------------------------------------------------- the submission and the probes


class _OwnModules:
    """Jupyter-style imports of the submission's own modules: ``import rotations`` or ``from rotations import R1``
    (as a notebook or a script run inside the work folder writes them) find ``submission.rotations``.  Asked only
    for names that no other finder knows (it comes last), never for the grader's own packages."""

    def __init__(self, root: str):
        self.root = root

    def internal(self, name: str) -> bool:
        top = name.partition(".")[0]
        return bool(top) and top.isidentifier() and top not in BLOCKED and top != PACKAGE and (
            os.path.isfile(os.path.join(self.root, top + ".py"))
            or os.path.isfile(os.path.join(self.root, top, "__init__.py")))

    def find_spec(self, fullname, path=None, target=None):
        if path is not None or "." in fullname or not self.internal(fullname):
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        return importlib.import_module(f"{PACKAGE}.{spec.name}")

    def exec_module(self, module):
        pass


def _import_submission(path: str):
    """Import the submission as the package ``submission``; returns it and what the report should say about its
    notebooks (the definitions of a notebook that raised)."""
    own = _OwnModules(path)
    if not any(isinstance(f, _OwnModules) for f in sys.meta_path):
        sys.meta_path.append(own)
    spec = importlib.util.spec_from_file_location(
        PACKAGE, os.path.join(path, "__init__.py"), submodule_search_locations=[path]
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules[PACKAGE] = module
    spec.loader.exec_module(module)
    return module, _place_notebooks(path, own)


#: written by the loader next to the submission's modules (students cannot submit .json files)
NOTEBOOK_MANIFEST = "_notebooks.json"


def _place_notebooks(path: str, own: _OwnModules) -> list[str]:
    """Run the definitions of the submission's notebooks (each as a module of its own) and put each name into
    the template's modules the loader chose; a function or class of the template that a module had imported
    from another (``from .rotations import R1``) is replaced there too."""
    manifest = os.path.join(path, NOTEBOOK_MANIFEST)
    if not os.path.isfile(manifest):
        return []
    import types

    with open(manifest, encoding="utf-8") as handle:
        books = json.load(handle)["notebooks"]
    notes: list[str] = []
    replaced: dict[int, tuple[object, object]] = {}
    for book in books:
        file = str(book["file"])
        name = f"{PACKAGE}.{book['module']}"
        module = types.ModuleType(name, f"The definitions of the notebook {file}.")
        module.__package__ = PACKAGE
        module.__file__ = os.path.join(path, file)
        sys.modules[name] = module
        cells = [(int(number), str(code)) for number, code in book["cells"]]
        notes += [f"notebook {file}: {note}" for note in notebook.run_cells(
            cells, module.__dict__, set(book["defined"]), lambda n, f=file: os.path.join(path, f"{f}, cell {n}"),
            own.internal)]
        for defined, targets in book["placed"].items():
            if defined not in module.__dict__:
                notes.append(f"notebook {file}: {defined} is not defined after its cells ran (see above), so the "
                             "template's stays")
                continue
            value = module.__dict__[defined]
            for target in targets:
                target_module = importlib.import_module(f"{PACKAGE}.{target}")
                old = target_module.__dict__.get(defined)
                if isinstance(old, (types.FunctionType, type)) and old is not value:
                    replaced[id(old)] = (old, value)
                setattr(target_module, defined, value)
    for module_name, module in list(sys.modules.items()):
        if module is None or not (module_name == PACKAGE or module_name.startswith(PACKAGE + ".")):
            continue
        for key, value in list(vars(module).items()):
            entry = replaced.get(id(value))
            if entry is not None and entry[0] is value:
                setattr(module, key, entry[1])
    return notes


def _handle(request: dict, package, submission: str):
    """The reply to ``request`` and the (possibly just imported) package."""
    req_id = request.get("id")
    phase = "import" if package is None else "call"
    op = request.get("op")
    try:
        if op == "import":
            package, notes = _import_submission(submission)
            reply = {"id": req_id, "ok": True, "value": {"notes": notes[:50]}}
        elif op == "call":
            try:
                probe = _probes.lookup(request.get("probe", ""))
                args = _codec.decode(request.get("args", []))
            except _probes.ProbeLookupError as exc:
                return error_reply(req_id, "probe", exc), package
            if package is None:
                package, _ = _import_submission(submission)
            phase = "call"
            value = probe(package, *args)
            try:
                reply = {"id": req_id, "ok": True, "value": _codec.encode(value)}
            except (TypeError, ValueError) as exc:
                reply = error_reply(req_id, "bad_value", exc)
        else:
            reply = error_reply(req_id, "probe", ValueError(f"unknown operation {op!r}"))
    except NotImplementedError as exc:
        reply = error_reply(req_id, "not_implemented", exc)
    except SystemExit as exc:
        reply = error_reply(req_id, "exit", exc)
    except ImportError as exc:
        # a probe importing a dependency the sandbox lacks is the installation's fault; the submission's own
        # imports are the student's
        kind = "probe" if _raised_in_probes(exc) else "exception"
        reply = error_reply(req_id, kind, exc)
    except BaseException as exc:  # noqa: BLE001 - every failure of student code is reported, not raised
        reply = error_reply(req_id, "exception", exc)
    reply["phase"] = phase
    return reply, package


def serve(request_fd: int, reply_fd: int, submission: str) -> int:
    package = None
    while True:
        request = protocol.read_message(request_fd)
        if request is None or request.get("op") == "exit":
            return 0
        reply, package = _handle(request, package, submission)
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        try:
            protocol.write_message(reply_fd, reply)
        except protocol.ProtocolError as exc:  # a value too large to send
            protocol.write_message(reply_fd, dict(error_reply(reply.get("id"), "bad_value", exc), phase=reply["phase"]))


def import_dependencies(required: list[str]) -> None:
    """Import what the probes need, so that a missing dependency shows now and not as the student's error."""
    global _codec, _probes
    _probes = importlib.import_module("probes")
    _codec = importlib.import_module("probes._codec")
    numpy = importlib.import_module("numpy")
    if getattr(numpy, "__file__", None) is None:  # an empty folder of that name: not numpy
        raise ModuleNotFoundError("No module named 'numpy' (only an empty folder of that name)", name="numpy")
    missing = [name for name in required if getattr(importlib.util.find_spec(name), "origin", None) is None]
    if missing:
        raise ModuleNotFoundError(f"No module named {missing[0]!r} (missing: {', '.join(missing)})", name=missing[0])


class BlockTrustedPackages:
    """Refuses imports of the grader's trusted packages."""

    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in BLOCKED:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None


def setup_fault(exc: BaseException) -> dict:
    """The reply that says the start-up failed (a fault of the installation, never of a submission): what was
    raised, and the module that is missing when an import failed."""
    reply = error_reply(0, "setup", exc, f"{type(exc).__name__}: {exc}")
    reply["missing"] = getattr(exc, "name", None) if isinstance(exc, ImportError) else None
    return reply


def seal() -> None:
    """After the start-up's imports, before any code of a submission: the grader's own packages can no longer be
    imported, and those that were are forgotten."""
    sys.meta_path.insert(0, BlockTrustedPackages())
    for name in [m for m in sys.modules.copy() if m.split(".")[0] in BLOCKED]:
        del sys.modules[name]
    sys.setrecursionlimit(3000)


def main(argv: list[str]) -> int:
    request_fd, reply_fd = int(argv[1]), int(argv[2])
    submission = argv[3]
    config = json.loads(argv[4]) if len(argv) > 4 else {}
    sys.stdin.close()
    try:
        info = confinement.confine(config)
        import_dependencies(config.get("require", []))
    except BaseException as exc:  # noqa: BLE001 - reported to the grader as a fault of the set-up
        protocol.write_message(reply_fd, setup_fault(exc))
        return 70
    seal()
    os.environ["GRADER_SUBMISSION"] = submission
    protocol.write_message(reply_fd, {"id": 0, "ok": True, "op": "ready", "info": info})
    return serve(request_fd, reply_fd, submission)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
