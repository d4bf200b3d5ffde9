"""Declared terms: the reference splits its result into named terms, and a term missing, sign-flipped or added is
found by least squares over the inputs."""

from __future__ import annotations

import itertools

import numpy as np

from checks._diagnoses import DIAGNOSES, TERMS
from .evidence import array_of, at, distinct, Hypothesis, within

__all__ = [
    "term_values",
    "term_slips",
]


def term_values(terms: dict, path, shape) -> dict:
    found = {}
    for name, structure in (terms or {}).items():
        value = array_of(at(structure, path))
        if value is not None and value.shape == shape and np.any(value != 0):
            found[name] = value
    return found


def term_slips(inputs: list) -> list:
    """The declared terms' slips that reproduce every input: the coefficients of ``got - expected`` on the terms
    (each present term's change: -1 missing, -2 sign-flipped, +1 doubled, -1/2 halved; each extra term's: +-1),
    found by least squares over the inputs and checked entrywise within the tolerance; several when the inputs
    cannot tell them apart.  A value that is zero on every input is no slip of a value made of several terms: all
    of them left out give it, and so do many other mistakes (the mutants' tier keeps no slip that gives zeros
    either); of a value made of one term, it is that term left out."""
    if any(one.terms is None for one in inputs):
        return []
    present = sorted(set().union(*(set(one.terms) for one in inputs)))
    if len(present) > 1 and all(not distinct(one.evidence.got, np.zeros_like(one.evidence.got), one.evidence.tol)
                                for one in inputs):
        return []
    extra = sorted(set().union(*(set(one.extras or {}) for one in inputs)))
    columns = [("term", t) for t in present] + [("extra", t) for t in extra]
    if not columns or len(columns) > 8:
        return []
    for one in inputs:  # a term that is zero on an input (a flag off there, say) is a column of zeros
        zero = np.zeros_like(one.evidence.expected)
        one.terms = {t: one.terms.get(t, zero) for t in present}
        one.extras = {t: (one.extras or {}).get(t, zero) for t in extra}
    rows, rhs = [], []
    for one in inputs:
        ev = one.evidence
        rows.append(np.stack([(one.terms if kind == "term" else one.extras)[t].ravel() for kind, t in columns],
                             axis=1))
        rhs.append((ev.got - ev.expected).ravel())
    A, b = np.vstack(rows), np.concatenate(rhs)
    solution = np.linalg.lstsq(A, b, rcond=None)[0]
    allowed = {"term": (0.0, -1.0, -2.0, 1.0, -0.5), "extra": (0.0, 1.0, -1.0)}
    guess = tuple(min(allowed[kind], key=lambda v: abs(v - s)) for (kind, _), s in zip(columns, solution))
    candidates = {guess}
    for changes in itertools.product(*(allowed[kind] for kind, _ in columns)):
        if 0 < sum(c != 0 for c in changes) <= 2:
            candidates.add(changes)
    matching = []
    for changes in candidates:
        if not any(changes):
            continue
        ok = True
        for one in inputs:
            ev = one.evidence
            model = ev.expected + sum(c * (one.terms if kind == "term" else one.extras)[t]
                                      for c, (kind, t) in zip(changes, columns) if c)
            if not within(ev.got, model, ev.tol):
                ok = False
                break
        if ok:
            matching.append(changes)
    if not matching:
        return []
    fewest = min(sum(c != 0 for c in changes) for changes in matching)
    found = []
    for changes in matching:
        if sum(c != 0 for c in changes) != fewest:
            continue
        for c, (kind, term) in zip(changes, columns):
            if not c:
                continue
            fit = "a least-squares fit of your values on the reference's terms over the inputs"
            if kind == "term" and c == -1.0:
                name, detail = f"missing_{term}", f"{fit} leaves it out and reproduces them"
            elif kind == "term" and c in (1.0, -0.5):
                name = "factor_two" if c == 1.0 else "factor_half"
                detail = f"{fit} takes {TERMS.get(term, term)} {'twice' if c == 1.0 else 'half'} and reproduces them"
            elif kind == "term":
                name, detail = f"{term}_sign", f"{fit} turns it around and reproduces them"
            else:
                name, detail = f"extra_{term}", f"{fit} adds it and reproduces them"
            if name in DIAGNOSES:
                found.append(Hypothesis(f"term:{kind}:{term}:{c}", name, 1 + fewest, detail))
            if kind == "term" and c == 1.0 and f"{term}_twice" in DIAGNOSES:  # a term at twice its value: counted twice
                found.append(Hypothesis(f"term:{kind}:{term}:twice", f"{term}_twice", 1 + fewest, detail, twin=True))
    return found
