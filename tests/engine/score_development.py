"""How well the diagnosis engine tells the cause of the realistic mistakes of its own development set
(``tests/engine/realistic/problem_NN.toml``, in the format of ``tests/diagnosis/``'s sets), graded and classified
as ``tests/diagnosis/score.py`` grades and classifies the held-out set; ``--off`` grades with the engine off (what
the catalogues alone tell).  Tune the engine on this set, never on the held-out one.

    python tests/engine/score_development.py -v
    python tests/engine/score_development.py --off
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from tests.diagnosis.score import defects, fresh_mistakes, grade_all, naming, summary  # noqa: E402

__all__ = ["REALISTIC", "main"]

REALISTIC = ROOT / "tests" / "engine" / "realistic"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--problems", help="only these problems, e.g. 39,47")
    parser.add_argument("--off", action="store_true", help="grade with the diagnosis engine off")
    parser.add_argument("-v", "--verbose", action="store_true", help="one line per mistake")
    args = parser.parse_args(argv)
    mistakes = fresh_mistakes(REALISTIC)
    if args.problems:
        wanted = {int(p) for p in args.problems.split(",")}
        mistakes = [m for m in mistakes if m.problem in wanted]
    problems = defects(mistakes)
    if problems:
        print("the development set has defects:", *problems, sep="\n  ", file=sys.stderr)
        return 2
    if args.off:
        from grader import diagnosis

        diagnosis.ENABLED = False
    naming_ = naming()
    started = time.monotonic()
    graded = grade_all(mistakes, naming_.family_of)
    print(summary(graded, naming_, time.monotonic() - started, args.verbose, "development"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
