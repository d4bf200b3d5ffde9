"""The one door to the reference: every value of the reference that a check uses comes through an oracle.

* ``LiveOracle`` imports ``reference`` and runs a probe on it (the instructor's grader, batch grading, Gradescope).
  Results are cached in memory and, for ``persist=True``, on disk; a disk entry names its probe call and carries a
  keyed digest of its payload, and an entry that does not verify is discarded and recomputed.
* ``KeyOracle`` answers from a recorded *answer key* (the student kit, which holds no reference code): the
  reference calls made while the reference itself was graded, the pools of randomized inputs and the random draws
  of the public checks.  Secret and hidden checks are not run with it (they are graded on submission).
* ``RecordingOracle`` is a live oracle that records every call, pool and draw into an ``AnswerKey``: ``grade kit``
  grades the reference with it to build the key.

``current()`` picks the oracle of the process: ``GRADER_ORACLE=live`` or ``GRADER_ORACLE=key:PATH`` forces a mode;
otherwise an answer key installed with the kit is used when there is one, else the live reference.
"""

from __future__ import annotations

import atexit
import gzip
import hashlib
import hmac
import importlib
import importlib.util
import json
import os
import shutil
import tempfile
import threading
import zlib
from collections import OrderedDict
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import probes
from probes import call_key

from .errors import GraderFault

__all__ = [
    "AnswerKey",
    "Oracle",
    "LiveOracle",
    "KeyOracle",
    "RecordingOracle",
    "current",
    "set_current",
    "installed_key_path",
    "reference_available",
    "sources_fingerprint",
    "KEY_FILE",
    "draw_pool",
    "hypothesis_run",
    "private_hypothesis_home",
]

#: where the kit installs its answer key (inside the ``grader`` package)
KEY_FILE = "answer_key.json.gz"
KEY_FORMAT = "mbd-autograder answer key"
KEY_VERSION = 1


def _roundtrip(value):
    """``value`` as it comes back from the child: encoded to plain data and decoded again."""
    from probes._codec import decode, encode

    return decode(encode(value))


def _site_seed(seed: int, site: str) -> list[int]:
    """The seed of one draw site: the run's (or the kit's) seed and a hash of the site's name."""
    return [int(seed) & 0xFFFFFFFF, zlib.crc32(site.encode())]


_HYPOTHESIS_HOME: Path | None = None


def private_hypothesis_home() -> Path:
    """Point hypothesis's storage (its example database, and the constants it collects from the source files of
    local modules, the reference's included) at a private temporary folder removed at exit: never the folder where
    ``grade`` runs, nor anywhere a student can read."""
    global _HYPOTHESIS_HOME
    if _HYPOTHESIS_HOME is None:
        from hypothesis.configuration import set_hypothesis_home_dir

        home = Path(tempfile.mkdtemp(prefix="grader-hypothesis-"))
        atexit.register(shutil.rmtree, home, True)
        set_hypothesis_home_dir(home)
        _HYPOTHESIS_HOME = home
    return _HYPOTHESIS_HOME


#: the grader's own runs of hypothesis in this process (``hypothesis_run``), and the lock that counts them
_RUNS = {"count": 0, "saved": None}
_RUNS_LOCK = threading.Lock()


@contextmanager
def hypothesis_run():
    """A run of hypothesis by the grader (a shrink, a pool of draws): its storage private (``private_hypothesis_home``)
    and its draws independent of the source files of the process.

    hypothesis (since 6.131) now and then draws a literal that it found in the source of the process's "local"
    modules, those outside site-packages: the grader itself when installed editable, the reference, whatever a
    caller imported before.  An input drawn from a seed, and the minimal failing input shrunk from it, would then
    depend on how the grader was installed and on which modules were imported first (a batch slot imports every
    problem's, ``grade problem-N`` one problem's), and the first draw of each process would parse every such file
    (seconds, in a grading of a second).  Within the grader's runs hypothesis sees no local constants (its own
    built-in ones stay); other code of the process (a notebook's own use of hypothesis) keeps its behaviour."""
    private_hypothesis_home()
    with _RUNS_LOCK:
        if _RUNS["count"] == 0:
            _RUNS["saved"] = _blind_to_local_constants()
        _RUNS["count"] += 1
    try:
        yield
    finally:
        with _RUNS_LOCK:
            _RUNS["count"] -= 1
            if _RUNS["count"] == 0 and _RUNS["saved"] is not None:
                _RUNS["saved"]()
                _RUNS["saved"] = None


def _blind_to_local_constants():
    """Make hypothesis's providers see no local constants, with a cache of permitted constants of their own; returns
    the undoing, or None where this hypothesis collects none (before 6.131) or keeps them elsewhere."""
    try:
        from hypothesis.internal.conjecture import providers

        collect, cache = providers._get_local_constants, providers.CONSTANTS_CACHE
        none, blind_cache = providers.Constants(), type(cache)(1024)
    except (ImportError, AttributeError, TypeError):
        return None

    providers._get_local_constants = lambda: none
    providers.CONSTANTS_CACHE = blind_cache

    def undo():
        providers._get_local_constants, providers.CONSTANTS_CACHE = collect, cache

    return undo


def draw_pool(strategy, examples: int, seed: int) -> list:
    """``examples`` argument tuples drawn from ``strategy`` with ``seed``.  A strategy of ``grader.strategies``
    draws them itself (no hypothesis); a hypothesis strategy runs hypothesis's generation only (no test runs,
    nothing shrinks, nothing is stored)."""
    from .strategies import Strategy, draw_examples

    if isinstance(strategy, Strategy):
        return draw_examples(strategy, examples, seed)
    from hypothesis import HealthCheck, Phase, Verbosity, given, settings
    from hypothesis import seed as hyp_seed

    drawn: list = []

    @settings(
        max_examples=examples,
        database=None,
        deadline=None,
        derandomize=False,
        suppress_health_check=list(HealthCheck),
        phases=(Phase.generate,),
        verbosity=Verbosity.quiet,
        report_multiple_bugs=False,
        print_blob=False,
    )
    @hyp_seed(seed)
    @given(strategy)
    def collect(args):
        drawn.append(args)

    with hypothesis_run():
        collect()
    return drawn[:examples]


# ---------------------------------------------------------------------------------------------- the key


@dataclass
class AnswerKey:
    """What the student kit knows of the reference.

    ``calls``: ``call_key(probe, args)`` → ``{"value": encoded result, "checks": [check ids that made the call]}``,
    with ``"sheet": True`` where the value is held at the sheet's digits only (``round_fixed_cases``);
    ``pools``: site (``"p06.cardan_values#0"``: check id and the index of the draw within the check) → the encoded
    argument tuples of a randomized comparison; ``draws``: site → the encoded data a check drew with ``ctx.draw``.
    ``withheld``: public checks that use a value a secret or hidden check uses (a port that prints the predicted
    output, say): the key holds nothing of theirs, and the kit defers them like the secret ones.
    ``upstream``: ``call_key(probe, args)`` of a probe that a check judges on the student's own functions of
    earlier problems → the calls ``[function, encoded args, parent]`` that the reference's logic of it makes of them
    (``parent``: the index of the call within whose own code it was made, -1 for the probe's own code; see
    ``grader.upstream``; their values are among ``calls``, as the probe ``_upstream.call``).
    ``fingerprint`` identifies the checks and probes the key was recorded with; ``seed`` is the kit's seed.
    """

    seed: int
    fingerprint: str
    grader_version: str = ""
    calls: dict = field(default_factory=dict)
    pools: dict = field(default_factory=dict)
    draws: dict = field(default_factory=dict)
    withheld: list = field(default_factory=list)
    upstream: dict = field(default_factory=dict)

    def drop_checks(self, check_ids) -> None:
        """Remove everything recorded only for ``check_ids``: their calls (unless another check made them too),
        their pools and their draws."""
        check_ids = set(check_ids)
        for key in list(self.calls):
            if set(self.calls[key]["checks"]) <= check_ids:
                del self.calls[key]
        for table in (self.pools, self.draws):
            for site in list(table):
                if site.rpartition("#")[0] in check_ids:
                    del table[site]

    def round_fixed_cases(self, fixed) -> dict:
        """Hold the fixed cases at the sheet's digits only: every call in ``fixed`` (the reference's answers to the
        fixed cases of the public checks, outside randomized comparisons and the diagnosis engine's own calls: the
        sheet's cases, which every grading asks again, and what a check asks of the student when one fails) gets its
        numbers at the sheet's precision (``checking.round_to_sheet``), so that a lookup of the key cannot stand in for the student's code.  Two
        kinds keep their precision: the traces of runs (``_is_run``: a check of a run also runs one of its own,
        drawn at each grading, which no key holds), and the calls of the student's own upstream functions
        (``_upstream.call``: the kit tells with them whether those functions differ from the reference's).
        Returns the values before, by call."""
        originals = {}
        for key in sorted(set(fixed) & set(self.calls)):
            if key.startswith("_upstream.call[") or _is_run(self.calls[key]["value"]):
                continue
            entry = self.calls[key]
            originals[key] = entry["value"]
            entry["value"], entry["sheet"] = _rounded(entry["value"]), True
        return originals

    def to_json(self) -> dict:
        return {
            "format": KEY_FORMAT,
            "version": KEY_VERSION,
            "grader_version": self.grader_version,
            "fingerprint": self.fingerprint,
            "seed": self.seed,
            "calls": self.calls,
            "pools": self.pools,
            "draws": self.draws,
            "withheld": self.withheld,
            "upstream": self.upstream,
        }

    def dumps(self) -> bytes:
        """The key as gzip-compressed JSON (deterministic: sorted keys, no time stamp)."""
        text = json.dumps(self.to_json(), sort_keys=True, separators=(",", ":")).encode()
        return gzip.compress(text, compresslevel=9, mtime=0)

    def save(self, path: str | Path) -> Path:
        path = Path(path)
        path.write_bytes(self.dumps())
        return path

    @classmethod
    def loads(cls, data: bytes) -> "AnswerKey":
        try:
            raw = json.loads(gzip.decompress(data))
        except (OSError, ValueError, EOFError) as exc:
            raise GraderFault(f"the answer key cannot be read: {exc}") from exc
        if not isinstance(raw, dict) or raw.get("format") != KEY_FORMAT or raw.get("version") != KEY_VERSION:
            raise GraderFault("the answer key has an unknown format: reinstall the kit your instructor gave you")
        return cls(int(raw["seed"]), str(raw["fingerprint"]), str(raw.get("grader_version", "")),
                   dict(raw["calls"]), dict(raw["pools"]), dict(raw.get("draws", {})), list(raw.get("withheld", [])),
                   dict(raw.get("upstream", {})))

    @classmethod
    def load(cls, path: str | Path) -> "AnswerKey":
        try:
            data = Path(path).read_bytes()
        except OSError as exc:
            raise GraderFault(f"the answer key {path} cannot be read: {exc}") from exc
        return cls.loads(data)


def _is_run(encoded) -> bool:
    """True for the traces of a run (a dict of arrays over its output times ``t`` or steps ``step``)."""
    return isinstance(encoded, dict) and ("t" in encoded or "step" in encoded)


def _rounded(encoded):
    """Encoded plain data with every number at the sheet's precision (``round_to_sheet``), but the output times
    ``"t"`` of a run."""
    from .checking import round_to_sheet

    if isinstance(encoded, bool) or encoded is None or isinstance(encoded, str):
        return encoded
    if isinstance(encoded, float):
        return round_to_sheet(encoded)
    if isinstance(encoded, int):
        return encoded
    if isinstance(encoded, list):
        return [_rounded(item) for item in encoded]
    if isinstance(encoded, dict):  # a run's output times are its grid, not an answer: they keep their precision
        return {key: (value if key in ("__array__", "t") else _rounded(value)) for key, value in encoded.items()}
    return encoded


def sources_fingerprint() -> str:
    """A digest of what decides which reference calls a check makes: the check modules and the probes."""
    from .sources import digest, package_files

    return digest(package_files("checks", "probes"))[:16]


# ---------------------------------------------------------------------------------------------- oracles


class Oracle:
    """The interface checks reach through the grading context."""

    #: "live" (the reference), "kit" (a recorded answer key) or "record" (live, recording a key)
    mode = "live"
    #: randomized comparisons draw from recorded pools (kit, record) rather than fresh hypothesis inputs
    pooled = False
    #: the reference's code can run on the student's own upstream functions (``grader.upstream``): not in the kit
    composes = True

    def reference(self, probe: str, args: tuple, persist: bool = False, check: str | None = None):
        raise NotImplementedError

    def pool(self, site: str, strategy, examples: int, check: str | None = None) -> list:
        raise NotImplementedError

    def draw(self, site: str, make, seed: int, check: str | None = None):
        import numpy as np

        return _roundtrip(make(np.random.default_rng(_site_seed(seed, site))))

    def runs(self, spec, check_id: str) -> bool:
        """Whether a check runs here: the kit (and the recording of its key) leave out secret and hidden checks."""
        return True

    def held_at_sheet_digits(self, probe: str, args: tuple) -> bool:
        """In the kit: the key holds the value of this call at the sheet's digits only."""
        return False

    @contextmanager
    def diagnosing(self):
        """While the diagnosis engine asks the reference (its inputs transformed, its terms, its own second input):
        what it asks is a value a diagnosis needs, which the kit's key holds at full precision
        (``AnswerKey.round_fixed_cases``) unless a check asks the same call for a fixed case."""
        before = _in_diagnosis()
        _ASKING.diagnosis = True
        try:
            yield
        finally:
            _ASKING.diagnosis = before

    def record_upstream(self, key: str, calls) -> None:
        """While a key is recorded: the forwarded calls ``[(function, args, parent)]`` of the probe call ``key``
        (see ``grader.upstream``)."""

    def upstream_calls(self, key: str) -> list:
        """In the kit: the forwarded calls ``[(function, args, parent)]`` recorded for the probe call ``key``."""
        raise NotImplementedError

    def model_answers(self) -> dict:
        """The reference's answers.toml (model answers of free-text questions); empty without the reference."""
        return {}


def reference_available() -> bool:
    try:
        return importlib.util.find_spec("reference") is not None
    except (ImportError, ValueError):
        return False


@lru_cache(maxsize=1)
def _reference_package():
    try:
        return importlib.import_module("reference")
    except ImportError as exc:
        raise GraderFault("the reference solution is not installed: this grader needs the full project "
                          f"({exc})") from exc


@lru_cache(maxsize=1)
def _source_hash() -> str:
    """A digest of the reference and probe sources: persisted reference results are valid for one digest only."""
    from .sources import digest, package_files

    return digest(package_files("reference", "probes"))[:16]


def _cache_base() -> Path:
    base = os.environ.get("GRADER_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "mbd-autograder"
    )
    return Path(base)


def _cache_secret(base: Path) -> bytes | None:
    """The secret that keys the digests of the disk cache (created on first use, readable by its owner only);
    None when it can be neither read nor created (then nothing is persisted)."""
    path = base / "cache.secret"
    for _ in range(2):
        try:
            secret = path.read_bytes()
            if len(secret) == 32:
                return secret
            path.unlink()
        except FileNotFoundError:
            pass
        except OSError:
            return None
        try:
            base.mkdir(parents=True, exist_ok=True, mode=0o700)
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        except FileExistsError:
            continue
        except OSError:
            return None
        with os.fdopen(fd, "wb") as handle:
            handle.write(os.urandom(32))
    return None


#: reference results a live oracle keeps in memory, the least recently used dropped first: a batch's slot grades
#: student after student, each with random inputs of their own (about 1,700 new results, 16 MB, for the whole
#: course), so an unbounded memory grows without end; the sheet's fixed cases, which every student asks for, are
#: used again at each student and stay
MEMORY_ENTRIES = 4096


class LiveOracle(Oracle):
    """The reference itself: probes run on the imported ``reference`` package (in the grader's process)."""

    mode = "live"

    def __init__(self):
        self._memory: OrderedDict[str, tuple[object, object]] = OrderedDict()  # key -> (encoded, decoded)

    # ---------------------------------------------------------------- computing

    def _run(self, probe: str, args: tuple):
        from .gate import probe_function

        return probe_function(probe)(_reference_package(), *args)

    def compute(self, probe: str, args: tuple, persist: bool = False):
        """``(key, encoded, value)`` of the probe's result on the reference, through the caches."""
        from probes._codec import decode, encode

        key = call_key(probe, args)
        if key in self._memory:
            self._memory.move_to_end(key)
            encoded, value = self._memory[key]
            return key, encoded, value
        encoded = self._disk_read(key) if persist else None
        if encoded is None:
            try:
                # Round-trip through the codec so that the reference's result has exactly the student's types.
                encoded = encode(self._run(probe, args))
            except GraderFault:
                raise
            except Exception as exc:  # noqa: BLE001 - any failure here is the grader's
                raise GraderFault(f"the reference failed on {probe}{args!r}: {type(exc).__name__}: {exc}") from exc
            if persist:
                self._disk_write(key, encoded)
        value = decode(encoded)
        self._memory[key] = (encoded, value)
        while len(self._memory) > MEMORY_ENTRIES:
            self._memory.popitem(last=False)
        return key, encoded, value

    def reference(self, probe: str, args: tuple, persist: bool = False, check: str | None = None):
        return self.compute(probe, args, persist)[2]

    def model_answers(self) -> dict:
        from .loader import read_answers

        answers, _ = read_answers(Path(_reference_package().__file__).parent)
        return answers

    # ---------------------------------------------------------------- the disk cache

    @staticmethod
    def _digest(secret: bytes, key: str, payload: str) -> str:
        return hmac.new(secret, key.encode() + b"\0" + payload.encode(), hashlib.sha256).hexdigest()

    @staticmethod
    def _entry_path(key: str) -> Path:
        return _cache_base() / _source_hash() / (hashlib.sha256(key.encode()).hexdigest() + ".json")

    def _disk_read(self, key: str):
        """The encoded payload cached for ``key``, or None; an entry that does not verify is removed."""
        path = self._entry_path(key)
        if not path.exists():
            return None
        secret = _cache_secret(_cache_base())
        try:
            entry = json.loads(path.read_text())
            payload = entry["payload"]
            valid = (secret is not None and isinstance(entry, dict) and entry.get("key") == key
                     and isinstance(payload, str)
                     and hmac.compare_digest(str(entry.get("digest", "")), self._digest(secret, key, payload)))
            if valid:
                return json.loads(payload)
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            pass
        try:
            path.unlink()
        except OSError:
            pass
        return None

    def _disk_write(self, key: str, encoded) -> None:
        secret = _cache_secret(_cache_base())
        if secret is None:
            return
        path = self._entry_path(key)
        payload = json.dumps(encoded)
        entry = {"key": key, "payload": payload, "digest": self._digest(secret, key, payload)}
        try:
            path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            tmp.write_text(json.dumps(entry))
            os.replace(tmp, path)
        except OSError:
            pass


#: whether the diagnosis engine is asking the reference (``Oracle.diagnosing``), per thread
_ASKING = threading.local()


def _in_diagnosis() -> bool:
    return getattr(_ASKING, "diagnosis", False)


def _reference_only(probe: str) -> bool:
    """True for a probe that reads the reference's own data (a constant, a key, a catalogue of mistakes): never a
    student's answer, so the kit holds it as it is."""
    try:
        return bool(getattr(probes.lookup(probes.name_of(probe)), "reference_only", False))
    except probes.ProbeLookupError:
        return False


def _secret(spec) -> bool:
    return spec.secret or spec.visibility == "hidden"


class RecordingOracle(LiveOracle):
    """A live oracle that records every reference call, pool and draw into an ``AnswerKey``.  It runs the public
    checks (the key), or with ``secret=True`` only the secret and hidden ones (to learn which values the key must
    not hold)."""

    mode = "record"
    pooled = True

    def __init__(self, seed: int, fingerprint: str | None = None, secret: bool = False):
        super().__init__()
        from . import __version__

        self.secret = secret
        self.key = AnswerKey(int(seed), fingerprint or sources_fingerprint(), __version__)
        self.fixed_keys: set[str] = set()  # calls of the reference on fixed cases (see round_fixed_cases)
        self.student_fixed_keys: set[str] = set()  # calls of the "student" (the reference) on fixed cases
        self.diagnosis_keys: set[str] = set()  # calls of the reference the diagnosis engine asked

    def reference(self, probe: str, args: tuple, persist: bool = False, check: str | None = None):
        from .checking import in_random_input

        key, encoded, value = self.compute(probe, args, persist)
        if not in_random_input() and not _in_diagnosis() and not _reference_only(probe):
            self.fixed_keys.add(key)
        if _in_diagnosis():
            self.diagnosis_keys.add(key)
        entry = self.key.calls.setdefault(key, {"value": encoded, "checks": []})
        if check is not None and check not in entry["checks"]:
            entry["checks"].append(check)
        return value

    def pool(self, site: str, strategy, examples: int, check: str | None = None) -> list:
        from probes._codec import decode, encode

        if site not in self.key.pools:
            drawn = draw_pool(strategy, examples, self.key.seed * 2**32 + zlib.crc32(site.encode()))
            self.key.pools[site] = [encode(list(args)) for args in drawn]
        return [tuple(decode(args)) for args in self.key.pools[site]]

    def draw(self, site: str, make, seed: int, check: str | None = None):
        import numpy as np
        from probes._codec import decode, encode

        if site not in self.key.draws:
            self.key.draws[site] = encode(make(np.random.default_rng(_site_seed(self.key.seed, site))))
        return decode(self.key.draws[site])

    def runs(self, spec, check_id: str) -> bool:
        return _secret(spec) == self.secret

    def record_upstream(self, key: str, calls) -> None:
        from probes._codec import encode

        self.key.upstream.setdefault(key, [[function, encode(list(args)), parent] for function, args, parent in calls])

    def recorded(self) -> dict:
        """What this oracle recorded, without its caches: for ``absorb`` in another process."""
        return {"calls": self.key.calls, "pools": self.key.pools, "draws": self.key.draws,
                "upstream": self.key.upstream, "fixed": self.fixed_keys, "student_fixed": self.student_fixed_keys,
                "diagnosis": self.diagnosis_keys}

    def absorb(self, recorded: dict) -> None:
        """Join another oracle's recording (``recorded``) of later problems as if this oracle had recorded them
        after its own: a call already held keeps its value and gains the other's checks, in order."""
        for call, entry in recorded["calls"].items():
            held = self.key.calls.setdefault(call, {"value": entry["value"], "checks": []})
            held["checks"] += [check for check in entry["checks"] if check not in held["checks"]]
        for mine, theirs in ((self.key.pools, "pools"), (self.key.draws, "draws"), (self.key.upstream, "upstream")):
            for name, value in recorded[theirs].items():
                mine.setdefault(name, value)
        self.fixed_keys |= recorded["fixed"]
        self.student_fixed_keys |= recorded["student_fixed"]
        self.diagnosis_keys |= recorded["diagnosis"]


class KeyOracle(Oracle):
    """The recorded answer key of the student kit."""

    mode = "kit"
    pooled = True
    composes = False

    def __init__(self, key: AnswerKey, check_fingerprint: bool = True):
        self.key = key
        self._memory: dict[str, object] = {}
        self.missing: list[str] = []  # calls a check asked that the key does not hold
        if check_fingerprint and key.fingerprint != sources_fingerprint():
            raise GraderFault("the answer key was recorded with other checks or probes than the installed ones: "
                              "rebuild the kit (grade kit) or reinstall the kit your instructor gave you")

    def reference(self, probe: str, args: tuple, persist: bool = False, check: str | None = None):
        from probes._codec import decode

        key = call_key(probe, args)
        if key in self._memory:
            return self._memory[key]
        entry = self.key.calls.get(key)
        if entry is None:
            self.missing.append(key)
            shown = key if len(key) <= 300 else key[:300] + "..."
            raise GraderFault(f"the answer key holds no value for {shown} (asked by {check or 'a check'}): the kit "
                              "answers only the calls made while the reference was graded")
        value = decode(entry["value"])
        self._memory[key] = value
        return value

    def pool(self, site: str, strategy, examples: int, check: str | None = None) -> list:
        from probes._codec import decode

        if site not in self.key.pools:
            raise GraderFault(f"the answer key holds no randomized inputs for {site}")
        return [tuple(decode(args)) for args in self.key.pools[site]]

    def draw(self, site: str, make, seed: int, check: str | None = None):
        from probes._codec import decode

        if site not in self.key.draws:
            raise GraderFault(f"the answer key holds no random draw for {site}")
        return decode(self.key.draws[site])

    def runs(self, spec, check_id: str) -> bool:
        return not _secret(spec) and check_id not in self._withheld

    def held_at_sheet_digits(self, probe: str, args: tuple) -> bool:
        entry = self.key.calls.get(call_key(probe, args))
        return bool(entry and entry.get("sheet"))

    def upstream_calls(self, key: str) -> list:
        from probes._codec import decode

        if key not in self.key.upstream:
            shown = key if len(key) <= 300 else key[:300] + "..."
            raise GraderFault(f"the answer key holds no upstream calls for {shown}")
        return [(function, tuple(decode(args)), int(parent)) for function, args, parent in self.key.upstream[key]]

    @property
    def _withheld(self) -> set:
        return set(self.key.withheld)


# ---------------------------------------------------------------------------------------------- choosing one


def installed_key_path() -> Path | None:
    """The answer key installed with the student kit, if any."""
    path = Path(__file__).with_name(KEY_FILE)
    return path if path.is_file() else None


_CURRENT: Oracle | None = None


def _from_environment() -> Oracle:
    spec = os.environ.get("GRADER_ORACLE", "").strip()
    if spec == "live":
        return LiveOracle()
    if spec.startswith("key:"):
        return KeyOracle(AnswerKey.load(spec[4:]))
    if spec == "key":
        path = installed_key_path()
        if path is None:
            raise GraderFault("GRADER_ORACLE=key, but no answer key is installed")
        return KeyOracle(AnswerKey.load(path))
    if spec:
        raise GraderFault(f"GRADER_ORACLE must be 'live', 'key' or 'key:PATH', not {spec!r}")
    path = installed_key_path()
    if path is not None:
        return KeyOracle(AnswerKey.load(path))
    return LiveOracle()


def current() -> Oracle:
    """The oracle of this process (chosen once, see the module's docstring)."""
    global _CURRENT
    if _CURRENT is None:
        _CURRENT = _from_environment()
    return _CURRENT


def set_current(oracle: Oracle | None) -> Oracle | None:
    """Replace the process's oracle (None: choose again from the environment); returns the previous one."""
    global _CURRENT
    previous, _CURRENT = _CURRENT, oracle
    return previous
