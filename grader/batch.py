"""Batch grading of a folder of submissions (placeholder parser until the batch grader lands)."""


def add_batch_parser(sub) -> None:
    p = sub.add_parser("batch", help="grade every submission of a folder")
    p.add_argument("submissions")
    p.add_argument("--out", required=True)
    p.set_defaults(func=lambda args: (print("batch grading is not available yet"), 2)[1])
