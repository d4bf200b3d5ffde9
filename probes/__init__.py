"""Probes: small functions that drive a package's API with plain inputs and return plain data.

A probe runs twice with the same arguments: in the sandboxed child on the student's package, and in the grader
on the reference.  Probes import nothing from ``reference``, ``checks`` or ``grader``; they receive the package
as their first argument.  Arguments and results are JSON-able data (numpy arrays are encoded by ``_codec``).

A probe may declare, as plain data beside ``@probe``, what its arguments and result are, so that the grader's
diagnosis engine can try common slips on them (``grader.diagnosis``) when the student's value is wrong:

* ``args``: a role per argument (nested like the argument for a dict or a tuple; "" for none): ``"angle"`` (a
  scalar in radians), ``"angles"`` (an array of them), ``"vector"``, ``"rotation"`` (a rotation matrix),
  ``"scalar"`` (a number such as a mass or a length), ``"inertia"`` (a symmetric positive definite matrix, drawn
  with other moments about other axes), ``"matrix"``, ``"step"`` and ``"count"``;
* ``rotation``: the argument (an index, or a path ``(index, key)``) that holds the problem's rotation, to try the
  result and the vector arguments in the other frame;
* ``terms``: the probe (same arguments, run on the reference) that splits the result into named terms:
  ``{"terms": {name: value shaped like the result}, "extra": {name: ...}}``, where the ``terms`` sum to the result
  and the ``extra`` ones are terms that do not belong (gravity counted twice, say); the names are those of
  ``checks._diagnoses.TERMS``;
* ``motion``: for a run, ``{"time": key, "states": (keys,), "events": (keys,)}``; with ``"rhs"``, the probe of the run's
  right-hand side (``rhs(*args, cases)`` for ``(t, y)`` cases, ``y`` the states in their order; ``"rhs_args"``: the
  indices of the run's arguments it takes first, None for one not given; ``"rhs_through"``: the events it holds through,
  where the run goes on by the same model), at which the engine tells a wrong model from a wrong integration; with
  ``"parameters"`` (``{"arg": index, "names": (...), "sheet": probe}``), the argument that holds the run's parameters (a
  mass, an inertia, g; the probe of their sheet values for a run not given them), which the engine tries exchanged and
  scaled by re-running the reference, or ``{"args": (indices), "names": (...), "sheet": probe}`` for parameters given
  one argument each (exchanged, and each given one at its sheet value); with ``"start"`` (``{"arg": index, "name": ...,
  "sheet": probe}``), the argument that holds the run's start and the probe of the sheet's, which the engine tries in
  its place (the start ignored); with ``"parts"`` (``{"arg": index, "names": (...), "sheet": probe}``), an argument that
  holds other values of the run's set-up (a wire's anchor and length), which the engine tries each at the sheet's value
  (that value ignored); with ``"variants"`` (``{"arg": index, "starts": ((i, j), ...), "tolerances": True}``), the
  probe's argument by which the engine asks the reference's run with ``solve_ivp`` called as a slip would call it
  (``_dynamics.solver_variant``: from a start with two entries exchanged, at looser tolerances); with ``"at_events"``
  (``{key: (event, state[, entry])}``), the result's values taken from the state at an event, which the engine tries
  read from its other rows and from other slices of the whole state there (a key that holds a whole state gives the
  engine that state at the event exactly, where it jumps);
* ``constants``: the probe (no arguments) of the problem's named constants (a mass, g, a length);
* ``draw``: False when the engine must not draw a second input itself (the probe is slow, or its arguments must
  keep their relations);
* ``part``: ``{"keys": (key, ...), "probe": name, "args": (index, ...)}`` where the result's values at these keys
  are those of a cheaper probe (its result's values at the same keys) on the arguments at these indices: the
  engine's tier of formulas tries a mutant on that probe first, and on the whole one only where the cheaper one
  reproduces the student's value (the rest of the result is not computed for the mutants that cannot).  It is no
  declaration of the arguments or of the result: a probe that declares only its part is tried by the other tiers
  as one that declares nothing.
* ``rebind``: ``{"module": name, "names": (constant, ...)}``, the constants of the problem's module, numbers or
  rows of numbers (the sheet's angles, lengths, masses, a point) that the probe's functions read rather than take
  as arguments: where the call has nothing else to draw, the engine's second input is the same call with these
  constants drawn anew for its duration (``probes._rebound``).  Like ``part``, it declares nothing of the arguments
  or of the result.
* ``rows``: the index of the argument that is a batch whose rows give the result's rows one each (problem 32's
  torques at the points of a trajectory): the engine's tier of formulas measures a mutant on the few rows that
  differ first, and on the whole batch only where those reproduce the student's value.  Like ``part``, it declares
  nothing of the arguments or of the result.
"""

import contextlib
import importlib
import threading

__all__ = ["probe", "module", "lookup", "name_of", "call_key", "remembered", "fresh", "kept_for_one_code",
           "ProbeLookupError"]

#: the keywords a probe may declare
DECLARATIONS = ("args", "rotation", "terms", "motion", "constants", "step", "draw", "part", "rebind", "rows")


def probe(func=None, *, returns=None, says="", reference_only=False, **declared):
    """Mark ``func(package, *args)`` as callable from the grader: ``@probe(returns=FORM, ...)``.

    ``returns``: the form of its reply (``probes._forms``), to which the grader holds every reply of the student's
    side before a check uses it; ``says``: how a message names the call (``"R{0}({1})"``, formatted with the
    arguments shown short); ``reference_only``: the probe reads the reference's own data (a key, a constant, a
    catalogue of mistakes, the terms of a value) and is never run on a student's package; the other keywords are
    the declarations of the module's docstring.  ``probe(func)`` alone only marks it (a probe replaced inside the
    student's process)."""
    unknown = set(declared) - set(DECLARATIONS)
    if unknown:
        raise TypeError(f"unknown probe declarations: {sorted(unknown)}")

    def mark(f):
        f.is_probe = True
        f.returns = returns
        f.says = says
        f.reference_only = reference_only
        f.declared = dict(declared)
        return f

    return mark(func) if func is not None else mark


class Flag(threading.local):
    """A flag of the running thread, off until ``within()`` sets it for the duration of a ``with`` block."""

    on = False

    @contextlib.contextmanager
    def within(self):
        before = self.on
        self.on = True
        try:
            yield
        finally:
            self.on = before


class _Fresh(Flag):
    """``Flag`` of ``fresh()``, with the store of ``kept_for_one_code()`` (None: nothing is kept within)."""

    kept = None


_FRESH = _Fresh()


def remembered(store: dict, key, make):
    """``store[key]``, made by ``make()`` the first time: what a probe computes once per package and process (a
    symbolic answer simplified and lambdified).  Within ``fresh()`` it is made anew and not kept, unless a
    ``kept_for_one_code()`` around it keeps it until that block ends."""
    if _FRESH.on:
        kept = _FRESH.kept
        if kept is None:
            return make()
        key = (id(store), key)
        if key not in kept:
            kept[key] = make()
        return kept[key]
    if key not in store:
        store[key] = make()
    return store[key]


@contextlib.contextmanager
def fresh(alone: bool = False):
    """Within: the probes of this thread remember nothing (``remembered``), for a package whose functions' code
    changes between calls (the diagnosis engine's mutants of the reference); ``alone``: nor do they hear what a
    ``kept_for_one_code()`` around keeps (the package's constants are bound to other values within)."""
    with _keeping(None) if alone else contextlib.nullcontext(), _FRESH.within():
        yield


def kept_for_one_code(store: dict | None = None):
    """Within: what the probes of this thread compute inside ``fresh()`` is remembered in ``store`` (a new one
    where None is given), as the calls of a package whose code does not change remember it: the calls of one code
    of a package on several inputs (one mutant of the reference) share it, and no other code hears it."""
    return _keeping({} if store is None else store)


@contextlib.contextmanager
def _keeping(store: dict | None):
    """Within: ``store`` is what ``remembered`` keeps inside ``fresh()`` (None: nothing), as it was after."""
    before = _FRESH.kept
    _FRESH.kept = store
    try:
        yield
    finally:
        _FRESH.kept = before


def module(package, name):
    """The submodule ``name`` of ``package`` (e.g. ``module(pkg, "rotations")``)."""
    return importlib.import_module(f"{package.__name__}.{name}")


class ProbeLookupError(LookupError):
    """A name that names no probe: a fault of the grader's checks, never of a submission."""


def name_of(probe) -> str:
    """The name of ``probe`` (``"problem_22.loop"``): the module below ``probes`` and the function's name.  The
    name crosses the sandbox's pipe, keys the oracle's cache and the kit's answer key; a name passes unchanged."""
    if isinstance(probe, str):
        return probe
    module_name = getattr(probe, "__module__", None) or ""
    func_name = getattr(probe, "__name__", None) or ""
    if not getattr(probe, "is_probe", False) or not module_name.startswith(f"{__name__}.") or not func_name:
        raise ProbeLookupError(f"{probe!r} is not a probe (a function of probes.* marked @probe)")
    return f"{module_name.removeprefix(f'{__name__}.')}.{func_name}"


def call_key(probe, args: tuple) -> str:
    """A stable text key for a probe call: the probe's name (of the probe, or the name itself) and its arguments as
    plain data (JSON).  It keys the oracle's cache and the kit's answer key, and names the diagnosis engine's draw
    sites."""
    import json

    from ._codec import encode

    return name_of(probe) + json.dumps(encode(list(args)), sort_keys=True)


def lookup(name: str):
    """The probe function named ``name`` (``"problem_22.loop"``), the inverse of ``name_of``; ``ProbeLookupError``
    when the name names no probe."""
    module_name, _, func_name = str(name).rpartition(".")
    if not module_name or not func_name:
        raise ProbeLookupError(f"{name!r} does not name a probe (module.function)")
    try:
        found = importlib.import_module(f"{__name__}.{module_name}")
    except ImportError as exc:
        raise ProbeLookupError(f"the probe module {__name__}.{module_name} cannot be imported: {exc}") from exc
    func = getattr(found, func_name, None)
    if func is None or not getattr(func, "is_probe", False):
        raise ProbeLookupError(f"{__name__}.{module_name} has no probe {func_name!r}")
    return func
