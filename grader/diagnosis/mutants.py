"""Formulas: mutated copies of the reference's own code.

Most mistakes no transform of the output or of the inputs reproduces are slips *inside* a formula: one term's sign, a
factor or an operand left out, two arguments exchanged, a neighbouring index.  This tier evaluates the reference's code
with one such slip on the very inputs of the failing comparison.  The code mutated is what the student writes: the
functions that hold a solution region (``# BEGIN SOLUTION problem N``) of the problem of the check (or of a neighbouring
problem: one region may serve two of the sheet's problems), that the probe's call runs, and that no earlier problem owns
(``checks._upstream.SHARED``: a mistake of ``R3`` belongs to problem 6). The student's file of problem N
(``problem_NN.py``) also holds code that the template gives whole (a function with no region: problem 34's gait, problem
24's pendulum): a slip there is the student's too, but less likely than one in the code they wrote, so its functions'
slips (``given``) are tried only where no slip of a region reproduced the student's value, and no earlier tier explained
it, within a budget of their own (``GIVEN_TIME_BUDGET``); a list's entry written 0 there is data left out, told as a
term left out and as an offset (``_ENTRIES``).  Where the slips of the regions that reproduce it are all exchanges, or
all signs, the given code's slips of the other of the two families are heard as well, within the same budget
(``OPPOSITES``): two arguments exchanged in a call of a given function that takes their difference (``pd(q, qd_des,
q_des, qd)``) are as truly that difference's sign, and the value cannot tell the edit from its effect; for the same
reason a check that tells a sign from what the value shows hears the exchanges of two operands of the regions
(``opposite_slips``, asked by ``diagnosis.rival``).  Last, where nothing else reproduced it, the module constants that
the call reads, of the problem's own module and of the library (the modules of no problem), directly, through a
function's default or a constant computed from them, are typed otherwise (``constant_mutants``: a number of one with the
wrong sign, twice or half itself, ten, a hundred or a thousand times or a tenth, a hundredth or a thousandth of itself
(a decimal point misplaced, another unit), in degrees where radians belong (exactly, or rounded as a student types the
degrees read off it: 0.35 as 20) or the reverse, an expression in it with its minus left out or given one
(``np.cos(SLOPE)`` for ``-np.cos(SLOPE)``), its square root or its square; an entry of one of its lists written 0, two
entries exchanged, a matrix written out row by row transposed, a vector written as its direction alone; two constants
of one module exchanged; an integer stays an integer, and is not typed a hundred or a thousand times itself or
squared; a step or a count of steps, ``DT``, ``N_STEPS``, typed otherwise is a step typed otherwise), each measured with
the constants, defaults and imported names its module computed from it bound again, within ``CONSTANT_TIME_BUDGET`` and
``CONSTANT_MUTANTS``.

Each mutant changes one place of one function's solution region (``SLIPS``: a term's sign, a term or a factor missing (a
ratio's numerator of constants too: ``1 / T`` for ``2 pi / T``), two arguments, two groups of arguments, factors or
entries exchanged (of a list, a tuple, or the values of a dict: ``{a: beta, b: alpha}``), the arguments a call is to
hand on (``*args``, ``**kwargs``) left out, a default taken whatever the argument (``np.eye(3) if I is None else I`` as
``np.eye(3)``), a loop's first item's own value given to every item or the others' to the first (``P_r_PDp=(0, 0, 0) if
k == 0 else (half, 0, 0)`` as either: a position so written is an offset, a rotation a wrong frame), a number of a
point's position written out doubled or halved (``P_r_PDp=(half, 0, 0)`` as ``(2 * half, 0, 0)``: a factor, and an
offset beside it), an angle the function binds itself (``x, z, phi = y``) read in degrees throughout or an angle
converted to degrees before its sine (``phi = np.rad2deg(phi)``), an event's residual returned as a test or a magnitude
(``y[0] > 0``, ``abs(gap)``, in a function of ``(t, y)``), a list of angles passed in reverse order (``ANGLES0[::-1]``),
a number doubled or halved, ``/`` for ``*``, a square or a square root missing or added, sin for cos (in one call,
throughout one expression, or in one read of a name bound to a sine or a cosine: ``c2`` for ``s2`` where ``c2, s2 =
np.cos(q2), np.sin(q2)``), degrees, a transpose or one on the wrong factor (or a matrix written out row by row,
transposed), a neighbouring index (or a slice of as many entries one row on or back: ``y[1:4]`` for ``y[:3]``; or the
first entry for a later one: ``x[0]`` for ``x[3]``), two names exchanged (throughout, or two of a kind in one
expression), a term of a sum left outside the solve it belongs under (``solve(M, f + g) + tau``), every term subtracted
added instead (``a + f + g`` for ``a - f - g``), a factor of one term multiplying the whole sum (``m * (a + b)`` for ``m
* a + b``), the weights of two terms exchanged (``w * a + (1 - w) * b`` for ``(1 - w) * a + w * b``), a range counted
from one (``np.arange(1, n + 1)`` for ``np.arange(n)``: an offset), the identity written where a square block of zeros
belongs (``np.eye(k)`` for ``np.zeros((k, k))``: a term added), a solve or an inverse left out or made with the matrix's
diagonal alone (``b / np.diag(M)`` for ``np.linalg.solve(M, b)``), an entry of a matrix or vector written 0 (told beside
an offset where it is the same on every input), a sum that keeps only its last term, a running sum left out (``steps``
for ``np.cumsum(steps, axis=0)``), a count for a sum, a quantity read where its rate belongs or the reverse (``qd`` for
``qdd``, ``B_omega_B`` for ``B_omegaDot_B``, ``B_v_B`` for ``B_r_IB``: a name of the function or an attribute of the
reference, related by the course's notation; a list of names each so read at once, ``[q1, q2]`` for ``[dq1, dq2]``), a
quantity read in another frame's coordinates (``B_v_B`` for ``I_v_B``), a coordinate system read for another
(``C1.get_transform()`` for ``C3.get_transform()``, or left out of a call or given to one: a wrong frame), a factor of a
sum applied to one term only (``A @ x + y`` for ``A @ (x + y)``), one entry of a list with the wrong sign (a term
written with a plus given a minus: ``-C / 2`` for ``+C / 2``), a value that the object keeps added to where it is
replaced (``self.r = self.r + r`` for ``self.r = r``, outside a constructor: a term added), one factor of a product
inverted where the product's inverse belongs (``solve(A, B @ b)``, ``inv(A) @ B @ b``, for ``solve(A @ B, b)``: no
inverse), a ratio upside down (``m / 12`` for ``12 / m``), two neighbouring factors of a longer product exchanged (``R3
@ R1 @ R2`` for ``R3 @ R2 @ R1``), the halves of a run's state read as alternate entries (``y[::2]``, ``y[1::2]`` for
``y[:3]``, ``y[3:]``), a matrix read for its sibling of a pair (``B_J_R`` for ``B_J_S``), the first term of a difference
left out (``r r^T`` for ``r.r E - r r^T``, its second read as it is, and ``-qd`` for ``qd_des - qd``, its second keeping
its minus), a position taken from the origin where it is measured from a point (``I_r_E`` for ``I_r_E - anchor``, and
``I_r_E`` or ``-I_r_E`` for ``anchor - I_r_E``: an offset, not a term left out), an argument left out of every product
it is a factor of (the step of an integration, ``dt``, left out of a product, there or in one place: each update takes a
whole unit of time), a length where its square belongs (``np.sqrt(r @ r)`` for ``r @ r``) or its square where the length
belongs (``w @ w`` for ``np.linalg.norm(w)``), a vector or matrix the function writes out passed to a call with the
wrong sign (``f(..., -hip)`` where ``hip = sp.Matrix([...])``), a power or a root over the wrong part of a product (``(m
* a)**2`` for ``m * a**2``, ``np.sqrt(x) / m`` or ``m * np.sqrt(x)`` for ``np.sqrt(x / m)``), an absolute value left out
(``v * v`` for ``abs(v) * v``: a sign), a slice's axes exchanged in one statement (``V[2, :] = -V[2, :]`` for ``V[:, 2]
= -V[:, 2]``: a transpose), a list of three to six names that starts with its last or its second (``[phi, x, y]`` for
``[x, y, phi]``, read or bound: ``phi, x, y = q``; entries swapped), and one read of a name for another of its kind: an
angle where another angle belongs (``np.cos(beta)`` for ``np.cos(phi)``, ``R1(gamma)`` for ``R1(alpha)``: an order slip,
``wrong_angle``, and where one angle is bound to a sum of the other and more, ``g_e = q2 + q4``, a term added or left
out as well; the angles of a function are the names it reads in a sine or a cosine or passes where a function of the
reference reads its parameter so), and a parameter read as the constant or the number of its default, as its module's
constant of its name in capitals (``WIRE_LENGTH`` for ``wire_length``, ``ANGLES0`` for ``angles``: its value at the
start) or, a gravity, as the Earth's (``m * 9.81`` for ``m * g``), at one read or at all of them: the argument ignored
(and every parameter that has a default read as it at once: every argument ignored); a name computed from a value at the
start read, once, as that start (``cardan(*ANGLES0)`` for ``cardan(*angles)`` where ``angles = _run(step, ANGLES0)``:
the start returned for the end, an initial state); a name bound to a sum read, once, as one of its terms (``l2 * cb``
for ``radius * cb`` where ``radius = l2 + l3 * np.sin(phi)``: a term left out there); a constructor's argument stored
from another one it stores (``self.B_a_B = _vector_or_zeros(B_omegaDot_B)``, a line copied from its neighbour) and a
list of names with one entry that is read nowhere else written as its neighbour (``(m1, m1)`` for ``(m1, m2)``, in a
loop's iterable too): a value left unused, an argument ignored; one read of an argument where another that the same line
reads in its arithmetic belongs (``length**2 + width**2`` for ``length**2 + height**2``: the wrong argument); one read
of a coordinate where another unpacked with it belongs (``q2`` for ``q1`` of ``q1, q2 = q``: read from another's row); a
number a product or a quotient takes typed as another that a formula of the module takes (``m / 20`` for ``m / 12``: a
factor off); and an entry written into a neighbouring index (``a[0] = ...`` for ``a[1] = ...``: a wrong index).  Among
the slips of a place are also a loop (or any loop of a comprehension) over one item fewer, that stops one short or
starts one late (``for body in bodies[:-1]``, ``range(1, n)``: a term of its sum left out), a loop of steps over a range
one step longer (``range(n + 1)``: one step too many), a keyword argument left out of a call of a function or a class of
the reference whose parameter of that name has a default (the callee then uses the default: a term left out, a joint
built without its ``A_PDp``; a point's position by the notation left out, ``P_r_PDp``, moves the point: an offset),
every inverse and solve of one statement left out together (``J M J^T`` for ``(J M^-1 J^T)^-1``: no inverse), and the
identity matrix written as the number 1 (``1.0 + W`` for ``np.eye(3) + W``: numpy adds it to every entry, a term added,
told as an offset as well where it is the same on every input) or left out of a product (``r @ r`` for ``(r @ r) *
np.eye(3)``: the identity left out, a term of its own), and a body's matrix turned into inertial coordinates in one
statement where the function has the rotation at hand (``A_IB @ B_I_B @ A_IB.T`` for ``B_I_B``, ``self.A_IB`` beside
``self.B_I_B``: a wrong frame), and so one read of a vector in the body's coordinates (``A_IB @ B_v_B`` for ``B_v_B``);
last of all, after the reads of names, every read of one of a function's arguments multiplied by the factor of a
conversion of units into the ones the function computes in (``CONVERSIONS``: ``omega * np.pi / 30`` of a rate already in
rad/s, ``phi * np.pi / 180`` of an angle already in radians: a scale).  The reads of names and the indices written come
after every other slip of every function, as many as ``MAX_MUTANTS`` leaves room for, so that the budget reaches the
older slips first), and the slips of precision (``PRECISION_SLIPS``: a dtype of double precision given as single,
``np.asarray(q, dtype=np.float32)``, also inside a loop's bounds, where it changes no count (given as an integer,
``dtype=int``, it cuts every value to a whole number, as do an array created of integers and filled with floats,
``np.zeros(n, dtype=int)``, a number converted with ``int`` where ``float`` belongs, and a division by a whole number
written ``//``: far outside the band, not one of these); an array given no dtype created in single precision; an
argument converted to float32 at a function's start; a constant typed short, pi as 3.14 or 3.1416, 9.81 as 9.8, and an
expression of numbers or a read of a module's constant rounded to two, three or four decimals (the sheet prints four),
``np.pi / 6`` as 0.52, ``np.sqrt(1.0 / 3.0)`` as 0.577, ``GAMMA`` as 0.52: these come with the reads of names, after the
other slips).  A slip of precision is told only where the student's value is in the band such slips make
(``PRECISION_BAND``; on the other inputs and the call's other values, in that band or the expected value itself),
differs from the expected one beyond the tolerance and is reproduced closely (``PRECISION_SHARE`` of the difference left
at most), and none is tried where the value shown is beyond the band; on a comparison of one input (no second one to
draw) the slips of precision alone are tried there, where the value is in the band.  An edit that is as truly a slip of
another family is told with both names, as a twin (``rivals``): a product with a quantity where the division by it
belongs (or the reverse) uses the quantity as its reciprocal; a quantity and its rate exchanged read each where the
other belongs (a state row); a parameter with a default that the edit leaves unused is an argument ignored, where the
engine could test none of the call's arguments itself, and so is an argument of the call that the engine's test had no
budget to change. A slip is one kind of mistake even where it takes more than one edit (sin and cos exchanged in a
term); an exchange of reads of a run's state, or a read of its other half, is a state read from the wrong rows; a skew
matrix transposed is its negative, told as a sign or a transpose, and a cross product the other way round as a sign or
the factors' order (``grammar.EQUIVALENCES``); inside a loop's iterable only the slips that keep its count are made
(``_KEEP_COUNT``: exchanges, a dtype, a name written as its neighbour, a quantity read for its rate).  A mutant is kept
when its value reproduces the student's within the comparison's tolerance on the input shown *and* on the second one
(and on a third where the engine can draw one), and differs from the expected value (an equivalent mutant says nothing).
Where the probe computes more than the compared value and declares the cheaper call that holds it (``part``:
``lagrange``'s ``M``, ``f``, ``g`` are ``mfg``'s), a mutant is evaluated on that call first and on the whole probe only
where it reproduces the student's value there: the mutants kept are those the whole probe keeps, at the cost of the part
for the others. Each call gets its own copy of the input's arguments (a mutant may change them in place), copied from
one kept for the input.  A slip inside an index is one of the index.  A cause is named only when the mutants kept are of
one family of the vocabulary, or of two; the hint says what kind of slip and in which of the student's functions, never
the reference's code.

The reference runs in the grader's process here, so the tier is bounded: loop bounds and conditions are never
mutated, the mutants of one explanation are at most ``MAX_MUTANTS`` and their measuring (the reference's runs on
the answer's inputs) takes at most ``TIME_BUDGET`` seconds of the thread's CPU time (``SCREENED_TIME_BUDGET`` where
they are screened without sympy's simplifications, below; a mutant that is still running then is interrupted, and
nothing is named).  Their making (the reference's code mutated and compiled) is the same
for every answer and kept for the process, so it is counted apart, within ``MAKING_TIME_BUDGET``: what the tier
names does not depend on whether an earlier explanation of the process made the mutants, nor on how much a loaded
machine slows their making.  The worst an explanation's formula tier may spend is so ``MAKING_TIME_BUDGET`` +
``TIME_BUDGET`` (or ``SCREENED_TIME_BUDGET`` and ``CONFIRMING_TIME_BUDGET``) + ``GIVEN_TIME_BUDGET`` of CPU time (or
``LATE_TIME_BUDGET`` in place of the last), the first only where the process has not made those mutants yet.  These are
seconds of the machines where the budgets were set: on a slower one (``pace``, measured once for the process, at most
``PACE_MOST`` times) each budget is as many times longer, so that what the tier names does not depend on the machine's
speed either.  The codes the compared call runs are traced once for an explanation's stages (``_TRACES``), and a grading
whose explanations ask the tier the same question (the same inputs, student's values and families told: a run's
right-hand side behind its state and its event) measures the mutants once (``_Measured``; a measure that ran out of its
time is made again); where an earlier tier already explained the answer, the tier is heard for rivals within a budget of
its own, ``LATE_MUTANTS`` mutants and ``LATE_TIME_BUDGET``, those of the families not told yet first (``late``: a rival
of a family told adds a name, not an explanation), warnings are silenced and a mutant that raises is dropped.  The
student's code runs only for the third input, within the scene's budget of the student's calls.  The student kit holds
no reference code: the tier runs with the live reference only (``left_to_live``: the kit then says that the graded
submission may say more).

A symbolic answer costs most in its simplification (``trigsimp`` of problem 40's matrices: a quarter of a second)
and in sympy's ``lambdify``, neither of which changes its value.  Where a function of the problem simplifies
(``SIMPLIFIERS``), its mutants are screened on a copy of their code without the simplifications, the answers read by
``probes._symbolic.quick`` (a walk of the expression, not generated code), and so are the call that finds the functions
run and the slips of the functions the module gives whole (``_given``) that the call reaches; this holds only where the
reference's own value, so computed, is the expected one on every input (``_holds``), else every mutant is evaluated as
it is.  A mutant that reproduces the student's value when screened is evaluated again as it is, and that value decides:
the screen can only leave out a mutant whose value depends on an expression's form.  That evaluation is counted apart
from the screening, against a budget of its own (``CONFIRMING_TIME_BUDGET``: one of problem 40's mutants takes longer to
simplify than all of them to screen); what the probes compute once for a mutant's code is kept for its inputs and later
explanations (``_CONFIRMED``); and a screened mutant of a slip of the same function as one kept already is kept on its
screened value, for it adds no name to the finding.
"""

from __future__ import annotations

import __future__
import ast
import collections
import contextlib
import copy
import ctypes
import dataclasses
import gc
import itertools
import pickle
import re
import sys
import threading
import time
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from checks._diagnoses import DIAGNOSES

from ..errors import GraderFault
from . import trace
from .passes import Shared
from .evidence import (array_of, at_point, declaration, distinct, Evidence, Hypothesis, part_of, reproduces, rows_of,
                       Source, stepped, within)
from .grammar import EARTH_GRAVITY, equivalents

__all__ = ["MAX_MUTANTS", "TIME_BUDGET", "SCREENED_TIME_BUDGET", "MAKING_TIME_BUDGET", "CONFIRMING_TIME_BUDGET",
           "LATE_MUTANTS", "LATE_TIME_BUDGET", "NEIGHBOURS", "COST", "KIT_NOTE", "NAMES_A_FUNCTION", "SLIPS",
           "PRECISION_SLIPS", "PRECISION_BAND", "PRECISION_SHARE", "RIVALS", "UNUSED_READS", "OPPOSITES",
           "OPERANDS_EXCHANGED", "FACTORS_REORDERED", "TRANSPOSED", "EFFECT_RIVALS", "PACE_NOMINAL", "PACE_MOST",
           "Mutant", "rivals", "mutants_of", "mutant_slips", "Contested", "opposite_slips", "late", "left_to_live",
           "pace"]


#: the mutants one explanation evaluates at most (past it, nothing is named: the slips were not all tried)
MAX_MUTANTS = 600
#: the CPU time the measuring of one explanation's mutants may take [s] (the thread's own, so that a loaded machine
#: names what an idle one names): the reference's runs on the answer's inputs; a mutant still running then is
#: interrupted.  Their making (``MAKING_TIME_BUDGET``) is not counted here
TIME_BUDGET = 2.0
#: the CPU time the making of one explanation's mutants may take [s]: the reference's code parsed, mutated and
#: compiled, which is the same for every answer and kept for the process (``_codes``: an explanation of a problem
#: whose mutants an earlier one made spends next to nothing on it).  It depends on the reference alone, not on the
#: student: the most, every function of problem 26 and its neighbours, take about 2 s on an idle machine
MAKING_TIME_BUDGET = 8.0
#: the CPU time the measuring of one explanation's mutants may take where they are screened without sympy's
#: simplifications [s], in place of ``TIME_BUDGET``: each still builds a symbolic answer (problem 7's derivation of
#: its 238 mutants takes about 1.5 s on an idle machine, and a loaded one counts more of the thread's time)
SCREENED_TIME_BUDGET = 4.0
#: the CPU time of one explanation's mutants that a screening without sympy's simplifications kept, evaluated as
#: they are (their simplifications, which decide) [s]: few reproduce the student's value, and one of problem 40's
#: takes 1.5 s to simplify on an idle machine (the reference's own value, 0.4 s), more than the screening of all
CONFIRMING_TIME_BUDGET = 4.0
#: where an earlier tier already explained the answer, the formula tier's mutants tried at most, those of the
#: families not told yet first, then those of the families told (a rival of a family told adds a name, not an
#: explanation), within ``LATE_TIME_BUDGET``: where the time runs out before the rivals of other families were all
#: tried, the earlier finding stands.  The mutants come in the order of the code, and a rival may be the last of
#: them (problem 43's solve left out, 157th of 159: the first 40 lost it), so all of them, as many as the tier makes
LATE_MUTANTS = MAX_MUTANTS
#: the CPU time of the evaluation of the mutants heard after an earlier tier explained the answer [s] (their making,
#: which the process caches, is bounded by ``MAKING_TIME_BUDGET``: problem 31's 477 took more than this the first
#: time)
LATE_TIME_BUDGET = 0.4
#: the CPU time of the measuring of the slips of the code a problem's module gives whole (``_given``), tried where
#: no slip of the solution regions reproduced the student's value [s] (their making, as the regions', is bounded by
#: ``MAKING_TIME_BUDGET``)
GIVEN_TIME_BUDGET = 2.0
#: a solution region of problem N +- this many counts as the check's problem's own (the screw axis of problem 13
#: is the region of problem 14)
NEIGHBOURS = 1
#: the simplicity of a mutant's hypothesis (the grammar's slips of outputs and inputs are simpler: 1 to 3)
COST = 4
#: the families of the mutants kept, at most, for a cause to be named ("could be X or Y")
MAX_FAMILIES = 2

#: what the student kit adds to a failure it names no cause of, where the graded submission tries the formulas
KIT_NOTE = ("The graded submission may say more about the cause: it also tries slips inside the formulas of your "
            "functions.")
#: a hint of this tier names the student's function in backquotes (no other tier does)
NAMES_A_FUNCTION = re.compile(r"`[A-Za-z_][A-Za-z_0-9]*`")

_REGION = re.compile(r"#\s*BEGIN SOLUTION problem (\d+)")
#: a problem's own module, the file of the student's submission that the sheet's problem NN is graded from
_OWN_MODULE = re.compile(r"problem_(\d+)")
_END = re.compile(r"#\s*END SOLUTION")
#: a rotation matrix by the course's notation (``A_IB``, ``R3(...)``): dropping it leaves a vector in another frame
_ROTATION = re.compile(r"^(A_\w+|A|R[123]?|R_\w+|rotation\w*|expm_skew)$")
_TRIG = {"sin": "cos", "cos": "sin"}
#: a point's position by the course's notation (``I_r_IB``, ``B_r_BP``, ``I_r_E``)
_POSITION = re.compile(r"^[A-Za-z0-9]+_r_[A-Za-z0-9]+$")
_DEGREES = ("radians", "deg2rad")
#: the guard of a loop's iterable: exchanges only (a permuted iterable runs the loop as often)
ITERABLE = "iterable"
#: the slips made inside a loop's iterable
_EXCHANGES = frozenset({"entries", "entries_rates", "arguments", "arguments_rates", "blocks", "rows", "names",
                        "names_rates"})
#: a run's state by the course's notation (``y`` of ``fun(t, y)`` and of solve_ivp's result, ``y_event``)
_STATE = re.compile(r"^(y|y_\w+|state)$")


class _Timeout(BaseException):
    """The time of an explanation's mutants is up (a BaseException: the reference's ``except Exception`` lets it
    through)."""


@dataclass(frozen=True)
class Mutant:
    """One slip (a key of ``SLIPS``) in one function (``module``, the path of names to it in the module), and the
    mutated code object."""

    module: str
    path: tuple
    slip: str
    code: object
    unused: tuple = ()  # the parameters that the slip leaves unused (``anchor - I_r_E`` as ``I_r_E``)
    defaulted: frozenset = frozenset()  # its parameters with a default (``anchor=ANCHOR``)
    quick: object = None  # the code without sympy's simplifications (``_unsimplified``), where it has any
    given: bool = False  # a slip of a function that the problem's module gives whole (``_Function.given``)
    bindings: tuple = ()  # a slip of a module's constant: ``(holder, attribute, value)`` set while it is measured
    unread: tuple = ()  # the names the function binds and reads that the slip leaves unread (``qdd``, returned as qd)

    @property
    def function(self) -> str:
        return self.path[-1]

    @property
    def name(self) -> str:
        """The diagnosis."""
        return SLIPS[self.slip][0]

    @property
    def detail(self) -> str:
        """What the hint says of it, naming the student's function."""
        return SLIPS[self.slip][1].format(f=self.function)


# ---------------------------------------------------------------------------------------------- the source


@dataclass(frozen=True)
class _Function:
    """A function of the reference that holds solution regions: its module, path of names, its definition (with
    the class it sits in, to compile a method as one) and the lines of its regions, with their problems."""

    module: str
    path: tuple
    node: ast.FunctionDef
    regions: tuple  # ((problem, first line, last line), ...)
    attributes: frozenset = frozenset()  # the attributes the reference reads or sets (``B_omega_B``)
    constants: frozenset = frozenset()  # the constants its module binds at its top level (``WIRE_LENGTH``)
    angled: frozenset = frozenset()  # ``(function, position)`` of the reference's parameters that are angles
    sympy: frozenset = frozenset()  # the names its module's top level binds to sympy (``sp``) or its simplifiers
    given: bool = False  # a function of a problem's own module that holds no region: the template gives it whole
    keywords: frozenset = frozenset()  # ``(callee, keyword)`` of the reference's parameters that have a default
    numbers: frozenset = frozenset()  # the numbers its module's formulas multiply or divide by (``12`` of ``m / 12``)


@lru_cache(maxsize=4)
def _functions(root: str) -> tuple[_Function, ...]:
    """Every function of the reference's modules (top level, or a method of a top-level class) that holds a
    solution region, and every function of a problem's own module (``problem_NN.py``) that holds none (``given``,
    its whole body counted as a region of problem NN: the student's file holds it too); the parsed modules are
    kept for the process."""
    modules = []
    for path in sorted(Path(root).glob("*.py")):
        if path.name != "__init__.py":
            source = path.read_text(encoding="utf-8")
            modules.append((path, _regions(source.splitlines()), ast.parse(source, filename=str(path))))
    attributes = frozenset(n.attr for _, _, tree in modules for n in ast.walk(tree) if isinstance(n, ast.Attribute))
    angled = frozenset(pair for _, _, tree in modules for pair in _angled(tree))
    keywords = _keyword_defaults([tree for _, _, tree in modules])
    found = []
    for path, regions, tree in modules:
        constants, sympy, numbers = _constants(tree), _sympy_names(tree.body), _factor_numbers(tree)
        own = _OWN_MODULE.fullmatch(path.stem)
        for node, names in _definitions(tree):
            inside = tuple(r for r in regions if node.lineno <= r[1] <= node.end_lineno)
            if inside:
                found.append(_Function(path.stem, names, node, inside, attributes, constants, angled, sympy,
                                       keywords=keywords, numbers=numbers))
            else:  # given whole: by a problem's own module, or by the library (any problem's, ``LIBRARY``)
                whole = ((int(own.group(1)) if own else LIBRARY, node.lineno, node.end_lineno + 1),)
                found.append(_Function(path.stem, names, node, whole, attributes, constants, angled, sympy,
                                       given=True, keywords=keywords))
    return tuple(found)


#: the problem of the regions of the functions the library gives whole (a constructor, a helper): each problem's
LIBRARY = 0


def _factor_numbers(tree: ast.Module) -> frozenset:
    """The numbers a module's formulas multiply or divide by (``12`` of ``m / 12``, ``20.0`` of ``20.0 / m``), but 0
    and 1: one formula's number typed into another (the cuboid's twelfth for the ellipsoid's twentieth)."""
    return frozenset(child.value for node in ast.walk(tree) if isinstance(node, ast.BinOp)
                     and isinstance(node.op, (ast.Mult, ast.Div)) for child in (node.left, node.right)
                     if _factor_number(child))


def _factor_number(node) -> bool:
    return isinstance(node, ast.Constant) and type(node.value) in (int, float) and abs(node.value) not in (0, 1)


def _constants(tree: ast.Module) -> frozenset:
    """The names a module binds at its top level in capitals (``WIRE_LENGTH``, ``GRAVITY_39``), or imports so from
    another module of the reference (``from .mjcf import LENGTH``): its constants."""
    bound = {t.id for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
             for t in (node.targets if isinstance(node, ast.Assign) else [node.target])
             if isinstance(t, ast.Name) and t.id.isupper()}
    imported = {a.asname or a.name for node in tree.body if isinstance(node, ast.ImportFrom) and node.level == 1
                for a in node.names if (a.asname or a.name).isupper()}
    return frozenset(bound | imported)


def _angled(tree: ast.Module):
    """``(function, position)`` and ``(function, name)`` of the parameters that a function of the module (at any
    depth: ``rot(axis, x)`` defined inside another) reads as the argument of a sine or a cosine: the angles it
    takes (a method's positions counted without ``self``)."""
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            positional = [a.arg for a in node.args.posonlyargs + node.args.args]
            if positional[:1] in (["self"], ["cls"]):
                positional = positional[1:]
            parameters = set(positional) | {a.arg for a in node.args.kwonlyargs}
            angles = _trig_arguments(node) & parameters
            for name in angles:
                yield node.name, name
                if name in positional:
                    yield node.name, positional.index(name)


def _keyword_defaults(trees: list) -> frozenset:
    """``(callee, keyword)`` of every parameter with a default of the reference's functions (at any depth, by their
    names) and of its classes' constructors (by the class's name: a class without its own ``__init__``, or whose
    ``__init__`` takes ``**kwargs``, also takes the keywords of its bases' constructors): the keywords a call may
    leave out, its callee then using the default."""
    found, classes = set(), {}
    for tree in trees:
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                found |= {(node.name, name) for name in _defaulted(node)}
            elif isinstance(node, ast.ClassDef):
                init = next((item for item in node.body if isinstance(item, ast.FunctionDef)
                             and item.name == "__init__"), None)
                own = _defaulted(init) if init is not None else frozenset()
                inherits = init is None or init.args.kwarg is not None
                bases = [b.id if isinstance(b, ast.Name) else b.attr if isinstance(b, ast.Attribute) else ""
                         for b in node.bases] if inherits else []
                classes[node.name] = (own, bases)

    def of(name, seen=()):
        own, bases = classes.get(name, (frozenset(), []))
        return set(own).union(*(of(b, seen + (name,)) for b in bases if b not in seen and b in classes))

    found |= {(name, keyword) for name in classes for keyword in of(name)}
    return frozenset(found)


def _trig_arguments(node) -> set:
    """The names read as the one argument of a sine or a cosine under ``node`` (``phi`` of ``np.cos(phi)``)."""
    return {n.args[0].id for n in ast.walk(node) if isinstance(n, ast.Call) and _callee(n) in _TRIG
            and len(n.args) == 1 and not n.keywords and isinstance(n.args[0], ast.Name)}


def _regions(lines: list[str]) -> list[tuple[int, int, int]]:
    found, start = [], None
    for number, line in enumerate(lines, 1):
        begin = _REGION.search(line)
        if begin:
            start = (int(begin.group(1)), number)
        elif start is not None and _END.search(line):
            found.append((start[0], start[1], number))
            start = None
    return found


def _definitions(tree: ast.Module):
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node, (node.name,)
        elif isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    yield item, (node.name, item.name)


# ---------------------------------------------------------------------------------------------- the slips


def _walk(node, guarded=False, indexing=False):
    """``(node, guarded, indexing)`` in pre-order; ``guarded``: inside a loop's bounds, a condition or a creator's
    counts (``np.zeros(n)``; but the values it fills in or spans: ``_filled``), never mutated (``ITERABLE``: inside the
    iterable of a loop, where only an exchange is made: the loop runs as often); ``indexing``: inside an index
    (``q[2 * k - 1]``), where every slip is one of the index."""
    yield node, guarded, indexing
    for field, value in ast.iter_fields(node):
        guard = guarded if guarded is True else (_guards(node, field) or guarded)
        index = indexing or (isinstance(node, ast.Subscript) and field == "slice")
        for position, item in enumerate(value if isinstance(value, list) else [value]):
            if isinstance(item, ast.AST):
                # a value among a creator's counts (``np.full(6, m / 6)``'s fill, ``np.linspace``'s ends) is mutated
                value_guard = guarded if guard is True and _filled(node, field, position, item) else guard
                yield from _walk(item, value_guard, index)


#: ``{creator: (the positions of its arguments that are values, not counts or shapes; their keywords)}``
_FILLS = {"full": ((1,), ("fill_value",)), "linspace": ((0, 1), ("start", "stop"))}


def _filled(node, field: str, position: int, item) -> bool:
    """Whether ``item`` (at ``position`` of ``node``'s ``field``) is a value that a creator of arrays fills in or
    spans (``_FILLS``), which a slip may change as any value, where its counts are left as they are."""
    if not isinstance(node, ast.Call) or _callee(node) not in _FILLS:
        return False
    positions, keywords = _FILLS[_callee(node)]
    return (field == "args" and position in positions) or (field == "keywords" and item.arg in keywords)


def _guards(node, field: str):
    """True where nothing is mutated, ``ITERABLE`` in the iterable of a loop, else False."""
    if (isinstance(node, (ast.For, ast.comprehension)) and field == "iter"):
        return ITERABLE
    return ((isinstance(node, (ast.While, ast.If, ast.IfExp)) and field == "test")
            or isinstance(node, (ast.comprehension, ast.Raise, ast.Assert))
            or (isinstance(node, ast.Call) and _callee(node) in ("range", "len", "reshape", "zeros", "ones", "eye",
                                                                 "empty", "full", "linspace", "arange")))


def _callee(call: ast.Call) -> str:
    func = call.func
    return func.attr if isinstance(func, ast.Attribute) else func.id if isinstance(func, ast.Name) else ""


def _label(node) -> str:
    """A name that says what an operand is (``A_IB`` of ``self.A_IB`` and of ``A_IB.T``, ``R3`` of ``R3(phi)``)."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return _label(node.value) if node.attr == "T" else node.attr
    if isinstance(node, ast.Call):
        return _callee(node)
    if isinstance(node, ast.Subscript):
        return _label(node.value)
    return ""


#: each slip: its diagnosis and what the hint says of it (``{f}``: the student's function, in backquotes)
SLIPS = {
    "sign": ("sign_flip", "one term or factor of `{f}` has the wrong sign"),
    "cross": ("sign_flip", "a cross product in `{f}` is taken the other way round (its sign flips)"),
    "skew": ("sign_flip", "a skew matrix in `{f}` is transposed, or multiplied from the other side (either negates "
                          "it)"),
    "skew_factors": ("sign_flip", "a product with a skew matrix in `{f}` is taken from the other side (``r @ skew(w)`` "
                                  "for ``skew(w) @ r``: the cross product ``r x w`` for ``w x r``), which negates it"),
    "term": ("missing_term", "one term of a sum in `{f}` is left out"),
    "factor": ("missing_factor", "one factor of a product in `{f}` is left out"),
    "inverse_factor": ("inverse_left_out", "`{f}` leaves an inverse factor out of a product (``J.T @ Lam`` for "
                                           "``M_inv @ J.T @ Lam``)"),
    "matrix_factor": ("missing_matrix_factor", "a matrix or vector factor of a product in `{f}` is left out (``J`` "
                                               "for ``J @ qd``)"),
    "rotation": ("wrong_frame", "a rotation is left out in `{f}`: a vector stays in the coordinates of another frame"),
    "number": ("wrong_factor", "a number in `{f}` is left out of a product"),
    "doubled": ("wrong_factor", "a number in `{f}` is doubled"),
    "halved": ("wrong_factor", "a number in `{f}` is halved"),
    # named by the reference's operation; the phrase says what the student's code does instead
    "multiplies": ("wrong_factor", "`{f}` divides where it should multiply"),
    "divides": ("wrong_factor", "`{f}` multiplies where it should divide"),
    "multiplies_by": ("wrong_factor", "`{f}` divides where it should multiply"),
    "divides_by": ("wrong_factor", "`{f}` multiplies where it should divide"),
    "power_scope": ("wrong_factor", "`{f}` raises a whole product to a power where its last factor alone is "
                                    "(``(m * a)**2`` for ``m * a**2``)"),
    "root_scope": ("wrong_factor", "`{f}` takes a factor out of a square root without taking its root "
                                   "(``np.sqrt(x) / m`` for ``np.sqrt(x / m)``)"),
    "magnitude": ("sign_flip", "`{f}` leaves out an absolute value (``v * v`` for ``abs(v) * v``): the sign of a "
                               "value that can be negative is lost"),
    "square": ("wrong_factor", "a square is missing in `{f}`"),
    "unweighted": ("weights_left_out", "`{f}` sums the rows of a product unweighted (``points.sum(axis=0)`` for "
                                       "``masses @ points``): the weights are ignored"),
    "square_of_sum": ("extra_term", "`{f}` squares a sum where the sum of the squares belongs (``(a + b)**2`` for "
                                    "``a**2 + b**2``): a cross term ``2 a b`` is added"),
    "root": ("wrong_factor", "a square root is missing in `{f}`"),
    "trig": ("sin_cos_swapped", "`{f}` takes sin where cos belongs, or the reverse"),
    "degrees": ("degrees", "`{f}` takes an angle in degrees where it is in radians"),
    "radians": ("degrees", "`{f}` converts an angle to radians that already is in radians"),
    "transpose": ("transpose", "a matrix in `{f}` is transposed where it should not be, or the reverse"),
    "turned_back": ("transpose", "a rotation written out in `{f}` is transposed: the signs of its sines are "
                                 "exchanged, which turns it the other way"),
    "index": ("wrong_index", "`{f}` reads an entry from a neighbouring index"),
    "arguments": ("argument_order", "two arguments of a call in `{f}` are exchanged"),
    "names": ("argument_order", "two quantities are exchanged throughout `{f}`"),
    "parameters": ("argument_order", "two of the arguments of `{f}` are exchanged"),
    "names_rates": ("argument_order", "two quantities are exchanged throughout `{f}`"),
    "parameters_rates": ("argument_order", "two of the arguments of `{f}` are exchanged"),
    "factors": ("factor_order", "two factors of a product in `{f}` are multiplied the other way round"),
    "entries": ("swapped", "two entries that `{f}` builds are exchanged"),
    "entries_rates": ("swapped", "two entries that `{f}` builds are exchanged"),
    "arguments_rates": ("argument_order", "two arguments of a call in `{f}` are exchanged"),
    "blocks": ("argument_order", "two groups of arguments of a call in `{f}` are exchanged"),
    "angles_reversed": ("argument_order", "a call in `{f}` is given a list of angles in reverse order"),
    "unpacked_reversed": ("argument_order", "a call in `{f}` unpacks its arguments in reverse order"),
    "sides": ("transpose", "a product in `{f}` transposes the wrong factor"),
    "trigs": ("sin_cos_swapped", "`{f}` takes sin where cos belongs and cos where sin belongs in one expression"),
    "rows": ("state_row", "`{f}` reads a part of the state from the wrong rows"),
    "solved": ("multiplied_not_solved", "`{f}` multiplies by a matrix where it should solve with it"),
    "unsolved": ("no_inverse", "`{f}` leaves out a solve: the right-hand side where the matrix's inverse times it "
                               "belongs"),
    "solve_scope": ("no_inverse", "`{f}` solves with a matrix for part of a sum only: the rest is added outside the "
                                  "solve, without the inverse it belongs under"),
    "inverse": ("no_inverse", "`{f}` uses a matrix where its inverse belongs"),
    "diagonal": ("principal_axes_only", "`{f}` divides by the diagonal of a matrix where it should solve with the "
                                        "whole matrix (or invert it)"),
    "accumulated": ("missing_term", "a sum that `{f}` accumulates keeps only its last term"),
    "running_sum": ("missing_term", "`{f}` leaves out a running sum (``np.cumsum``): each entry keeps its own term "
                                    "alone"),
    "components": ("swapped", "two quantities of one kind (two components of a vector, two gains, ...) are "
                              "exchanged in one expression of `{f}`"),
    "returned_degrees": ("degrees", "`{f}` returns an angle in degrees"),
    "count": ("wrong_factor", "`{f}` divides by the number of entries where their sum belongs"),
    "norm": ("wrong_factor", "`{f}` takes a square root of a sum of squares where the sum belongs"),
    "rates": ("state_row", "`{f}` reads a quantity where its rate belongs, or a rate where the quantity belongs"),
    "frame_objects": ("wrong_frame", "`{f}` reads one coordinate system where another belongs (``C1`` for ``C3``)"),
    "trig_names": ("sin_cos_swapped", "`{f}` reads a sine's values where the cosine's belong (or the reverse)"),
    "frames": ("wrong_frame", "`{f}` reads a quantity in the coordinates of another frame"),
    "frames_turned": ("wrong_frame", "`{f}` reads a rotation the other way round (``A_BI`` for ``A_IB``): its "
                                     "transpose"),
    "identity_block": ("extra_term", "`{f}` writes the identity where a square block of zeros belongs (``np.eye(k)`` "
                                     "for ``np.zeros((k, k))``)"),
    "one_based": ("offset", "`{f}` counts from one where numpy counts from zero (``np.arange(1, n + 1)`` for "
                            "``np.arange(n)``)"),
    "weights": ("swapped", "the weights of two terms of a sum in `{f}` are exchanged (``w * a + (1 - w) * b`` for "
                           "``(1 - w) * a + w * b``)"),
    "spread": ("wrong_factor", "a factor of one term in `{f}` multiplies the whole sum (``m * (a + b)`` for ``m * a + "
                               "b``)"),
    "distributed": ("missing_factor", "a factor in `{f}` multiplies one term of a sum only, not the whole sum"),
    "rotated": ("wrong_frame", "a rotation in `{f}` is applied to one term of a sum only, not the whole sum"),
    "entry_sign": ("sign_flip", "one entry that `{f}` builds has the wrong sign"),
    "vector_sign": ("sign_flip", "a vector that `{f}` writes out has the wrong sign (every entry's sign turned)"),
    "written_index": ("wrong_index", "`{f}` writes an entry into a neighbouring index (row or column)"),
    "kept_adding": ("extra_term", "`{f}` adds a new value to the one its object keeps where it should replace it"),
    "one_inverted": ("no_inverse", "`{f}` inverts one factor of a product where the whole product's inverse "
                                   "belongs ((A B)^-1 is B^-1 A^-1)"),
    "zeroed": ("missing_term", "one entry of a matrix or vector that `{f}` builds is left out (written 0)"),
    "ratio": ("ratio_inverted", "a ratio in `{f}` is upside down"),
    "neighbours": ("factor_order", "two neighbouring factors of a product in `{f}` are multiplied in the wrong "
                                   "order"),
    "rotations": ("rotation_order", "two neighbouring rotations of a product in `{f}` are multiplied in the wrong "
                                    "order"),
    "interleaved": ("state_row", "`{f}` reads the parts of the state from alternate entries where they are its "
                                 "halves"),
    "origin": ("from_origin", "`{f}` measures a position from the origin where it is measured from another "
                                                    "point"),
    "minuend": ("missing_term", "the first term of a difference in `{f}` is left out"),
    "unit": ("missing_factor", "`{f}` leaves one of its arguments out of every product it is a factor of"),
    "step_unit": ("step_left_out", "`{f}` leaves its step out of every product it is a factor of: each update takes "
                                   "a whole unit of time where one step belongs"),
    "step_left_out": ("step_left_out", "the step is left out of a product in `{f}`: the update takes a whole unit of "
                                       "time where one step belongs"),
    "siblings": ("sibling_matrix", "`{f}` reads a matrix where its sibling belongs (one of a pair such as J_R and "
                                   "J_S)"),
    "single": ("float32", "`{f}` computes in single precision (float32) where numpy's float64 belongs"),
    "integer": ("integer_truncated", "`{f}` converts values with an integer dtype (``dtype=int``) where floats "
                                     "belong: every value is cut to a whole number"),
    "integer_array": ("integer_truncated", "`{f}` creates an array of integers (``np.zeros(n, dtype=int)``) where "
                                           "one of floats belongs: every value written into it is cut to a whole "
                                           "number"),
    "integer_call": ("integer_truncated", "`{f}` converts a number with ``int`` where ``float`` belongs: it is cut to "
                                          "a whole number"),
    "floor": ("integer_truncated", "`{f}` divides with ``//`` where ``/`` belongs: the quotient is rounded down to a "
                                   "whole number"),
    "single_argument": ("float32", "`{f}` converts an argument to single precision (float32) before it uses it"),
    "short": ("rounded", "`{f}` uses a constant typed short (pi as 3.14, g as 9.8)"),
    "typed": ("rounded", "`{f}` uses a constant typed short (pi / 6 as 0.52, sqrt(1/3) as 0.577)"),
    "angle": ("wrong_angle", "`{f}` reads one angle where another belongs"),
    "angle_sum": ("wrong_angle", "`{f}` reads one angle where another belongs"),
    "angle_part": ("wrong_angle", "`{f}` reads one angle where another belongs"),
    "sum_part": ("missing_term", "`{f}` reads a name bound to a sum as one of its terms (``l2`` for ``radius`` where "
                                 "``radius = l2 + l3 * sin(phi)``): the other terms are left out there"),
    "term_doubled": ("factor_two", "`{f}` takes one term of a sum twice (as the Coriolis term of a moving point "
                                   "is, ``2 * omega x v``)"),
    "term_halved": ("factor_half", "`{f}` takes one term of a sum halved (a factor 1/2 that belongs elsewhere: "
                                   "in a kinetic energy, a drag's ``rho v**2 / 2``)"),
    "step_term": ("step_typed", "`{f}` takes the term of its step halved (``x + dt * f / 2`` for ``x + dt * f``): the "
                                "run takes steps of half the size"),
    "sibling_number": ("wrong_factor", "`{f}` takes a number of another formula of its module (the cuboid's 12 "
                                       "where the ellipsoid's 20 belongs)"),
    "coordinate": ("state_row", "`{f}` reads one coordinate where another unpacked with it belongs (``q1`` for ``q2`` "
                                "of ``q1, q2 = q``): a value read from another's row"),
    "unsolved_read": ("inverse_left_out", "`{f}` reads the right-hand side of a solve where the solved value belongs "
                                          "(``J @ J.T`` for ``J @ Minv_JT`` of ``Minv_JT = solve(M, J.T)``): the "
                                          "matrix's inverse left out there"),
    "parameter_read": ("wrong_parameter", "`{f}` reads one of its arguments where another one that the same line "
                                          "reads belongs (the width for the height)"),
    "stored_from": ("value_unused", "`{f}` stores one of its arguments from another (a line copied from its "
                                    "neighbour): the argument that belongs there is never used"),
    "repeated": ("value_unused", "`{f}` writes one entry of a list of names as its neighbour (``(m1, m1)`` for "
                                 "``(m1, m2)``): the name that belongs there is never used"),
    "zeros_filled": ("extra_term", "`{f}` passes a value where an array of zeros belongs (``forward_dynamics(M, f, g, "
                                   "qd)`` for ``forward_dynamics(M, f, g, np.zeros(n))``: the rates as the torques): a "
                                   "term that does not belong is added"),
    "argument_repeated": ("value_unused", "`{f}` passes one argument of a call as its neighbour (``f(y, m, m, g)`` "
                                          "for ``f(y, m, theta, g)``): the name that belongs there is never used"),
    "default": ("ignored_argument", "`{f}` reads a constant (the default, or the module's constant of that name) "
                                    "where its argument belongs: the argument is ignored"),
    "defaults": ("ignored_argument", "`{f}` reads every parameter that has a default as that default (the module's "
                 "constants), whatever it is given: every argument ignored"),
    "start_value": ("start_value", "`{f}` reads the value at the start where the value it computed from it belongs "
                    "(the computation left unused: the start returned for the end)"),
    "earth": ("earth_gravity", "`{f}` uses the Earth's gravity (9.81, or the vector (0, -9.81, 0)) where the gravity "
                               "it is given belongs"),
    "axes": ("transpose", "`{f}` takes a row of a matrix where its column belongs, or the reverse"),
    "cycled": ("swapped", "`{f}` lists quantities in another order (the last first, or the first last)"),
    "unpacked": ("swapped", "`{f}` unpacks the coordinates into its names in another order"),
    # the slips of a module's constant (``_constant_slips``): ``{f}`` is the constant's name
    "constant_sign": ("sign_flip", "a number of the constant `{f}` has the wrong sign"),
    "constant_doubled": ("factor_two", "a number of the constant `{f}` is twice the one that belongs"),
    "constant_halved": ("factor_half", "a number of the constant `{f}` is half the one that belongs"),
    "constant_tenfold": ("wrong_factor", "a number of the constant `{f}` is ten times the one that belongs (its "
                                         "decimal point misplaced)"),
    "constant_tenth": ("wrong_factor", "a number of the constant `{f}` is a tenth of the one that belongs (its "
                                       "decimal point misplaced)"),
    "constant_thousandfold": ("wrong_factor", "a number of the constant `{f}` is a thousand times the one that "
                                              "belongs (in another unit: mm for m, g for kg)"),
    "constant_thousandth": ("wrong_factor", "a number of the constant `{f}` is a thousandth of the one that belongs "
                                            "(in another unit: m for mm, kg for g)"),
    "constant_hundredfold": ("wrong_factor", "a number of the constant `{f}` is a hundred times the one that belongs "
                                             "(in another unit: cm for m)"),
    "constant_hundredth": ("wrong_factor", "a number of the constant `{f}` is a hundredth of the one that belongs (in "
                                           "another unit: m for cm)"),
    "constant_step": ("step_typed", "the constant `{f}`, a step or a count of steps, is typed otherwise (a factor 2, "
                                    "10, 100 or 1000 off, or its square root or square): the run takes steps of "
                                    "another size"),
    "constant_degrees": ("degrees", "a number of the constant `{f}` is an angle in degrees where radians belong"),
    "constant_radians": ("degrees", "a number of the constant `{f}` is an angle in radians where degrees belong"),
    "constant_root": ("wrong_factor", "a number of the constant `{f}` is the square root of the one that belongs"),
    "constant_square": ("wrong_factor", "a number of the constant `{f}` is the square of the one that belongs"),
    "constant_direction": ("wrong_factor", "the vector constant `{f}` is written as its direction alone (divided by "
                                           "its length: gravity as a unit vector)"),
    "constant_entries": ("swapped", "two entries of the constant `{f}` are exchanged"),
    "constant_trig": ("sin_cos_swapped", "the constant `{f}` takes sin where cos belongs, or the reverse"),
    "constant_zeroed": ("missing_term", "an entry of the constant `{f}` is left out (written 0)"),
    "constant_converted_back": ("degrees", "the constant `{f}` is converted the wrong way (rad2deg where deg2rad "
                                           "belongs, or the reverse)"),
    "constant_typed": ("rounded", "the constant `{f}` is typed short (pi / 2 as 1.57)"),
    "constant_single": ("float32", "the constant `{f}` is an array of single precision (``dtype=np.float32``) where "
                                   "numpy's float64 belongs"),
    "constant_transposed": ("transpose", "a matrix of the constant `{f}` is written transposed (its rows as "
                                         "columns)"),
    "constants": ("swapped", "the constants `{f}` are exchanged"),
    "loop_short": ("missing_term", "a loop in `{f}` stops one short: its last item is left out"),
    "loop_late": ("missing_term", "a loop in `{f}` starts one late: its first item is left out"),
    "steps_short": ("step_count", "the loop of steps in `{f}` takes one step too few (it stops one short, or "
                                  "starts one late)"),
    "steps_late": ("step_count", "the loop of steps in `{f}` takes one step too few (it stops one short, or "
                                 "starts one late)"),
    "steps_long": ("step_count", "the loop of steps in `{f}` takes one step too many (``range(n + 1)`` for "
                                 "``range(n)``)"),
    "start_zeroed": ("initial_state", "an entry of the start `{f}` is written 0: the run starts from another state"),
    "start_zeros": ("initial_state", "the start `{f}` is written as zeros: the run starts from another state"),
    "start_identity": ("initial_state", "the start `{f}` is written as the identity: the run starts from another "
                                        "orientation"),
    "point_doubled": ("wrong_factor", "a number of a point's position that `{f}` writes out is doubled (a full "
                                      "length where a half belongs)"),
    "point_halved": ("wrong_factor", "a number of a point's position that `{f}` writes out is halved (a half where "
                                     "a full length belongs)"),
    "first_offset": ("offset", "`{f}` places every item of a loop as its first, or the first as the others (the "
                               "first's own position, ``if k == 0``, given to all or to none)"),
    "first_frame": ("wrong_frame", "`{f}` turns every item of a loop as its first, or the first as the others (the "
                                   "first's own rotation, ``if k == 0``, given to all or to none)"),
    "default_taken": ("ignored_argument", "`{f}` takes the default whatever its argument (``np.eye(3) if I is None "
                      "else I`` written ``np.eye(3)``): the argument is ignored"),
    "handed_on": ("ignored_argument", "a call in `{f}` leaves out the arguments it is to hand on (``*args``, "
                  "``**kwargs``), so that the callee uses its defaults: those arguments are ignored"),
    "keyword": ("missing_term", "a call in `{f}` leaves out one of its keyword arguments, so that the callee's "
                                "default is used"),
    "keyword_point": ("offset", "a call in `{f}` leaves out a point's position among its keyword arguments, so that "
                                "the callee's default puts the point elsewhere"),
    "inverses": ("no_inverse", "`{f}` leaves out every inverse (and solve) of one statement"),
    "principal": ("missing_term", "`{f}` multiplies by an inertia's diagonal alone (the principal moments), its "
                                  "off-diagonal entries left out"),
    "whole_sum": ("extra_term", "`{f}` sums every entry of a matrix where its trace (the diagonal's sum) belongs"),
    "identity": ("extra_term", "`{f}` writes the identity matrix as the number 1 (numpy adds it to every entry, not "
                               "to the diagonal alone)"),
    "identity_left_out": ("missing_identity", "the identity matrix of a product in `{f}` is left out (the number "
                                              "it multiplies is added to every entry, not to the diagonal alone)"),
    "event_residual": ("event_residual", "the event function in `{f}` returns a test or a magnitude (`y > 0`, "
                       "`abs(...)`) where a residual belongs that changes sign at the event"),
    "converted_degrees": ("degrees", "`{f}` converts an angle to degrees where it takes its sine or cosine in "
                                     "radians"),
    "converted_radians": ("degrees", "`{f}` converts an argument to radians that already is in radians"),
    "converted_back": ("degrees", "`{f}` converts an angle the wrong way (rad2deg where deg2rad belongs, or the "
                                  "reverse)"),
    "converted_rpm": ("wrong_factor", "`{f}` converts an argument from rpm to rad/s that already is in rad/s"),
    "inertial_vector": ("wrong_frame", "`{f}` turns a vector of body coordinates into inertial ones (``A_IB @ B_v_B``) "
                                       "where the body's own belong"),
    "inertial_matrix": ("wrong_frame", "`{f}` turns a matrix of body coordinates into inertial ones (A M A^T) where "
                                       "the body's own belongs"),
}
#: the slips of a dtype, tried where a value is guarded too (a dtype changes no count)
_DTYPES = frozenset({"single", "integer", "integer_call"})
#: the slips made in the iterable of a loop, which runs as often: exchanges, a dtype, an entry of a list of names
#: written as its neighbour, a quantity read for its rate (``zip(q, qdd)`` for ``zip(q, qd)``)
_KEEP_COUNT = _EXCHANGES | _DTYPES | frozenset({"repeated", "rates"})
#: the slips of precision: told only where the student's value is in the band of precision (``PRECISION_BAND``)
PRECISION_SLIPS = frozenset({"single", "single_argument", "short", "typed", "constant_typed", "constant_single"})
#: the largest difference between the student's value and the expected one, relative to the expected value's size,
#: that a slip of precision makes (a constant typed to two decimals, float32 accumulated over a run: pi as 3.14 is
#: 5e-4, g as 9.8 is 1e-3, float32 alone about 1e-7); past it a slip of precision is not told
PRECISION_BAND = 1e-2
#: a slip of precision is told only where it leaves at most this share of the difference between the student's
#: value and the expected one (a value merely near the student's, inside a loose tolerance, is no reproduction)
PRECISION_SHARE = 0.1
#: how pi is typed short
SHORT_PI = (3.14, 3.1416)
#: the decimals a number of the code is typed short to
SHORT_DECIMALS = (1, 2)
#: the decimals a constant of the code that is not one number (``np.pi / 6``, ``np.sqrt(1.0 / 3.0)``, a module's
#: constant ``GAMMA``) is typed short to, as its value rounded (``round(np.pi / 6, 2)``: 0.52), up to the four
#: decimals the sheet prints; not one decimal, which writes a small entry 0 (a slope's ``sin`` of 0.017 left out is
#: a term left out, not a value typed short)
TYPED_DECIMALS = (2, 3, 4)
#: the names a constant expression may read besides numbers: its modules and pi
_CONSTANT_NAMES = frozenset({"np", "numpy", "math", "sp", "sympy", "pi"})
#: the functions a constant expression may call (``np.sqrt(3)``, ``np.deg2rad(30.0)``)
_CONSTANT_CALLS = frozenset({"sqrt", "deg2rad", "radians", "Rational", "cos", "sin", "tan", "exp"})
#: the names of a function's arguments that a slip of precision converts at its start (a run's state, coordinates)
_SINGLE = re.compile(r"^(y|y_\w+|state|q|qd|x)$")


def _constant_expression(node) -> bool:
    """An expression of numbers that is not one number (``np.pi / 6``, ``np.sqrt(1.0 / 3.0)``, ``sp.pi / 6``):
    operations and calls (``_CONSTANT_CALLS``) of numbers and pi, no other name read."""
    if not isinstance(node, (ast.BinOp, ast.UnaryOp, ast.Call)) and not _pi(node):
        return False
    for inner in ast.walk(node):
        if isinstance(inner, ast.Name) and inner.id not in _CONSTANT_NAMES:
            return False
        if isinstance(inner, ast.Call) and (_callee(inner) not in _CONSTANT_CALLS or inner.keywords):
            return False
        if isinstance(inner, ast.Attribute) and not (_pi(inner) or isinstance(inner.value, ast.Name)):
            return False
        if not isinstance(inner, (ast.BinOp, ast.UnaryOp, ast.Call, ast.Name, ast.Attribute, ast.Constant,
                                  ast.Load, ast.operator, ast.unaryop)):
            return False
        if isinstance(inner, ast.Constant) and not _number(inner):
            return False
    return not (isinstance(node, ast.UnaryOp) and _number(node.operand))


def _typed_slips(node, parent, constants: frozenset):
    """A constant typed short, to ``TYPED_DECIMALS`` decimals: an expression of numbers (``np.pi / 6`` as 0.52),
    the largest one there (not a part of another), or a read of a module's constant (``GAMMA``), in its place
    the value rounded (a slip of precision: the value it gives is held to the band of precision): an expression,
    a number, as ``round(float(expression), decimals)``; a constant, a number or an array, with numpy's round; and a
    division by a number written as a product with its reciprocal typed short (``m / 12`` as ``0.0833 * m``)."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div) and _number(node.right) and node.right.value \
            and not _constant_expression(node.left):  # ``m / 12`` typed ``0.0833 * m``: the reciprocal typed short
        reciprocal = 1.0 / node.right.value
        for decimals in TYPED_DECIMALS:
            typed = round(reciprocal, decimals)
            if typed != 0.0 and typed != reciprocal:
                yield "typed", lambda n, typed=typed: ast.BinOp(ast.Constant(typed), ast.Mult(), n.left)
        return
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in constants:
        rounded = _np_round
    elif _constant_expression(node) and not _pi(node) and not _constant_expression(parent):
        rounded = _float_round
    else:
        return
    for decimals in TYPED_DECIMALS:
        yield "typed", lambda n, decimals=decimals: rounded(n, decimals)


def _float_round(node, decimals: int):
    """``round(float(node), decimals)``: a number typed to ``decimals`` decimals (a float, whatever ``node`` is:
    sympy's own rounding keeps only the digits typed as its precision)."""
    value = ast.Call(ast.Name("float", ast.Load()), [node], [])
    return ast.Call(ast.Name("round", ast.Load()), [value, ast.Constant(decimals)], [])


def _np_round(node, decimals: int):
    """numpy's ``round(node, decimals)``, read without a name of the module (the function may bind none)."""
    numpy = ast.Call(ast.Name("__import__", ast.Load()), [ast.Constant("numpy")], [])
    return ast.Call(ast.Attribute(numpy, "round", ast.Load()), [node, ast.Constant(decimals)], [])


#: the names of an integration's step, by the course's notation (``dt``, ``h``, ``self.dt``, ``time_step``)
_STEP = re.compile(r"^(?:dt|h|step|time_step|delta_t|d_t)$")
#: the names of an inverse (``M_inv``, ``Minv``, ``inv_M``), for a factor left out
_INVERSE = re.compile(r"^(?:[A-Za-z]\w*_?inv|inv_[A-Za-z]\w*)$")


def _dropped(operand) -> str:
    """The slip of a factor left out of a product: a number, the identity matrix (``(r @ r) * np.eye(3)`` as
    ``r @ r``: the number is added to every entry, not to the diagonal alone), a rotation (a frame slip), the step
    of an integration (``expm_skew(I_Om)`` for ``expm_skew(dt * I_Om)``: a whole unit of time taken for a step) or
    an inverse (``J.T @ Lam`` for ``M_inv @ J.T @ Lam``: the inverse left out, and as truly a factor left out) or
    another factor."""
    if _number(operand) or (isinstance(operand, ast.UnaryOp) and _number(operand.operand)):
        return "number"
    if isinstance(operand, ast.Call) and _callee(operand) in ("eye", "identity"):
        return "identity_left_out"
    if isinstance(operand, (ast.Name, ast.Attribute)) and _STEP.match(_label(operand) or "-"):
        return "step_left_out"
    if (isinstance(operand, ast.Name) and _INVERSE.match(operand.id)) \
            or (isinstance(operand, ast.Call) and _callee(operand) == "inv"):
        return "inverse_factor"
    return "rotation" if _ROTATION.match(_label(operand) or "-") else "factor"


def _negated(node):
    return ast.UnaryOp(ast.USub(), node)


def _transposed(node):
    return ast.Attribute(node, "T", ast.Load())


def _number(node) -> bool:
    return isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool)


def _pi(node) -> bool:
    """``np.pi``, ``math.pi`` or ``pi`` read."""
    return (isinstance(node, ast.Attribute) and node.attr == "pi" or isinstance(node, ast.Name) and node.id == "pi") \
        and isinstance(node.ctx, ast.Load)


def _typed_short(value: float) -> list:
    """The values of a number of the code typed to fewer decimals (``SHORT_DECIMALS``: 9.81 as 9.8), each a slip of
    precision (not zero, off by at most ``PRECISION_BAND`` of it)."""
    found = []
    for decimals in SHORT_DECIMALS:
        typed = round(value, decimals)
        if typed != 0.0 and typed != value and abs(typed - value) <= PRECISION_BAND * abs(value) \
                and typed not in found:
            found.append(typed)
    return found


#: how numpy's double precision is named in a dtype
_DOUBLE = frozenset({"float", "float64", "double", "f8", "float_"})


def _double(node) -> bool:
    """A dtype of double precision (``float``, ``np.float64``, ``"float64"``)."""
    if isinstance(node, ast.Name):
        return node.id in _DOUBLE
    if isinstance(node, ast.Attribute):
        return node.attr in _DOUBLE
    return isinstance(node, ast.Constant) and node.value in _DOUBLE


def _float32():
    return ast.Attribute(ast.Name("np", ast.Load()), "float32", ast.Load())


def _integer():
    return ast.Name("int", ast.Load())


#: numpy's creators of an array of a given shape (their positional arguments before a dtype): an array of them made
#: of integers cuts every float written into it to a whole number
_CREATORS = {"zeros": 1, "ones": 1, "empty": 1, "zeros_like": 1, "ones_like": 1, "empty_like": 1, "full": 2,
             "full_like": 2}


def _single_slips(node: ast.Call):
    """A dtype of double precision given as single (``np.asarray(q, dtype=float)``, ``.astype(float)``), or as an
    integer (``dtype=int``: every value cut to a whole number), an array given no dtype created in single precision
    (``np.array([x, y], dtype=np.float32)``), and a number converted with ``int`` where ``float`` belongs."""
    callee = _callee(node)
    if callee == "float" and isinstance(node.func, ast.Name) and len(node.args) == 1 and not node.keywords:
        yield "integer_call", lambda n: _with(n, func=_integer())
    for slip, dtype in (("single", _float32), ("integer", _integer)):
        for k, keyword in enumerate(node.keywords):
            if keyword.arg == "dtype" and _double(keyword.value):
                yield slip, lambda n, k=k, dtype=dtype: _with(n, keywords=[
                    ast.keyword("dtype", dtype()) if i == k else w for i, w in enumerate(n.keywords)])
        if _callee(node) in ("astype", "array", "asarray") and node.args and _double(node.args[-1]) \
                and len(node.args) == (1 if _callee(node) == "astype" else 2):
            yield slip, lambda n, dtype=dtype: _with(n, args=n.args[:-1] + [dtype()])
    if callee in ("array", "asarray") and isinstance(node.func, ast.Attribute) and len(node.args) == 1 \
            and not node.keywords:  # an array given no dtype, created in single precision
        yield "single", lambda n: _with(n, keywords=[ast.keyword("dtype", _float32())])


def _slips(node, parent):
    """``(slip, edit)`` of the slips at ``node`` (``slip``: a key of ``SLIPS``): ``edit(copy)`` gives the node
    that replaces the copy of ``node``, or ``("names", a, b)`` exchanges two names throughout the function."""
    if isinstance(node, ast.BinOp):
        yield from _binop_slips(node)
    elif isinstance(node, ast.AugAssign) and isinstance(node.op, (ast.Add, ast.Sub)):
        other = ast.Sub() if isinstance(node.op, ast.Add) else ast.Add()
        yield "sign", lambda n: _with(n, op=other)
        yield "term", lambda n: ast.Pass()
        if isinstance(node.target, ast.Name):
            yield "accumulated", _assigned
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        yield "sign", lambda n: n.operand
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.UAdd):  # ``+C / 2`` written ``-C / 2``
        yield "sign", lambda n: _with(n, op=ast.USub())
    elif isinstance(node, ast.Call):
        yield from _call_slips(node)
        callee = _callee(node)
        if callee in _CREATORS and isinstance(parent, ast.Assign) and isinstance(node.func, ast.Attribute) \
                and len(node.args) == _CREATORS[callee] and not any(k.arg == "dtype" for k in node.keywords):
            # ``table = np.zeros((7, 3), dtype=int)``, then filled with floats: each cut to a whole number
            yield "integer_array", lambda n: _with(n, keywords=n.keywords + [ast.keyword("dtype", _integer())])
    elif isinstance(node, ast.Attribute) and node.attr == "T" and isinstance(node.ctx, ast.Load):
        yield "transpose", lambda n: n.value
    elif _pi(node):
        for typed in SHORT_PI:
            yield "short", lambda n, typed=typed: ast.Constant(typed)
    elif _number(node) and isinstance(node.value, float):
        for typed in _typed_short(node.value):
            yield "short", lambda n, typed=typed: ast.Constant(typed)
    elif isinstance(node, (ast.Tuple, ast.List)) and 2 <= len(node.elts) <= 6 \
            and not any(isinstance(e, ast.Starred) for e in node.elts):
        reads = _reads(node, parent)
        for i, j in _pairs(len(node.elts)):
            exchange = "rows" if _state_read(reads[i]) and _state_read(reads[j]) else \
                "entries_rates" if _rate_exchange(node.elts[i], node.elts[j]) else "entries"
            yield exchange, lambda n, i=i, j=j: _exchanged(n, "elts", i, j)
        if all(_reciprocal(e) for e in node.elts):
            yield "inverse", lambda n: _with(n, elts=[e.right for e in n.elts])
        if isinstance(node.ctx, ast.Load) and _halves(node.elts):  # ``y[:3], y[3:]`` as ``y[::2], y[1::2]``
            yield "interleaved", _interleaved
        if isinstance(node.ctx, ast.Load) and _written_out(node):  # ``[[c, s], [-s, c]]`` for [[c, -s], [s, c]]
            yield "turned_back" if _turning(node) else "transpose", _literal_transposed
    elif isinstance(node, ast.Dict) and 2 <= len(node.values) <= 6 and None not in node.keys:
        for i, j in _pairs(len(node.values)):  # ``{a: alpha, b: beta}`` as ``{a: beta, b: alpha}``: keys kept
            yield "entries", lambda n, i=i, j=j: _exchanged(n, "values", i, j)
    elif isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Load):
        yield from _index_slips(node)
        if _state_read(node) and _half(node.slice):
            yield "rows", lambda n: _with(n, slice=ast.Slice(n.slice.upper, n.slice.lower, None))
    if isinstance(node, ast.Call) and any(isinstance(a, ast.Starred) for a in node.args):  # ``f(*angles[::-1])``
        yield "unpacked_reversed", _unpacked_reversed
    if isinstance(node, ast.Call):  # ``_run(step, ANGLES0[::-1])``: a list of angles passed in reverse order
        for k, argument in enumerate(node.args):
            if isinstance(argument, ast.Name) and _ANGLES.search(argument.id):
                yield "angles_reversed", lambda n, k=k: _with(n, args=n.args[:k] + [ast.Subscript(
                    n.args[k], ast.Slice(None, None, ast.Constant(-1)), ast.Load())] + n.args[k + 1:])
    if _conversion(node):
        yield "converted_back", _converted_back
    if isinstance(node, ast.Assign) and _stored(node):  # ``self.r = r`` as ``self.r = self.r + r``
        yield "kept_adding", lambda n: _with(n, value=ast.BinOp(_loaded(n.targets[0]), ast.Add(), n.value))
    if isinstance(node, ast.Return):
        for k in _returned_names(node):  # ``np.array([x, y, gamma])`` with gamma in degrees
            yield "returned_degrees", lambda n, k=k: _in_degrees(n, k)
    if isinstance(node, ast.Return) and node.value is not None and _event_function(parent):
        for op in (ast.Gt(), ast.Lt()):  # ``y[0] > 0`` for ``y[0]``: a test where a residual belongs
            yield "event_residual", lambda n, op=op: _with(n, value=ast.Compare(n.value, [op], [ast.Constant(0.0)]))
        yield "event_residual", lambda n: _with(n, value=ast.Call(ast.Name("abs", ast.Load()), [n.value], []))
    if isinstance(node, (ast.For, ast.ListComp, ast.GeneratorExp, ast.SetComp, ast.DictComp)):
        steps = _stepping(node)
        for k in range(1 if isinstance(node, ast.For) else len(node.generators)):  # each of a comprehension's loops
            yield "steps_short" if steps else "loop_short", \
                lambda n, k=k: _loop_cut(n, ast.Slice(None, ast.Constant(-1), None), k)
            yield "steps_late" if steps else "loop_late", \
                lambda n, k=k: _loop_cut(n, ast.Slice(ast.Constant(1), None, None), k)
        if steps and isinstance(node.iter, ast.Call) and _callee(node.iter) == "range" and node.iter.args \
                and not node.iter.keywords and len(node.iter.args) <= 2:  # ``range(n + 1)``: one step more
            yield "steps_long", lambda n: _with(n, iter=_with(n.iter, args=n.iter.args[:-1] + [
                ast.BinOp(n.iter.args[-1], ast.Add(), ast.Constant(1))]))
    if isinstance(node, (ast.Assign, ast.Return, ast.AugAssign, ast.Expr)) and _inverses(node) >= 2:
        yield "inverses", lambda n: _Uninverted().visit(n)
    if isinstance(node, (ast.Assign, ast.Return, ast.AugAssign)):
        if _trigs(node) >= {"sin", "cos"}:
            yield "trigs", _all_trigs_exchanged
        for a, b in _components(node):
            yield "components", lambda n, a=a, b=b: _renamed_in(n, a, b)
    if isinstance(parent, ast.BinOp) and isinstance(parent.op, (ast.Add, ast.Sub, ast.Mult, ast.MatMult)) \
            and isinstance(node, (ast.Name, ast.Attribute, ast.Subscript, ast.Call)):
        yield "sign", _negated
        if isinstance(parent.op, ast.MatMult) and not (isinstance(node, ast.Attribute) and node.attr == "T"):
            yield "transpose", _transposed


def _stepping(node) -> bool:
    """True for a loop of steps: a ``for`` loop whose items its body does not read, and whose body computes a
    name from that name's own value (``x = step(x, omega, dt)``, ``q = q + dt * qd``, ``t += dt``): one item fewer
    is one step fewer of a run, where a loop over items that it reads (a sum of terms) leaves an item out."""
    if not isinstance(node, ast.For):
        return False
    items = {n.id for n in ast.walk(node.target) if isinstance(n, ast.Name)}
    body = ast.Module(node.body, [])
    if items & {n.id for n in ast.walk(body) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}:
        return False
    for statement in ast.walk(body):
        if isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name):
            return True
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1 \
                and isinstance(statement.targets[0], ast.Name) and statement.targets[0].id in _read(statement.value):
            return True
    return False


def _loop_cut(node, cut: ast.Slice, k: int = 0):
    """The loop (or the comprehension's ``k``-th loop) over its items ``cut``: ``[*items][:-1]`` (one short) or
    ``[*items][1:]`` (one late), whatever the items are (a list, a range, an ``enumerate``)."""
    def cut_of(items):
        return ast.Subscript(ast.List([ast.Starred(items, ast.Load())], ast.Load()), cut, ast.Load())

    if isinstance(node, ast.For):
        return _with(node, iter=cut_of(node.iter))
    loop = _with(node.generators[k], iter=cut_of(node.generators[k].iter))
    return _with(node, generators=node.generators[:k] + [loop] + node.generators[k + 1:])


def _inverse_call(node) -> bool:
    """``np.linalg.inv(A)``, sympy's ``A.inv()`` or ``np.linalg.solve(A, b)``."""
    if not isinstance(node, ast.Call) or node.keywords:
        return False
    callee = _callee(node)
    return (callee == "inv" and (len(node.args) == 1 or (not node.args and isinstance(node.func, ast.Attribute)))
            or callee == "solve" and len(node.args) == 2)


def _inverses(statement) -> int:
    return sum(_inverse_call(n) for n in ast.walk(statement))


class _Uninverted(ast.NodeTransformer):
    """Every inverse of a statement left out: ``inv(A)`` and ``A.inv()`` as ``A``, ``solve(A, b)`` as ``A @ b``."""

    def visit_Call(self, node):
        self.generic_visit(node)
        if not _inverse_call(node):
            return node
        if _callee(node) == "solve":
            return ast.BinOp(node.args[0], ast.MatMult(), node.args[1])
        return node.args[0] if node.args else node.func.value


def _keyword_slips(node, keywords: frozenset):
    """A keyword argument left out of a call of a function (or a class) of the reference whose parameter of that
    name has a default (``keywords``: ``_keyword_defaults``): the callee then uses the default; a point's position
    by the course's notation left out (``P_r_PDp``) moves the point, an offset."""
    if isinstance(node, ast.Call):
        callee = _callee(node)
        for k, keyword in enumerate(node.keywords):
            # ``super().__init__()`` for ``super().__init__(**kinematics)``: the keywords to hand on left out
            slip = "handed_on" if keyword.arg is None else \
                "keyword_point" if (callee, keyword.arg) in keywords and _POSITION.match(keyword.arg) else \
                "keyword" if (callee, keyword.arg) in keywords else None
            if slip is not None:
                yield slip, lambda n, k=k: _with(n, keywords=n.keywords[:k] + n.keywords[k + 1:])
        for k, argument in enumerate(node.args):
            if isinstance(argument, ast.Starred):
                yield "handed_on", lambda n, k=k: _with(n, args=n.args[:k] + n.args[k + 1:])
    if isinstance(node, ast.IfExp) and _none_test(node.test):  # ``eye(3) if I is None else I`` as ``eye(3)``
        yield "default_taken", lambda n: n.body if isinstance(n.test.ops[0], ast.Is) else n.orelse


def _position_slips(node):
    """A number of a point's position written out (``P_r_PDp=(half, 0.0, 0.0)``, ``P_r_PDp = (0.0, -0.5, 0.0)``, in
    either branch of a choice) doubled or halved: a full length for a half, or the reverse, which places the point
    elsewhere (told as a factor, and as an offset beside it: ``RIVALS``)."""
    target = _bound_name(node)
    if not target or not _POSITION.match(target):
        return
    for i, point in enumerate(_points(node.value)):
        for k, entry in enumerate(point.elts):
            if _scalable(entry):
                for slip, factor in (("point_doubled", 2.0), ("point_halved", 0.5)):
                    yield slip, lambda n, i=i, k=k, factor=factor: _scaled_entry(n, i, k, factor)


def _bound_name(node) -> str | None:
    """The name a keyword argument or an assignment to one name gives its value (``P_r_PDp`` of ``P_r_PDp=...`` or
    of ``P_r_PDp = ...``), or None."""
    if isinstance(node, ast.keyword):
        return node.arg
    if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
        return node.targets[0].id
    return None


def _points(value) -> list:
    """The points written out in ``value`` (lists or tuples of two or three entries), in ``ast.walk``'s order."""
    return [t for t in ast.walk(value) if isinstance(t, (ast.Tuple, ast.List)) and 2 <= len(t.elts) <= 3]


def _scalable(entry) -> bool:
    """A number other than zero, a name, or either negated."""
    if isinstance(entry, ast.UnaryOp) and isinstance(entry.op, ast.USub):
        entry = entry.operand
    return isinstance(entry, ast.Name) or _number(entry) and entry.value != 0


def _scaled_entry(node, i: int, k: int, factor: float):
    point = _points(node.value)[i]
    entry = point.elts[k]
    point.elts[k] = ast.Constant(entry.value * factor) if _number(entry) else \
        ast.BinOp(ast.Constant(factor), ast.Mult(), entry)
    return node


def _first_slips(node, parent):
    """The first item's own value of a loop (``P_r_PDp=(0, 0, 0) if k == 0 else (half, 0, 0)``) given to every
    item, or the others' given to the first: a position so written is an offset, a rotation a frame."""
    if not (isinstance(node, ast.IfExp) and isinstance(node.test, ast.Compare) and len(node.test.ops) == 1
            and isinstance(node.test.ops[0], ast.Eq) and isinstance(node.test.left, ast.Name)
            and _number(node.test.comparators[0]) and node.test.comparators[0].value == 0):
        return
    target = _bound_name(parent)
    slip = "first_offset" if target and _POSITION.match(target) else \
        "first_frame" if target and _ROTATION.match(target) else None
    if slip is not None:
        yield slip, lambda n: n.body
        yield slip, lambda n: n.orelse



def _none_test(test) -> bool:
    """``x is None`` or ``x is not None`` (the test of an argument left at its default)."""
    return isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], (ast.Is, ast.IsNot)) \
        and isinstance(test.comparators[0], ast.Constant) and test.comparators[0].value is None


#: a matrix in the coordinates of one frame by the course's notation (``B_I_B``, ``K_I_K``): the frame on both sides
_BODY_MATRIX = re.compile(r"^([A-Z][A-Za-z0-9]{0,4})_([A-Z][A-Za-z0-9]*)_\1$")


def _body_matrix(node) -> str | None:
    """The frame of a read of a body's matrix (``B`` of ``self.B_I_B`` or of ``B_I_B``), or None."""
    if isinstance(node, (ast.Name, ast.Attribute)) and isinstance(node.ctx, ast.Load):
        found = _BODY_MATRIX.match(node.id if isinstance(node, ast.Name) else node.attr)
        return found.group(1) if found else None
    return None


def _rotation_at_hand(node, frame: str, names: frozenset, attributes: frozenset):
    """The rotation ``A_I<frame>`` where the function has it at hand: a name it reads or binds (``A_IB``), or an
    attribute of the reference held by the matrix's own holder (``self.A_IB`` beside ``self.B_I_B``); else None."""
    rotation = f"A_I{frame}"
    if isinstance(node, ast.Name):
        return ast.Name(rotation, ast.Load()) if rotation in names else None
    return ast.Attribute(copy.deepcopy(node.value), rotation, ast.Load()) if rotation in attributes else None


#: a vector in the coordinates of a body's frame by the course's notation (``B_v_B``, ``B_omegaDot_B``,
#: ``B_r_BQ``): the frame first, a quantity's name in lower case, a point or a frame
_BODY_VECTOR = re.compile(r"^([A-HJ-Z][A-Za-z0-9]{0,4})_[a-z][A-Za-z0-9]*_[A-Z][A-Za-z0-9]*$")


def _body_vector(node) -> str | None:
    """The frame of a read of a vector in a body's coordinates (``B`` of ``self.B_v_B`` or of ``B_v_B``), or
    None."""
    if isinstance(node, (ast.Name, ast.Attribute)) and isinstance(node.ctx, ast.Load):
        found = _BODY_VECTOR.match(node.id if isinstance(node, ast.Name) else node.attr)
        return found.group(1) if found else None
    return None


def _frame_slips(node, names: frozenset, attributes: frozenset):
    """Every read of a body's matrix in a statement (``B_I_B``) turned into inertial coordinates, ``A_IB @ B_I_B @
    A_IB.T``, where the function has the rotation at hand (``_rotation_at_hand``): the body's matrix where its own
    coordinates belong, taken as the inertial one; and so every read of a vector in the body's coordinates
    (``A_IB @ B_v_B`` for ``B_v_B``)."""
    if not isinstance(node, (ast.Assign, ast.Return, ast.AugAssign, ast.Expr)):
        return
    turned = {id(b.right) for b in ast.walk(node) if isinstance(b, ast.BinOp) and isinstance(b.op, ast.MatMult)
              and _ROTATION.match(_label(b.left) or "-")}  # a vector turned already (``A_IB @ B_omega_B``)
    seen = set()
    for k, read in enumerate(_reads_of(node)):
        matrix, vector = _body_matrix(read), _body_vector(read)
        key = ast.dump(read)
        if matrix is not None and key not in seen:  # every read of a matrix at once
            seen.add(key)
            rotation = _rotation_at_hand(read, matrix, names, attributes)
            if rotation is not None:
                yield "inertial_matrix", lambda n, key=key, rotation=rotation: _Turned(key, rotation).visit(n)
        elif vector is not None and id(read) not in turned:  # each read of a vector alone
            rotation = _rotation_at_hand(read, vector, names, attributes)
            if rotation is not None:
                yield "inertial_vector", lambda n, k=k, rotation=rotation: _turned_read(n, k, rotation)


class _Turned(ast.NodeTransformer):
    """Every read whose ``ast.dump`` is ``key`` as ``rotation @ read @ rotation.T``."""

    def __init__(self, key: str, rotation):
        self.key, self.rotation = key, rotation

    def generic_visit(self, node):
        if isinstance(node, ast.expr) and ast.dump(node) == self.key:
            turned = ast.BinOp(copy.deepcopy(self.rotation), ast.MatMult(), node)
            return ast.BinOp(turned, ast.MatMult(), _transposed(copy.deepcopy(self.rotation)))
        return super().generic_visit(node)


def _reads_of(statement) -> list:
    """The names and attributes of a statement, in ``ast.walk``'s order (a copy of it lists its own alike)."""
    return [n for n in ast.walk(statement) if isinstance(n, (ast.Name, ast.Attribute))]


def _turned_read(statement, k: int, rotation):
    """The statement with its ``k``-th read (of names and attributes, in ``ast.walk``'s order) as ``rotation @
    read``."""
    parents = {id(child): parent for parent in ast.walk(statement) for child in ast.iter_child_nodes(parent)}
    read = _reads_of(statement)[k]
    _replace(parents[id(read)], read, ast.BinOp(copy.deepcopy(rotation), ast.MatMult(), read))
    return statement


#: the conversions of units a course applies to an argument (``_conversion_slips``), into the units a function
#: computes in: degrees to radians, rpm to rad/s, each by its factor
CONVERSIONS = (("converted_radians", np.pi / 180.0), ("converted_rpm", np.pi / 30.0))


def _conversion_slips(function: ast.FunctionDef, lines: tuple, angles: frozenset = frozenset()):
    """Every read of one of the function's arguments in the region multiplied by the factor of a conversion of
    units (``CONVERSIONS``): an argument converted that already is in the unit the function computes in (``omega *
    np.pi / 30`` of a rate given in rad/s), or converted the wrong way; and every read of a name the function binds
    itself and reads as an angle (``angles``: ``phi`` of ``x, z, phi = y`` and ``np.cos(phi)``) converted from
    degrees, as where each of its sines and cosines is taken of it in degrees; and every read of an angle, its own
    or an argument, converted to degrees (``phi = np.rad2deg(phi)`` before ``np.cos(phi)``)."""
    def scaled(name: str, factor: float):
        return "read_as", name, ast.BinOp(ast.Name(name, ast.Load()), ast.Mult(), ast.Constant(factor))

    used = {node.id for node in ast.walk(function) if isinstance(node, ast.Name) and _in(node, lines)}
    parameters = [a.arg for a in function.args.posonlyargs + function.args.args + function.args.kwonlyargs]
    for name in parameters:
        if name in used and name not in ("self", "cls"):
            for slip, factor in CONVERSIONS:
                yield slip, scaled(name, factor)
    slip, factor = CONVERSIONS[0]
    for name in sorted(angles & used - set(parameters)):
        yield slip, scaled(name, factor)
    for name in sorted(angles & used):  # ``phi = np.rad2deg(phi)`` before its sine and cosine are taken
        yield "converted_degrees", scaled(name, 1.0 / factor)


#: the marks of a rate in the course's notation: ``qd`` of ``q``, ``qdd`` of ``qd``, ``omegaDot`` of ``omega``,
#: ``dOm`` of ``Om``, ``x_dot`` of ``x``
_RATE_SUFFIXES = ("d", "dot", "Dot")
#: a quantity and its rate by their letters (``B_v_B`` and ``B_a_B``)
_RATE_LETTERS = {("r", "v"), ("v", "a")}
#: a part of a name that names a frame (``I``, ``B``, ``C3``, ``Dp``, ``DpDs``)
_FRAME_PART = re.compile(r"^[A-Z][A-Za-z0-9]{0,4}$")


def _rate(a: str, b: str) -> bool:
    """``b`` names the rate of what ``a`` names: one part of the name (between underscores) carries a rate's mark
    (``qd`` of ``q``, ``B_omegaDot_B`` of ``B_omega_B``, ``dq1`` of ``q1``) or the next letter of r, v, a; or, by
    the course's notation, ``b`` is the velocity of the point whose position ``a`` is, in the same frame's
    coordinates (``B_v_B`` of ``B_r_IB``: the position from I to B, the velocity of B)."""
    if b == f"{a}_dot":
        return True
    first, second = a.split("_"), b.split("_")
    if len(first) != len(second):
        return False
    if len(first) == 3 and first[0] == second[0] and (first[1], second[1]) == ("r", "v") \
            and len(second[2]) < len(first[2]) and first[2].endswith(second[2]) and second[2][:1].isupper():
        return True
    differ = [(x, y) for x, y in zip(first, second) if x != y]
    if len(differ) != 1 or not differ[0][0]:
        return False
    x, y = differ[0]
    return y in {x + mark for mark in _RATE_SUFFIXES} | {"d" + x} or (x, y) in _RATE_LETTERS


def _rates(a: str, b: str) -> bool:
    """One of two names names the other's rate."""
    return _rate(a, b) or _rate(b, a)


def _frames(a: str, b: str) -> bool:
    """Two names of one quantity in the coordinates of two frames, by the course's notation: ``I_v_B`` and
    ``B_v_B`` (the frame of the coordinates, the quantity, its points), ``A_IC2`` and ``A_IC3`` (two rotations)."""
    first, second = a.split("_"), b.split("_")
    if len(first) != len(second) or len(first) < 2:
        return False
    frame = 1 if len(first) == 2 and first[0] == second[0] == "A" else 0 if len(first) >= 3 else None
    if frame is None or first[:frame] + first[frame + 1:] != second[:frame] + second[frame + 1:]:
        return False
    return first[frame] != second[frame] and all(_FRAME_PART.match(p) for p in (first[frame], second[frame]))


def _turned_round(a: str, b: str) -> bool:
    """Two names of one rotation and of the rotation the other way round, by the course's notation: ``A_IB`` and
    ``A_BI``, ``A_DsDp`` and ``A_DpDs`` (the frames of the second in the reverse order of the first's)."""
    first, second = a.split("_"), b.split("_")
    if len(first) != 2 or len(second) != 2 or first[0] != "A" or second[0] != "A":
        return False
    frames = re.findall(r"[A-Z][a-z0-9]*", first[1])
    return len(frames) == 2 and "".join(frames) == first[1] and "".join(reversed(frames)) == second[1] \
        and frames[0] != frames[1]


def _siblings(a: str, b: str) -> bool:
    """Two matrices of a pair by the course's notation: one capital letter names the matrix and its last part, one
    capital letter, tells the two apart (``B_J_S`` and ``B_J_R``, ``S_J_S`` and ``S_J_R``)."""
    first, second = a.split("_"), b.split("_")
    return len(first) == len(second) >= 3 and first[:-1] == second[:-1] and first[-1] != second[-1] \
        and len(first[-2]) == 1 and first[-2].isupper() \
        and all(len(p) == 1 and p.isupper() for p in (first[-1], second[-1]))


def _trig_siblings(a: str, b: str) -> bool:
    """Two names of a sine's and a cosine's like values: one part (between underscores) ``sin`` in one where the
    other has ``cos`` (``sin_coeffs`` and ``cos_coeffs``)."""
    first, second = a.split("_"), b.split("_")
    differ = [(x, y) for x, y in zip(first, second) if x != y]
    return len(first) == len(second) >= 2 and len(differ) == 1 and set(differ[0]) == {"sin", "cos"}


def _related(a: str, b: str) -> str | None:
    """The slip of reading ``b`` where ``a`` belongs: "rates", "frames_turned" (a rotation the other way round),
    "frames", "siblings", "trig_names" or None."""
    if a == b:
        return None
    if _FRAME_OBJECT.match(a) and _FRAME_OBJECT.match(b):  # ``C1.get_transform()`` for ``C3.get_transform()``
        return "frame_objects"
    return "rates" if _rates(a, b) else "frames_turned" if _turned_round(a, b) else "frames" if _frames(a, b) \
        else "siblings" if _siblings(a, b) \
        else "trig_names" if _trig_siblings(a, b) else None


#: a coordinate system by the course's notation (``C1``, ``C2``, ``C3``: the frames of problems 6 and 9)
_FRAME_OBJECT = re.compile(r"^C\d$")
#: an inertia by the course's notation (``I``, ``B_I_B``, ``theta``), whose product with a vector the principal
#: moments alone do not give where axes are not principal
_INERTIA = re.compile(r"^(I|Theta|theta|inertia\w*|[A-Z][A-Za-z0-9]*_I_[A-Z][A-Za-z0-9]*)$")


def _text_key(index) -> bool:
    return isinstance(index, ast.Constant) and isinstance(index.value, str)


def _read_slips(node, names: frozenset, attributes: frozenset, keys: frozenset = frozenset()):
    """A read of a name (or of an object's attribute, or of an entry under a text key) replaced by a name of the
    function (an attribute of the module, a text key of the function's, ``_text_keys``) that is its rate or what it is
    the rate of, or the same quantity in another frame's coordinates (``_related``); a coordinate system read for
    another (``C1`` for ``C3``), left out of a call that takes it alone
    (``C3.get_transform()`` for ``C3.get_transform(C3)``: the default frame), or given to a call of one that takes
    none (``C3.get_transform(C1)`` for ``C3.get_transform()``)."""
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
        for other in sorted(names):
            slip = _related(node.id, other)
            if slip is not None:
                yield slip, lambda n, other=other: ast.Name(other, ast.Load())
    elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load) and node.attr != "T":
        for other in sorted(attributes):
            slip = _related(node.attr, other)
            if slip is not None:
                yield slip, lambda n, other=other: _with(n, attr=other)
    elif isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Load) and _text_key(node.slice):
        for other in sorted(keys):  # ``A["A_IC3"]`` for ``A["A_IC2"]``
            slip = _related(node.slice.value, other)
            if slip is not None:
                yield slip, lambda n, other=other: _with(n, slice=ast.Constant(other))
    elif isinstance(node, (ast.List, ast.Tuple)) and isinstance(node.ctx, ast.Load) and len(node.elts) >= 2 \
            and all(isinstance(e, ast.Name) for e in node.elts):
        # ``[q1, q2]`` for ``[dq1, dq2]``: every entry read as what its rate belongs to, or the reverse
        partners = [[other for other in sorted(names) if _related(e.id, other) == "rates"] for e in node.elts]
        if all(len(p) == 1 for p in partners) and len({p[0] for p in partners}) == len(partners):
            yield "rates", lambda n, partners=partners: _with(n, elts=[ast.Name(p[0], ast.Load()) for p in partners])
    elif isinstance(node, ast.Call) and len(node.args) == 1 and not node.keywords \
            and isinstance(node.args[0], ast.Name) and _FRAME_OBJECT.match(node.args[0].id):
        yield "frame_objects", lambda n: _with(n, args=[])  # ``C3.get_transform()`` for ``C3.get_transform(C3)``
    elif isinstance(node, ast.Call) and not node.args and not node.keywords and isinstance(node.func, ast.Attribute) \
            and isinstance(node.func.value, ast.Name) and _FRAME_OBJECT.match(node.func.value.id):
        for other in sorted(n for n in names if _FRAME_OBJECT.match(n)):  # ``C3.get_transform(C1)`` for ``...()``
            yield "frame_objects", lambda n, other=other: _with(n, args=[ast.Name(other, ast.Load())])


def _distributed_slips(node: ast.BinOp):
    """A factor that multiplies a sum applied to one term of it only (``A @ (x + y)`` as ``A @ x + y``,
    ``(x + y) / c`` as ``x + y / c``): a rotation so applied leaves the other term in another frame's
    coordinates."""
    if isinstance(node.op, (ast.Mult, ast.MatMult)) and _summed_operand(node.right):
        slip = "rotated" if _ROTATION.match(_label(node.left) or "-") else "distributed"
        yield slip, lambda n: _with(n.right, left=_with(n, right=n.right.left))
        yield slip, lambda n: _with(n.right, right=_with(n, right=n.right.right))
    if isinstance(node.op, (ast.Mult, ast.Div)) and _summed_operand(node.left):
        yield "distributed", lambda n: _with(n.left, right=_with(n, left=n.left.right))


def _summed_operand(node) -> bool:
    return isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub))


def _entry_slips(node, parent):
    """An entry of a list or tuple (a name, an attribute, an entry, a call's value) with the wrong sign; an entry of
    a list (a matrix's or a vector's, not a row of it) that is not zero written 0."""
    if isinstance(parent, (ast.Tuple, ast.List)) and isinstance(parent.ctx, ast.Load) \
            and isinstance(node, (ast.Name, ast.Attribute, ast.Subscript, ast.Call)):
        yield "entry_sign", _negated
    if isinstance(parent, ast.List) and isinstance(parent.ctx, ast.Load) \
            and not isinstance(node, (ast.List, ast.Tuple, ast.Starred)) and not _zero(node):
        yield "zeroed", lambda n: ast.Constant(0.0)
    if _written_vector(node):  # ``(DX, -DY, 0.0)`` for ``(-DX, DY, 0.0)``: every entry's sign turned
        yield "vector_sign", lambda n: _with(n, elts=[e if _zero(e) else _sign_turned(e) for e in n.elts])


def _written_vector(node) -> bool:
    """A vector written out of numbers and constants (``(-DX, DY, 0.0)``), two entries at least not zero."""
    def entry(e):
        e = e.operand if isinstance(e, ast.UnaryOp) and isinstance(e.op, ast.USub) else e
        return _number(e) or (isinstance(e, ast.Name) and e.id.isupper()) \
            or (isinstance(e, ast.Attribute) and e.attr.isupper())

    return isinstance(node, (ast.Tuple, ast.List)) and isinstance(node.ctx, ast.Load) and len(node.elts) >= 2 \
        and all(entry(e) for e in node.elts) and sum(not _zero(e) for e in node.elts) >= 2


def _sign_turned(node):
    """``node`` with its sign turned: a negation taken off, else one put on."""
    return node.operand if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) else _negated(node)


def _zero(node) -> bool:
    """A number that is zero (``0``, ``0.0``, ``-0.0``)."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        node = node.operand
    return _number(node) and node.value == 0


def _np(name: str):
    return ast.Attribute(ast.Name("np", ast.Load()), name, ast.Load())


def _diagonal_inverse(matrix):
    """``np.diag(1.0 / np.diag(matrix))``: the inverse of a matrix's diagonal alone (``b / np.diag(M)`` of a vector
    ``b`` is its product with ``b``)."""
    diagonal = ast.Call(_np("diag"), [matrix], [])
    return ast.Call(_np("diag"), [ast.BinOp(ast.Constant(1.0), ast.Div(), diagonal)], [])


def _trig_bound(function: ast.FunctionDef) -> dict:
    """``{name: the call}`` of the names the function binds once to a sine or a cosine of one argument (``s2 =
    np.sin(q2)``, ``c2, s2 = np.cos(q2), np.sin(q2)``)."""
    bound: dict = {}
    for node in ast.walk(function):
        for target in node.targets if isinstance(node, ast.Assign) else ():
            if isinstance(target, ast.Name):
                bound.setdefault(target.id, []).append(node.value)
            elif isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple) \
                    and len(target.elts) == len(node.value.elts):  # ``c2, s2 = np.cos(q2), np.sin(q2)``
                for name, value in zip(target.elts, node.value.elts):
                    bound.setdefault(name.id if isinstance(name, ast.Name) else "", []).append(value)
            elif isinstance(target, ast.Tuple):
                for name in target.elts:
                    bound.setdefault(name.id if isinstance(name, ast.Name) else "", []).append(None)
    return {name: values[0] for name, values in bound.items() if len(values) == 1
            and isinstance(values[0], ast.Call) and _callee(values[0]) in _TRIG and len(values[0].args) == 1
            and not values[0].keywords}


def _trig_names(function: ast.FunctionDef) -> dict:
    """The names the function binds once to a sine or a cosine of one argument (``s2 = np.sin(q2)``), each with
    the call of the other (``np.cos(q2)``), or the name bound to it where the function has one (``c2``)."""
    calls = _trig_bound(function)
    by_call = {(_callee(call), ast.dump(call.args[0])): name for name, call in calls.items()}
    others = {}
    for name, call in calls.items():
        sibling = by_call.get((_TRIG[_callee(call)], ast.dump(call.args[0])))
        others[name] = ast.Name(sibling, ast.Load()) if sibling is not None else _with(call, func=_renamed(call.func))
    return others


def _sum_terms(node) -> list:
    """The terms of a sum or a difference, first to last (``l2 + l3 * np.sin(phi)``: ``l2``, ``l3 * np.sin(phi)``; a
    term subtracted, under its minus); a node that is no sum is its one term."""
    terms = []
    while isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
        terms.insert(0, node.right if isinstance(node.op, ast.Add) else ast.UnaryOp(ast.USub(), node.right))
        node = node.left
    return [node, *terms]


def _trig_angles(function: ast.FunctionDef) -> dict:
    """``{name: ((other, slip), ...)}`` of the names the function binds once to a sine (a cosine) of one argument,
    each with the others bound to the same function of another argument (``s2 = np.sin(q2)`` and ``s24 =
    np.sin(q2 + q4)``): a read of the wrong one is one angle read for another (``s2`` for ``s24``, in a Jacobian's
    entry written out), ``angle_part`` where the other's argument is one of its terms (a term left out of the
    sum), ``angle_sum`` where its own argument is one of the other's (a term added), else ``angle``.  Where a
    function binds more than six names to one of the two, none of them is read for another (a table of sines, not the
    short names of a chain)."""
    calls = _trig_bound(function)
    found = {}
    for callee in _TRIG:
        named = {name: frozenset(ast.dump(term) for term in _sum_terms(call.args[0])) for name, call in calls.items()
                 if _callee(call) == callee}
        if not 2 <= len(named) <= 6:
            continue
        for name, terms in named.items():
            found[name] = tuple((other, "angle_part" if others < terms else "angle_sum" if terms < others else "angle")
                                for other, others in sorted(named.items()) if other != name and others != terms)
    return found


def _trig_angle_slips(node, angled: dict):
    """A read of a name bound to a sine (a cosine) read as another bound to the sine (the cosine) of another
    argument, one read at a time (``_trig_angles``)."""
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
        for other, slip in angled.get(node.id, ()):
            yield slip, lambda n, other=other: ast.Name(other, ast.Load())


def _trig_read_slips(node, parent, others: dict):
    """A read of a name bound to a sine (a cosine) read as the cosine (the sine) of the same argument, one read at
    a time (``-q3 * c2`` for ``-q3 * s2``), or the two names exchanged throughout one statement (``a @ s + b @ c``
    for ``a @ c + b @ s``)."""
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in others:
        yield "trig", lambda n, other=others[node.id]: copy.deepcopy(other)
    if isinstance(node, (ast.Assign, ast.Return, ast.AugAssign)):  # ``a @ s + b @ c`` for ``a @ c + b @ s``
        read = {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
        pairs = {tuple(sorted((name, others[name].id))) for name in read & set(others)
                 if isinstance(others[name], ast.Name) and others[name].id in read}
        for a, b in sorted(pairs):
            yield "trigs", lambda n, a=a, b=b: _renamed_in(n, a, b)


def _written_out(node) -> bool:
    """A matrix written out row by row: a list or tuple of two to four lists or tuples of as many entries."""
    return isinstance(node, (ast.List, ast.Tuple)) and 2 <= len(node.elts) <= 4 and all(
        isinstance(row, (ast.List, ast.Tuple)) and len(row.elts) == len(node.elts)
        and not any(isinstance(e, ast.Starred) for e in row.elts) for row in node.elts)


def _turning(node) -> bool:
    """A matrix written out (``_written_out``) with no zero on its diagonal, whose entries off it are zeros or come
    in pairs of opposite signs (``-s`` at one place, ``s`` at its mirror), one pair at least: the form of a rotation
    written out, whose transpose is the same matrix with those signs exchanged, the rotation by the negated angle."""
    rows = [row.elts for row in node.elts]
    if any(isinstance(row[i], ast.Constant) and row[i].value == 0 for i, row in enumerate(rows)):
        return False  # a zero on the diagonal: a skew matrix written out is no rotation
    paired = False
    for i in range(len(rows)):
        for j in range(i + 1, len(rows)):
            a, b = rows[i][j], rows[j][i]
            if all(isinstance(e, ast.Constant) and e.value == 0 for e in (a, b)):
                continue
            if isinstance(a, ast.UnaryOp) and isinstance(a.op, ast.USub) and ast.dump(a.operand) == ast.dump(b) \
                    or isinstance(b, ast.UnaryOp) and isinstance(b.op, ast.USub) and ast.dump(b.operand) == ast.dump(a):
                paired = True
                continue
            return False
    return paired


def _literal_transposed(node):
    """The matrix written out (``_written_out``) with its rows as columns."""
    rows = [row.elts for row in node.elts]
    return _with(node, elts=[_with(node.elts[j], elts=[rows[i][j] for i in range(len(rows))])
                             for j in range(len(rows))])


def _product(node) -> bool:
    """A product of two matrices (``A @ B``)."""
    return isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult)


def _stored(node: ast.Assign) -> bool:
    """An attribute of the object a method is called on set (``self.r = ...``), outside its constructor: a value
    the object keeps from call to call, replaced."""
    target = node.targets[0]
    return len(node.targets) == 1 and isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name) \
        and target.value.id == "self"


def _loaded(target: ast.Attribute):
    return ast.Attribute(ast.Name(target.value.id, ast.Load()), target.attr, ast.Load())


def _assigned(node: ast.AugAssign):
    """``s += x`` as ``s = x`` (``s -= x`` as ``s = -x``): a sum that keeps only its last term."""
    value = node.value if isinstance(node.op, ast.Add) else _negated(node.value)
    return ast.copy_location(ast.Assign([ast.Name(node.target.id, ast.Store())], value), node)


def _state_read(node) -> bool:
    """A read of a part of a run's state (``y[:3]``, ``result.y[3:].T``, ``y_event[0]``)."""
    while isinstance(node, ast.Attribute) and node.attr == "T":
        node = node.value
    return isinstance(node, ast.Subscript) and bool(_STATE.match(_label(node.value) or "-"))


def _reads(node, parent) -> list:
    """What each entry of a tuple or list reads: its own value, or for the names a tuple assigns
    (``q, qd = y[:3], y[3:]``) the values assigned to them; the names a part of a run's state is unpacked into
    (``x, h, phi = y[:3]``) each read an entry of the state."""
    if isinstance(node.ctx, ast.Store) and isinstance(parent, ast.Assign) and isinstance(parent.value, ast.Tuple) \
            and len(parent.value.elts) == len(node.elts):
        return list(parent.value.elts)
    if isinstance(node.ctx, ast.Store) and isinstance(parent, ast.Assign) and _state_read(parent.value):
        return [parent.value] * len(node.elts)
    return list(node.elts)


#: the part of a name that tells one of a kind from another, at most this long (``x`` of ``r_x``, ``P`` of
#: ``P_GAIN``, ``2`` of ``m2``)
_KIND = 2


def _of_a_kind(a: str, b: str) -> bool:
    """Two names of one kind: they differ in one short part between underscores (``r_x``, ``r_y``; ``P_GAIN``,
    ``D_GAIN``) or in a last digit or axis (``m1``, ``m2``)."""
    first, second = a.split("_"), b.split("_")
    if len(first) == len(second) > 1:
        differ = [(x, y) for x, y in zip(first, second) if x != y]
        return len(differ) == 1 and all(0 < len(part) <= _KIND for part in differ[0])
    return len(a) > 1 and a[:-1] == b[:-1] and all(c in "xyz123456" for c in (a[-1], b[-1]))


def _components(statement) -> list:
    """Pairs of names of one statement that are two of a kind (two components of one vector, two gains)."""
    names = sorted({n.id for n in ast.walk(statement) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)})
    return [(names[i], names[j]) for i, j in _pairs(len(names)) if _of_a_kind(names[i], names[j])]


def _renamed_in(statement, a: str, b: str):
    """``a`` for ``b`` and ``b`` for ``a`` in one statement's reads (the copy is changed in place)."""
    for node in ast.walk(statement):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
            node.id = b if node.id == a else a if node.id == b else node.id
    return statement


def _returned_list(statement: ast.Return):
    """The list or tuple a return statement builds (itself, or the first argument of ``np.array(...)``)."""
    value = statement.value
    if isinstance(value, ast.Call) and _callee(value) == "array" and value.args:
        value = value.args[0]
    return value if isinstance(value, (ast.List, ast.Tuple)) and len(value.elts) <= 6 else None


def _returned_names(statement: ast.Return) -> list:
    """The entries of a returned list that are names (an angle among them may be returned in degrees)."""
    built = _returned_list(statement)
    return [] if built is None else [k for k, e in enumerate(built.elts) if isinstance(e, ast.Name)]


def _in_degrees(statement: ast.Return, k: int):
    built = _returned_list(statement)
    built.elts[k] = ast.Call(ast.Attribute(ast.Name("np", ast.Load()), "rad2deg", ast.Load()), [built.elts[k]], [])
    return statement


def _square(node) -> bool:
    return isinstance(node, ast.BinOp) and isinstance(node.op, ast.Pow) and _number(node.right) \
        and node.right.value == 2


def _summed(call: ast.Call):
    """What ``x.sum()`` or ``np.sum(x)`` sums (a plain sum, no axis), or None."""
    if call.keywords:
        return None
    if _callee(call) == "sum" and isinstance(call.func, ast.Attribute) and not call.args \
            and isinstance(call.func.value, (ast.Name, ast.Attribute)):
        return call.func.value
    if _callee(call) == "sum" and isinstance(call.func, ast.Attribute) and len(call.args) == 1 \
            and _label(call.func.value) == "np" and isinstance(call.args[0], (ast.Name, ast.Attribute)):
        return call.args[0]
    return None


def _half(index) -> bool:
    """``[:k]`` or ``[k:]``: one half of a vector, whose other half is ``[k:]`` or ``[:k]``."""
    return isinstance(index, ast.Slice) and index.step is None and (index.lower is None) != (index.upper is None)


def _halves(entries: list) -> bool:
    """Two reads of a run's state, its first half and its second (``y[:k], y[k:]``)."""
    if len(entries) != 2 or not all(_state_read(e) and isinstance(e, ast.Subscript) for e in entries):
        return False
    first, second = (e.slice for e in entries)
    return _half(first) and _half(second) and first.lower is None and second.upper is None \
        and ast.dump(first.upper) == ast.dump(second.lower) and ast.dump(entries[0].value) == ast.dump(entries[1].value)


def _interleaved(node):
    """``y[:k], y[k:]`` as ``y[::2], y[1::2]``."""
    first, second = node.elts
    return _with(node, elts=[_with(first, slice=ast.Slice(None, None, ast.Constant(2))),
                             _with(second, slice=ast.Slice(ast.Constant(1), None, ast.Constant(2)))])


def _event_function(node) -> bool:
    """A function of ``(t, y, ...)``: what solve_ivp calls, an event among them (``_STATE``: ``y`` or ``state``)."""
    if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return False
    names = [a.arg for a in node.args.posonlyargs + node.args.args]
    return len(names) >= 2 and names[0] == "t" and bool(_STATE.match(names[1]))


#: a name of a vector of generalized coordinates or of a run's state (``q``, ``qd``, ``q_des``, ``y``, ``state``)
_COORDINATES = re.compile(r"^(q|qd|qdd|q_\w+|qd_\w+|y|y_\w+|state)$")


def _unpacked_coordinates(node, parent) -> bool:
    """The name and the slot left unread (``_``) that a vector of two coordinates or a state is unpacked into (``_,
    q2 = np.asarray(q, dtype=float)``): the two exchanged read the coordinate from the other's row.  Two names
    exchanged (``y, x = q``) are two quantities exchanged, as any two entries."""
    return _unpacked_state(node, parent) and len(node.elts) == 2 and sum(e.id == "_" for e in node.elts) == 1


def _unpacked_state(node, parent) -> bool:
    """The names that a vector of coordinates or a state is unpacked into (``x, y, phi = q``): bound in another
    order, each takes the value of another's row, which is as truly quantities in another order as a state read
    from the wrong rows.  (The names of a slice of a run's state, ``x, h, phi = y[:3]``, are its reads: exchanged,
    they are the state read from the wrong rows.)"""
    if not (isinstance(node, ast.Tuple) and isinstance(node.ctx, ast.Store) and isinstance(parent, ast.Assign)
            and all(isinstance(e, ast.Name) for e in node.elts)):
        return False
    value = parent.value
    if isinstance(value, ast.Call) and _callee(value) in ("asarray", "array", "ravel", "atleast_1d") and value.args:
        value = value.args[0]
    return isinstance(value, ast.Name) and bool(_COORDINATES.match(value.id))


def _state_parts(function: ast.FunctionDef) -> set:
    """The names the function binds to parts of a run's state (``q, qd = y[:3], y[3:]``, ``x, h = y[:2]``)."""
    found = set()
    for node in ast.walk(function):
        if not isinstance(node, ast.Assign) or len(node.targets) != 1:
            continue
        target, value = node.targets[0], node.value
        pairs = zip(target.elts, value.elts) if isinstance(target, ast.Tuple) and isinstance(value, ast.Tuple) \
            and len(target.elts) == len(value.elts) else \
            [(t, value) for t in target.elts] if isinstance(target, ast.Tuple) else [(target, value)]
        found |= {t.id for t, v in pairs if isinstance(t, ast.Name) and _state_read(v)}
    return found


def _skews(function: ast.FunctionDef) -> set:
    """The names the function binds to a skew matrix (``lever = skew(r)``, or one of several bound at once:
    ``P_Om, P_dOm = skew(w), skew(dw)``)."""
    found = set()
    for node in ast.walk(function):
        if not isinstance(node, ast.Assign):
            continue
        for target in node.targets:
            pairs = zip(target.elts, node.value.elts) \
                if isinstance(target, ast.Tuple) and isinstance(node.value, ast.Tuple) \
                and len(target.elts) == len(node.value.elts) else [(target, node.value)]
            found |= {t.id for t, value in pairs
                      if isinstance(t, ast.Name) and isinstance(value, ast.Call) and _callee(value) == "skew"}
    return found


def _skew(node, skews: set, slip: str = "transpose") -> bool:
    """A skew matrix, or its transpose (``skew(r)``, ``lever.T`` where ``lever = skew(r)``); for the slips of a
    product, a factor of it."""
    if slip != "transpose" and isinstance(node, ast.BinOp):
        return _skew(node.left, skews) or _skew(node.right, skews)
    if isinstance(node, ast.Attribute) and node.attr == "T":
        node = node.value
    return (isinstance(node, ast.Call) and _callee(node) == "skew") or (isinstance(node, ast.Name)
                                                                        and node.id in skews)


def _reciprocal(node) -> bool:
    return isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div) and _number(node.left) \
        and node.left.value == 1


def _trigs(node) -> set:
    return {_callee(n) for n in ast.walk(node) if isinstance(n, ast.Call) and _callee(n) in _TRIG
            and len(n.args) == 1}


def _all_trigs_exchanged(node):
    """sin for cos and cos for sin throughout one statement (the copy is changed in place)."""
    for call in ast.walk(node):
        if isinstance(call, ast.Call) and _callee(call) in _TRIG and len(call.args) == 1:
            call.func = _renamed(call.func)
    return node


def _edge(node, side: str):
    """``(holder, field)`` of the factor of a product at its ``side`` ("left" or "right") end."""
    holder, field = None, None
    while isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Mult, ast.MatMult)):
        holder, field, node = node, side, getattr(node, side)
    return holder, field


def _transposed_leaf(node) -> bool:
    return isinstance(node, ast.Attribute) and node.attr == "T"


def _meeting(node: ast.BinOp):
    """The two factors that meet at a product (``J.T`` and ``J`` of ``m * J.T @ J``), with their holders."""
    (left, lfield), (right, rfield) = _edge(node.left, "right"), _edge(node.right, "left")
    left, lfield = (node, "left") if left is None else (left, lfield)
    right, rfield = (node, "right") if right is None else (right, rfield)
    return (left, lfield), (right, rfield)


def _movable(node: ast.BinOp) -> bool:
    (left, lfield), (right, rfield) = _meeting(node)
    return _transposed_leaf(getattr(left, lfield)) != _transposed_leaf(getattr(right, rfield))


def _moved(node: ast.BinOp):
    """``A.T @ B`` as ``A @ B.T`` (``m * J.T @ J`` as ``m * J @ J.T``): the transpose of the factor on one side
    of the product moved to the factor on the other (the copy is changed in place)."""
    (left, lfield), (right, rfield) = _meeting(node)
    a, b = getattr(left, lfield), getattr(right, rfield)
    if _transposed_leaf(a):
        setattr(left, lfield, a.value)
        setattr(right, rfield, _transposed(b))
    else:
        setattr(left, lfield, _transposed(a))
        setattr(right, rfield, b.value)
    return node


def _chained(node) -> bool:
    """A product of matrices (``A @ B``), the left operand of a longer one."""
    return isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult)


def _neighbours_exchanged(node: ast.BinOp):
    """``A @ B @ C`` as ``A @ C @ B``: the two factors that meet at the product exchanged (the copy is changed in
    place)."""
    (left, lfield), (right, rfield) = _meeting(node)
    a, b = getattr(left, lfield), getattr(right, rfield)
    setattr(left, lfield, b)
    setattr(right, rfield, a)
    return node


def _conversion(node) -> bool:
    """A conversion of an angle by numpy's name for it (``np.deg2rad(x)``, ``np.degrees(x)``: ``_BACK``)."""
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in _BACK


def _converted_back(node: ast.Call):
    """The conversion the other way: ``np.rad2deg(x)`` for ``np.deg2rad(x)``."""
    return _with(node, func=_with(node.func, attr=_BACK[node.func.attr]))


#: a name of a list of angles (``angles``, ``ANGLES0``, ``start_angles``)
_ANGLES = re.compile(r"angles", re.IGNORECASE)


def _unpacked_reversed(node: ast.Call):
    """``f(*x)`` as ``f(*x[::-1])``: every argument unpacked into the call in reverse order."""
    reverse = ast.Slice(None, None, ast.Constant(-1))
    return _with(node, args=[ast.Starred(ast.Subscript(a.value, reverse, ast.Load()), ast.Load())
                             if isinstance(a, ast.Starred) else a for a in node.args])


def _nested_exchanged(node: ast.BinOp):
    """``A @ (B @ v)`` as ``B @ (A @ v)``: the factor outside the parentheses exchanged with the first inside."""
    return _with(node, left=node.right.left, right=_with(node.right, left=node.left))


def _ends(node: ast.BinOp):
    """The first and the last factor of a product (``J.T`` and ``J`` of ``J.T @ I @ J``), with their holders."""
    return _edge(node, "left"), _edge(node, "right")


def _flipped(node, ends):
    """``node`` with the transpose moved from one end of its product to the other (changed in place)."""
    (left, lfield), (right, rfield) = ends
    a, b = getattr(left, lfield), getattr(right, rfield)
    setattr(left, lfield, a.value if _transposed_leaf(a) else _transposed(a))
    setattr(right, rfield, b.value if _transposed_leaf(b) else _transposed(b))
    return node


def _own_transpose(node: ast.BinOp, factors=None) -> bool:
    """A product of a matrix with its own transpose at the two factors that meet (``J.T @ J``), or at
    ``factors``."""
    (left, lfield), (right, rfield) = factors or _meeting(node)
    a, b = getattr(left, lfield), getattr(right, rfield)
    if _transposed_leaf(a) == _transposed_leaf(b):
        return False
    a, b = (a.value, b) if _transposed_leaf(a) else (a, b.value)
    return ast.dump(a) == ast.dump(b)


def _blocks(args: list, first: int, size: int) -> list:
    args = list(args)
    args[first:first + 2 * size] = args[first + size:first + 2 * size] + args[first:first + size]
    return args


def _keywords(node: ast.Call, a: str, b: str) -> list:
    values = {k.arg: k.value for k in node.keywords}
    return [ast.keyword(k.arg, values[b] if k.arg == a else values[a] if k.arg == b else k.value)
            for k in node.keywords]


def _pairs(count: int):
    return [(i, j) for i in range(count) for j in range(i + 1, count)]


def _binop_slips(node: ast.BinOp):
    yield from _distributed_slips(node)
    op = node.op
    if isinstance(op, ast.MatMult) and _INERTIA.match(_label(node.left) or "-"):  # ``np.diag(I) * w`` for ``I @ w``
        yield "principal", lambda n: ast.BinOp(ast.Call(_np("diag"), [n.left], []), ast.Mult(), n.right)
    if isinstance(op, ast.Sub) and isinstance(node.left, ast.BinOp) and isinstance(node.left.op, ast.Sub):
        yield "sign", _all_added  # ``a + f + g`` for ``a - f - g``: every term subtracted added instead
    if isinstance(op, ast.Add) and all(isinstance(side, ast.BinOp) and isinstance(side.op, ast.Mult)
                                       for side in (node.left, node.right)) \
            and not (_number(node.left.left) and _number(node.right.left)):
        # ``w * a + (1 - w) * b`` for ``(1 - w) * a + w * b``: the weights of two terms exchanged (not two numbers)
        yield "weights", lambda n: _with(n, left=_with(n.left, left=n.right.left),
                                         right=_with(n.right, left=n.left.left))
    if isinstance(op, (ast.Add, ast.Sub)) and _leading_factor(node.left) is not None:
        # ``m * (a + b)`` for ``m * a + b`` (``m * (J.T @ J + R)`` for ``m * J.T @ J + R``): the first term's factor
        # on both
        yield "spread", _spread
    if isinstance(op, (ast.Add, ast.Sub)):
        other = ast.Sub() if isinstance(op, ast.Add) else ast.Add()
        yield "sign", lambda n: _with(n, op=other)
        if isinstance(op, ast.Add) and _square(node.left) and _square(node.right):
            yield "norm", _root_of  # |r| for |r|^2
            # ``(a + b)**2`` for ``a**2 + b**2``: the square of the sum, a cross term 2 a b added
            yield "square_of_sum", lambda n: ast.BinOp(ast.BinOp(n.left.left, ast.Add(), n.right.left), ast.Pow(),
                                                       ast.Constant(2))
        # ``I_r_E - anchor`` as ``I_r_E``: a position taken from the origin, not from the point subtracted
        yield "origin" if isinstance(op, ast.Sub) and _POSITION.match(_label(node.left) or "-") else "term", \
            lambda n: n.left
        # ``a - b`` as ``b``: the first term left out, the second kept as it reads (``r r^T`` for ``r.r E - r r^T``);
        # ``anchor - I_r_E`` as ``I_r_E`` or ``-I_r_E``: the point taken at the origin, as for ``I_r_E - anchor``
        if isinstance(op, ast.Sub) and _from_point(node):
            yield "origin", lambda n: n.right
            yield "origin", lambda n: _negated(n.right)
        else:
            yield "term" if isinstance(op, ast.Add) else "minuend", lambda n: n.right
            if isinstance(op, ast.Sub):  # ``-qd`` for ``qd_des - qd``: the first term left out, the second's minus kept
                yield "minuend", lambda n: _negated(n.right)
    elif isinstance(op, ast.Mult):
        for side, other in (("left", "right"), ("right", "left")):
            yield _dropped(getattr(node, side)), lambda n, other=other: getattr(n, other)
            operand = getattr(node, side)
            if isinstance(operand, ast.UnaryOp) and isinstance(operand.op, ast.USub) and not _number(operand.operand):
                # ``-m * theta``: the factor m left out keeps the minus
                yield _dropped(operand.operand), lambda n, other=other: _negated(getattr(n, other))
        yield "multiplies" if _number(node.right) else "multiplies_by", lambda n: _with(n, op=ast.Div())
        for side, other in (("left", "right"), ("right", "left")):  # ``L // 2`` for ``0.5 * L``: integer division
            if _number(getattr(node, side)) and getattr(node, side).value == 0.5:
                yield "floor", lambda n, other=other: ast.BinOp(getattr(n, other), ast.FloorDiv(), ast.Constant(2))
    elif isinstance(op, ast.Div):
        yield "divides" if _number(node.right) else "divides_by", lambda n: _with(n, op=ast.Mult())
        if _number(node.right) and isinstance(node.right.value, int):  # ``m // 12``: a habit of integer division
            yield "floor", lambda n: _with(n, op=ast.FloorDiv())
        yield _dropped(node.right), lambda n: n.left
        if _constant_expression(node.left):  # ``2 pi / T`` as ``1 / T``: a numerator of constants left out
            yield "factor", lambda n: _with(n, left=ast.Constant(1.0))
        elif isinstance(node.left, (ast.Name, ast.Attribute)) and _number(node.right):
            yield "factor", lambda n: _with(n, left=ast.Constant(1.0))  # ``m / 12`` as ``1 / 12``: the mass left out
        if not _reciprocal(node):  # ``12 / m`` as ``m / 12`` (``1 / x`` as ``x``: a reciprocal, the inputs' slip)
            yield "ratio", lambda n: _with(n, left=n.right, right=n.left)
        if isinstance(node.left, ast.BinOp) and isinstance(node.left.op, ast.Mult):
            # ``-m J v / (m a**2 + J)`` as ``-(m a**2 + J) v / (m J)``: the ratio that scales a quantity upside
            # down, the quantity kept on top (the last factor of the numerator, or the first)
            yield "ratio", lambda n: ast.BinOp(ast.BinOp(n.right, ast.Mult(), n.left.right), ast.Div(), n.left.left)
            yield "ratio", lambda n: ast.BinOp(ast.BinOp(n.left.left, ast.Mult(), n.right), ast.Div(), n.left.right)
    elif isinstance(op, ast.MatMult):
        if ast.dump(node.left) == ast.dump(node.right) and not isinstance(node.left, (ast.Attribute, ast.Call)):
            yield "norm", _root_of  # ``np.sqrt(r @ r)`` for ``r @ r``: the length where its square belongs
        if _movable(node):
            yield "sides", _moved
        if _own_transpose(node, _ends(node)):  # ``J.T @ I @ J`` as ``J @ I @ J.T``
            yield "sides", lambda n: _flipped(n, _ends(n))
        # ``X.T @ X`` the other way round is ``X @ X.T``: the transpose on the wrong factor
        yield "sides" if _own_transpose(node) else "factors", lambda n: _with(n, left=n.right, right=n.left)
        if _chained(node.left) and not _own_transpose(node):  # ``A @ B @ C`` as ``A @ C @ B``
            (left, lfield), (right, rfield) = _meeting(node)
            both = _ROTATION.match(_label(getattr(left, lfield)) or "-") and \
                _ROTATION.match(_label(getattr(right, rfield)) or "-")
            yield "rotations" if both else "neighbours", _neighbours_exchanged
        if _chained(node.right) and not _chained(node.left):  # ``A @ (B @ v)`` as ``B @ (A @ v)``
            both = _ROTATION.match(_label(node.left) or "-") and _ROTATION.match(_label(node.right.left) or "-")
            yield "rotations" if both else "neighbours", _nested_exchanged
        for side, other in (("left", "right"), ("right", "left")):  # ``J`` for ``J @ qd``: a matrix factor
            dropped = _dropped(getattr(node, side))
            yield "matrix_factor" if dropped == "factor" else dropped, lambda n, other=other: getattr(n, other)
        if isinstance(node.left, ast.Name) and isinstance(node.right, ast.Name):
            # ``points.sum(axis=0)`` for ``masses @ points``: a weighted sum taken unweighted
            yield "unweighted", lambda n: ast.Call(ast.Attribute(n.right, "sum", ast.Load()), [],
                                                   [ast.keyword("axis", ast.Constant(0))])
    elif isinstance(op, ast.Pow) and _number(node.right) and node.right.value == 2:
        yield "square", lambda n: n.left
    if isinstance(op, (ast.Mult, ast.Div)) and isinstance(node.right, ast.BinOp) \
            and isinstance(node.right.op, ast.Pow) and _number(node.right.right):  # ``(m * arm)**2`` for ``m * arm**2``
        yield "power_scope", lambda n: ast.BinOp(_with(n, right=n.right.left), ast.Pow(), n.right.right)
    if not isinstance(op, ast.Pow):
        for side in ("left", "right"):
            if _number(getattr(node, side)) and getattr(node, side).value not in (0, 1):
                for slip, factor in (("doubled", 2.0), ("halved", 0.5)):
                    yield slip, lambda n, side=side, factor=factor: _with(
                        n, **{side: ast.Constant(getattr(n, side).value * factor)})


def _leading_factor(node):
    """``(factor, rest)`` of a product whose first factor is a name multiplied in (``m`` and ``J.T @ J`` of ``m *
    J.T @ J``), or None."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult) and isinstance(node.left, (ast.Name,
                                                                                                 ast.Attribute)):
        return node.left, node.right
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Mult, ast.MatMult)):
        inner = _leading_factor(node.left)
        if inner is not None:
            return inner[0], ast.BinOp(inner[1], node.op, node.right)
    return None


def _spread(node: ast.BinOp):
    factor, rest = _leading_factor(node.left)
    return ast.BinOp(factor, ast.Mult(), ast.BinOp(rest, node.op, node.right))


def _all_added(node: ast.BinOp):
    """``a - f - g`` as ``a + f + g``: every subtraction of the chain's left spine made an addition."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub):
        return ast.BinOp(_all_added(node.left), ast.Add(), node.right)
    return node


def _root_of(node):
    """``np.sqrt(node)``."""
    return ast.Call(_np("sqrt"), [node], [])


def _from_point(node: ast.BinOp) -> bool:
    """``p - X_r_Y``: a position subtracted from a point that is no position of the notation (an anchor, a centre):
    the vector from the position to the point, which is the position itself, negated, where the point is at the
    origin."""
    return bool(_POSITION.match(_label(node.right) or "-")) and not _POSITION.match(_label(node.left) or "-")


def _rate_exchange(a, b) -> bool:
    """Two expressions alike but for one name, which names the other's rate (``R @ qd`` and ``R @ qdd``)."""
    first = [n for n in ast.walk(a) if isinstance(n, ast.Name)]
    second = [n for n in ast.walk(b) if isinstance(n, ast.Name)]
    pairs = {(x.id, y.id) for x, y in zip(first, second) if x.id != y.id}
    if len(first) != len(second) or len(pairs) != 1:
        return False
    old, new = next(iter(pairs))
    if not _rates(old, new):
        return False
    renamed = copy.deepcopy(a)
    for n in ast.walk(renamed):
        if isinstance(n, ast.Name) and n.id == old:
            n.id = new
    return ast.dump(renamed) == ast.dump(b)


def _call_slips(node: ast.Call):
    callee = _callee(node)
    args = node.args
    if callee in _TRIG and len(args) == 1:
        yield "trig", lambda n: _with(n, func=_renamed(n.func))
        yield "degrees", lambda n: _with(n, args=[ast.Call(
            ast.Attribute(ast.Name("np", ast.Load()), "deg2rad", ast.Load()), [n.args[0]], [])])
    if callee in _DEGREES and len(args) == 1:
        yield "radians", lambda n: n.args[0]
    if callee == "sqrt" and len(args) == 1:
        yield "root", lambda n: n.args[0]
    if callee == "norm" and len(args) == 1 and not node.keywords:  # ``w @ w`` for ``np.linalg.norm(w)``
        yield "root", lambda n: ast.BinOp(n, ast.Pow(), ast.Constant(2))
    if callee == "zeros" and len(args) == 1 and isinstance(args[0], ast.Tuple) and len(args[0].elts) == 2 \
            and ast.dump(args[0].elts[0]) == ast.dump(args[0].elts[1]):  # ``np.eye(k)`` for ``np.zeros((k, k))``
        yield "identity_block", lambda n: ast.Call(_np("eye"), [n.args[0].elts[0]], [])
    if callee == "arange" and len(args) == 1 and not node.keywords:  # ``np.arange(1, n + 1)``: counted from one
        yield "one_based", lambda n: _with(n, args=[ast.Constant(1), ast.BinOp(n.args[0], ast.Add(), ast.Constant(1))])
    if callee == "cumsum" and len(args) == 1:  # ``steps`` for ``np.cumsum(steps, axis=0)``: each its own term alone
        yield "running_sum", lambda n: n.args[0]
    if callee == "dot" and len(args) == 2 and ast.dump(args[0]) == ast.dump(args[1]):
        yield "norm", _root_of  # ``np.sqrt(np.dot(r, r))`` for ``np.dot(r, r)``
    summed = _summed(node)
    if summed is not None:  # ``masses.sum()`` as ``len(masses)``
        yield "count", lambda n: ast.Call(ast.Name("len", ast.Load()), [_summed(n)], [])
    if callee == "solve" and len(args) == 2 and not node.keywords:
        yield "solved", lambda n: ast.BinOp(n.args[0], ast.MatMult(), n.args[1])
        yield "unsolved", lambda n: n.args[1]  # ``b`` for ``solve(A, b)``: the matrix's inverse left out
        if not (isinstance(args[0], ast.Attribute) and args[0].attr == "T"):  # ``solve(A.T, b)``: the system's
            # matrix transposed (its blocks ``-J.T`` and ``J`` exchanged), as a product's factor may be
            yield "transpose", lambda n: _with(n, args=[_transposed(n.args[0]), n.args[1]])
    if callee == "solve" and len(args) == 2 and not node.keywords and _product(args[0]):
        # ``inv(A) @ B @ b`` (or ``inv(B) @ A @ b``) for ``solve(A @ B, b)``: one factor of the product inverted
        yield "one_inverted", lambda n: _with(n, args=[n.args[0].left, ast.BinOp(n.args[0].right, ast.MatMult(),
                                                                                   n.args[1])])
        yield "one_inverted", lambda n: _with(n, args=[n.args[0].right, ast.BinOp(n.args[0].left, ast.MatMult(),
                                                                                    n.args[1])])
    if callee == "solve" and len(args) == 2 and not node.keywords and _summed_operand(args[1]):
        # ``solve(M, f + g) + tau`` for ``solve(M, f + g + tau)``: a term of the sum left outside the solve
        yield "solve_scope", lambda n: ast.BinOp(_with(n, args=[n.args[0], n.args[1].left]), n.args[1].op,
                                                 n.args[1].right)
        if _summed_operand(args[1].left):  # ``solve(M, f) + g + tau``: every term but the first outside
            yield "solve_scope", lambda n: _outside(n)
    if callee == "solve" and len(args) == 2 and not node.keywords:  # ``b / np.diag(M)``
        yield "diagonal", lambda n: ast.BinOp(_diagonal_inverse(n.args[0]), ast.MatMult(), n.args[1])
    if callee == "inv" and len(args) == 1:
        yield "inverse", lambda n: n.args[0]
        yield "diagonal", lambda n: _diagonal_inverse(n.args[0])
    if callee == "inv" and not args and isinstance(node.func, ast.Attribute):  # sympy's ``M.inv()``
        yield "inverse", lambda n: n.func.value
    if callee == "sqrt" and len(args) == 1 and isinstance(args[0], ast.BinOp) \
            and isinstance(args[0].op, (ast.Mult, ast.Div)):  # ``np.sqrt(3 * S) / m`` for ``np.sqrt(3 * S / m)``
        yield "root_scope", lambda n: ast.BinOp(_with(n, args=[n.args[0].left]), n.args[0].op, n.args[0].right)
        # ``12 / m * np.sqrt(S)`` for ``np.sqrt(12 / m * S)``: the root taken of the last factor only
        yield "root_scope", lambda n: ast.BinOp(n.args[0].left, n.args[0].op, _with(n, args=[n.args[0].right]))
    if callee in ("abs", "absolute", "fabs") and len(args) == 1 and not node.keywords:
        yield "magnitude", lambda n: n.args[0]
    if callee == "eye" and len(args) == 1 and not node.keywords:  # ``np.eye(3) + W`` as ``1.0 + W``
        yield "identity", lambda n: ast.Constant(1.0)
    if callee == "trace" and len(args) == 1 and not node.keywords:  # ``np.sum(S)`` for ``np.trace(S)``
        yield "whole_sum", lambda n: ast.Call(_np("sum"), [n.args[0]], [])
    elif callee == "trace" and not args and not node.keywords and isinstance(node.func, ast.Attribute):
        yield "whole_sum", lambda n: ast.Call(_np("sum"), [n.func.value], [])  # ``S.sum()`` for ``S.trace()``
    yield from _single_slips(node)
    if callee in ("inv", "solve") or any(isinstance(a, ast.Starred) for a in args):
        return
    positional = args[:4]
    for i, j in _pairs(len(args[:6])):
        exchange = "rows" if _state_read(args[i]) and _state_read(args[j]) else "cross" if callee == "cross" \
            else "arguments_rates" if _rate_exchange(args[i], args[j]) else "arguments"
        yield exchange, lambda n, i=i, j=j: _exchanged(n, "args", i, j)
    for size in range(2, len(args[:8]) // 2 + 1):  # ``f(q, qd, q_des, qd_des)`` as ``f(q_des, qd_des, q, qd)``
        for first in range(len(args[:8]) - 2 * size + 1):
            yield "blocks", lambda n, size=size, first=first: _with(n, args=_blocks(n.args, first, size))
    keywords = [k for k in node.keywords[:4] if k.arg is not None]
    for i, j in _pairs(len(keywords)):
        exchange = "rows" if _state_read(keywords[i].value) and _state_read(keywords[j].value) else "arguments"
        yield exchange, lambda n, a=keywords[i].arg, b=keywords[j].arg: _with(n, keywords=_keywords(n, a, b))
    names = [a.id for a in positional if isinstance(a, ast.Name)]
    for i, j in _pairs(len(names)):
        if names[i] != names[j]:
            yield "names", ("names", names[i], names[j])
    yield "sign", _negated


def _outside(call: ast.Call):
    """``solve(A, a + b + c)`` as ``solve(A, a) + b + c``: the first term of the sum alone solved for."""
    terms, ops, rest = [], [], call.args[1]
    while _summed_operand(rest):
        terms.insert(0, rest.right)
        ops.insert(0, rest.op)
        rest = rest.left
    result = _with(call, args=[call.args[0], rest])
    for op, term in zip(ops, terms):
        result = ast.BinOp(result, op, term)
    return result


def _index_slips(node: ast.Subscript):
    """A neighbouring index: a number one more or less (not below 0), or 0 for a number of 2 or more (the first
    entry where a later one belongs), an expression plus or minus one, a slice of whole numbers one row on or back
    (as many entries), a slice to the end one row early (as many entries: to the last but one)."""
    index = node.slice
    entries = index.elts if isinstance(index, ast.Tuple) else [index]
    for k, entry in enumerate(entries):
        if _number(entry) and isinstance(entry.value, int) and entry.value >= 0:
            for step in (-1, 1):
                if entry.value + step >= 0:
                    yield "index", lambda n, k=k, step=step: _reindexed(n, k, step)
            if entry.value >= 2:  # ``x[0]`` for ``x[3]``: the first entry where a later one belongs
                yield "index", lambda n, k=k, step=-entry.value: _reindexed(n, k, step)
        elif isinstance(entry, (ast.Name, ast.BinOp)):
            for step in (-1, 1):
                yield "index", lambda n, k=k, step=step: _reindexed(n, k, step)
        elif _shiftable(entry):  # ``y[1:4]`` for ``y[:3]``: a slice of as many entries one row off
            for step in (-1, 1):
                if _bound(entry.lower) + step >= 0:
                    yield "index", lambda n, k=k, step=step: _reindexed(n, k, step)
        elif _open_ended(entry):  # ``y[1:3]`` for ``y[2:]`` of four: as many entries, one row early
            yield "index", lambda n, k=k: _reindexed(n, k, -1)


def _bound(value) -> int:
    return 0 if value is None else value.value


def _shiftable(entry) -> bool:
    """A slice of whole numbers from a start (0 where none is written) to an end, without a step."""
    return isinstance(entry, ast.Slice) and entry.step is None and _number(entry.upper) \
        and isinstance(entry.upper.value, int) and (entry.lower is None or _number(entry.lower)
                                                    and isinstance(entry.lower.value, int) and entry.lower.value >= 0)


def _open_ended(entry) -> bool:
    """A slice from a whole number of 1 or more to the end, without a step (``y[2:]``)."""
    return isinstance(entry, ast.Slice) and entry.step is None and entry.upper is None and _number(entry.lower) \
        and isinstance(entry.lower.value, int) and entry.lower.value >= 1


def _reindexed(node: ast.Subscript, k: int, step: int):
    index = node.slice
    entries = list(index.elts) if isinstance(index, ast.Tuple) else [index]
    entry = entries[k]
    if _number(entry):
        entries[k] = ast.Constant(entry.value + step)
    elif isinstance(entry, ast.Slice) and entry.upper is None:  # open-ended, one row early: to the last but one
        entries[k] = ast.Slice(ast.Constant(entry.lower.value + step), ast.Constant(step), None)
    elif isinstance(entry, ast.Slice):
        entries[k] = ast.Slice(ast.Constant(_bound(entry.lower) + step), ast.Constant(entry.upper.value + step), None)
    else:
        entries[k] = ast.BinOp(entry, ast.Add() if step > 0 else ast.Sub(), ast.Constant(1))
    return _with(node, slice=ast.Tuple(entries, ast.Load()) if isinstance(index, ast.Tuple) else entries[0])


def _renamed(func):
    if isinstance(func, ast.Attribute):
        return ast.Attribute(func.value, _TRIG[func.attr], ast.Load())
    return ast.Name(_TRIG[func.id], ast.Load())


def _with(node, **changes):
    fresh = copy.copy(node)
    for key, value in changes.items():
        setattr(fresh, key, value)
    return fresh


def _exchanged(node, field: str, i: int, j: int):
    items = list(getattr(node, field))
    items[i], items[j] = items[j], items[i]
    return _with(node, **{field: items})


def _parameter_slips(function: ast.FunctionDef, lines: tuple):
    """Two of the function's own arguments exchanged wherever the region uses them; an argument that the region
    reads only as a factor of products left out of all of them (``-d * c2``, ``-d * s2`` as ``-c2``, ``-s2``)."""
    used = {node.id for node in ast.walk(function) if isinstance(node, ast.Name) and _in(node, lines)}
    names = [a.arg for a in function.args.args + function.args.kwonlyargs if a.arg in used and a.arg != "self"]
    for i, j in _pairs(len(names)):
        yield "parameters", ("names", names[i], names[j])
    for name in _factors_only(function, lines, names):
        yield "step_unit" if _STEP.match(name) else "unit", ("unit", name)
    for name in names:
        if _SINGLE.match(name):
            yield "single_argument", ("single", name)
    for attribute in _own_attributes(function, lines):  # ``self.B_omega_B.astype(np.float32)``: what a method reads
        yield "single_argument", ("single_attribute", attribute)


def _own_attributes(function: ast.FunctionDef, lines: tuple) -> list:
    """The attributes of its object (``self.x``) that a method's region reads, in the order first read."""
    found = []
    for node in ast.walk(function):
        if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load) and isinstance(node.value, ast.Name) \
                and node.value.id == "self" and _in(node, lines) and node.attr not in found:
            found.append(node.attr)
    return found if function.args.args and function.args.args[0].arg == "self" else []


def _factors_only(function: ast.FunctionDef, lines: tuple, names: list) -> list:
    """The arguments ``names`` that the region reads at least twice, each time as a factor of a product (itself,
    or under a minus)."""
    parents = {id(child): node for node in ast.walk(function) for child in ast.iter_child_nodes(node)}
    reads: dict = {}
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in names and _in(node, lines):
            parent = parents.get(id(node))
            if isinstance(parent, ast.UnaryOp) and isinstance(parent.op, ast.USub):
                parent = parents.get(id(parent))
            factor = isinstance(parent, ast.BinOp) and isinstance(parent.op, ast.Mult)
            reads.setdefault(node.id, []).append(factor)
    return [name for name in names if len(reads.get(name, ())) >= 2 and all(reads[name])]


def _unit(function: ast.FunctionDef, lines: tuple, name: str) -> None:
    """Every read of ``name`` in the region as 1 (the function changed in place)."""
    for node in ast.walk(function):
        for field, value in ast.iter_fields(node):
            for k, item in enumerate(value if isinstance(value, list) else [value]):
                if isinstance(item, ast.Name) and item.id == name and isinstance(item.ctx, ast.Load) \
                        and _in(item, lines):
                    one = ast.copy_location(ast.Constant(1.0), item)
                    if isinstance(value, list):
                        value[k] = one
                    else:
                        setattr(node, field, one)


def _read_as(function: ast.FunctionDef, lines: tuple, name: str, value) -> None:
    """Every read of ``name`` in the region as ``value`` (the function changed in place)."""
    for node in ast.walk(function):
        for field, held in ast.iter_fields(node):
            for k, item in enumerate(held if isinstance(held, list) else [held]):
                if isinstance(item, ast.Name) and item.id == name and isinstance(item.ctx, ast.Load) \
                        and _in(item, lines):
                    read = ast.copy_location(copy.deepcopy(value), item)
                    if isinstance(held, list):
                        held[k] = read
                    else:
                        setattr(node, field, read)


#: a parameter that names the gravity (``g``, ``gravity``), which a student may read as the Earth's
_GRAVITY = re.compile(r"^(g|g_\w+|grav\w*)$", re.IGNORECASE)
#: a gravity vector by the course's notation (``I_grav``, ``I_g``): read as the Earth's, along the course's -y
_GRAVITY_VECTOR = re.compile(r"^I_(g|grav\w*)$")


def _defaults(function: _Function) -> dict:
    """``{parameter: [(slip, value), ...]}``: what a read of each of the function's parameters may be read as
    instead, the argument then ignored: the constant or the number of its default (``WIRE_LENGTH`` of
    ``wire_length=WIRE_LENGTH``), the module's constant of its name in capitals, or of its name and a number (its
    value at the start: ``WIRE_LENGTH`` of ``wire_length``, ``ANGLES0`` of ``angles``), and for a gravity the
    Earth's (``9.81`` of ``g``, ``(0, -9.81, 0)`` of ``I_grav``)."""
    node = function.node
    positional = node.args.posonlyargs + node.args.args
    given = dict(zip([a.arg for a in positional[len(positional) - len(node.args.defaults):]], node.args.defaults)) \
        if node.args.defaults else {}
    given.update({a.arg: d for a, d in zip(node.args.kwonlyargs, node.args.kw_defaults) if d is not None})
    found: dict = {}
    for parameter in positional + node.args.kwonlyargs:
        name = parameter.arg
        if name in ("self", "cls"):
            continue
        reads, default = [], given.get(name)
        if default is not None and ((isinstance(default, ast.Name) and default.id in function.constants)
                                    or _number(default)):
            reads.append(("default", default))
        for constant in sorted(function.constants):
            if re.fullmatch(rf"{re.escape(name)}_?\d*", constant, re.IGNORECASE) \
                    and not (isinstance(default, ast.Name) and default.id == constant):
                reads.append(("default", ast.Name(constant, ast.Load())))
        if _GRAVITY.match(name):
            reads.append(("earth", ast.Constant(EARTH_GRAVITY)))
        elif _GRAVITY_VECTOR.match(name):  # ``np.array([0.0, -9.81, 0.0])`` for ``I_grav``: the course's -y
            reads.append(("earth", ast.Call(ast.Attribute(ast.Name("np", ast.Load()), "array", ast.Load()),
                                            [ast.List([ast.Constant(0.0), ast.Constant(-EARTH_GRAVITY),
                                                       ast.Constant(0.0)], ast.Load())], [])))
        if reads:
            found[name] = reads
    return found


def _default_slips(function: ast.FunctionDef, lines: tuple, defaults: dict):
    """Every read of a parameter in the region read as its default, its module's constant or the Earth's gravity
    (``_defaults``): the argument ignored throughout; and, where several parameters have one, every read of each
    read as its first (``np.diag([I_AXIAL, I_TRANSVERSE, I_TRANSVERSE])`` for ``np.diag([I_axial, I_transverse,
    I_transverse])``: every argument ignored, the answer the one at the module's constants)."""
    for name, reads in defaults.items():
        for slip, value in reads:
            yield slip, ("read_as", name, value)
    firsts = tuple((name, reads[0][1]) for name, reads in defaults.items() if reads[0][0] == "default")
    if len(firsts) > 1:
        yield "defaults", ("read_all_as", firsts)


#: a name of a value at the start, of a module's constant or a parameter (``ANGLES0``, ``START_ANGLES``, ``x0``)
_START = re.compile(r"^([A-Za-z]\w*0|(start|initial)_\w+|\w+_(start|initial))$", re.IGNORECASE)


def _starts(function: _Function) -> dict:
    """``{name: start}`` of the names the function binds (not its parameters) to a value computed from one value
    at the start, a module's constant or a parameter named so (``angles = START_ANGLES.copy()``, ``angles =
    _run(step, ANGLES0)``, ``x = x0``): a read of such a name may be a read of its start, the value computed from
    it then left unused (``cardan(*ANGLES0)`` for ``cardan(*angles)``: the start returned for the end)."""
    parameters = _parameters(function.node)
    known = function.constants | parameters
    found: dict = {}
    for node in ast.walk(function.node):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name) \
                and node.targets[0].id not in parameters:
            read = {n.id for n in ast.walk(node.value) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)
                    and n.id in known and _START.match(n.id)}
            found.setdefault(node.targets[0].id, set()).update(read - {node.targets[0].id})
    return {name: next(iter(read)) for name, read in found.items() if len(read) == 1}


def _angles(function: _Function) -> frozenset:
    """The names the function reads as angles: the argument of a sine or a cosine (``phi`` of ``np.cos(phi)``),
    and an argument passed where a function of the reference takes an angle (``a`` of ``rot(1, a)`` where
    ``rot(axis, x)`` takes ``np.cos(x)``)."""
    found = set(_trig_arguments(function.node))
    for call in ast.walk(function.node):
        if isinstance(call, ast.Call):
            callee = _callee(call)
            found |= {a.id for k, a in enumerate(call.args) if isinstance(a, ast.Name)
                      and (callee, k) in function.angled}
            found |= {w.value.id for w in call.keywords if w.arg is not None and isinstance(w.value, ast.Name)
                      and (callee, w.arg) in function.angled}
    return frozenset(found)


def _bound_once(function: ast.FunctionDef) -> dict:
    """``{name: its value}`` of the names the function binds once, and by themselves (not unpacked)."""
    bound: dict = {}
    for node in ast.walk(function):
        for target in node.targets if isinstance(node, ast.Assign) else ():
            for name in ast.walk(target):
                if isinstance(name, ast.Name):
                    bound.setdefault(name.id, []).append(node.value if target is name else None)
    return {name: values[0] for name, values in bound.items() if len(values) == 1 and values[0] is not None}


def _sums(function: ast.FunctionDef) -> dict:
    """``{name: the names it sums}`` of the names the function binds once to a sum or a difference of names
    (``g_e = q2 + q4``)."""
    return {name: frozenset(n.id for n in ast.walk(value) if isinstance(n, ast.Name))
            for name, value in _bound_once(function).items()
            if isinstance(value, ast.BinOp) and isinstance(value.op, (ast.Add, ast.Sub))}


def _bound_terms(function: ast.FunctionDef) -> dict:
    """``{name: its terms}`` of the names the function binds once, and to a sum or a difference of two to four
    terms (``radius = l2 + l3 * np.sin(phi)``: ``l2``, ``l3 * np.sin(phi)``; a term subtracted, under its minus)."""
    terms = {name: _sum_terms(value) for name, value in _bound_once(function).items()}
    return {name: tuple(each) for name, each in terms.items() if 2 <= len(each) <= 4}


def _bound_solves(function: ast.FunctionDef) -> dict:
    """``{name: the right-hand side}`` of the names the function binds once, and to a solve (``Minv_JT =
    np.linalg.solve(M, J.T)``: ``J.T``)."""
    return {name: value.args[1] for name, value in _bound_once(function).items()
            if isinstance(value, ast.Call) and _callee(value) == "solve" and len(value.args) == 2
            and not value.keywords}


#: the calls that make an array of zeros: one passed to a call stands for a quantity that is zero there (no torque)
_ZEROS = frozenset({"zeros", "zeros_like"})
#: the names of a function that a slip of one argument of zeros tries in its place, at most
MAX_FILLS = 6


def _zero_arguments(function: ast.FunctionDef) -> dict:
    """``{id of an argument of zeros: the names}`` of the arrays of zeros that the function passes to a call by
    themselves (``forward_dynamics(M, f, g, np.zeros(3))``; not one inside a list, a state's rates at rest), with the
    names a slip could pass there instead: the function's parameters and the names it binds before that line, but
    ``self`` and the module's constants (upper case)."""
    parameters = _parameters(function) - {"self", "cls"}
    bound = [(n.lineno, n.id) for n in ast.walk(function) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)]
    found = {}
    for call in ast.walk(function):
        if not isinstance(call, ast.Call) or _callee(call) in _ZEROS:
            continue
        for argument in call.args:
            if not (isinstance(argument, ast.Call) and _callee(argument) in _ZEROS):
                continue
            names = sorted(parameters | {name for line, name in bound if line < call.lineno})
            names = [name for name in names if not name.isupper() and name != "_"]
            if names:
                found[id(argument)] = tuple(names[:MAX_FILLS])
    return found


def _stored_reads(function: ast.FunctionDef) -> dict:
    """``{id of a read: the other arguments}`` of a constructor's reads of its arguments in the statements that
    store them (``self.B_a_B = _vector_or_zeros(B_a_B)``), where it stores two or more: the others, each one a read
    copied from a neighbouring line would take."""
    if function.name != "__init__":
        return {}
    parameters = _parameters(function) - {"self"}
    reads = [(node, name) for node in ast.walk(function) if isinstance(node, ast.Assign)
             and all(isinstance(t, ast.Attribute) and isinstance(t.value, ast.Name) and t.value.id == "self"
                     for t in node.targets)
             for name in ast.walk(node.value) if isinstance(name, ast.Name) and name.id in parameters]
    stored = {name.id for _, name in reads}
    if len(stored) < 2:
        return {}
    return {id(name): tuple(sorted(stored - {name.id})) for _, name in reads}


def _sibling_reads(function: ast.FunctionDef) -> dict:
    """``{id of a read: the other parameters}`` of the reads of the function's parameters as operands of arithmetic
    (``length**2 + height**2``) in a statement that so reads two to five of them: the others, each one a read of the
    wrong name would take (the width for the height).  A parameter passed to a call by itself (``f`` of
    ``np.cross(r - c, f)``) is of another kind."""
    parameters = _parameters(function) - {"self", "cls"}
    found = {}
    for statement in ast.walk(function):
        if not isinstance(statement, (ast.Assign, ast.AugAssign, ast.Return)) or statement.value is None:
            continue
        operands = [child for node in ast.walk(statement.value) if isinstance(node, (ast.BinOp, ast.UnaryOp))
                    for child in ast.iter_child_nodes(node)]
        reads = [n for n in operands if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load) and n.id in parameters]
        names = sorted({n.id for n in reads})
        if 2 <= len(names) <= 5:
            found.update({id(n): tuple(other for other in names if other != n.id) for n in reads})
    return found


def _unpacked_together(function: ast.FunctionDef) -> dict:
    """``{name: the others}`` of the names the function unpacks together from one vector (``q1, q2 = q``, ``x, h =
    y[:2]``, ``np.asarray(q, dtype=float)``): its coordinates, each of which a read of the wrong one would take (``q1``
    for ``q2``).  A tuple of values bound at once (``a, b = f(x), g(y)``) or the results of another call (sympy's
    ``symbols()``) unpack no vector."""
    found: dict = {}
    for node in ast.walk(function):
        for target in node.targets if isinstance(node, ast.Assign) and _vector_read(node.value) else ():
            if isinstance(target, ast.Tuple) and 2 <= len(target.elts) <= 6 \
                    and all(isinstance(e, ast.Name) for e in target.elts):
                names = [e.id for e in target.elts if e.id != "_"]
                for name in names:
                    found.setdefault(name, set()).update(other for other in names if other != name)
    return {name: tuple(sorted(others)) for name, others in found.items() if others}


def _vector_read(value) -> bool:
    """A vector read as it is: a name, an index or a slice of one, or one converted (``np.asarray(q, dtype=float)``)."""
    if isinstance(value, ast.Call) and _callee(value) in ("asarray", "array", "ravel") and len(value.args) == 1:
        value = value.args[0]
    return isinstance(value, (ast.Name, ast.Subscript, ast.Attribute))


def _unread_once(function: ast.FunctionDef) -> frozenset:
    """The names the function reads once only: a list of names with one of them written as its neighbour leaves it
    unused (``(m1, m1)`` for ``(m1, m2)``)."""
    counts = collections.Counter(n.id for n in ast.walk(function) if isinstance(n, ast.Name)
                                 and isinstance(n.ctx, ast.Load))
    return frozenset(name for name, count in counts.items() if count == 1)


def _built(function: ast.FunctionDef) -> frozenset:
    """The names the function binds to a vector or matrix it writes out (``hip = sp.Matrix([-dx, dy, 0])``,
    ``r = np.array([x, y, 0.0])``): one passed to a call with the wrong sign is a sign slip of the call's argument."""
    return frozenset(t.id for node in ast.walk(function) if isinstance(node, ast.Assign) and len(node.targets) == 1
                     and isinstance(node.value, ast.Call) and _callee(node.value) in ("Matrix", "array")
                     and node.value.args and isinstance(node.value.args[0], (ast.List, ast.Tuple))
                     for t in node.targets if isinstance(t, ast.Name))


def _name_slips(node, parent, angles: frozenset, defaults: dict, sums: dict, starts: dict,
                built: frozenset = frozenset(), reads: tuple = ({}, {}, frozenset(), {}, {}, {}, {}),
                numbers: frozenset = frozenset()):
    """One read of a name for another of its kind: an angle for another angle that the function reads (``np.cos(beta)``
    for ``np.cos(phi)``; where one is bound to a sum of the other and more, ``g_e = q2 + q4``, the read of the sum for
    its term is as truly a term added, and the reverse a term left out: ``sums``), a parameter read as its default, its
    module's constant or the Earth's gravity (``_defaults``: the argument ignored), a name bound to a value computed
    from a start read as that start (``_starts``: the computation left unused); a slice's axes exchanged in one
    statement (``V[2, :]`` for ``V[:, 2]``, on both sides of ``V[:, 2] = -V[:, 2]``); and a list of names (coordinates,
    say) in the order of another that starts with its last or its second (``[phi, x, y]`` for ``[x, y, phi]``).
    ``reads``: ``(_bound_terms, _stored_reads, _unread_once, _sibling_reads, _unpacked_together, _bound_solves,
    _zero_arguments)`` of the function: a name bound to a sum read as one of its terms (the others left out there), a
    constructor's argument stored from another one it stores (a line copied from its neighbour), a list of names with
    one that is read nowhere else written as its neighbour, one read of an argument where another that the same line
    reads belongs (not of an angle: its own slip), one read of a coordinate where another unpacked with it belongs
    (``q1`` for ``q2`` of ``q1, q2 = q``: read from the other's row; of two angles, the angle's slip), and one read of a
    name bound to a solve as the solve's right-hand side (``J @ J.T`` for ``J @ Minv_JT`` of ``Minv_JT = solve(M,
    J.T)``: the inverse left out of that product alone), and an argument of zeros passed to a call as a name the
    function has bound before it (``forward_dynamics(M, f, g, qd)`` for ``forward_dynamics(M, f, g, np.zeros(n))``: the
    rates as the torques, a term that does not belong added).  A number a product or a quotient takes typed as another
    that a formula of the module takes (``numbers``: ``m / 20`` for ``m / 12``)."""
    terms, stored, once, siblings, unpacked, solved, fills = reads
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
        if node.id in angles:
            for other in sorted(angles - {node.id}):
                slip = "angle_sum" if node.id in sums.get(other, ()) else \
                    "angle_part" if other in sums.get(node.id, ()) else "angle"
                yield slip, lambda n, other=other: ast.Name(other, ast.Load())
        for term in terms.get(node.id, ()):  # after the angles: a sum of angles read as one is one angle for another
            yield "sum_part", lambda n, term=term: copy.deepcopy(term)
        for other in stored.get(id(node), ()):
            yield "stored_from", lambda n, other=other: ast.Name(other, ast.Load())
        for other in siblings.get(id(node), ()) if node.id not in angles else ():
            yield "parameter_read", lambda n, other=other: ast.Name(other, ast.Load())
        for other in unpacked.get(node.id, ()):
            if not (node.id in angles and other in angles):
                yield "coordinate", lambda n, other=other: ast.Name(other, ast.Load())
        if node.id in solved:  # ``J @ J.T`` for ``J @ Minv_JT``: the solve's right-hand side where its value belongs
            yield "unsolved_read", lambda n: copy.deepcopy(solved[n.id])
        for slip, value in defaults.get(node.id, ()):
            yield slip, lambda n, value=value: copy.deepcopy(value)
        if node.id in starts:  # ``cardan(*ANGLES0)`` for ``cardan(*angles)``: the start for the value computed
            yield "start_value", lambda n: ast.Name(starts[n.id], ast.Load())
        if node.id in built and isinstance(parent, ast.Call) and node in parent.args:  # ``f(..., -hip)``
            yield "sign", _negated
    for other in fills.get(id(node), ()):  # ``forward_dynamics(M, f, g, qd)`` for ``..., np.zeros(n))``
        yield "zeros_filled", lambda n, other=other: ast.Name(other, ast.Load())
    if _factor_number(node) and isinstance(parent, ast.BinOp) and isinstance(parent.op, (ast.Mult, ast.Div)):
        for other in sorted(numbers - {node.value}, key=float):  # ``m / 20`` for ``m / 12``: another formula's
            typed = int(other) if type(node.value) is int and float(other).is_integer() else float(other)
            yield "sibling_number", lambda n, typed=typed: ast.Constant(typed)
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)) and not _number(node.right):
        # one term of a sum taken twice or halved; a sum's first term only where it is no sum itself (else its own last)
        yield from _scaled_terms(node, "right")
        if not (isinstance(node.left, ast.BinOp) and isinstance(node.left.op, (ast.Add, ast.Sub))) \
                and not _number(node.left):
            yield from _scaled_terms(node, "left")
    if isinstance(node, (ast.Assign, ast.AugAssign, ast.Return, ast.Expr)):
        for pattern in sorted({_axes(n) for n in ast.walk(node)} - {None}):
            yield "axes", lambda n, pattern=pattern: _axes_exchanged(n, pattern)
    if isinstance(node, (ast.Tuple, ast.List)) and isinstance(node.ctx, ast.Load) and 2 <= len(node.elts) <= 4 \
            and all(isinstance(e, ast.Name) for e in node.elts) and len({e.id for e in node.elts}) == len(node.elts):
        for k, entry in enumerate(node.elts):  # ``(m1, m1)`` for ``(m1, m2)``: m2, read nowhere else, unused
            # (a module's constant written as another is a constant typed with the other's value: its slips say so)
            for j in (k - 1, k + 1) if entry.id in once and not entry.id.isupper() else ():
                if 0 <= j < len(node.elts):
                    yield "repeated", lambda n, k=k, j=j: _with(n, elts=n.elts[:k] + [copy.deepcopy(n.elts[j])]
                                                                + n.elts[k + 1:])
    if isinstance(node, ast.Call):  # ``f(y, m, m, g)`` for ``f(y, m, theta, g)``: theta, read nowhere else, unused
        named = {k: a.id for k, a in enumerate(node.args) if isinstance(a, ast.Name)}
        for k, name in named.items() if len(set(named.values())) == len(named) else ():
            for j in (k - 1, k + 1) if name in once and not name.isupper() else ():
                if j in named:
                    yield "argument_repeated", lambda n, k=k, j=j: _with(
                        n, args=n.args[:k] + [copy.deepcopy(n.args[j])] + n.args[k + 1:])
    if isinstance(node, (ast.Tuple, ast.List)) and 3 <= len(node.elts) <= 6 \
            and all(isinstance(e, ast.Name) for e in node.elts):  # ``[phi, x, y]`` for ``[x, y, phi]``, read or bound
        yield "cycled", lambda n: _with(n, elts=n.elts[-1:] + n.elts[:-1])
        yield "cycled", lambda n: _with(n, elts=n.elts[1:] + n.elts[:1])


def _full(index) -> bool:
    return isinstance(index, ast.Slice) and index.lower is None and index.upper is None and index.step is None


def _axes(node) -> str | None:
    """What a read of a matrix's row or column is (``V[:, 2]``: the matrix and the index), or None."""
    if not isinstance(node, ast.Subscript) or not isinstance(node.slice, ast.Tuple) or len(node.slice.elts) != 2:
        return None
    first, second = node.slice.elts
    if _full(first) == _full(second) or isinstance(first if _full(second) else second, ast.Slice):
        return None
    return ast.dump(node.value) + ast.dump(node.slice)


def _axes_exchanged(statement, pattern: str):
    """Every read or write of the row or column ``pattern`` in a statement made of the other axis (the copy is
    changed in place)."""
    for node in ast.walk(statement):
        if _axes(node) == pattern:
            node.slice = ast.Tuple(list(reversed(node.slice.elts)), ast.Load())
    return statement


def _single(function: ast.FunctionDef, name: str) -> None:
    """The argument ``name`` converted to single precision at the function's start (changed in place)."""
    cast = ast.Call(ast.Attribute(ast.Name("np", ast.Load()), "asarray", ast.Load()), [ast.Name(name, ast.Load())],
                    [ast.keyword("dtype", _float32())])
    function.body.insert(0, ast.copy_location(ast.Assign([ast.Name(name, ast.Store())], cast), function.body[0]))


class _SingleAttribute(ast.NodeTransformer):
    """Every read of ``self.<attribute>`` within the region's lines converted to single precision."""

    def __init__(self, attribute: str, lines: tuple):
        self.attribute, self.lines = attribute, lines

    def visit_Attribute(self, node):
        if isinstance(node.ctx, ast.Load) and isinstance(node.value, ast.Name) and node.value.id == "self" \
                and node.attr == self.attribute and _in(node, self.lines):
            return ast.copy_location(ast.Call(ast.Attribute(ast.Name("np", ast.Load()), "asarray", ast.Load()),
                                              [node], [ast.keyword("dtype", _float32())]), node)
        return self.generic_visit(node)


def _single_attribute(function: ast.FunctionDef, lines: tuple, attribute: str) -> None:
    """The reads of ``self.<attribute>`` in the region converted to single precision (changed in place)."""
    _SingleAttribute(attribute, lines).visit(function)
    ast.fix_missing_locations(function)


def _swap_names(function: ast.FunctionDef, lines: tuple, a: str, b: str) -> None:
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and _in(node, lines):
            node.id = b if node.id == a else a if node.id == b else node.id


def _in(node, lines: tuple) -> bool:
    line = getattr(node, "lineno", None)
    return line is not None and any(first < line < last for first, last in lines)


def _written_index_slips(node):
    """An entry written into a neighbouring index, ``a[0] = ...`` for ``a[1] = ...``: tried with the reads of names,
    after every other slip (``LATE_SLIPS``)."""
    if isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Store):
        for _, edit in _index_slips(node):
            yield "written_index", edit


def _mutated(function: _Function, lines: tuple):
    """``(slip, new definition, parameters it leaves unused, names bound in the function it leaves unread)`` of
    every slip of the function's regions ``lines``, each once."""
    sites = [(index, node, parent, guarded, indexing)
             for index, (node, parent, guarded, indexing) in enumerate(_parented(function.node))
             if _in(node, lines)]
    seen = {ast.dump(function.node)}
    parts, skews = _state_parts(function.node), _skews(function.node)
    names, parameters, keys = _names(function.node), _parameters(function.node), _text_keys(function.node)
    others, angled = _trig_names(function.node), _trig_angles(function.node)
    used = _used_parameters(function.node, parameters)
    bound = _read_bound(function.node, parameters)
    angles, defaults, sums, starts = _angles(function), _defaults(function), _sums(function.node), _starts(function)
    built = _built(function.node)
    reads = (_bound_terms(function.node), _stored_reads(function.node), _unread_once(function.node),
             _sibling_reads(function.node), _unpacked_together(function.node), _bound_solves(function.node),
             _zero_arguments(function.node))
    symbolic = _symbolic(function)
    # the reads of one name for another come after every other slip: the tier tries them last, within its budget;
    # the arguments converted to other units come last of all
    places = [(None, function.node, None, False, False, False)] + [site + (False,) for site in sites] + \
        [(None, function.node, None, False, False, True)] + [site + (True,) for site in sites] + \
        [(None, function.node, None, False, False, CONVERSIONS)]
    for index, node, parent, guarded, indexing, late_pass in places:
        if index is None:
            slips = _conversion_slips(function.node, lines, angles if not symbolic else frozenset()) \
                if late_pass is CONVERSIONS else \
                _default_slips(function.node, lines, defaults) if late_pass else _parameter_slips(function.node, lines)
        elif late_pass:
            slips = () if (guarded and guarded != ITERABLE) or indexing else itertools.chain(
                _name_slips(node, parent, angles, defaults, sums, starts, built, reads, function.numbers),
                _trig_angle_slips(node, angled),
                _written_index_slips(node),
                _typed_slips(node, parent, function.constants))  # constants typed short: late slips too
        elif guarded is True:  # a guarded place is not mutated, but for its precision: a dtype changes no count
            slips = _single_slips(node) if isinstance(node, ast.Call) else ()
        else:
            slips = itertools.chain(_slips(node, parent), _entry_slips(node, parent),
                                    _read_slips(node, names, function.attributes, keys),
                                    _trig_read_slips(node, parent, others),
                                    _keyword_slips(node, function.keywords), _first_slips(node, parent),
                                    _position_slips(node),
                                    _frame_slips(node, names, function.attributes))
        for slip, edit in slips:
            if guarded == ITERABLE and slip not in _KEEP_COUNT:
                continue
            if slip == "kept_adding" and function.node.name == "__init__":
                continue  # a constructor sets what its object keeps for the first time
            if isinstance(node, ast.Dict) and symbolic:
                continue  # a substitution of sympy's exchanged grinds on for seconds, as an angle converted does
            slip = "index" if indexing else slip  # a slip inside an index reads a wrong entry
            if isinstance(edit, tuple) and len(edit) == 3 and edit[1] in parts and edit[2] in parts:
                slip = "rows"  # two parts of the state exchanged: read from each other's rows
            elif slip == "entries" and _unpacked_coordinates(node, parent):
                slip = "rows"  # ``q2, _ = q`` for ``_, q2 = q``: a coordinate read from the other's row
            elif slip in ("entries", "cycled") and _unpacked_state(node, parent):
                slip = "unpacked"  # ``y, x, phi = q``: names in another order, each read from another's row
            elif isinstance(edit, tuple) and len(edit) == 3 and slip in ("names", "parameters") \
                    and _rates(edit[1], edit[2]):
                slip = f"{slip}_rates"  # a quantity and its rate exchanged: each read where the other belongs
            if slip in ("transpose", "factors", "sides") and _skew(node, skews, slip):
                # a skew matrix transposed is the matrix negated (``w @ S`` is ``S.T @ w``); a product with it taken
                # from the other side is a cross product of its operands exchanged (``r @ skew(w)`` is ``r x w``)
                slip = "skew_factors" if slip == "factors" else "skew"
            copies: dict = {}
            tree = _tree_copy(function.node, copies)
            if isinstance(edit, tuple) and edit[0] == "unit":
                _unit(tree, lines, edit[1])
            elif isinstance(edit, tuple) and edit[0] == "read_as":
                _read_as(tree, lines, edit[1], edit[2])
            elif isinstance(edit, tuple) and edit[0] == "read_all_as":
                for name, value in edit[1]:
                    _read_as(tree, lines, name, value)
            elif isinstance(edit, tuple) and edit[0] == "single":
                _single(tree, edit[1])
            elif isinstance(edit, tuple) and edit[0] == "single_attribute":
                _single_attribute(tree, lines, edit[1])
            elif isinstance(edit, tuple):
                _swap_names(tree, lines, edit[1], edit[2])
            else:
                target, holder = copies[id(node)], copies.get(id(parent))
                replacement = edit(target)
                if replacement is None or not _replace(holder, target, replacement):
                    continue
            key = ast.dump(tree)  # the new nodes' places are filled in where the tree is compiled (``_compiled``)
            if key not in seen:
                seen.add(key)
                yield slip, tree, tuple(sorted(p for p in used if not _read_in(key, p))), \
                    tuple(sorted(n for n in bound if not _read_in(key, n)))


def _read_bound(function: ast.FunctionDef, parameters: frozenset) -> frozenset:
    """The names other than its parameters that the function binds (by assignment, or unpacking) and reads."""
    stored = {n.id for n in ast.walk(function) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    read = {n.id for n in ast.walk(function) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
    return frozenset((stored & read) - parameters)


def _read_in(dumped: str, name: str) -> bool:
    """The tree whose ``ast.dump`` is ``dumped`` reads the name (as ``_used_parameters`` finds it, without another
    walk of the tree)."""
    return f"Name(id={name!r}, ctx=Load())" in dumped


def _tree_copy(node, copies: dict):
    """A deep copy of the syntax tree ``node``, as ``copy.deepcopy`` makes it (a node met twice, such as the
    parser's shared ``Load``, copied once), at a fraction of its cost; ``copies`` maps the ``id`` of each node of
    the original to its copy, so that a place found in the original is found in the copy without another walk."""
    made = copies.get(id(node))
    if made is not None:
        return made
    made = copies[id(node)] = type(node).__new__(type(node))
    fields = made.__dict__
    for key, value in node.__dict__.items():
        if isinstance(value, ast.AST):
            value = _tree_copy(value, copies)
        elif isinstance(value, list):
            value = [_tree_copy(item, copies) if isinstance(item, ast.AST) else item for item in value]
        fields[key] = value
    return made


def _parameters(function: ast.FunctionDef) -> frozenset:
    """The names of the function's parameters."""
    arguments = function.args.posonlyargs + function.args.args + function.args.kwonlyargs
    return frozenset(a.arg for a in arguments)


def _defaulted(function: ast.FunctionDef) -> frozenset:
    """The function's parameters that have a default (``anchor=ANCHOR``): a constant of the problem that a call
    leaves as it is, which the test of an ignored argument does not change."""
    positional = function.args.posonlyargs + function.args.args
    named = positional[len(positional) - len(function.args.defaults):] if function.args.defaults else []
    named += [a for a, d in zip(function.args.kwonlyargs, function.args.kw_defaults) if d is not None]
    return frozenset(a.arg for a in named)


def _used_parameters(function: ast.FunctionDef, parameters: frozenset) -> frozenset:
    """The ``parameters`` that the function's body reads, in its own code or in a function it defines."""
    if not parameters:
        return frozenset()
    return frozenset(n.id for n in ast.walk(function)
                     if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load) and n.id in parameters)


def _names(function: ast.FunctionDef) -> frozenset:
    """The names a function reads or binds, and its arguments."""
    arguments = function.args.posonlyargs + function.args.args + function.args.kwonlyargs
    return frozenset({n.id for n in ast.walk(function) if isinstance(n, ast.Name)} | {a.arg for a in arguments})


def _text_keys(function: ast.FunctionDef) -> frozenset:
    """The text keys of a function's subscripts and of its dicts' entries (``A["A_IC2"]``)."""
    return frozenset({n.slice.value for n in ast.walk(function) if isinstance(n, ast.Subscript)
                      and _text_key(n.slice)}
                     | {k.value for n in ast.walk(function) if isinstance(n, ast.Dict) for k in n.keys if _text_key(k)})


def _parented(root):
    """``(node, parent, guarded, indexing)`` in the pre-order of ``_walk``."""
    parents = {}
    for node in ast.walk(root):
        for child in ast.iter_child_nodes(node):
            parents[id(child)] = node
    for node, guarded, indexing in _walk(root):
        yield node, parents.get(id(node)), guarded, indexing


def _replace(parent, old, new) -> bool:
    for field, value in ast.iter_fields(parent):
        if value is old:
            setattr(parent, field, new)
            return True
        if isinstance(value, list):
            for k, item in enumerate(value):
                if item is old:
                    value[k] = new
                    return True
    return False


def _compiled(function: _Function, tree: ast.FunctionDef, filename: str):
    """The code object of a mutated definition (a method compiled inside a class, for its ``__class__`` cell)."""
    arguments = _with(tree.args, defaults=[], kw_defaults=[None] * len(tree.args.kwonlyargs))
    tree = _with(tree, decorator_list=[], args=arguments)  # the live function keeps its own defaults
    body = [ast.ClassDef(function.path[0], [], [], [tree], [])] if len(function.path) > 1 else [tree]
    module = ast.fix_missing_locations(ast.Module(body, []))
    space: dict = {}
    flags = __future__.annotations.compiler_flag  # annotations are not evaluated
    exec(compile(module, filename, "exec", flags=flags, dont_inherit=True), {"__name__": "_mutant"}, space)
    made = space[function.path[0]]
    if len(function.path) > 1:
        made = made.__dict__[function.path[1]]
    return _code_holder(made).__code__


# ---------------------------------------------------------------------------------------------- symbolic answers

#: the functions of sympy that change an expression's form and not its value: the mutants are screened without
#: them (``_unsimplified``), where the reference's own value is the same so (``_twins``)
SIMPLIFIERS = frozenset({"simplify", "trigsimp", "expand", "factor_terms", "factor", "cancel", "ratsimp", "radsimp",
                         "powsimp", "expand_trig", "fu", "signsimp", "combsimp", "gammasimp"})
#: what a simplifier passed as a value (``M.applyfunc(sp.simplify)``) becomes
_IDENTITY = "(lambda _expression, *_arguments, **_keywords: _expression)"


def _symbolic(function: _Function) -> bool:
    """Whether the function reads sympy (``sp.Matrix``, ``sp.cos``): its angles are symbols, and a conversion of
    one of them gives floats that sympy's simplification grinds on for seconds."""
    return any(isinstance(node, ast.Name) and node.id in function.sympy for node in ast.walk(function.node))


def _sympy_names(nodes) -> frozenset:
    """The names that the imports among ``nodes`` (at any depth) bind to sympy (``sp`` of ``import sympy as sp``)
    and to its simplifiers (``from sympy import simplify``), the latter marked ``from:``."""
    found = set()
    for node in (n for top in nodes for n in ast.walk(top)):
        if isinstance(node, ast.Import):
            found |= {a.asname or a.name.split(".")[0] for a in node.names if a.name.split(".")[0] == "sympy"}
        elif isinstance(node, ast.ImportFrom) and not node.level and (node.module or "").split(".")[0] == "sympy":
            found |= {f"from:{a.asname or a.name}" for a in node.names if a.name in SIMPLIFIERS}
    return frozenset(found)


class _Unsimplified(ast.NodeTransformer):
    """Every call of a simplifier of sympy replaced by the expression it simplifies (``sp.trigsimp(e, method="fu")``
    by ``e``, ``M.simplify()`` by ``M``), and a simplifier passed as a value by the identity."""

    def __init__(self, names: frozenset):
        self.modules = {n for n in names if not n.startswith("from:")}
        self.functions = {n[5:] for n in names if n.startswith("from:")}
        self.changed = False

    def _kind(self, func) -> str | None:
        if isinstance(func, ast.Attribute) and func.attr in SIMPLIFIERS:
            return "function" if isinstance(func.value, ast.Name) and func.value.id in self.modules else "method"
        if isinstance(func, ast.Name) and func.id in self.functions:
            return "function"
        return None

    def visit_Call(self, node):
        kind = self._kind(node.func)
        if kind is None:
            return self.generic_visit(node)
        node.args = [self.visit(a) for a in node.args]
        node.keywords = [self.visit(k) for k in node.keywords]
        if isinstance(node.func, ast.Attribute):
            node.func.value = self.visit(node.func.value)
        if kind == "function" and node.args and not isinstance(node.args[0], ast.Starred):
            self.changed = True
            return node.args[0]
        if kind == "method" and not node.args:  # ``e.factor(x)`` may be no sympy's: left as it is
            self.changed = True
            return node.func.value
        return node

    def _value(self, node):
        self.changed = True
        return ast.parse(_IDENTITY, mode="eval").body

    def visit_Attribute(self, node):
        if isinstance(node.ctx, ast.Load) and self._kind(node) == "function":
            return self._value(node)
        return self.generic_visit(node)

    def visit_Name(self, node):
        if isinstance(node.ctx, ast.Load) and node.id in self.functions:
            return self._value(node)
        return node


def _simplifies(function: _Function) -> bool:
    """The function reads sympy (its own import, or its module's) and names one of its simplifiers."""
    names = function.sympy | _sympy_names([function.node])
    return bool(names) and any(isinstance(n, ast.Attribute) and n.attr in SIMPLIFIERS or isinstance(n, ast.Name)
                               and f"from:{n.id}" in names for n in ast.walk(function.node))


def _unsimplified(function: _Function, tree: ast.FunctionDef, filename: str, freevars: tuple):
    """The code of ``tree`` (the function's definition, mutated or not) without sympy's simplifications, or None
    where it has none (or its code would not fit the live function's closure)."""
    quick = _Unsimplified(function.sympy | _sympy_names([function.node]))
    tree = ast.fix_missing_locations(quick.visit(copy.deepcopy(tree)))
    if not quick.changed:
        return None
    try:
        code = _compiled(function, tree, filename)
    except (SyntaxError, ValueError, TypeError, KeyError, NameError, AttributeError):
        return None
    return code if code.co_freevars == freevars else None


@lru_cache(maxsize=64)
def _simplifying(root: str, problem: int) -> tuple:
    """The functions of ``problem``'s solution regions (and its neighbours', as ``mutants_of`` takes them) that
    simplify."""
    return tuple(f for f in _functions(root)
                 if any(abs(label - problem) <= NEIGHBOURS for label, _, _ in f.regions) and _simplifies(f))


#: the code without simplifications of a function of the reference, by its live code: made once for the process
_TWINS: dict = {}


def _twins(package, root: Path, problem: int) -> tuple:
    """``(live function, its code without simplifications)`` of the problem's functions that simplify."""
    import importlib

    found = []
    for function in _simplifying(str(root), problem):
        try:
            importlib.import_module(f"{package.__name__}.{function.module}")  # as the probe's call would
        except Exception:  # noqa: BLE001 - a module that does not import has no function to screen with
            continue
        live = _live(package, function.module, function.path)
        if live is None:
            continue
        key = (function, live.__code__)
        if key not in _TWINS:
            _TWINS[key] = _unsimplified(function, function.node, live.__code__.co_filename, live.__code__.co_freevars)
        if _TWINS[key] is not None:
            found.append((live, _TWINS[key]))
    return tuple(found)


def _holds(package, twins: tuple, inputs: list[Evidence]) -> bool:
    """The reference's value without its simplifications, read quickly, is the expected value on every input
    (within the comparison's tolerance): the mutants may be screened so."""
    own = [(holder, holder.__code__) for holder, _ in twins]
    try:
        for holder, twin in twins:
            holder.__code__ = twin
        for evidence in inputs:
            if evidence.expected is None:
                return False
            value = _value(package, evidence, (evidence.source.probe, evidence.source.args), quick=True)
            if value is None or not within(value, evidence.expected, evidence.tol):
                return False
        return True
    finally:
        for holder, code in own:
            holder.__code__ = code


# ---------------------------------------------------------------------------------------------- the package


_LOCK = threading.Lock()
_PACKAGES: dict = {}


def _package():
    """The reference imported once under a private name (``grader.private``), whose functions' code the mutants
    replace in turn."""
    from ..private import private_import, reference_root

    root = reference_root("the diagnosis of formulas")
    if root not in _PACKAGES:
        _PACKAGES[root] = private_import("_mutated_reference", root)
    return root, _PACKAGES[root]


def _code_holder(obj):
    """The function whose ``__code__`` runs for a module's or class's attribute (a property's getter, ...)."""
    if isinstance(obj, property):
        obj = obj.fget
    if isinstance(obj, (staticmethod, classmethod)):
        obj = obj.__func__
    return obj if hasattr(obj, "__code__") else None


def _live(package, module_name: str, path: tuple):
    """The function of the private package that holds the code of ``module_name``'s ``path``, or None."""
    obj = sys.modules.get(f"{package.__name__}.{module_name}")
    for name in path:
        obj = vars(obj).get(name) if obj is not None and hasattr(obj, "__dict__") else None
    return _code_holder(obj) if obj is not None else None


def _probe(probe):
    """The probe function (given by itself, or by its name ``"problem_22.loop"``)."""
    if callable(probe):
        return probe
    import importlib

    module_name, _, name = str(probe).rpartition(".")
    return getattr(importlib.import_module(f"probes.{module_name}"), name)


def _call(package, probe, args, path, quick: bool = False, replies: dict | None = None, remember: bool = False):
    """The value at ``path`` of ``probe`` on the package, called on a copy of ``args`` (a tuple, or the arguments kept
    by ``_kept_once``) and made anew by the probe (``probes.fresh``: a probe that keeps what it computed once per
    package would give the reference's value for every mutant); ``quick``: a symbolic answer is evaluated by reading its
    expressions (``probes._symbolic.quick``) rather than by sympy's ``lambdify``.  ``replies`` (given): the whole
    replies of the calls made so far with the package's code as it is now, by the call, which a call on the same
    arguments reads rather than makes again (a comparison's other values of the same call, ``_siblings``), and a call
    that raised raises again.  An integer of ``path`` also indexes the first axis of an array (the value of one point of
    a probe that returns one per point, as a symbolic answer evaluated at several).  ``remember``: the package's code is
    the reference's own, and the probe keeps what it computes once as it does for any call of the package
    (``probes.remembered``)."""
    from probes import fresh
    from probes._codec import decode, encode
    from probes._symbolic import quick as reading

    key = (probe, args if isinstance(args, _Kept) else id(args), quick)
    if replies is not None and key in replies:
        value = replies[key]
        if isinstance(value, Exception):  # a reply is plain data: an exception is the call's own
            raise value
        return array_of(at_point(value, path))
    try:
        with contextlib.nullcontext() if remember else fresh(), \
                (reading() if quick else contextlib.nullcontext()):
            value = decode(encode(_probe(probe)(package, *_copied(args))))
    except Exception as error:  # noqa: BLE001 - kept for the same call, then raised as it was
        if replies is not None:
            replies[key] = error
        raise
    if replies is not None:
        replies[key] = value
    return array_of(at_point(value, path))


class _Kept:
    """The arguments of one input, kept once for the many calls of its mutants: a copy of their own, which each call
    copies again (``_copied``), and their pickled bytes, by which two kept inputs are the same call (``_call``'s
    replies)."""

    __slots__ = ("args", "blob")

    def __init__(self, args: tuple, blob: bytes):
        self.args, self.blob = _fresh(args, {}), blob

    def __eq__(self, other) -> bool:
        return isinstance(other, _Kept) and self.blob == other.blob

    def __hash__(self) -> int:
        return hash(self.blob)


def _kept_once(args: tuple):
    """The arguments of one input, kept once for the many calls of its mutants (``_Kept``), where they can be
    pickled; else as they are (deep-copied at each call)."""
    try:
        args = tuple(args)
        return _Kept(args, pickle.dumps(args, protocol=pickle.HIGHEST_PROTOCOL))
    except Exception:  # noqa: BLE001 - arguments that cannot be pickled are deep-copied at each call
        return tuple(args)


#: the types whose values a copy of arguments shares rather than copies (immutable)
_SHARED = frozenset((float, int, bool, str, bytes, type(None), complex))


def _fresh(value, memo: dict):
    """A deep copy of plain arguments (numbers, strings, numeric arrays, and dicts, lists and tuples of them), made
    by walking them, which costs a fraction of ``copy.deepcopy`` or of unpickling; a value shared twice is copied
    once, as ``copy.deepcopy`` copies it; anything else is deep-copied."""
    kind = type(value)
    if kind in _SHARED:
        return value
    seen = memo.get(id(value))
    if seen is not None:
        return seen
    if kind is np.ndarray and value.dtype.kind in "biuf":
        made = value.copy()
    elif kind is dict:
        made = {key: _fresh(item, memo) for key, item in value.items()}
    elif kind is list:
        made = [_fresh(item, memo) for item in value]
    elif kind is tuple:
        made = tuple(_fresh(item, memo) for item in value)
    else:
        made = copy.deepcopy(value)
    memo[id(value)] = made
    return made


def _copied(args) -> tuple:
    """A copy of the arguments for one call (a mutant may change them in place)."""
    return _fresh(args.args, {}) if isinstance(args, _Kept) else copy.deepcopy(tuple(args))


#: the codes each call ran (``_traced``), by the call, while ``_kept`` measures one explanation (None outside it):
#: its stages (the regions', the given code's, the constants') trace the same call
_TRACES: dict = {"calls": None}


def _traced(package, root: Path, probe, args, quick: tuple = ()) -> frozenset:
    """The code objects of the reference's folder that ``probe(*args)`` runs on the private package; with
    ``quick`` (``_twins``), run with those codes without simplifications in their functions' place (a profiler
    slows sympy's simplifications tenfold), each counted as its function's own code.  Traced once for each
    explanation (``_TRACES``), and once for each grading where its arguments can be told apart by their pickled
    bytes (``_Refuted.traced``: problem 12's wheel, about 0.3 s a tracing, compares two values of one run)."""
    calls = _TRACES["calls"]
    if calls is None:
        return _traced_once(package, root, probe, args, quick)
    twins = tuple((id(holder), id(twin)) for holder, twin in quick)
    key = (id(package), str(root), probe, id(args), twins)
    if key not in calls:
        ran = _REFUTED.traced(_hashable((id(package), str(root), probe, _kept_once(args), twins)),
                              lambda: _traced_once(package, root, probe, args, quick))
        calls[key] = (args, ran)  # the arguments kept: their id holds
    return calls[key][1]


def _traced_once(package, root: Path, probe, args, quick: tuple = ()) -> frozenset:
    seen: set = set()
    prefix = str(root)

    def profile(frame, event, arg):
        if event == "call" and frame.f_code.co_filename.startswith(prefix):
            seen.add(frame.f_code)

    own = {twin: holder.__code__ for holder, twin in quick}
    previous = sys.getprofile()
    try:
        for holder, twin in quick:
            holder.__code__ = twin
        sys.setprofile(profile)
        _call(package, probe, args, (), quick=bool(quick))
    except Exception:  # noqa: BLE001 - the oracle computed this call: a failure here leaves nothing to mutate
        return frozenset()
    finally:
        sys.setprofile(previous)
        for holder, twin in quick:
            holder.__code__ = own[twin]
    return frozenset(own.get(code, code) for code in seen)


# ---------------------------------------------------------------------------------------------- the mutants


def _problem(check_id: str, probe) -> int | None:
    """The problem of the check (``"p22.loop_values"``), else of the probe (``"problem_22.loop"``)."""
    for text in (str(check_id or ""), str(getattr(probe, "__module__", probe))):
        found = re.search(r"(?:^p|problem_)(\d+)", text)
        if found:
            return int(found.group(1))
    return None


def _owned_earlier(function: _Function, problem: int) -> bool:
    from checks._upstream import SHARED

    owner = SHARED.get(f"{function.module}.{function.path[-1]}")
    return owner is not None and owner[0] < problem


def _scaled_terms(node: ast.BinOp, side: str):
    """The term on ``side`` of a sum taken twice, and halved: a term that takes a step (``dt * f`` of ``x + dt * f``)
    so halved is a step of half the size; so doubled it is as truly the update written twice, which the term taken
    twice tells."""
    for slip, factor in (("term_doubled", 2), ("term_halved", 0.5)):
        slip = "step_term" if factor < 1 and _takes_step(getattr(node, side)) else slip
        yield slip, lambda n, k=factor: _with(n, **{side: ast.BinOp(ast.Constant(k), ast.Mult(), getattr(n, side))})


def _takes_step(term) -> bool:
    """The term is a product that takes a step by the course's names (``dt * f``, ``h * k1``, ``dt * W @ A``)."""
    return isinstance(term, ast.BinOp) and isinstance(term.op, (ast.Mult, ast.MatMult, ast.Div)) and any(
        isinstance(n, ast.Name) and _STEP_CONSTANT.match(n.id.upper()) for n in ast.walk(term))


#: the slips of a read of one name for another (``_name_slips``, ``_default_slips``): tried after every other slip
#: of every function, as many as ``MAX_MUTANTS`` leaves room for
LATE_SLIPS = frozenset({"angle", "angle_sum", "angle_part", "default", "defaults", "start_value", "earth", "axes",
                        "cycled", "typed", "written_index", "converted_radians", "converted_rpm", "converted_degrees",
                        "sum_part", "stored_from", "repeated", "argument_repeated", "zeros_filled", "term_doubled",
                        "term_halved", "step_term", "parameter_read", "coordinate", "sibling_number"})


def mutants_of(package, root: Path, problem: int, probe, args, quick: tuple = (),
               ran: frozenset | None = None, given: bool = False, deadline: _Deadline | None = None,
               library: bool = False) -> list[Mutant] | None:
    """The mutants of the functions of ``problem`` that ``probe(*args)`` runs on the private package, or None when
    there are more than ``MAX_MUTANTS`` of the slips other than the reads of names (the slips cannot all be tried);
    the reads of names (``LATE_SLIPS``) come after all the others, as many as the bound leaves room for.  ``quick``
    (``_twins``): the functions' codes without simplifications, which the call that finds the functions runs;
    ``ran``: the codes that call runs, where the caller traced it.  ``given``: the mutants of the functions of the
    problem's own module that hold no region instead (those of problem N's module for problem N alone), or with
    ``library`` those of the library's modules (a constructor, a helper that the template gives whole), in the
    same order.  ``deadline``: the explanation's, against whose budget of making (``_Deadline.making``) the
    compiling of the mutants is counted."""
    ran = _traced(package, root, probe, args, quick) if ran is None else ran
    found: list[Mutant] = []
    reads: list[Mutant] = []
    for function in _functions(str(root)):
        if function.given != given:
            continue
        lines = tuple((first, last) for label, first, last in function.regions
                      if (label == (LIBRARY if library else problem) if given else abs(label - problem) <= NEIGHBOURS))
        live = _live(package, function.module, function.path)
        if not lines or live is None or live.__code__ not in ran or _owned_earlier(function, problem):
            continue
        defaulted = _defaulted(function.node)
        with deadline.making() if deadline is not None else contextlib.nullcontext():
            codes = _codes(function, lines, live.__code__.co_filename, live.__code__.co_freevars)
        for slip, code, unused, unread, twin in codes:
            mutant = Mutant(function.module, function.path, slip, code, unused, defaulted, twin, function.given,
                            unread=unread)
            (reads if slip in LATE_SLIPS else found).append(mutant)
            if len(found) > MAX_MUTANTS:
                return None
    return found + reads[:MAX_MUTANTS - len(found)]


@lru_cache(maxsize=512)
def _codes(function: _Function, lines: tuple, filename: str, freevars: tuple) -> tuple:
    """``(slip, code object, parameters left unused, names left unread, code without simplifications or None)`` of
    the function's mutants, compiled once for the process (a mutant whose code does not fit the live function's
    closure is left out)."""
    found = []
    simplifies = _simplifies(function)
    for slip, tree, unused, unread in _mutated(function, lines):
        try:
            code = _compiled(function, tree, filename)
        except (SyntaxError, ValueError, TypeError, KeyError, NameError, AttributeError):
            continue
        if code.co_freevars == freevars:
            found.append((slip, code, unused, unread,
                          _unsimplified(function, tree, filename, freevars) if simplifies else None))
    return tuple(found)


#: the loop in which a deadline's interruption that fired too late to interrupt anything is met [iterations]
_ABSORB = 100_000
#: how often the deadline looks at the clock [s]
_POLL = 0.02
#: how long a thread may stay inside a deadline that interrupted it before it is interrupted again [s]: an
#: interruption that lands in a garbage collector's callback or in a finalizer (``__del__``) is lost there
_REFIRE = 0.5
#: a thread that waits rather than works is interrupted after this many times the budget of wall time (not counting
#: the time it was ready to run and waited for a core, where the system tells it)
WAIT_FACTOR = 5.0
#: the mutants measured before the measuring may be given up as one that cannot end within its budget
#: (``_hopeless``), and the factor by which their pace must overrun the budget's remainder: a run of problem 12's
#: wheel (3001 steps) costs about 0.08 s of the budget's seconds, and its 167 mutants about seven times the budget,
#: which they spent to the end and named nothing, on each of the check's compared values.  Two: in the 684
#: measurings of the engine's tests that ended within their budget, the lower median of the first two mutants' times
#: (the faster) projected the rest at 0.86 of the remainder at most, where the first alone projected up to 29 times
#: it (a first call that compiles or fills a cache), and the wheel's at five times
PROJECTED_AFTER = 2
PROJECTED_FACTOR = 2.0


#: the time each thread inside a deadline has spent in the garbage collector, ``[cpu, wall, deadlines]`` [s] by
#: thread ident (the thread's deadlines open now: its entry goes with the last), and where the collection under way
#: in such a thread began (``_collecting``)
_COLLECTED: dict[int, list] = {}
_COLLECTING: dict[int, tuple[float, float]] = {}


def _collecting(phase: str, info: dict) -> None:
    """The garbage collector's callback that counts the time of each collection for the thread it runs in, where a
    deadline watches that thread.  A collection's cost is the process's: it walks every object the process holds (a
    batch's worker, a test run's, holds many, from every grading before), and a full one may take a good part of a
    tier's budget, whichever answer is being explained; the deadline does not count it (``_Deadline``)."""
    thread = threading.get_ident()
    spent = _COLLECTED.get(thread)
    if spent is None:
        return
    if phase == "start":
        _COLLECTING[thread] = (time.thread_time(), time.monotonic())
        return
    began = _COLLECTING.pop(thread, None)
    if began is not None:
        spent[0] += time.thread_time() - began[0]
        spent[1] += time.monotonic() - began[1]


if _collecting not in gc.callbacks:
    gc.callbacks.append(_collecting)


def _collected(thread: int, clock) -> float:
    """The time ``thread`` has spent in the garbage collector so far, the one under way included: its CPU time where
    ``clock`` (its CPU clock) is given, else wall time [s]."""
    spent = _COLLECTED.get(thread, (0.0, 0.0, 0))
    began = _COLLECTING.get(thread)
    if clock is not None:
        return spent[0] + (time.clock_gettime(clock) - began[0] if began is not None else 0.0)
    return spent[1] + (time.monotonic() - began[1] if began is not None else 0.0)


#: the CPU time [s] that ``_pace_work`` takes on the machines where the budgets above were set: the deadlines count
#: those machines' seconds, so that a slower machine (an old laptop) tries the slips a typical one tries.  Estimated
#: from the reference's own derivation of problem 40 (``CONFIRMING_TIME_BUDGET``: 0.4 s there), which took 2.2
#: times as long (0.9 s) on a machine where ``_pace_work`` took 14 ms
PACE_NOMINAL = 0.0065
#: the most the deadlines widen for a slow machine: a machine slower than that names less rather than take longer
PACE_MOST = 4.0
#: ``[pace]`` once measured (``pace``)
_PACE: list = []


def _pace_work() -> int:
    """A small piece of the engine's usual work (products of 3 x 3 arrays, a skew matrix built entry by entry,
    sums in Python), to time the machine by."""
    a, v, total = np.eye(3), np.ones(3), 0
    for _ in range(1200):
        w = np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
        a = a @ w * 0.1 + np.eye(3)
        v = a @ v / (1.0 + float(np.abs(v).sum()))
        total += sum(range(20))
    return total


def pace() -> float:
    """How many times slower than the machines where the budgets were set this one does the engine's work
    (``PACE_NOMINAL``): at least 1 (a faster machine keeps the budgets) and at most ``PACE_MOST``; measured once
    for the process, by the thread's CPU time (the best of three), so that a loaded machine is not taken for a slow
    one."""
    if not _PACE:
        times = []
        for _ in range(3):
            start = time.thread_time()
            _pace_work()
            times.append(time.thread_time() - start)
        _PACE.append(min(PACE_MOST, max(1.0, min(times) / PACE_NOMINAL)))
    return _PACE[0]


def _cpu_clock(thread: int):
    """The CPU-time clock of ``thread`` (an ident of ``threading``), or None where it cannot be read."""
    try:
        return time.pthread_getcpuclockid(thread)
    except (AttributeError, OSError):
        return None


def _schedstat(native_id: int) -> str | None:
    """The scheduler's statistics of a thread of this process (Linux: CPU time, time spent ready to run but waiting
    for a core, in ns), or None where they cannot be read."""
    path = f"/proc/self/task/{native_id}/schedstat"
    return path if _queued(path) is not None else None


def _queued(path: str | None) -> float | None:
    """Seconds the thread has spent ready to run and waiting for a core, or None."""
    if path is None:
        return None
    try:
        with open(path, encoding="ascii") as stats:
            return int(stats.read().split()[1]) / 1e9
    except (OSError, ValueError, IndexError):
        return None


class _Deadline:
    """Interrupts the running thread with ``_Timeout`` once it has spent ``seconds`` of CPU time, unless left
    before: what the tier may try does not depend on how loaded the machine is (a busy machine slows the wall clock,
    not the work), nor on how much the process holds (the time of the garbage collector's collections in the thread
    is not counted: ``_collecting``).  Where a thread's CPU clock cannot be read (``time.pthread_getcpuclockid``:
    not on macOS or Windows) it counts wall time; and a thread that waits without working (for a lock, say) is
    interrupted after ``WAIT_FACTOR`` times ``seconds`` of wall time in any case, less the time it was ready to run
    and waited for a core where the scheduler tells it (Linux), so that a heavily loaded machine does not stop the
    work early.  That bound counts the collections too: work that does nothing but collect garbage is stopped.

    Two kinds of work are counted apart, each against a budget of its own, so that ``seconds`` bounds the
    screening of one answer's mutants alone: the work inside ``making()`` (the making of mutants: the same for every
    answer, and kept for the process), against ``making`` seconds (``MAKING_TIME_BUDGET``), whether or not an
    earlier explanation of the process made its mutants already; and the work inside ``confirming()`` (a mutant
    that a screening without simplifications kept, evaluated as it is), against ``confirming`` seconds
    (``CONFIRMING_TIME_BUDGET``): a simplification of a symbolic answer may take longer than the screening of every
    mutant, and it is paid only for the few that reproduce the student's value.

    Every budget is in the seconds of the machines where the budgets were set: the clocks read divided by the
    machine's ``pace()``, so that a slow machine tries what a typical one tries."""

    def __init__(self, seconds: float, making: float | None = None, confirming: float | None = None):
        self.thread = threading.get_ident()
        self.pace = pace()
        self.seconds = seconds
        self.apart = {"making": MAKING_TIME_BUDGET if making is None else making,
                      "confirming": CONFIRMING_TIME_BUDGET if confirming is None else confirming}
        self.lock = threading.Lock()
        self.armed = True
        self.fired = False
        self.fires = 0  # interruptions sent: more than one where the first was lost, or the thread is slow to leave
        self.done = threading.Event()
        self.clock = _cpu_clock(self.thread)
        self.schedstat = _schedstat(threading.get_native_id())
        self.queued = 0.0  # the last time ready to run and waiting for a core that the scheduler told
        self.start = (0.0, 0.0)
        self.closed = {kind: (0.0, 0.0) for kind in self.apart}  # the CPU and wall time of each kind, periods closed
        self.open = None  # ``(kind, since)``: the period of work counted apart now open
        self.timer = threading.Thread(target=self._watch, daemon=True)

    def _now(self) -> tuple[float, float]:
        """The thread's CPU time (wall time where it has no clock) less the time it spent collecting garbage, and
        the wall time less the time it waited for a core, each divided by the machine's pace."""
        wall = time.monotonic()
        queued = _queued(self.schedstat)
        if queued is not None:
            self.queued = queued
        collected = _collected(self.thread, self.clock)
        cpu = (time.clock_gettime(self.clock) if self.clock is not None else wall) - collected
        return cpu / self.pace, (wall - self.queued) / self.pace

    def _accounts(self, now: tuple[float, float]) -> tuple[tuple[float, float], dict]:
        """``((cpu, wall) screening, {kind: (cpu, wall)} of the work counted apart)`` spent until ``now``."""
        with self.lock:
            apart, current = dict(self.closed), self.open
        if current is not None:
            kind, since = current
            apart[kind] = (apart[kind][0] + now[0] - since[0], apart[kind][1] + now[1] - since[1])
        cpu = sum(spent[0] for spent in apart.values())
        wall = sum(spent[1] for spent in apart.values())
        return (now[0] - self.start[0] - cpu, now[1] - self.start[1] - wall), apart

    def spent(self) -> tuple[float, float]:
        """The CPU time spent so far screening, and making [s]."""
        measuring, apart = self._accounts(self._now())
        return measuring[0], apart["making"][0]

    def _spent(self) -> bool:
        measuring, apart = self._accounts(self._now())
        return (measuring[0] >= self.seconds or measuring[1] >= WAIT_FACTOR * self.seconds
                or any(apart[kind][0] >= budget or apart[kind][1] >= WAIT_FACTOR * budget
                       for kind, budget in self.apart.items()))

    @contextlib.contextmanager
    def _apart(self, kind: str):
        """The work inside is of ``kind``, counted against its own budget (nested in any such period, the outer
        counts)."""
        if self.open is not None:
            yield self
            return
        since = self._now()
        with self.lock:
            self.open = (kind, since)
        try:
            yield self
        finally:
            now = self._now()
            with self.lock:
                spent = self.closed[kind]
                self.closed[kind] = (spent[0] + now[0] - since[0], spent[1] + now[1] - since[1])
                self.open = None

    def making(self):
        """The work inside is the making of mutants (``MAKING_TIME_BUDGET``)."""
        return self._apart("making")

    def confirming(self):
        """The work inside is a screened mutant evaluated as it is (``CONFIRMING_TIME_BUDGET``)."""
        return self._apart("confirming")

    def _watch(self) -> None:
        while not self.done.wait(min(_POLL, self.seconds, *self.apart.values())):
            if self._spent():
                break
        else:
            return
        self._fire()
        while not self.done.wait(_REFIRE):  # still inside: the interruption was lost (or is still to be met)
            self._fire()

    def _fire(self) -> None:
        with self.lock:
            if self.armed:
                self.fired = True
                self.fires += 1
                ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(self.thread), ctypes.py_object(_Timeout))

    def __enter__(self):
        _COLLECTED.setdefault(self.thread, [0.0, 0.0, 0])[2] += 1
        self.start = self._now()
        self.timer.start()
        return self

    def __exit__(self, kind, value, traceback):
        self.done.set()
        with self.lock:
            self.armed = False
            # fired, but not met yet (or sent again while the first was on its way out): met here, where it can
            # interrupt nothing (withdrawing it, SetAsyncExc(NULL), upsets a later profiler)
            pending = self.fired and (self.fires > 1 or not (kind is not None and issubclass(kind, _Timeout)))
        if pending:
            try:
                for _ in range(_ABSORB):
                    pass
            except _Timeout:
                pass
        spent = _COLLECTED[self.thread]
        spent[2] -= 1
        if not spent[2]:
            del _COLLECTED[self.thread]
            _COLLECTING.pop(self.thread, None)
        return False


def _evaluate(package, mutants: list[Mutant], inputs: list[Evidence], deadline: _Deadline,
              originals: dict, judged: bool = True, kept: list | None = None,
              progress: dict | None = None, twins: tuple = (), ran: frozenset | None = None,
              vanishing: bool = False) -> list[Mutant] | None:
    """The mutants that reproduce the student's value on every input (and, ``judged``, differ from the expected
    value on one, and from zero unless ``vanishing``: a value that vanishes is the effect a check named), or None
    when the time ran out first.  ``originals`` keeps the code of every
    function changed (``_restore`` puts it back); ``kept`` (given) gathers the mutants kept as they are found and
    ``progress["tried"]`` counts the mutants tried to the end, for a caller that uses them when the time runs out.
    ``twins`` (``_twins``, where the reference's value holds without them): the codes without simplifications of
    the functions that simplify, with which each mutant is screened, its symbolic answers read quickly; a mutant
    that reproduces the student's value so is evaluated again as it is, and that value decides (unless a mutant of
    the same slip of the same function is kept already: it would add no name).  ``ran``: the codes the first input's
    call runs, where the grading's refutations (``_Refuted``) are kept and heard."""
    from probes import kept_for_one_code

    kept = [] if kept is None else kept
    progress = {} if progress is None else progress
    calls = [(e.source.probe, _kept_once(e.source.args)) for e in inputs]
    parts = [part_of(e.source) for e in inputs]
    parts = [None if part is None else (part[0], _kept_once(part[1])) for part in parts]
    rows = [rows_of(e) for e in inputs]
    rows = [None if row is None else (row[0], (row[1][0], _kept_once(row[1][1]))) for row in rows]
    screened = bool(twins)
    banded = bool(inputs) and _in_band(inputs[0], differs=False)  # else no slip of precision is told: none is tried
    shared = Shared(package, originals, str(Path(package.__file__).parent))
    for holder, twin in twins:
        originals.setdefault(id(holder), (holder, holder.__code__))
    costs = []  # the measuring time of each mutant measured [s]
    last = deadline.spent()[0]  # the measuring time spent when the last mutant measured ended [s]
    # the same calls in another explanation of the grading: each input's probe and kept arguments, not the codes the
    # first input's call runs (two tracings of problem 12's wheel told 14, then 9: the first met code that runs once)
    call = _hashable(tuple(calls))
    paced = _REFUTED.given_up(call, ran)  # the pace at which an earlier value of the same call was given up
    if paced is not None and _projected(paced, deadline.seconds - last, mutants, ran, measured=0) is not None:
        return None
    for tried, mutant in enumerate(mutants):
        progress["tried"] = tried
        if deadline.fired:
            return None
        if _REFUTED.refuted(mutant, ran) or (mutant.slip in PRECISION_SLIPS and not banded):
            continue
        paced = _hopeless(deadline.seconds - last, costs, mutants[tried:], ran)
        if paced is not None:
            _REFUTED.give_up(call, ran, paced)
            return None
        misses = []  # the input at which the mutant's value is not the student's
        if mutant.bindings:  # a constant's slip: its value (and what its module computed from it) bound
            try:
                _bind(mutant.bindings, originals)
                with kept_for_one_code():
                    values = _staged(package, inputs, calls, parts, rows, misses=misses)
            finally:
                _unbind(mutant.bindings, originals)
        else:
            # a slip of the same function that the kept ones hold already adds no name: its screened value decides
            again = any(k.slip == mutant.slip and k.module == mutant.module and k.path == mutant.path for k in kept)
            values = _mutated_values(package, mutant, inputs, calls, (parts, rows), originals, twins, screened,
                                     misses, deadline, confirm=not again, shared=shared)
        now = deadline.spent()[0]
        costs.append(now - last)
        last = now
        if values is None:
            if misses == [0] and not screened:
                _REFUTED.refute(mutant, ran)
            continue
        if mutant.slip in PRECISION_SLIPS and not all(_closely(v, e) for v, e in zip(values, inputs)):
            continue
        if not judged:
            kept.append(mutant)
            continue
        beyond = mutant.slip in PRECISION_SLIPS and not all(within(v, e.expected, e.tol)
                                                             for v, e in zip(values, inputs))
        if not beyond and not any(distinct(v, e.expected, e.tol) for v, e in zip(values, inputs)):
            continue  # an equivalent mutant (one of precision differs by little, but beyond the tolerance)
        if not vanishing and not any(distinct(v, np.zeros_like(v), e.tol) for v, e in zip(values, inputs)):
            continue
        kept.append(mutant)
    progress["tried"] = len(mutants)
    return kept


def _hopeless(remaining: float, costs: list, left: list[Mutant], ran) -> float | None:
    """The pace of the mutants measured so far, where the mutants ``left`` (those still to measure, refuted ones
    aside) cannot all be measured at it within what remains of the deadline's budget (``remaining`` [s]); else None.
    The pace is the lower median of the times the mutants measured so far took (``costs``, at least
    ``PROJECTED_AFTER`` of them), and the mutants left cannot be measured where they would take more than
    ``PROJECTED_FACTOR`` times that remainder (``_projected``).  Judged after ``PROJECTED_AFTER`` mutants and again
    at each doubling of their number, so that the count of the mutants left is not paid for at every mutant.  The
    measuring is then given up as one whose time runs out: it would have named nothing, at the whole budget's cost.
    The deadline's clock is read once a mutant (``_evaluate``; a reading takes about 30 microseconds, which hundreds
    of mutants add up)."""
    count = len(costs)
    if count < PROJECTED_AFTER or count & (count - 1):
        return None
    return _projected(sorted(costs)[(count - 1) // 2], remaining, left, ran, measured=count)


def _projected(pace: float, remaining: float, left: list[Mutant], ran, measured: int) -> float | None:
    """``pace`` where the mutants ``left`` that are not refuted, each measured at ``pace`` [s], would take more than
    ``PROJECTED_FACTOR`` times the budget's ``remaining`` seconds; else None.  ``measured``: the mutants the pace was
    measured on here (none where it is an earlier value's of the same call, ``_Refuted.given_up``), for the trace."""
    left = sum(1 for mutant in left if not _REFUTED.refuted(mutant, ran))
    if pace * left <= PROJECTED_FACTOR * max(remaining, 0.0):
        return None
    trace.note("hopeless", measured=measured, left=left, each=round(pace, 4), remaining=round(remaining, 3))
    return pace


def _hashable(key: tuple) -> tuple | None:
    """``key``, or None where it cannot be hashed (arguments kept as they are, ``_kept_once``, that cannot be told
    apart by their pickled bytes): a key of what one grading keeps (``_Refuted``)."""
    try:
        hash(key)
    except TypeError:
        return None
    return key


def _mutated_values(package, mutant: Mutant, inputs: list[Evidence], calls: list, cheaper: tuple, originals: dict,
                    twins: tuple, screened: bool, misses: list, deadline: _Deadline, confirm: bool,
                    shared: Shared | None = None) -> list | None:
    """The values of the calls with the mutant's code in its function's place (see ``_evaluate``), or None
    (``misses`` gets the input at which it is not the student's); ``cheaper``: the inputs' ``(parts, rows)`` (see
    ``_staged``); a screened mutant that reproduces it is evaluated as it is, where ``confirm``, within
    ``deadline``'s budget of confirming; ``shared``: the passes of state the mutants' calls share
    (``passes.Shared``)."""
    from probes import kept_for_one_code

    holder = _live(package, mutant.module, mutant.path)
    originals.setdefault(id(holder), (holder, holder.__code__))
    try:
        for other, twin in twins:
            other.__code__ = twin
        holder.__code__ = (mutant.quick or mutant.code) if screened else mutant.code
        sharing = contextlib.nullcontext() if shared is None else shared.around(holder)
        with sharing, kept_for_one_code():  # one code on every input: what a probe makes once for it, it makes once
            values = _staged(package, inputs, calls, *cheaper, quick=screened, misses=misses)
        if values is not None and screened and confirm:  # the mutant's own value decides
            for other, _ in twins:
                other.__code__ = originals[id(other)][1]
            holder.__code__ = mutant.code
            sharing = contextlib.nullcontext() if shared is None else shared.around(holder)
            with sharing, kept_for_one_code(_confirmed_store(package, mutant)), deadline.confirming():
                values = _reproduced(package, inputs, calls, misses=misses)
    finally:
        for other, _ in twins:
            other.__code__ = originals[id(other)][1]
        holder.__code__ = originals[id(holder)][1]
    return values


#: what the probes computed once for a mutant's own code (``probes.kept_for_one_code``), by the mutant's code: a
#: screened mutant is evaluated as it is on each of an explanation's inputs, and again on a third input and in the
#: grading's later explanations, and its symbolic answer, simplified, is the same for all of them (problem 40's
#: takes seconds).  It depends on the reference's code alone, so it holds for every grading of the process; the
#: latest ``CONFIRMED_KEPT`` are kept
_CONFIRMED: collections.OrderedDict = collections.OrderedDict()
CONFIRMED_KEPT = 8


def _confirmed_store(package, mutant: Mutant) -> dict:
    key = (id(package), mutant.module, mutant.path, mutant.code)
    store = _CONFIRMED.pop(key, None)
    _CONFIRMED[key] = {} if store is None else store
    while len(_CONFIRMED) > CONFIRMED_KEPT:
        _CONFIRMED.popitem(last=False)
    return _CONFIRMED[key]


def _restore(originals: dict) -> None:
    for kept in originals.values():
        if len(kept) == 3:  # a binding of a constant's slip: ``(holder, attribute, value)``
            setattr(*kept)
        else:
            kept[0].__code__ = kept[1]


def _bind(bindings: tuple, originals: dict) -> None:
    """Sets the bindings of a constant's slip, each one's value before it kept in ``originals``."""
    for holder, attribute, value in bindings:
        originals.setdefault((id(holder), attribute), (holder, attribute, getattr(holder, attribute)))
        setattr(holder, attribute, value)


def _unbind(bindings: tuple, originals: dict) -> None:
    for holder, attribute, _ in bindings:
        setattr(holder, attribute, originals[(id(holder), attribute)][2])


def _staged(package, inputs: list[Evidence], calls: list, parts: list, rows: list, quick: bool = False,
            misses: list | None = None) -> list | None:
    """The mutated package's values of ``calls`` where they reproduce the student's values, or None, measured
    cheapest first: on the few rows of a batch (``rows``: ``evidence.rows_of``) of the inputs that declare them,
    then on the cheaper calls that hold the values (``parts``: ``evidence.part_of``), then on the calls themselves
    (``quick``, ``misses``: see ``_reproduced``)."""
    for index, row in enumerate(rows):
        if row is not None and _reproduced(package, [row[0]], [row[1]], quick) is None:
            if misses is not None:
                misses.append(index)
            return None
    if any(parts) and _reproduced(package, inputs, [part or call for part, call in zip(parts, calls)], quick,
                                  misses) is None:
        return None
    return _reproduced(package, inputs, calls, quick, misses)


def _reproduced(package, inputs: list[Evidence], calls: list, quick: bool = False,
                misses: list | None = None) -> list | None:
    """The mutated package's values of ``calls`` (``(probe, arguments)``: each input's call, or its declared part),
    or None at the first that does not reproduce the student's value (``quick``: see ``_call``; ``misses``, given,
    gets that input's index)."""
    values, replies = [], {}
    for index, (evidence, call) in enumerate(zip(inputs, calls)):
        value = _value(package, evidence, call, quick, replies)
        if value is None or not reproduces(evidence.got, value, evidence.tol):
            if misses is not None:
                misses.append(index)
            return None
        values.append(value)
    return values


def _value(package, evidence: Evidence, call: tuple, quick: bool = False, replies: dict | None = None):
    """The mutated package's value of ``call`` (``(probe, arguments)``: the comparison's call, or its declared
    part) at the comparison's path, in the shape of the student's value where it differs from it by axes of one
    entry only (the student's own call gives a column where the check compared a vector); None when the mutant
    raises or gives another shape (``quick``, ``replies``: see ``_call``)."""
    probe, args = call
    try:
        value = _call(package, probe, args, evidence.source.path, quick, replies)
    except (Exception, RecursionError):  # noqa: BLE001 - a mutant that raises reproduces nothing
        return None
    if value is not None and value.shape != evidence.got.shape \
            and tuple(n for n in value.shape if n != 1) == tuple(n for n in evidence.got.shape if n != 1):
        value = value.reshape(evidence.got.shape)  # a column for a vector, as the check read the student's
    if value is None or value.shape != evidence.got.shape:
        return None
    return value


#: the slips that write a matrix's transpose otherwise: ``v @ A`` is ``A.T @ v``, and a rotation read the other way
#: round (``A_DpDs`` for ``A_DsDp``) is its transpose; where a matrix transposed (``TRANSPOSED``) reproduces the
#: answer as well, they are readings of that transpose, told beside it as twins, not rivals of other families
TRANSPOSED_READINGS = frozenset({"factors", "frames_turned"})


def _readings(kept: list[Mutant]) -> set:
    """The ids of the mutants kept that read a transpose kept beside them otherwise (``TRANSPOSED_READINGS``)."""
    if not any(m.slip in TRANSPOSED for m in kept):
        return set()
    return {id(m) for m in kept if m.slip in TRANSPOSED_READINGS}


def _families(kept: list[Mutant], readings: set) -> set:
    """The families of the mutants kept, the readings of a transpose (``_readings``) aside: those they explain with."""
    return {DIAGNOSES[m.name].family for m in kept if id(m) not in readings}


def _hypotheses(kept: list[Mutant], evidences: list[Evidence] = (), untested: bool = False,
                unreached=()) -> list[Hypothesis]:
    readings = _readings(kept)
    families = _families(kept, readings)
    if not kept or len(families) > MAX_FAMILIES:
        return []
    constant = families <= _TERMS and _constant_difference(evidences)
    found = {}
    for mutant in kept:
        name, detail = mutant.name, mutant.detail
        if constant and mutant.slip not in _ENTRIES | _ADDED:  # a term that is the same on every input: an offset
            name, detail = "offset", f"{detail}, and it is the same on every input: your values are all off by it"
        key = f"mutant:{name}:{detail}"
        found.setdefault(key, Hypothesis(key, name, COST, detail, twin=id(mutant) in readings))
        if constant and mutant.slip in _ENTRIES | _ADDED:  # an entry left out (or the identity's 1 added to every
            # entry), and every value off by the same amount
            found.setdefault(f"{key}=offset", Hypothesis(f"{key}=offset", "offset", COST, (
                f"{detail}; it is the same on every input: your values are all off by it"), twin=True))
        elif (mutant.given or mutant.bindings) and mutant.slip in _ENTRIES:  # a number of data the template
            # gives (a list that a given function sets, a module's constant): where a value starts or sits
            data = f"the constant `{mutant.function}`" if mutant.bindings else f"the data `{mutant.function}` sets"
            found.setdefault(f"{key}=offset", Hypothesis(f"{key}=offset", "offset", COST, (
                f"{detail}; it is a number of {data}, so it may be where a value starts or sits: an offset"),
                twin=True))
        if mutant.slip == "rotation" and evidences and evidences[0].expected.ndim == 2:
            # a rotation left out of a product whose value is a matrix (one of a chain of rotations, ``A_IC`` of
            # ``skew(omega) @ A_IC``): no vector left in another frame's coordinates, as truly a factor left out
            found.setdefault(f"{key}=factor", Hypothesis(f"{key}=factor", "missing_matrix_factor", COST, (
                f"a matrix factor of a product in `{mutant.function}` is left out (a rotation, of a value that is "
                "a matrix)"), twin=True))
        if mutant.function == "__init__" and DIAGNOSES[name].family == "ignored_argument" and evidences \
                and evidences[0].source is not None and stepped(declaration(evidences[0].source.probe)):
            # an object that a run steps from its start, built ignoring a value it is given: the run starts from
            # another state
            found.setdefault(f"{key}=start", Hypothesis(f"{key}=start", "initial_state", COST, (
                f"{detail}: the object the run steps starts from another state than the one given"), twin=True))
        unused = _unreached(mutant, evidences[0].source.probe, unreached) if unreached else frozenset()
        for twin in equivalents(found[key], KINDS.get(mutant.slip, ())) + rivals(mutant, key, untested, unused):
            found.setdefault(twin.key, twin)  # one value by mathematics, or one edit read two ways: both told
    return list(found.values())


#: the slips whose edit is as truly a slip of another family: a product with a quantity for a division by it uses
#: the quantity where its reciprocal belongs (a number's factor is a scale: ``x * 2`` for ``x / 2``); two entries
#: or arguments exchanged that are one expression of a quantity and of its rate (``R @ qd``, ``R @ qdd``) read each
#: where the other belongs; the names a state is unpacked into, bound in another order, read each from another's row;
#: an inverse left out of a product is a matrix factor left out; a term taken twice is that term added once more
RIVALS = {
    "term_doubled": ("extra_term", "`{f}` adds one term of a sum once more (an update written twice)"),
    "point_doubled": ("offset", "`{f}` places a point elsewhere: a number of its position is doubled"),
    "point_halved": ("offset", "`{f}` places a point elsewhere: a number of its position is halved"),
    "multiplies_by": ("reciprocal_argument", "`{f}` divides by a quantity where it should multiply by it (the "
                                             "quantity used as its reciprocal)"),
    "divides_by": ("reciprocal_argument", "`{f}` multiplies by a quantity where it should divide by it (the "
                                          "quantity used as its reciprocal)"),
    "entries_rates": ("state_row", "`{f}` reads a quantity where its rate belongs, and the rate where the quantity "
                                   "belongs"),
    "arguments_rates": ("state_row", "`{f}` reads a quantity where its rate belongs, and the rate where the "
                                     "quantity belongs"),
    "names_rates": ("state_row", "`{f}` reads a quantity where its rate belongs, and the rate where the quantity "
                                 "belongs"),
    "parameters_rates": ("state_row", "`{f}` reads a quantity where its rate belongs, and the rate where the "
                                      "quantity belongs"),
    "inverse_factor": ("missing_matrix_factor", "a matrix factor of a product in `{f}` is left out"),
    "unsolved_read": ("missing_matrix_factor", "a matrix factor of a product in `{f}` is left out"),
    "unpacked": ("state_row", "`{f}` reads each coordinate it unpacks from another's row of the state"),
    "angle_sum": ("extra_term", "`{f}` reads a sum of angles where one of its terms belongs (a term added)"),
    "angle_part": ("missing_term", "`{f}` reads one term of a sum of angles where the sum belongs (a term left "
                                   "out)"),
}


#: the slips that read one value where another belongs (a quantity for its rate, a frame's coordinates for
#: another's, one argument, angle or coordinate for another): where the edit leaves a name the function binds
#: unread, the value it computed there is read nowhere, as truly a value left unused
UNUSED_READS = frozenset({"rates", "frames", "parameter_read", "angle", "coordinate"})


def rivals(mutant: Mutant, key: str, untested: bool = False, unreached: frozenset = frozenset()) -> list[Hypothesis]:
    """The other readings of one mutant's edit, told beside its own name as a twin is (never where they would take
    the families told past two): a quantity used as its reciprocal (``RIVALS``); where the test of an ignored
    argument could change none of the call's arguments (``untested``: a probe of an event function, say), an
    argument with a default (a constant of the problem that a call leaves as it is) that the edit leaves unused
    (``anchor - I_r_E`` as ``I_r_E``: the anchor ignored); and an argument of the call that the edit leaves unused
    where that test ran out of its budget before it came to it (``unreached``: the names of the compared call's
    parameters it did not change; ``m = L W H`` for ``m = L W H rho``: a factor left out, and the density
    ignored).  Where that test changed an argument it is the measure of an argument ignored, heard as a tier of its
    own: an argument it found followed is no twin.  A read of one value for another (``UNUSED_READS``) that leaves
    a name the function binds unread leaves the value it computed there unused (``return q, qd, qd`` for ``return
    q, qd, qdd``).  A slip of a module's constant that is a start (``_START``: ``Q0``, ``START_ANGLES``: two of its
    entries exchanged, one typed in degrees) starts the run from another state as truly: a wrong initial state, told
    beside it."""
    found = []
    if mutant.slip in RIVALS:
        name, detail = RIVALS[mutant.slip]
        found.append(Hypothesis(f"{key}={name}", name, COST, detail.format(f=mutant.function), twin=True))
    if mutant.bindings and _START.match(mutant.function) and DIAGNOSES[mutant.name].family != "initial_state":
        found.append(Hypothesis(f"{key}=start", "initial_state", COST, f"the start `{mutant.function}` is typed "
                                "otherwise: the run starts from another state", twin=True))
    for name in mutant.unread if mutant.slip in UNUSED_READS else ():
        found.append(Hypothesis(f"{key}=unread:{name}", "value_unused", COST, (
            f"`{mutant.function}` reads another value where `{name}` belongs: the value it computes as `{name}` is "
            "never used"), twin=True))
    for parameter in mutant.unused:
        if (untested and parameter in mutant.defaulted) or parameter in unreached:
            found.append(Hypothesis(f"{key}=unused:{parameter}", "ignored_argument", COST,
                                    f"`{mutant.function}` leaves its argument `{parameter}` unused", twin=True))
    return found


def _unreached(mutant: Mutant, probe, positions) -> frozenset:
    """The names of the parameters at ``positions`` of the compared call (``probe``'s arguments after the package),
    where the mutant is of the function of the probe's name (else none: the positions are of another function's
    call)."""
    import inspect

    from probes import ProbeLookupError, lookup

    try:
        function = lookup(probe) if isinstance(probe, str) else probe
        parameters = list(inspect.signature(function).parameters)[1:]
    except (ProbeLookupError, TypeError, ValueError):
        return frozenset()
    if getattr(function, "__name__", None) != mutant.function:
        return frozenset()
    return frozenset(parameters[i] for i in positions if i < len(parameters))


#: what the expression of a slip is, for the grammar's equivalences (``grammar.EQUIVALENCES``)
KINDS = {"skew": ("skew",), "cross": ("cross",), "skew_factors": ("skew",), "turned_back": ("rotation",)}


#: the families of a term left out or added: where the term is the same on every input, the slip is an offset
_TERMS = {"missing_term", "extra_term"}
#: the slips of an entry of a matrix or vector left out: where it is the same on every input, the slip is told as
#: an entry left out and, beside it, as an offset (an entry of a Jacobian is no point moved, a height may be); so
#: is one in the code a problem's module gives whole (``given``), where a list's numbers are data (a gait's mean,
#: a hip's height): a number of it written 0 is as truly a value off by it as a term left out
_ENTRIES = {"zeroed", "constant_zeroed"}
#: the slips that add a term of their own kind, told as themselves and, where the term is the same on every input,
#: as an offset as well: the identity written 1 adds 1 to every entry (a term added, and the same one on every input)
_ADDED = {"identity"}


def _constant_difference(evidences: list[Evidence]) -> bool:
    """True when the student's values differ from the expected ones by the same amount on every input (at least
    two, whose expected values differ): what a constant term left out or added gives."""
    if len(evidences) < 2:
        return False
    first = evidences[0]
    difference = first.got - first.expected
    for other in evidences[1:]:
        if other.got.shape != first.got.shape or not distinct(other.expected, first.expected, first.tol):
            return False
        if not within(other.got - other.expected, difference, first.tol):
            return False
    return True


def _tried(evidences: list[Evidence]) -> bool:
    """Whether the formula tier tries its slips: on two inputs, or on the one a value that does not change with
    the call's arguments has (``Evidence.alone``: one input is all there is)."""
    return bool(evidences) and (len(evidences) >= 2 or evidences[0].alone) \
        and all(e.source is not None and e.got is not None for e in evidences)


def left_to_live(scene, evidences: list[Evidence]) -> bool:
    """True in the student kit where the live grading would try the mutants of a problem of the course (the kit
    holds no reference code)."""
    if getattr(scene.ctx.oracle, "mode", "") != "kit" or not _tried(evidences):
        return False
    import importlib.util

    problem = _problem(getattr(scene.ctx, "check_id", ""), evidences[0].source.probe)
    return problem is not None and importlib.util.find_spec(f"checks.problem_{problem:02d}") is not None


def mutant_slips(scene, evidences: list[Evidence], another=None, told=None, untested=False,
                 unreached=()) -> list[Hypothesis]:
    """The slips of the reference's own code that reproduce the student's value on the input shown and on the
    second one (``evidences``: two, each with its reference call ``source``), and on a third one where
    ``another()`` gives it (an input the engine draws, the student's value there within the scene's budget): two
    inputs a shrunk failure shows may be simple enough for a slip to coincide with another.  None in the kit.
    ``told``: the families an earlier tier already explained the answer with (None: none did); the tier then
    tries rivals within a budget of its own, those of other families first (``late``).  ``untested``: the test of
    an ignored argument could change none of the call's arguments, and a parameter with a default that a slip
    leaves unused is told beside it (``rivals``); ``unreached``: the positions of the call's arguments that the
    test ran out of its budget before changing, an argument of which a slip leaves unused told beside it.  Where the
    student's own call stands in for the probe the expected value came from (``own_calls``), its code is mutated
    first, and the stand-in's where that reproduces nothing."""
    if getattr(scene.ctx.oracle, "mode", "") != "live":
        return []
    owned = own_calls(evidences)
    if owned is evidences:
        return _slips_on(scene, evidences, another, told, untested, unreached)
    drawn = another
    found = _slips_on(scene, owned, None if drawn is None else lambda: next(
        iter(own_calls([e for e in [drawn()] if e is not None])), None), told, untested, unreached)
    if not found:  # no slip of the code the student's own call runs: the stand-in's code, as where it holds none
        trace.note("own_call", fallback=True)
        found = _slips_on(scene, evidences, drawn, told, untested, unreached)
    return found


def _slips_on(scene, evidences: list[Evidence], another, told, untested, unreached) -> list[Hypothesis]:
    """``mutant_slips`` on these evidences (the student's own calls in place of stand-ins, or as they are)."""
    if not _tried(evidences):
        return _imprecise(scene, evidences, another)
    if any(_rebound_alike(e) for e in evidences[1:]):  # right at the constants drawn: a constant typed short?
        found = _imprecise(scene, evidences[:1], None) or _drawn_constants(scene, evidences)
        if found:
            return found
    problem = _problem(getattr(scene.ctx, "check_id", ""), evidences[0].source.probe)
    if problem is None:
        return []
    inputs = list(evidences)
    try:
        key = _measure_key(problem, evidences, told)
        kept = _MEASURED.get(scene.ctx, key)
        if kept is None:
            outcome = {}
            with _REFUTED.grading(scene.ctx):
                kept = _kept(problem, evidences, told=told, outcome=outcome)
            if not outcome.get("timeout"):
                _MEASURED.put(scene.ctx, key, kept)
        else:
            trace.note("measured", count=len(kept))
        kept = None if kept is None else [m for m in kept if _precise(m, inputs)]
        trace.note("mutants", problem=problem, kept=None if kept is None else sorted({m.name for m in kept}))
        if kept and another is not None:
            third = _another(another)
            if third is not None:
                kept = _kept(problem, [third], kept)
                inputs.append(third)
                trace.note("third", kept=None if kept is None else sorted({m.name for m in kept}))
    except GraderFault:
        return []
    if told is not None and kept:
        _contest(kept, told)
    return _hypotheses(kept or [], inputs, untested, unreached)


class Contested(Exception):
    """An earlier tier's explanation that the formula tier contests: slips of the reference's code of more
    families than can be told (``MAX_FAMILIES``), some of them not the earlier tier's, reproduce the answer as
    well, so the earlier finding is one reading among too many (a value with its sign turned, which a term
    exchanged, a factor scaled and an entry read from another row each give as well).  No cost outranks a rival
    that reproduces the answer on the same inputs: nothing is told."""

    def __init__(self, families):
        super().__init__(", ".join(families))
        self.families = tuple(families)


def _contest(kept: list, told) -> None:
    """Raise ``Contested`` where the formula tier heard late (``told``: the families an earlier tier explained the
    answer with) kept slips of more than ``MAX_FAMILIES`` families, one of them at least not told."""
    families = _families(kept, _readings(kept))
    if len(families) > MAX_FAMILIES and families - set(told):
        trace.note("contested", told=sorted(told), families=sorted(families))
        raise Contested(sorted(families))


def own_calls(evidences: list[Evidence]) -> list[Evidence]:
    """The evidences, each whose expected value came from a stand-in of the reference's (a probe for the reference
    alone, ``reference_only``: problem 7's ``expressions`` evaluates the package's numeric rotations where the
    student's ``symbolic`` evaluates their derivation; or another probe, such as the numeric twin of a symbolic
    answer, problem 16's ``body`` beside its ``symbolic``) with the student's own call in its place: the mutants of the
    reference are to run the code the student's call runs, not the stand-in's.  Only where the reference's value of
    the student's call is the expected value on every such input (within the comparison's tolerance, in the
    stand-in's shape: a column where it gives a vector); else the evidences as they are.  The reference's own code
    runs these calls, so what a probe computes once (a symbolic derivation simplified) is kept for later ones."""
    stand_ins = [e for e in evidences if _stands_in(e)]
    if not stand_ins:
        return evidences
    replaced, replies = {}, {}  # one call of the reference for the values of one call of the student's
    with _LOCK, warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        _, package = _package()
        for e in stand_ins:
            own = Source(e.student.probe, tuple(e.student.args), tuple(e.student.path))
            try:
                value = _call(package, own.probe, _kept_once(own.args), own.path, replies=replies, remember=True)
            except Exception:  # noqa: BLE001 - a call the reference cannot make has no code to mutate
                value = None
            if value is None or value.size != e.expected.size \
                    or not within(value.reshape(e.expected.shape), e.expected, e.tol):
                trace.note("own_call", probe=own.probe, holds=False)
                return evidences
            replaced[id(e)] = dataclasses.replace(e, source=own)
    trace.note("own_call", probe=stand_ins[0].student.probe, holds=True)
    return [replaced.get(id(e), e) for e in evidences]


def _stands_in(evidence: Evidence) -> bool:
    """The evidence's expected value came from another probe than the student's (a probe for the reference alone, or
    the reference's numeric twin of a symbolic answer), and the student's is not for the reference alone."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or evidence.got is None or evidence.expected is None \
            or source.probe == student.probe or not isinstance(source.probe, str) or not isinstance(student.probe, str):
        return False
    try:
        return not getattr(_probe(student.probe), "reference_only", False)
    except (ImportError, AttributeError):
        return False


class _Measured:
    """The mutants kept on a comparison's inputs (``_kept``), by what decides them, for the grading in which they
    were measured (its context: one submission's problem; a batch's oracle serves every submission of a worker): a
    run's failure that several checks explain (a right-hand side behind a run's state and its event) asks the
    formula tier the same question on the same inputs, and the reference's code mutated gives the same answer to
    it.  Measures that ran out of their time are not kept (the next may finish); one grading's measures are never
    another's (the cost of one grading does not depend on an earlier one), and only the latest grading's are
    kept."""

    def __init__(self):
        self._owner = None  # the context of the grading the measures belong to
        self._kept: dict = {}

    def get(self, owner, key):
        if key is None or owner is None or self._owner is not owner:
            return None
        kept = self._kept.get(key)
        return None if kept is None else list(kept)

    def put(self, owner, key, kept) -> None:
        if key is None or kept is None or owner is None:
            return
        if self._owner is not owner:
            self._owner, self._kept = owner, {}
        self._kept[key] = tuple(kept)


_MEASURED = _Measured()


class _Refuted:
    """The mutants that an explanation of the grading has shown are not the student's code: on the first input of
    a comparison, the mutated reference's value of the student's own call is not the student's value (or the mutant
    raised where the student's code gave one).  A slip of the student's that a mutant is gives the student's value
    on every call, so a mutant refuted once is not measured again in the grading's later explanations (problem 37's
    checks of ``M``, ``f``, ``g`` ask the same mutants of the same functions on three calls).  It is left out only
    where the call that refuted it ran no code of the reference that the later call does not run (``ran``): a second
    slip in a function that only the earlier call ran would have refuted the first slip's mutant there.  Only a
    mutant measured as it is refutes (not one screened by ``_twins``), and one grading's refutations are never
    another's (``grading``: the context of the grading that the explanations belong to, one submission's problem;
    a batch's oracle serves every submission of a worker).  Each thread keeps its own: a process that grades in
    several threads never hears one thread's refutations in another's grading.

    It keeps too the calls whose measuring was given up as one that cannot end within its budget (``_hopeless``),
    with the pace their mutants were measured at: the check's other compared values of the same call (problem 12's
    wheel: the body's point and the contact's, from one run of 3001 steps) ask the same mutants of the same call at
    the same cost, and are given up at once (``given_up``), unless fewer of them are left to measure.  And the codes
    each call runs (``traced``), which those values would trace again."""

    def __init__(self):
        # ``owner``, ``by`` (mutant -> the codes of the calls that refuted it), ``on``, ``paces`` (call -> pace),
        # ``traces`` (call -> the codes it runs)
        self._local = threading.local()

    @contextlib.contextmanager
    def grading(self, owner):
        local = self._local
        if owner is not getattr(local, "owner", None):
            local.owner, local.by, local.paces, local.traces = owner, {}, {}, {}
        local.on = owner is not None
        try:
            yield
        finally:
            local.on = False

    def _on(self, ran) -> bool:
        return ran is not None and getattr(self._local, "on", False)

    def refute(self, mutant: Mutant, ran: frozenset | None) -> None:
        if self._on(ran):
            self._local.by.setdefault(_identity(mutant), []).append(ran)

    def refuted(self, mutant: Mutant, ran: frozenset | None) -> bool:
        return self._on(ran) and any(earlier <= ran for earlier in self._local.by.get(_identity(mutant), ()))

    def give_up(self, call: tuple | None, ran: frozenset | None, pace: float) -> None:
        if call is not None and self._on(ran):
            self._local.paces[call] = pace

    def given_up(self, call: tuple | None, ran: frozenset | None) -> float | None:
        return self._local.paces.get(call) if call is not None and self._on(ran) else None

    def traced(self, key: tuple | None, trace) -> frozenset:
        """The codes a call runs (``_traced``), traced once for the grading where the call has a ``key`` (with its
        arguments kept, ``_kept_once``; ``_hashable``), else each time (``trace()``)."""
        local = self._local
        if key is None or not getattr(local, "on", False):
            return trace()
        if key not in local.traces:
            local.traces[key] = trace()
        return local.traces[key]


_REFUTED = _Refuted()


def _identity(mutant: Mutant) -> tuple:
    """What makes a mutant the same slip in another explanation: its function, slip and code (code objects compare
    by their contents), or the values its bindings set."""
    return (mutant.module, mutant.path, mutant.slip, mutant.given, mutant.code,
            tuple((id(holder), attribute, _fingerprint(value)) for holder, attribute, value in mutant.bindings))


def _fingerprint(value):
    try:
        return pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 - a value that cannot be pickled is told by its identity
        return id(value)


def _measure_key(problem: int, evidences: list[Evidence], told) -> tuple | None:
    """What the mutants kept on ``evidences`` depend on: the reference, the problem, the families told and each
    input's call, the student's and the expected value and the tolerance; None where an input's arguments cannot be
    pickled."""
    key = [_package()[0], problem, None if told is None else frozenset(told)]
    for e in evidences:
        source = e.source
        try:
            args = pickle.dumps(tuple(source.args), protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # noqa: BLE001 - arguments that cannot be pickled are measured each time
            return None
        key.append((source.probe, args, tuple(source.path), e.tol, _bytes_of(e.got), _bytes_of(e.expected)))
    try:
        hash(tuple(key))
    except TypeError:
        return None
    return tuple(key)


def _bytes_of(value):
    if value is None:
        return None
    value = np.asarray(value)
    return value.dtype.str, value.shape, value.tobytes()


def _imprecise(scene, evidences: list[Evidence], another) -> list[Hypothesis]:
    """The slips of precision (``PRECISION_SLIPS``) that reproduce the student's value on the one input a
    comparison has, where that value is in the band of precision (``PRECISION_BAND``): a constant typed short, or a
    computation in float32, reproduced to within ``PRECISION_SHARE`` of the difference, says what no other slip of
    the code does so closely; a third input, where the engine can draw one, must show it too."""
    first = evidences[0] if evidences else None
    if first is None or first.source is None or first.got is None or not _in_band(first):
        return []
    problem = _problem(getattr(scene.ctx, "check_id", ""), first.source.probe)
    if problem is None:
        return []
    inputs = [first]
    try:
        kept = _kept(problem, inputs, only=PRECISION_SLIPS)
        kept = [m for m in kept or () if _precise(m, inputs)]
        trace.note("imprecise", problem=problem, kept=sorted({m.name for m in kept}))
        if kept and another is not None:
            third = _another(another)
            if third is not None:
                inputs.append(third)
                kept = [m for m in _kept(problem, [third], kept) or () if _precise(m, inputs)]
    except GraderFault:
        return []
    return _hypotheses(kept, inputs)


def _in_band(evidence: Evidence, differs: bool = True) -> bool:
    """The student's value differs from the expected one by no more than a slip of precision makes
    (``PRECISION_BAND`` of the expected value's size), and differs (``differs``; else it may be the expected one)."""
    got, expected = evidence.got, evidence.expected
    if got is None or expected is None or got.shape != expected.shape or not np.all(np.isfinite(got)):
        return False
    scale = float(np.max(np.abs(expected))) if expected.size else 0.0
    difference = float(np.max(np.abs(got - expected))) if got.size else 0.0
    if not differs and difference == 0:
        return True
    return scale > 0 and 0 < difference <= PRECISION_BAND * scale


def _precise(mutant: Mutant, inputs: list[Evidence]) -> bool:
    """A mutant of another slip than precision, or one of precision where the student's value is in the band of
    precision on the input shown and on every other input either in that band or the expected value itself (a value
    of the same call that the slip leaves as it is: a state's positions where the velocities were rounded), as the
    mutant's own is there (``_evaluate`` holds it to ``PRECISION_SHARE`` of the difference as well)."""
    return mutant.slip not in PRECISION_SLIPS or (
        bool(inputs) and _in_band(inputs[0]) and all(_in_band(e, differs=False) for e in inputs[1:]))


def _drawn_constants(scene, evidences: list[Evidence]) -> list[Hypothesis]:
    """Where the student's value is the expected one at the constants drawn anew (``_rebound_alike``) and not on
    the input shown, what differs is in the values of those constants, which the drawn input binds on both sides:
    their slips of typing (``constant_mutants``: a number of one typed otherwise, converted the wrong way, an entry
    written 0), judged on the input shown alone."""
    first = evidences[0]
    names = frozenset((module, name) for e in evidences[1:] if _rebound_alike(e)
                      for module, name, _ in e.source.args[1])
    problem = _problem(getattr(scene.ctx, "check_id", ""), first.source.probe)
    if problem is None or not names:
        return []
    try:
        kept = [m for m in _kept(problem, [first], constants=names) or () if _precise(m, [first])]
    except GraderFault:
        return []
    trace.note("drawn_constants", constants=sorted(name for _, name in names),
               kept=sorted({m.name for m in kept or ()}))
    return _hypotheses(kept or [], [first])


def _rebound_alike(evidence: Evidence) -> bool:
    """The student's value is the expected one on an input at the problem's constants drawn anew (``rebound``): a
    constant of theirs typed short is bound to the drawn value there, so the slips of precision are judged on the
    input shown alone (``_imprecise``), as where no second input could be drawn."""
    from .rebound import REBOUND

    source = evidence.source
    got, expected = evidence.got, evidence.expected
    return source is not None and source.probe == REBOUND and got is not None and got.shape == expected.shape \
        and not distinct(got, expected, evidence.tol)


def _closely(value: np.ndarray, evidence: Evidence) -> bool:
    """``value`` leaves at most ``PRECISION_SHARE`` of the difference between the student's value and the expected
    one (a slip of precision reproduces the student's value, not merely a value inside the tolerance of it); on an
    input where the student's value is the expected one within the tolerance (another part of a run, whose last
    digits its other operations round otherwise), there is no difference to reproduce."""
    if within(evidence.got, evidence.expected, evidence.tol):
        return True
    difference = float(np.max(np.abs(evidence.got - evidence.expected))) if evidence.got.size else 0.0
    return float(np.max(np.abs(evidence.got - value))) <= PRECISION_SHARE * difference


def _another(another) -> Evidence | None:
    from .scene import Budget

    try:
        third = another()
    except (Budget, GraderFault):
        return None
    return third if third is not None and third.source is not None and third.got is not None else None


def late(mutants: list[Mutant], told) -> tuple[list[Mutant], int]:
    """The mutants heard after an earlier tier explained the answer with the families ``told``, in the order they
    are tried, and how many of them come first as rivals of other families: those of other families, then those
    of the families told (a rival of a family told adds a name, not an explanation: it is tried as time allows),
    the first ``LATE_MUTANTS`` of them."""
    others = [m for m in mutants if DIAGNOSES[m.name].family not in told]
    same = [m for m in mutants if DIAGNOSES[m.name].family in told]
    order = (others + same)[:LATE_MUTANTS]
    return order, min(len(others), len(order))


def _given(package, root: Path, problem: int, evidences: list[Evidence], originals: dict, judged: bool,
           progress: dict, twins: tuple = (), library: bool = False) -> tuple:
    """``(kept, mutants)`` of the slips of the functions that the problem's own module gives whole (``given``),
    tried where no slip of a solution region reproduced the student's value: the student's file holds them too,
    and a slip there is less likely than in the code the student wrote, so they come after all of it, within a
    budget of their own (``GIVEN_TIME_BUDGET``; kept None when it runs out).  ``twins``: those the regions' slips
    were screened with (``_twins``, where they hold), with which the call is traced and each of these mutants
    screened too (a slip of a given function that a simplifying function of a region reads, problem 40's
    ``particle_positions``, would else pay the simplification for every mutant).  ``library``: the functions the
    library's modules give whole instead (a constructor, a helper), tried last of all, after the module
    constants: a student edits the code the template gives in a library module less often still, and a default
    taken in a constructor gives what a call that leaves the argument out gives."""
    started = time.thread_time()
    first = evidences[0]
    with _Deadline(GIVEN_TIME_BUDGET) as deadline:
        mutants = mutants_of(package, root, problem, first.source.probe, first.source.args, twins, given=True,
                             deadline=deadline, library=library)
        trace.note("library" if library else "given", count=None if mutants is None else len(mutants),
                   functions=sorted({m.function for m in mutants or ()}),
                   seconds=round(time.thread_time() - started, 3), making=round(deadline.spent()[1], 3))
        ran = _traced(package, root, first.source.probe, first.source.args, twins)
        kept = _evaluate(package, mutants, evidences, deadline, originals, judged=judged,
                         progress=progress, twins=twins, ran=ran) if mutants else []
    return kept, mutants


#: the families whose edits may each have the other's effect: two operands exchanged that enter as a difference
#: (``qd - qd_des`` for ``qd_des - qd``, or the arguments of a call that takes that difference) negate it, a sign
#: slip; the one reproduces the student's value wherever the other does, and the value cannot tell them apart
OPPOSITES = {"order": "sign", "sign": "order"}


def _opposite(kept: list[Mutant]) -> str | None:
    """The family of ``OPPOSITES`` that the mutants kept are not of, where they are all of the other; else None."""
    families = {DIAGNOSES[m.name].family for m in kept}
    return OPPOSITES.get(next(iter(families))) if len(families) == 1 else None


#: the slips that exchange two operands of one expression (two arguments of a call, two names, two parameters, two
#: groups of arguments, two entries, two components, two factors): their effect may be a sign (``OPPOSITES``)
OPERANDS_EXCHANGED = frozenset({"arguments", "names", "parameters", "blocks", "entries", "components", "factors",
                                "skew_factors"})


#: the slips that reorder two factors of a product: their effect may be a term that vanishes (``I @ skew(w) @ w``
#: for ``skew(w) @ I @ w``)
FACTORS_REORDERED = frozenset({"factors", "neighbours"})
#: the slips that transpose a matrix: a rotation transposed turns the other way, its angle's sign as its effect
#: (``A_DpDs.T`` for ``A_DpDs``)
TRANSPOSED = frozenset({"transpose", "turned_back"})
#: ``{family a check tells from what the value shows: (the rivals' families, the slips whose effect it may be,
#: whether a mutant whose value vanishes is one: the effect of a term that is not there)}``
EFFECT_RIVALS = {"sign": (("order", "transpose"), OPERANDS_EXCHANGED | TRANSPOSED, False),
                 "missing_term": (("order",), FACTORS_REORDERED, True),
                 "initial_state": (("order",), OPERANDS_EXCHANGED, False)}


def opposite_slips(scene, evidences: list[Evidence], family: str) -> list[Hypothesis]:
    """The slips whose effect ``family`` may be (``EFFECT_RIVALS``) that reproduce the student's value on ``evidences``,
    for a check that told ``family`` from what the value shows (``diagnosis.rival``): where the check named a sign, the
    exchanges of two operands (``OPERANDS_EXCHANGED``) and a matrix transposed (``TRANSPOSED``: a rotation turned the
    other way); where it named a term that is not there, two factors of a product reordered (``FACTORS_REORDERED``: the
    term written, in an order in which it vanishes); where it named a wrong start, the exchanges of two operands (a
    signature's start values in another order).  On the input shown alone where the engine has no second one (a call of
    no arguments): a rival adds a name to the check's, which the value proves already, and explains nothing by itself.
    None in the kit."""
    opposite, only, vanishing = EFFECT_RIVALS.get(family, ((), frozenset(), False))
    first = evidences[0] if evidences else None
    if getattr(scene.ctx.oracle, "mode", "") != "live" or not opposite or first is None \
            or first.source is None or first.got is None or any(e.source is None or e.got is None for e in evidences):
        return []
    problem = _problem(getattr(scene.ctx, "check_id", ""), first.source.probe)
    if problem is None:
        return []
    try:
        kept = _kept(problem, list(evidences), only=only, vanishing=vanishing)
    except GraderFault:
        return []
    trace.note("opposite", families=list(opposite), kept=None if kept is None else sorted({m.name for m in kept}))
    exchanged = [Hypothesis(f"mutant:factor_order:{m.detail}", "factor_order", COST, SKEW_EXCHANGED.format(
        f=m.function)) for m in kept or [] if m.slip == "skew_factors"]
    others = [m for m in kept or [] if m.slip != "skew_factors"]  # read as the exchange alone, not as its twins
    return [h for h in _hypotheses(others, list(evidences)) + exchanged if DIAGNOSES[h.name].family in opposite]


#: a product with a skew matrix taken from the other side, read as the exchange it is where a check told its sign
#: (``opposite_slips``): the formula tier tells it a sign (a skew matrix negated, or transposed), as the value says
SKEW_EXCHANGED = ("the two factors of a cross product in `{f}` are taken in the other order (``r x w`` for ``w x r``, "
                  "``r @ skew(w)`` for ``skew(w) @ r``), which negates it")


def _heard_in_given(package, root: Path, problem: int, evidences: list[Evidence], originals: dict, judged: bool,
                    twins: tuple, family: str) -> list[Mutant]:
    """The slips of ``family`` (``OPPOSITES``) in the code the problem's module gives whole (``_given``) that
    reproduce the student's value where the slips of a solution region that did are all of the opposite family: a
    region's call that passes two arguments exchanged to a given function that takes their difference is as truly
    that difference's sign, which lives in the given code, so the region's finding would else be told alone.  Within
    ``GIVEN_TIME_BUDGET``: where it runs out, none (the region's finding stands)."""
    try:
        heard, _ = _given(package, root, problem, evidences, originals, judged, {}, twins)
    except _Timeout:
        heard = None
    heard = [m for m in heard or () if DIAGNOSES[m.name].family == family]
    trace.note("opposite", family=family, kept=sorted({m.name for m in heard}))
    return heard


# ---------------------------------------------------------------------------------------------- the constants

#: the CPU time of the measuring of the slips of module constants (``_constant_stage``), tried where no slip of the
#: code reproduced the student's value [s] (their making is bounded by ``MAKING_TIME_BUDGET``)
CONSTANT_TIME_BUDGET = 1.0
#: the slips of module constants one explanation tries at most (past it, the first so many): problem 32's arm reads
#: 331, the course's g among the last
CONSTANT_MUTANTS = 400
#: a number of a constant typed otherwise: as a factor of it (``None``: its square root, or its square)
_NUMBER_SLIPS = (("constant_sign", -1.0), ("constant_doubled", 2.0), ("constant_halved", 0.5),
                 ("constant_degrees", 180.0 / np.pi), ("constant_radians", np.pi / 180.0),
                 ("constant_tenfold", 10.0), ("constant_tenth", 0.1), ("constant_thousandfold", 1000.0),
                 ("constant_thousandth", 1e-3), ("constant_hundredfold", 100.0), ("constant_hundredth", 0.01),
                 ("constant_root", None), ("constant_square", None))
#: the number slips that change a constant's size (a factor 2, 10, 100 or 1000 or its reciprocal, a square root, a
#: square)
_RESIZINGS = frozenset({"constant_doubled", "constant_halved", "constant_tenfold", "constant_tenth",
                        "constant_hundredfold", "constant_hundredth", "constant_thousandfold", "constant_thousandth",
                        "constant_root", "constant_square"})
#: a constant that is an integration's step or its count of steps, by the course's names (``DT``, ``H``, ``N_STEPS``,
#: ``STEPS``, ``WHEEL_DT``): scaled, the run takes steps of another size
_STEP_CONSTANT = re.compile(r"^(?:\w+_)?(?:DT|H|STEP|STEPS|N_STEPS|STEP_SIZE|TIME_STEP)$")
#: the number slips an integer is not typed with (it has no decimal point to misplace by more than a digit, and no
#: unit): a count of steps a hundred or a thousand times itself, or squared, would also cost as many steps again
_UNCOUNTED = frozenset({"constant_hundredfold", "constant_thousandfold", "constant_square"})
#: the entries of a list or tuple of a constant, at most, whose pairs are exchanged
_TABLE = 6
#: a constant that is a run's start, by the course's names (``A_IC0``, ``ANGLES0``, ``Q0``, ``X_START``,
#: ``START_ANGLES``): a slip of it makes the run start elsewhere
_START = re.compile(r"^(?:[A-Z_]*[A-Z_]0|\w*START\w*|\w*INITIAL\w*)$")
#: the slips of a start that write it whole as a plain value (``_start_slips``)
_WHOLE_STARTS = frozenset({"start_zeros", "start_identity"})


@lru_cache(maxsize=4)
def _modules(root: str) -> dict:
    """The parsed top level of every module of the reference, by its name."""
    return {path.stem: ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
            for path in sorted(Path(root).glob("*.py")) if path.name != "__init__.py"}


def _assigned_constants(tree: ast.Module) -> dict:
    """``{name: expression}`` of the module's constants: its top-level ``NAME = expression`` in capitals."""
    return {node.targets[0].id: node.value for node in tree.body
            if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)
            and node.targets[0].id.isupper()}


def _read(node) -> set:
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name)}


def _numeric(value) -> bool:
    try:
        array = np.asarray(value)
    except Exception:  # noqa: BLE001 - a value numpy cannot read is no number
        return False
    return array.dtype.kind in "fiu" and 0 < array.size <= 64


def _owned_constants(package, root: str, problem: int, ran: set) -> list:
    """``(module name, constant name)`` of the constants of the problem's own module and of the library (the modules
    of no problem) that the run reads: in the code it ran, in the defaults of the functions it ran, through a
    constant computed from them or a name imported from their module; the problem's own first."""
    trees = _modules(root)
    reads: dict = {}
    for code in ran:
        stem = Path(code.co_filename).stem
        names = reads.setdefault(stem, set())
        stack = [code]
        while stack:
            one = stack.pop()
            names.update(one.co_names)
            stack.extend(c for c in one.co_consts if hasattr(c, "co_names"))
        for node in ast.walk(trees.get(stem, ast.Module([], []))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name == code.co_name:
                for default in node.args.defaults + [d for d in node.args.kw_defaults if d is not None]:
                    names.update(_read(default))
    found, queue = set(), [(stem, name) for stem, names in reads.items() for name in names]
    while queue:
        stem, name = queue.pop()
        tree = trees.get(stem)
        if tree is None or (stem, name) in found:
            continue
        constants = _assigned_constants(tree)
        if name in constants:
            found.add((stem, name))
            queue.extend((stem, other) for other in _read(constants[name]))
        for node in tree.body:  # a name the module imports from another module of the reference
            if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
                queue.extend((node.module, a.name) for a in node.names if (a.asname or a.name) == name)
    own = f"problem_{problem:02d}"
    return sorted((key for key in found if key[0] == own or not _OWN_MODULE.fullmatch(key[0])),
                  key=lambda key: (key[0] != own, key[0], key[1]))


def _module(package, stem: str):
    return sys.modules.get(f"{package.__name__}.{stem}")


def _bindings(package, root: str, changed: dict) -> tuple | None:
    """The bindings that a module's constants given other values (``changed``: ``{(module, name): value}``) make
    of the reference as loaded: those values, the constants its modules computed from them and the names they
    imported of them (in the order of each module's code), and the defaults of the functions that read them; None
    where one of those cannot be computed again."""
    trees, bound = _modules(root), dict(changed)
    for _ in range(3):  # a constant imported, then computed from in another module: passes until nothing changes
        before = len(bound)
        for stem, tree in trees.items():
            module = _module(package, stem)
            if module is None:
                continue
            mine = {name for (m, name) in bound if m == stem}
            for node in tree.body:
                if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
                    for alias in node.names:
                        if (node.module, alias.name) in bound and (stem, alias.asname or alias.name) not in bound:
                            bound[(stem, alias.asname or alias.name)] = bound[(node.module, alias.name)]
                            mine.add(alias.asname or alias.name)
                elif isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name) \
                        and (stem, node.targets[0].id) not in changed and _read(node.value) & mine:
                    space = dict(vars(module), **{name: bound[(stem, name)] for name in mine})
                    try:
                        bound[(stem, node.targets[0].id)] = eval(compile(ast.Expression(node.value), "<constant>",
                                                                         "eval"), space)
                    except Exception:  # noqa: BLE001 - a constant that cannot be computed again: no slip
                        return None
                    mine.add(node.targets[0].id)
        if len(bound) == before:
            break
    found = [(_module(package, stem), name, value) for (stem, name), value in bound.items()]
    for stem, tree in trees.items():
        module = _module(package, stem)
        mine = {name for (m, name) in bound if m == stem}
        if module is None or not mine:
            continue
        space = dict(vars(module), **{name: bound[(stem, name)] for name in mine})
        for node in tree.body:  # the module's own functions (a method's defaults are left as they are)
            if not isinstance(node, ast.FunctionDef) or not any(_read(d) & mine for d in node.args.defaults):
                continue
            live = vars(module).get(node.name)
            if live is None or not hasattr(live, "__defaults__") or live.__defaults__ is None \
                    or len(live.__defaults__) != len(node.args.defaults):
                continue
            try:
                defaults = tuple(eval(compile(ast.Expression(d), "<default>", "eval"), space)
                                 for d in node.args.defaults)
            except Exception:  # noqa: BLE001 - a default that cannot be computed again is left as it is
                continue
            found.append((live, "__defaults__", defaults))
    return tuple(found)


def _value_of(expression, module):
    return eval(compile(ast.fix_missing_locations(ast.Expression(expression)), "<constant>", "eval"),
                dict(vars(module)))


#: the conversions of an angle, each with the one the other way
_BACK = {"deg2rad": "rad2deg", "rad2deg": "deg2rad", "radians": "degrees", "degrees": "radians"}


#: the decimals an angle in degrees is typed to, where it is typed rounded (0.35 rad as 20 or 20.1 degrees)
DEGREES_DECIMALS = (0, 1)


def _degrees_typed(degrees: float) -> list:
    """An angle in degrees as it is typed rounded (``DEGREES_DECIMALS``), each value once, none that is the angle
    itself or zero."""
    typed = []
    for decimals in DEGREES_DECIMALS:
        value = float(round(degrees, decimals))
        if value != 0 and value != degrees and value not in typed:
            typed.append(value)
    return typed


def _number_slips(expression):
    """``(slip, expression)`` of each number of the expression typed otherwise (``_NUMBER_SLIPS``; an integer that the
    slip keeps whole stays an integer, a count of steps that ``range`` takes), each entry of a list or tuple of it
    written 0, each two entries of one exchanged, a matrix of it written out row by row (``_written_out``) transposed, a
    conversion of an angle the other way (``_BACK``), a sine of it for a cosine or the reverse, and an expression of
    numbers in it that is not one number (``np.pi / 2``) typed short to ``TYPED_DECIMALS`` (a slip of precision)."""
    parents = {id(child): node for node in ast.walk(expression) for child in ast.iter_child_nodes(node)}
    if isinstance(expression, ast.Call) and _callee(expression) in ("array", "asarray") \
            and not any(k.arg == "dtype" for k in expression.keywords):  # ``np.array([...], dtype=np.float32)``
        yield "constant_single", 0, _with(expression, keywords=[*expression.keywords,
                                                                ast.keyword("dtype", _float32())])
    for index, node in enumerate(ast.walk(expression)):
        if _conversion(node):
            yield "constant_converted_back", index, _converted_back(node)
        if _constant_expression(node) and not _pi(node) and not _constant_expression(parents.get(id(node))):
            for decimals in TYPED_DECIMALS:
                yield "constant_typed", index, _float_round(node, decimals)
    for index, node in enumerate(ast.walk(expression)):
        if isinstance(node, ast.Constant) and type(node.value) is float and "e" not in repr(node.value):
            whole, _, decimals = repr(abs(node.value)).partition(".")
            digits = (whole + decimals).lstrip("0")  # its significant digits: a number of three or more typed
            short = round(node.value, len(decimals) - 1) if len(decimals) >= 2 and len(digits) >= 3 else 0.0
            if short != 0 and short != node.value:  # one decimal short (9.81 as 9.8) is a slip of precision
                yield "constant_typed", index, ast.Constant(float(short))
    for index, node in enumerate(ast.walk(expression)):
        if isinstance(node, ast.Constant) and type(node.value) in (int, float) and node.value != 0:
            for slip, factor in _NUMBER_SLIPS:
                if type(node.value) is int and slip in _UNCOUNTED:
                    continue
                number = float(node.value)
                value = number * factor if factor is not None else (
                    np.sqrt(abs(number)) if slip == "constant_root" else number * number)
                whole = type(node.value) is int and float(value).is_integer()  # a count stays a count: 1000 steps
                yield slip, index, ast.Constant(int(value) if whole else float(value))
                if slip == "constant_degrees":  # 0.35 rad typed as the degrees a student reads off it: 20
                    for typed in _degrees_typed(value):
                        yield slip, index, ast.Constant(typed)
    for index, node in enumerate(ast.walk(expression)):  # ``np.cos(SLOPE)`` for ``np.sin(SLOPE)``
        if isinstance(node, ast.Call) and _callee(node) in _TRIG and len(node.args) == 1:
            yield "constant_trig", index, _with(node, func=_renamed(node.func))
    for index, node in enumerate(ast.walk(expression)):  # ``np.cos(SLOPE)`` for ``-np.cos(SLOPE)``
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) and not _number(node.operand):
            yield "constant_sign", index, node.operand
    for index, node in enumerate(ast.walk(expression)):
        if isinstance(node, (ast.List, ast.Tuple)) and 1 < len(node.elts) <= _TABLE:
            for k, entry in enumerate(node.elts):
                if not isinstance(entry, (ast.Constant, ast.UnaryOp)) and not _constant_expression(entry):
                    yield "constant_sign", index, _with(node, elts=node.elts[:k] + [ast.UnaryOp(ast.USub(), entry)]
                                                        + node.elts[k + 1:])
            for k, entry in enumerate(node.elts):
                if not (isinstance(entry, ast.Constant) and entry.value == 0):
                    yield "constant_zeroed", index, _with(node, elts=node.elts[:k] + [ast.Constant(0.0)]
                                                          + node.elts[k + 1:])
            for i, j in _pairs(len(node.elts)):
                elts = list(node.elts)
                elts[i], elts[j] = elts[j], elts[i]
                yield "constant_entries", index, _with(node, elts=elts)
            if _written_out(node):
                yield "constant_transposed", index, _literal_transposed(node)


def _start_slips(value) -> list:
    """``(slip, value)`` of a start written whole as a plain value: all zeros (at rest, at the origin), and a
    square matrix as the identity (no turn)."""
    array = np.asarray(value, dtype=float)
    slips = [("start_zeros", np.zeros_like(array))]
    if array.ndim == 2 and array.shape[0] == array.shape[1]:
        slips.append(("start_identity", np.eye(array.shape[0])))
    return slips


def _direction_slips(value) -> list:
    """``(slip, value)`` of a vector constant written as its direction alone (divided by its length: gravity as the
    unit vector (0, -1, 0)), where its length is not 1."""
    array = np.asarray(value, dtype=float)
    length = float(np.linalg.norm(array)) if array.ndim == 1 and 2 <= array.size <= 3 else 0.0
    if length == 0.0 or not np.isfinite(length) or abs(length - 1.0) < 1e-9:
        return []
    return [("constant_direction", array / length)]


def _whole_starts_first(kept: list) -> list:
    """The kept slips of the constants, but those of a start of which a slip writing it whole as a plain value
    (zeros, the identity) is kept: its numbers typed otherwise (an angle a thousandth of its value, a turn of
    nearly nothing) then give that value only within the tolerance."""
    whole = {(m.module, m.path) for m in kept if m.slip in _WHOLE_STARTS}
    return [m for m in kept if m.slip in _WHOLE_STARTS or (m.module, m.path) not in whole]


def _replaced(expression, index: int, replacement):
    """A copy of the expression with its ``index``-th node (in the order of ``ast.walk``) replaced."""
    if index == 0:
        return ast.copy_location(replacement, expression)
    copies: dict = {}
    tree = _tree_copy(expression, copies)
    nodes = list(ast.walk(expression))
    target = copies[id(nodes[index])]
    for parent in ast.walk(tree):
        if _replace(parent, target, replacement):
            break
    return ast.fix_missing_locations(tree)


def constant_mutants(package, root: str, problem: int, ran: set) -> list[Mutant]:
    """The slips of the module constants the run reads (``_owned_constants``): a number of one typed otherwise, an
    entry of a table written 0 or two of its entries exchanged, a start (``_START``) written whole as zeros or the
    identity (``_start_slips``; an entry of it written 0 is a start's slip too), and two numeric constants of one
    module of one shape exchanged; each with the bindings it makes (``_bindings``), where its value differs; at most
    ``CONSTANT_MUTANTS``."""
    trees, found = _modules(root), []
    values: dict = {}
    for stem, name in _owned_constants(package, root, problem, ran):
        module = _module(package, stem)
        expression = _assigned_constants(trees[stem]).get(name)
        if module is None or expression is None or not _numeric(vars(module).get(name)):
            continue
        values[(stem, name)] = vars(module)[name]
        start = bool(_START.match(name))
        slips = _start_slips(values[(stem, name)]) if start else []
        slips += _direction_slips(values[(stem, name)])
        for slip, index, replacement in _number_slips(expression):
            try:
                slips.append((slip, _value_of(_replaced(expression, index, replacement), module)))
            except Exception:  # noqa: BLE001 - a slip whose value cannot be computed is no slip
                continue
        for slip, value in slips:
            if not _numeric(value) or np.shape(value) != np.shape(values[(stem, name)]) \
                    or np.array_equal(np.asarray(value), np.asarray(values[(stem, name)])):
                continue
            bindings = _bindings(package, root, {(stem, name): value})
            if bindings is not None:
                slip = "start_zeroed" if start and slip == "constant_zeroed" else slip
                slip = "constant_step" if slip in _RESIZINGS and _STEP_CONSTANT.match(name) else slip
                found.append(Mutant(stem, (name,), slip, None, bindings=bindings))
            if len(found) >= CONSTANT_MUTANTS:
                return found
    for (a, b) in itertools.combinations(list(values), 2):
        if a[0] == b[0] and np.shape(values[a]) == np.shape(values[b]) \
                and not np.array_equal(np.asarray(values[a]), np.asarray(values[b])):
            bindings = _bindings(package, root, {a: values[b], b: values[a]})
            if bindings is not None:
                found.append(Mutant(a[0], (f"{a[1]}` and `{b[1]}",), "constants", None, bindings=bindings))
    return found[:CONSTANT_MUTANTS]


@lru_cache(maxsize=64)
def _made_constants(package, root: str, problem: int, ran: frozenset) -> tuple:
    """``constant_mutants`` of the codes one call runs, kept for the process: they depend on the reference alone,
    the same for every answer, as the code's mutants are (``_codes``)."""
    return tuple(constant_mutants(package, root, problem, ran))


def _constant_stage(package, root: Path, problem: int, evidences: list[Evidence], originals: dict, judged: bool,
                    progress: dict, names: frozenset | None = None) -> tuple:
    """``(kept, mutants)`` of the slips of the module constants the first input's call reads, tried where no slip
    of the code reproduced the student's value: the constants of the problem's own module and of the library hold
    the problem's data (lengths, masses, gains, tables), which a student types from the sheet; within a budget of
    their own (``CONSTANT_TIME_BUDGET``; kept None when it runs out); ``names``: only those of these constants
    (``(module, name)``)."""
    started = time.thread_time()
    first = evidences[0]
    with _Deadline(CONSTANT_TIME_BUDGET) as deadline:
        ran = _traced(package, root, first.source.probe, first.source.args)
        with deadline.making():
            mutants = [m for m in _made_constants(package, str(root), problem, ran)
                       if names is None or (m.module, m.path[0]) in names]
        trace.note("constants", count=len(mutants), constants=sorted({m.function for m in mutants}),
                   seconds=round(time.thread_time() - started, 3), making=round(deadline.spent()[1], 3))
        kept = _evaluate(package, mutants, evidences, deadline, originals, judged=judged,
                         progress=progress, ran=ran) if mutants else []
    return (None if kept is None else _whole_starts_first(kept)), mutants


def _kept(problem: int, evidences: list[Evidence], mutants: list[Mutant] | None = None,
          told=None, only=None, outcome: dict | None = None, constants: frozenset | None = None,
          vanishing: bool = False) -> list[Mutant] | None:
    """The mutants (of the problem's functions that the first input's call runs, or ``mutants``) that reproduce
    the student's value on ``evidences``, or None when the time ran out; ``told``: see ``mutant_slips``; ``only``:
    the slips tried, where not all; where none of a solution region's slips reproduces it (and no earlier tier
    explained the answer), the slips of the code the problem's module gives whole (``_given``); ``outcome``
    (given) gets ``"timeout"`` where the time ran out on a stage; ``constants`` (given): only the slips of these
    module constants (``(module, name)``) are tried; ``vanishing``: a mutant whose value vanishes is kept (see
    ``_evaluate``)."""
    first = evidences[0]
    made = mutants is None
    judged = len(evidences) > 1 or only is not None  # one input of its own: a slip of precision, judged there
    started = time.thread_time()
    with _LOCK, warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        _TRACES["calls"] = {}
        kept, originals, found, progress, rivals, twins, making = None, {}, [], {}, None, (), 0.0
        called = None  # the codes the first input's call runs, where the mutants are made for it
        try:
            root, package = _package()
            if constants is not None:  # the slips of these constants alone (``_drawn_constants``)
                kept, mutants = _constant_stage(package, root, problem, evidences, originals, judged, progress,
                                                constants)
            else:
                with _Deadline(TIME_BUDGET) as deadline:
                    with deadline.making():
                        twins, ran = _twins(package, root, problem), None
                    for holder, _ in twins:  # put back by ``_restore`` wherever the time runs out
                        originals.setdefault(id(holder), (holder, holder.__code__))
                    if twins and mutants is None:  # only the functions that the call runs
                        ran = _traced(package, root, first.source.probe, first.source.args, twins)
                        twins = tuple((holder, twin) for holder, twin in twins if holder.__code__ in ran)
                    elif twins:  # the functions of the mutants given
                        holders = {id(_live(package, m.module, m.path)) for m in mutants}
                        twins = tuple((holder, twin) for holder, twin in twins if id(holder) in holders)
                    if twins:
                        holds = _holds(package, twins, evidences)
                        trace.note("screened", functions=sorted(h.__name__ for h, _ in twins), holds=holds)
                        twins, ran = (twins, ran) if holds else ((), None)  # traced without them, then
                        if holds:  # sympy's work on each mutant: milliseconds where numbers take microseconds
                            deadline.seconds = max(deadline.seconds, SCREENED_TIME_BUDGET)
                    if mutants is None:
                        mutants = mutants_of(package, root, problem, first.source.probe, first.source.args, twins, ran,
                                             deadline=deadline)
                        if mutants and only is not None:
                            mutants = [m for m in mutants if m.slip in only]
                        making = deadline.spent()[1]
                        called = ran if ran is not None else \
                            _traced(package, root, first.source.probe, first.source.args, twins)
                        trace.note("mutated", count=None if mutants is None else len(mutants),
                                   functions=sorted({m.function for m in mutants or ()}),
                                   seconds=round(time.thread_time() - started, 3), making=round(making, 3))
                        if mutants and told is not None:
                            mutants, rivals = late(mutants, told)
                            trace.note("late", told=sorted(told), count=len(mutants), rivals=rivals)
                    if mutants and rivals is None:
                        kept = _evaluate(package, mutants, evidences, deadline, originals, judged=judged, twins=twins,
                                         ran=called, vanishing=vanishing)
                if made and mutants == []:
                    kept = []  # no function of a region runs: none of their slips reproduces the value
                if kept and made and told is None and only is None and _opposite(kept) is not None:
                    kept = kept + _heard_in_given(package, root, problem, evidences, originals, judged, twins,
                                                  _opposite(kept))
                if kept == [] and made and told is None and only is None:
                    kept, mutants = _given(package, root, problem, evidences, originals, judged, progress, twins)
                if kept == [] and made and told is None and only is None:
                    kept, mutants = _constant_stage(package, root, problem, evidences, originals, judged, progress)
                if kept == [] and made and told is None and only is None:  # the library's given code, last
                    kept, mutants = _given(package, root, problem, evidences, originals, judged, progress, twins,
                                           library=True)
                if mutants and rivals is not None:  # the late budget counts the evaluation, not the making (cached)
                    with _Deadline(LATE_TIME_BUDGET) as deadline:
                        kept = _evaluate(package, mutants, evidences, deadline, originals, judged=judged,
                                         kept=found, progress=progress, twins=twins, ran=called)
            if kept:
                trace.note("positions", of=len(mutants), kept=[(k, m.slip) for k, m in enumerate(mutants)
                                                              if any(m is x for x in kept)])
        except _Timeout:
            kept = None
        finally:
            _restore(originals)  # once the deadline can interrupt nothing more
            _TRACES["calls"] = None
        if kept is None and mutants:
            trace.note("timeout", tried=progress.get("tried"))
            if outcome is not None:
                outcome["timeout"] = True
            if rivals is not None and progress.get("tried", 0) >= rivals:
                kept = found  # every rival of another family was tried: the time ran out on names of a family told
    trace.note("spent", seconds=round(time.thread_time() - started, 3), making=round(making, 3))
    return kept
