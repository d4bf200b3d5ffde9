"""Checks from inside Jupyter: ``from grader import check; check(6)`` (or ``%grade 6``) grades problem 6 from the
notebook's cells, in the same worker as ``grade problem-6``, and shows the report inline (the HTML report, figures
included; as text outside a notebook).

What is graded:

* the notebook's own file, when the kernel can tell which it is: ``__vsc_ipynb_file__`` (VS Code),
  ``__session__`` or ``JPY_SESSION_NAME`` (set by Jupyter's server: the notebook's path, absolute or from the
  server's root).  The folder of that notebook is graded, exactly as ``grade problem-6`` grades it when run there.
  The file is what the grader will see when the work is submitted; cells run since it was last saved are not in
  it, and the report then says to save it (Ctrl+S, or ⌘S).
* otherwise the cells run in this kernel, in the order they ran (their last definition of a name wins, as in the
  kernel), as a notebook named after the problem, beside the ``.py`` files and ``answers.toml`` of the current
  folder; the report says so, and how to name the file instead: ``check(6, notebook="problem_06.ipynb")``.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from .results import ProblemReport

__all__ = ["check", "Checked", "notebook_path", "kernel_cells", "load_ipython_extension"]

#: the files of a work folder that go beside the kernel's cells (its notebooks do not: they may hold other code)
_BESIDE = ("*.py", "answers.toml")
#: the height of the inline report's frame [px] before it fits its page
FRAME_HEIGHT = 640


@dataclass(frozen=True)
class Checked:
    """What ``check`` returns: the reports, and where the graded cells came from.  Shown inline in a notebook
    (``_repr_html_``), as the terminal's text elsewhere."""

    reports: tuple[ProblemReport, ...]
    source: str  # what was graded, in words
    notes: tuple[str, ...] = ()

    @property
    def verdicts(self) -> dict[str, str]:
        """Every check's status, by check id."""
        return {r.check_id: r.status.value for report in self.reports for r in report.results}

    @property
    def score(self) -> float:
        return sum(report.visible_score for report in self.reports)

    def __str__(self) -> str:
        from .report.text import render_terminal

        return "\n".join([*self.notes, f"graded: {self.source}", render_terminal(list(self.reports))])

    __repr__ = __str__

    def _repr_html_(self) -> str:
        from .report.html import render_notebook

        return render_notebook(list(self.reports), self.source, self.notes, FRAME_HEIGHT)


# ------------------------------------------------------------------------------------------ which cells


def _ipython():
    try:
        from IPython import get_ipython
    except ImportError:
        return None
    return get_ipython()


def _candidates(name: str) -> list[Path]:
    """Where a notebook named ``name`` (absolute, or relative to the server's root or to this folder) may be."""
    path = Path(name).expanduser()
    if path.is_absolute():
        return [path]
    here = Path.cwd()
    return [folder / path for folder in (here, *here.parents)] + [here / path.name]


def notebook_path(shell=None) -> Path | None:
    """The file of the notebook this kernel runs, where the kernel can tell (see the module's docstring)."""
    shell = shell if shell is not None else _ipython()
    namespace = getattr(shell, "user_ns", {}) or {}
    names = [namespace.get("__vsc_ipynb_file__"), namespace.get("__session__"), os.environ.get("JPY_SESSION_NAME")]
    for name in names:
        if not isinstance(name, str) or not name.endswith(".ipynb"):
            continue
        for path in _candidates(name):
            if path.is_file():
                return path.resolve()
    return None


def kernel_cells(shell=None) -> list[str]:
    """The code of the cells run in this kernel, in the order they ran, without the one running now."""
    shell = shell if shell is not None else _ipython()
    history = getattr(getattr(shell, "history_manager", None), "input_hist_raw", None) or []
    return [code for code in list(history)[1:-1] if code.strip()]


def _saved_cells(path: Path) -> set[str]:
    import nbformat

    try:
        book = nbformat.read(path, as_version=4)
    except Exception:  # noqa: BLE001 - an unreadable file is the loader's to report
        return set()
    return {_normal(c.source) for c in book.cells if c.cell_type == "code"}


def _normal(code: str) -> str:
    return "\n".join(line.rstrip() for line in code.strip().splitlines())


def _unsaved(path: Path, cells: list[str]) -> list[str]:
    """The cells run in this kernel that define something and are not in the notebook's file as it is saved."""
    from .sandbox.notebook import clean_cell, definitions

    saved = _saved_cells(path)
    unsaved = []
    for code in cells:
        try:
            defines = definitions(clean_cell(code)[0])
        except (SyntaxError, ValueError, RecursionError):
            continue
        if defines and _normal(code) not in saved:
            unsaved.append(code)
    return unsaved


def _from_kernel(cells: list[str], problem: int, folder: Path) -> Path:
    """A work folder holding the kernel's cells as ``problem_NN.ipynb`` (a name several problems use goes to this
    problem), beside the ``.py`` files and ``answers.toml`` of ``folder``."""
    from nbformat.v4 import new_code_cell, new_notebook
    import nbformat

    work = Path(tempfile.mkdtemp(prefix="grader-kernel-"))
    for pattern in _BESIDE:
        for path in folder.glob(pattern):
            if path.is_file() and not path.is_symlink():
                shutil.copy2(path, work / path.name)
    nbformat.write(new_notebook(cells=[new_code_cell(code) for code in cells]), work / f"problem_{problem:02d}.ipynb")
    return work


# ------------------------------------------------------------------------------------------ grading


def check(problem, *more, notebook: str | os.PathLike | None = None, seed: int | None = None,
          timeout: float | None = None) -> Checked:
    """Grade ``problem`` (and ``more``: ``check(6, 7)``) from this notebook's cells, as ``grade problem-N`` grades
    them, and return the report (shown inline by Jupyter).  ``notebook``: the notebook's file, where the kernel
    cannot tell it; ``seed``: the random inputs' seed (to reproduce a failure); ``timeout``: seconds per call of
    your code."""
    from .arguments import problem_number
    from .oracle import reference_available
    from .runner import grade_submission
    from .workers import Fresh
    from .sandbox import Limits, student_mode

    numbers = [problem_number(str(p)) for p in (problem, *more)]
    shell = _ipython()
    path = Path(notebook).resolve() if notebook is not None else notebook_path(shell)
    notes: list[str] = []
    made = None
    if path is not None:
        if not path.is_file():
            raise FileNotFoundError(f"no notebook {path}")
        source, shown = path.parent, f"{path.name} and the other files of {path.parent}"
        unsaved = _unsaved(path, kernel_cells(shell)) if shell is not None else []
        if unsaved:
            notes.append(f"note: {len(unsaved)} cell{'s' if len(unsaved) != 1 else ''} you ran "
                         f"{'are' if len(unsaved) != 1 else 'is'} not in {path.name} as it is saved: save the "
                         "notebook (Ctrl+S, or ⌘S) and check again, so that what is graded is what you see")
    else:
        cells = kernel_cells(shell)
        source = made = _from_kernel(cells, numbers[0], Path.cwd())
        shown = f"the {len(cells)} cells run in this kernel"
        notes.append("note: this notebook's file could not be found, so the cells run in this kernel were graded; "
                     f"to grade the file, name it: check({numbers[0]}, notebook=\"problem_{numbers[0]:02d}.ipynb\")")
    try:
        limits = Limits(call_timeout=timeout) if timeout else None
        reports = grade_submission(source, numbers, seed=seed,
                                   workers=Fresh(limits, student_mode(kit=not reference_available())))
    finally:
        if made is not None:
            shutil.rmtree(made, ignore_errors=True)
    return Checked(tuple(reports), shown, tuple(notes))


# ------------------------------------------------------------------------------------------ %grade


def _grade_magic(line: str):
    """``%grade 6`` (``%grade problem-6 7``): ``check`` of those problems."""
    words = line.replace(",", " ").split()
    if words[:1] and words[0].lower() in ("problem", "problems"):
        words = words[1:]
    if not words:
        raise ValueError("which problem? write e.g. %grade 6")
    return check(*words)


def load_ipython_extension(ipython) -> None:
    """``%load_ext grader``: the ``%grade`` magic (registered as well when ``check`` is imported in IPython)."""
    ipython.register_magic_function(_grade_magic, "line", "grade")


def _register() -> None:
    shell = _ipython()
    if shell is not None and hasattr(shell, "register_magic_function"):
        load_ipython_extension(shell)


_register()
