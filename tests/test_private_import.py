"""A private import of the reference (``grader.private``) dropped while another thread imports modules: problems
graded side by side each run the reference's code on a private import of their own (error carried forward, the
diagnosis of formulas), and one problem's drop must not fail because another problem's thread grew
``sys.modules`` meanwhile."""

import sys
import threading
import types

from grader.private import drop_private


def test_a_private_import_is_dropped_while_other_threads_import():
    stop = threading.Event()

    def importer():  # as another problem's thread importing modules: sys.modules grows and shrinks
        names = [f"_side_by_side_{n}" for n in range(200)]
        while not stop.is_set():
            for name in names:
                sys.modules[name] = types.ModuleType(name)
            for name in names:
                sys.modules.pop(name, None)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # switch threads as often as the interpreter can
    thread = threading.Thread(target=importer, daemon=True)
    thread.start()
    errors = []
    try:
        for n in range(3000):
            name = f"_private_drop_{n}"
            package = types.ModuleType(name)
            sys.modules[name] = package
            sys.modules[f"{name}.rotations"] = types.ModuleType(f"{name}.rotations")
            try:
                drop_private(package)
            except RuntimeError as exc:
                errors.append(exc)
                break
    finally:
        stop.set()
        thread.join()
        sys.setswitchinterval(interval)
        for name in [n for n in sys.modules.copy() if n.startswith(("_side_by_side_", "_private_drop_"))]:
            sys.modules.pop(name, None)
    assert not errors, errors[0]
    assert not any(n.startswith("_private_drop_") for n in sys.modules.copy())
