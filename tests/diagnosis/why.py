"""Why the engine named nothing for a set's mistakes: joins a score run's verdicts with the engine's trace.

    GRADER_DIAGNOSIS_TRACE=/tmp/trace.jsonl python tests/diagnosis/score.py --set fresh2 -v > /tmp/score.txt
    python tests/diagnosis/why.py /tmp/trace.jsonl /tmp/score.txt [--all]

One line per mistake named nothing (``--all``: every mistake): its true family and what the engine had for the
check it must fail (a reference call behind the expected value, the student's call, how many inputs, a run and its
model, what the grammar found, the mutants tried and kept, a budget spent).  "not asked": the check failed without
asking the engine (its catalogue named a symptom, or the failure carried no comparison)."""

from __future__ import annotations

import json
import re
import sys

__all__ = ["reasons", "main"]


def _verdicts(score_output: str) -> dict:
    verdicts = {}
    for line in score_output.splitlines():
        # a set with second families prints the strict verdict, then the lenient one, before the name
        match = re.match(r"^  (right|wrong|none|not caught)\s+(?:(?:right|wrong|none|not caught)\s+)?(\S+)", line)
        if match:
            verdicts[match.group(2)] = match.group(1)
    return verdicts


def _grouped(trace_lines) -> dict:
    grouped, current = {}, None
    for line in trace_lines:
        record = json.loads(line)
        if "mistake" in record:
            current = record
            grouped[record["mistake"]] = (record, [])
        elif current is not None:
            grouped[current["mistake"]][1].append(record)
    return grouped


def _reason(mistake: dict, records: list) -> str:
    mine = [r for r in records if r["check"] == mistake["check"]]
    if not mine:
        return "not asked"
    record = mine[-1]
    notes = {n["what"]: n for n in record["notes"]}
    if record["kind"] == "no_evidence":
        return "no evidence"
    parts = []
    if "evidence" in notes:
        e = notes["evidence"]
        parts.append(f"source={'yes' if e['source'] else 'no'} student={'yes' if e['student'] else 'no'}"
                     f" run={e['run']}")
    if "inputs" in notes:
        parts.append(f"inputs={notes['inputs']['count']}")
    if "model" in notes:
        parts.append(f"model={notes['model']['state']}")
    if "grammar" in notes:
        parts.append(f"grammar={notes['grammar']['found']}")
    if "mutated" in notes:
        parts.append(f"mutants={notes['mutated']['count']} kept={notes.get('mutants', {}).get('kept')}"
                     f" third={notes.get('third', {}).get('kept')}")
    for stop in ("sheet_digits", "timeout"):
        if stop in notes:
            parts.append(stop)
    for stop in ("stopped", "defect"):
        if stop in notes:
            parts.append(f"{stop}: {notes[stop]['reason']} {notes[stop]['detail'][:60]}")
    return " ".join(parts)


def reasons(trace_lines, score_output: str, every: bool = False) -> list[str]:
    verdicts = _verdicts(score_output)
    return [f"{name:45s} {verdicts.get(name, '?'):6s} {mistake['family']:16s} {_reason(mistake, records)}"
            for name, (mistake, records) in _grouped(trace_lines).items()
            if every or verdicts.get(name) == "none"]


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) < 2:
        print(__doc__)
        return 2
    with open(argv[0], encoding="utf-8") as trace, open(argv[1], encoding="utf-8") as score:
        print("\n".join(reasons(trace, score.read(), every="--all" in argv)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
