"""Notebooks written the way students write them, built from a folder submission (the reference or a planted
mistake), so that each grades like that folder: the same definitions, cut into cells, with what Jupyter users
add around them (magics, shell lines, prints, plots, a cell that raises, cells out of order)."""

from __future__ import annotations

import ast
from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

__all__ = ["definition", "problem_06_cells", "r3_transposed", "write_notebook", "self_contained_problem_06", "jupyter_problem_06",
           "exercise_notebook", "PROBLEM_06_NAMES"]

#: what problem 6 asks for, module by module
PROBLEM_06_NAMES = {"rotations": ("R1", "R2", "R3", "cardan"),
                    "problem_06": ("GAMMA", "BETA", "ALPHA", "C3_V", "frames", "vectors")}


def definition(folder: Path, module: str, name: str) -> str:
    """The source of the top-level statement of ``folder/module.py`` that defines ``name``."""
    source = (folder / f"{module}.py").read_text()
    for stmt in ast.parse(source).body:
        names = [getattr(stmt, "name", None)] + [t.id for t in getattr(stmt, "targets", []) if isinstance(t, ast.Name)]
        if name in names:
            return ast.get_source_segment(source, stmt)
    raise KeyError(f"{module}.{name}")


def problem_06_cells(folder: Path) -> list[str]:
    """Problem 6's definitions of ``folder``, one cell each, rotations first."""
    return [definition(folder, module, name) for module, names in PROBLEM_06_NAMES.items() for name in names]


def r3_transposed(cells: list[str]) -> list[str]:
    """Problem 6's cells with R3 transposed (some of its checks then pass and others fail)."""
    out = [cell.replace("[[c, -s, 0.0], [s, c, 0.0]", "[[c, s, 0.0], [-s, c, 0.0]") for cell in cells]
    assert sum("[[c, s, 0.0]" in cell for cell in out) == 1, "R3's rows changed in the reference"
    return out


def write_notebook(path: Path, cells: list) -> Path:
    """``cells``: code strings, or ("md", text) for a markdown cell."""
    notebook = new_notebook(cells=[new_markdown_cell(c[1]) if isinstance(c, tuple) else new_code_cell(c)
                                   for c in cells])
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(notebook, path)
    return path


def self_contained_problem_06(folder: Path, path: Path) -> Path:
    """One notebook with every definition problem 6 needs and no import of the package."""
    return write_notebook(path, [("md", "# Problem 6: Cardan angles"), "%matplotlib inline\nimport numpy as np",
                                 *problem_06_cells(folder), "print(frames())"])


def jupyter_problem_06(folder: Path, dest: Path, name: str = "Problem 6.ipynb") -> Path:
    """A work folder with ``rotations.py`` as a file and problem 6's own definitions in a notebook that imports
    it the way Jupyter does (``from rotations import ...``, the folder being the notebook's working folder)."""
    dest.mkdir(parents=True, exist_ok=True)
    (dest / "rotations.py").write_text((folder / "rotations.py").read_text())
    cells = [definition(folder, "problem_06", n) for n in PROBLEM_06_NAMES["problem_06"]]
    write_notebook(dest / name, ["import numpy as np\nfrom rotations import R1, R2, R3", *cells,
                                 "vectors()"])
    return dest


def exercise_notebook(folder: Path, path: Path) -> Path:
    """A whole exercise (problems 6 and 9) in one notebook, as a student leaves it after a session: sections per
    problem, magics and shell lines, prints, a plot, cells out of order (a value computed before the function
    it uses, a function before the constants it reads) and a cell that raises."""
    r = {n: definition(folder, "rotations", n) for n in PROBLEM_06_NAMES["rotations"]}
    p = {n: definition(folder, "problem_06", n) for n in PROBLEM_06_NAMES["problem_06"]}
    cells = [
        ("md", "# Exercise II\nAll of my work for this exercise."),
        "%matplotlib inline\n!pip install numpy\nimport numpy as np\nimport matplotlib.pyplot as plt",
        ("md", "## Problem 6: Euler angles"),
        "A_test = cardan(0.1, 0.2, 0.3)  # run before cardan was defined (cells out of order)\nprint(A_test)",
        p["frames"],  # uses the constants and R1..R3 of later cells
        r["R1"] + "\n\n" + r["R2"] + "\n\n" + r["R3"],
        "R1(np.pi / 2)",
        r["cardan"],
        "\n".join([p["GAMMA"], p["BETA"], p["ALPHA"], p["C3_V"]]),
        p["vectors"] + "\n\nprint(vectors())",
        "fig, ax = plt.subplots()\nax.plot([0, 1], [0, 1])\nplt.show()",
        "broken = frames()['A_IC4']  # a cell that raises KeyError",
        "%%time\nvectors()",
        ("md", "## Problem 9: relative coordinate systems"),
        definition(folder, "cosys", "CoSys"),
        "C1 = CoSys(R3(GAMMA))\nC1.get_transform()",
    ]
    return write_notebook(path, cells)
