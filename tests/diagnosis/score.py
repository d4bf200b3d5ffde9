"""How well the grader tells the cause of mistakes that no catalogue lists: grade every mistake of the fresh set
(``tests/diagnosis/fresh/problem_NN.toml``) and classify the diagnosis of the check it must fail.

    python tests/diagnosis/score.py                       # the whole set
    python tests/diagnosis/score.py --exercises VI,VII    # some exercises
    python tests/diagnosis/score.py --per-exercise 1 -v   # the first mistake of each exercise, one line each

Each mistake is planted in a copy of ``reference/`` (as ``tests/planted/`` plants its own) and graded as
``tests/test_planted.py`` grades planted mistakes: live, on a worker forked from a batch slot's warm process, with
the planted suite's seed.  The diagnosis of the check it must fail is

* **right** when it names the true cause's family, alone or as one of at most two candidate families ("could be
  X or Y");
* **wrong** when it names causes and none of them is of the true family (a name whose family is unknown counts as
  wrong, and is listed);
* **none** when it names nothing (no diagnosis, or only a symptom such as ``shape`` or ``not_finite``), or more
  than two candidate families.

A mistake whose check does not fail is counted apart ("not caught") and stays in the denominator: it is a
mistake the grader no longer tells at all.  The target of the diagnosis engine (issue 27) is at least 60% right
and at most 2% wrong; the script reports whether it is met and asserts nothing.

Names are mapped to families by the table of ``checks/_diagnoses.py`` when that module exists (``family_of(name)``
or a mapping ``FAMILIES``/``DIAGNOSES``), and otherwise by ``FALLBACK`` below, a table of the names in use when
the set was written; the output says which one was used.

The set holds only mistakes whose cause the grader did not tell when they were written (``today``, recorded with
each), so it starts at 0% right; ``--set named`` grades the candidates that were left out because they were
already named rightly, ``--set pool`` both.  The whole fresh set takes about two minutes on a two-core machine.

The first set was measured more than once while the engine was built.  ``--set fresh2`` is a second held-out set
(``tests/diagnosis/fresh2/``) for the final measure, written from the sheet, the problem data and the reference
alone, apart from the engine and from the first set.  Its mistakes were chosen by the same rule (graded on the
grader of the day they were written, their check fails and its diagnosis is not of the true family), so it too
starts at 0% right; the check of each is the first of its problem's checks that it fails.  Left out of it: a slip
that repeats one of the first set or of the planted suite, and a slip that is as truly a slip of another family
(``R3(-q)`` is ``R3(q).T``; a throw that ignores its ``v0`` starts from a wrong state), whose family is no fact.  ``--set named2`` holds its
candidates that were already named rightly, ``--set pool2`` both.  The whole second set takes about a minute.

Both sets were then read while the engine was built.  ``--set fresh3`` is a third held-out set
(``tests/diagnosis/fresh3/``), written apart from the engine in the same way (from the sheet, the problem data and
the reference alone) and kept from its builders until they were done.  Its rule is the second set's: graded on
the grader of the day it was written, the first of its problem's checks that it fails does not name the true
family (so it starts at 0% right); the family of a slip that is as truly of another is no fact and it was left
out; and a slip that repeats one of the earlier sets or of the planted suite (the same file and replaced text, or
the same edit) was dropped.  Candidates that no check failed are not in it.  ``--set named3`` holds its candidates
that were already named rightly, ``--set pool3`` both.

``--set fresh4`` is a fourth held-out set (``tests/diagnosis/fresh4/``), written like the third apart from the
engine (from the sheet, the problem data and the reference alone) and kept from its builders until they were done,
but chosen by another rule: it holds every realistic mistake whose check fails, whether the grader of the day named
its cause rightly or not (``today`` is recorded with each, and was not looked at while the set was chosen).  The
earlier sets kept only the mistakes that were not named rightly, which selects the engine's failures; this one
samples the mistakes themselves, so it does not start at 0% right, and the issue's target is read on those of its
mistakes that no check's own catalogue names.  As before, the check of each is the first of its problem's checks
that it fails, a slip whose family is no fact was left out, and a slip that repeats one of the earlier sets, of
their named companions, of the engine's own tests or of the planted suite (the same file and replaced text, or the
same planted text) was dropped.  Candidates that no check failed are not in it.

``--set fresh5`` is a fifth held-out set (``tests/diagnosis/fresh5/``), written like the fourth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (``today`` is recorded with each and was not
looked at while the set was chosen).  Its check is the first of its problem's checks that it fails; a slip whose
family is no fact was left out; a slip that repeats one of the four earlier sets, their named companions, the
engine's own tests or the planted suite (the same file and replaced text, or the same planted text) was dropped
(where an earlier entry makes another slip in the same line, the entry replaces a narrower text of it); candidates
that no check failed are not in it.

``--set fresh6`` is a sixth held-out set (``tests/diagnosis/fresh6/``), written like the fifth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (``today``, recorded with each after the set was
chosen; an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails;
a slip whose family is no fact was left out; a slip that repeats one of the five earlier sets, their named companions,
the engine's own tests or the planted suite (the same file and replaced text, the same planted text, or the same slip
written otherwise) was dropped; candidates that no check failed, or whose check errs instead of failing, are not in
it.  Most of its entries (87 of 94) make another slip in a line that an earlier entry also edits; each replaces a text
of that line that no earlier entry replaces.

**What the target is read on.**  The first three held-out sets hold only mistakes that the grader of their day did
not name rightly: a set chosen so starts at 0% and leaves out, with the mistakes a catalogue names, every mistake
the engine already named, so it is harder than the issue's "realistic mistakes that the catalogues do not list".
``--unlisted`` reads the issue's measure on any set: each mistake is graded twice, with the diagnosis engine
switched off and on; one whose check names its true cause with the engine off is *listed* (a check's own catalogue
or message tells it) and is left out of the measure, and the target is read on the others, graded with the engine
on.  On the first three held-out sets that measure is the set's own (nothing in them was named when they were
written); on a pool (one of them with its ``named`` companion) it is the issue's measure on all the realistic
mistakes that were written; on the fourth, fifth and sixth sets it is the issue's measure itself (``--set fresh4
--unlisted``, ``--set fresh5 --unlisted``, ``--set fresh6 --unlisted``); so it is on the seventh, the eighth and the
ninth (``--set fresh7 --unlisted``, ``--set fresh8 --unlisted``, ``--set fresh9 --unlisted``).

``--set fresh7`` is a seventh held-out set (``tests/diagnosis/fresh7/``), written like the sixth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (``today``, recorded after the set was chosen;
an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails; a
slip that repeats one of the six earlier sets, their named companions, the engine's own tests or the planted suite
(the same file and replaced text, the same planted text, or the same slip written otherwise) was dropped;
candidates that no check failed, or whose check errs instead of failing, are not in it.  Most of its entries
(96 of 102) make another slip in a line that an earlier entry also edits; each replaces a text of that line that no
earlier entry replaces.  Unlike the earlier sets it keeps the slips that are as truly of two families, with the
second in an optional field ``also`` (6 of its entries; decided from the slip alone when the entry was written:
two entries of a state exchanged are a state-row and an order slip, ``R(-q)`` for ``R(q)`` is a sign and a
transpose, ``r x omega`` for ``omega x r`` is a sign and an order slip).  The whole set takes about four minutes
on a two-core machine.

``--set fresh8`` is an eighth held-out set (``tests/diagnosis/fresh8/``), written like the seventh and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, an empty string where the check named nothing).  Its check
is the first of its problem's checks that it fails; a slip that repeats one of the seven earlier sets, their named
companions, the engine's own tests or the planted suite (the same file and replaced text, the same planted text, or
the same slip written otherwise) was dropped; candidates that no check failed, or whose check errs instead of failing,
are not in it.  It holds 96 entries; 29 of them make another slip in a line that an earlier entry also edits, each
replacing a text of that line that no earlier entry replaces; the other 67 edit lines that no earlier entry edits
(among them problem 34's biped and gait, problem 32's arm, problem 24's pendulum and problem 4's assembly).
Two entries name a second family (``also``), decided from the slip alone: ``R2(-beta)`` written as a negated sine in
the numeric rotation and ``R3(-gamma)`` in the symbolic one of problem 7 are a sign and a transpose.  The whole set
takes about four minutes on a two-core machine.

``--set fresh9`` is a ninth held-out set (``tests/diagnosis/fresh9/``), written like the eighth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 8a84ac2, the commit the set's branch started
from, an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails;
a slip that repeats one of the eight earlier sets, their named companions, the engine's own tests or the planted suite
(the same file and replaced text, the same planted text, or the same slip written otherwise) was dropped.  It holds
91 entries, at most five of one problem (5.5% of the set); 80 of them make another slip in a line that an earlier
entry also edits, each replacing a text of that line that no earlier entry replaces, and the other 11 edit lines that
no earlier entry edits.  Six entries name a second family (``also``), decided from the slip alone: a rotation or skew
matrix transposed where it turns the other way (the Euler and exponential steps of problem 8, ``R3(-q)`` of the
rolling contact in problems 33 and 35, ``dA^T A`` for ``A^T dA``) is a transpose and a sign, and problem 9's
transform asked of C1 relative to C3 where C3 relative to C1 is meant an inverse and a transpose.  Of 396 candidates
tried, 305 were dropped: 207 repeated an earlier entry (the same replaced text, planted text or name), 7 more were
the same slip as an earlier entry written otherwise, 68 failed no check, 12 erred in their first failing check, 2
had no family that could be stated from the slip alone, and 9 were left out for the spread (no problem above five
entries, Exercise VII within its share).  The whole set takes about two and a half minutes on a two-core machine.

``--set fresh10`` is a tenth held-out set (``tests/diagnosis/fresh10/``), written like the ninth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 25d3207, the commit the set's branch started
from, an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails;
a slip that repeats one of the nine earlier sets, their named companions, the engine's own tests or the planted suite
(the same file and replaced text, the same planted text, or the same slip written otherwise) was dropped.  It holds
50 entries, at most three of one problem (6% of the set); 24 of them make another slip in a line that an earlier
entry also edits, each replacing a text of that line that no earlier entry replaces, and the other 26 edit lines that
no earlier entry edits (among them constants typed from the sheet that a check reads: the gains of problem 37, the
prismatic axis of problem 27, the foot radius of problem 25).  Five entries name a second family (``also``), decided
from the slip alone: a rotation written transposed (``R1`` of problem 6, the symbolic ``rot3`` of problem 25, the
third joint frame of problem 32) is a transpose and a sign, omega read from ``W[0, 1]`` for ``W[1, 0]`` in problem 35
a sign and a transpose, and a constructor that drops the start position of problem 12 a wrong initial state and an
ignored argument.  Of 147 candidates tried, 97 were dropped: 37 repeated an earlier entry (36 the same replaced text,
planted text or name, 1 the same slip written otherwise), 50 failed no check, 4 erred in their first failing check
(or left it not implemented), 2 were left out before grading (one could change no answer, one would raise), and 4
were left out for the spread (no problem above three entries).  It is smaller than the earlier sets, and holds 14
entries of the simulated problems where they hold twenty or more: most slips of those problems were already taken.
The whole set takes about a minute and a half on a two-core machine.

``--set fresh11`` is an eleventh held-out set (``tests/diagnosis/fresh11/``), written like the tenth and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit c6d00a8, the commit the set's branch started
from, an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails;
a slip that repeats one of the ten earlier sets, their named companions, the engine's own tests or the planted suite
(the same file and replaced text, the same planted text, or the same slip written otherwise) was dropped.  It holds
48 entries, at most three of one problem (6% of the set), 15 of them in the simulated problems; 37 of them make
another slip in a line that an earlier entry also edits, each replacing a text of that line that no earlier entry
replaces, and the other 11 edit lines that no earlier entry edits (among them the brick's dimensions in
``mjcf.py``, standard gravity in ``conventions.py``, the bias pass of ``dynamics.equations_of_motion`` and the
walker's offsets of problem 25).  Three entries name a second family (``also``), decided from the slip alone: the
pitch rotation of problem 6 applied transposed is a transpose and a sign, omega's second component read from
``W[2, 0]`` in problem 7 a sign and a transpose, and the walker's first initial rate typed without its minus sign
in problem 38 a wrong initial state and a sign.  Of 123 candidates tried, 75 were dropped: 26 repeated an earlier
entry (22 the same replaced or planted text, 4 the same slip written otherwise), 33 failed no check (19 of them slips in
the problem modules of problems 11 to 22, whose helpers no check calls; their checks grade the shared modules),
8 erred in their first failing check (or left it not implemented), 5 had no family that could be stated from the
slip alone, and 3 were left out before grading (code no check reads, or not a realistic slip).  The whole set takes
about two minutes on a two-core machine.

``--set fresh12`` is a twelfth held-out set (``tests/diagnosis/fresh12/``), written like the eleventh and kept from the
engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 5f9eacd, the commit the set's branch started
from, an empty string where the check named nothing).  Its check is the first of its problem's checks that it fails;
a slip that repeats one of the eleven earlier sets, their named companions, the engine's own tests or the planted
suite (the same file and replaced text, the same planted text, or the same slip written otherwise) was dropped.  It
holds 42 entries, at most four of one problem (problem 37's; 9.5% of the set), 14 of them in the simulated problems;
33 of them make another slip in a line that an earlier entry also edits, each replacing a text of that line that no
earlier entry replaces, and the other 9 edit lines that no earlier entry edits (among them the call of the parent's
constructor in ``rigid_body.py``, the loop of problem 8's ``_run``, the signature of ``non_accelerating_point``, the
piecewise integration of ``dynamics.py`` and problem 28's list of colours).  Many of its slips are in arguments,
returns and the plumbing between functions (an argument left for a module constant, a tuple unpacked in another
order, a loop index off by one).  Two entries name a second family (``also``), decided from the slip alone: the
symbolic rotation about 3 of problem 7 typed transposed is a transpose and a sign, and problem 15's dynamics class
that calls its parent's constructor without the keyword arguments ignores an argument and starts from a wrong
state.  Of 174 candidates tried, 132 were dropped: 88 repeated an earlier entry (the same replaced text, planted text
or name), 3 more were the same slip as an earlier entry written otherwise, 30 failed no check, 6 erred in their first
failing check (or left it not implemented), 3 were left out after grading as not realistic slips (a value no reading
of the sheet gives, a call no student makes), and 2 were left out for the spread (no problem above four entries,
Exercise VII and the family ``order`` within their share).  The whole set takes about a minute on a two-core machine.

``--set fresh13`` is a thirteenth held-out set (``tests/diagnosis/fresh13/``), written like the twelfth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 6150e5a, the commit the set's branch started
from, an empty string where the check names nothing; every entry's check failed in that run, so none was dropped
after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the twelve
earlier sets, their named companions, the engine's own tests or the planted suite (the same file and replaced text,
the same planted text, or the same slip written otherwise) was dropped.  It holds 36 entries, at most three of one
problem (problems 4, 34 and 37; 8% of the set), 13 of them in the simulated problems; 27 of them make another slip in
a line that an earlier entry also edits, each replacing a text of that line that no earlier entry replaces, and the
other 9 edit lines that no earlier entry edits (among them the Newton steps and the bisection of problem 4's
assembly, the symbolic rotation helpers of problems 7 and 25, problem 34's gait constants, the symbolic joint
function of problem 35 and the recursive sum of ``dynamics.DynamicBody``).  Its slips are spread over 14 families,
none above five entries, and reach into given code a student edits (a body's share of the recursive sum, a link's
hinge in the MJCF helper) and into answers.toml (problems 19 and 42).  One entry names a second family (``also``),
decided from the slip alone: problem 35's symbolic joint function that stores its rotation transposed is a
transpose and a sign.  Of 281 candidates tried, 245 were dropped: 168 repeated an earlier entry (the same replaced
text, planted text or name), 9 more were the same slip as an earlier entry written otherwise, 50 failed no check
(among them all 12 tried in the problem modules of problems 12, 15, 21, 22, 31 and 33, whose helpers no check
calls, and all 8 in the given robot and trajectory of problem 32, which the checks of problems 32 and 37 take from
the reference), 9 erred in their first failing check (or left it not implemented), 4 were left out before grading
(their text did not occur once in the reference as written), 1 was left out after grading as not a realistic slip,
and 4 were left out for the spread (Exercise VII and the family ``order`` within their share, and no third exchange
of sine and cosine).  The whole set takes a little under two minutes on a two-core machine (103 s in the recording
run).

``--set fresh14`` is a fourteenth held-out set (``tests/diagnosis/fresh14/``), written like the thirteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 9968ed7, the commit the set's branch started
from, an empty string where the check names nothing; every entry's check failed in that run, so none was dropped
after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the thirteen
earlier sets, their named companions, the engine's own tests or the planted suite (the same file and replaced text,
the same planted text, or the same slip written otherwise) was dropped.  It holds 43 entries in 29 problems, at most
four of one problem (problem 37's; 9% of the set), 15 of them in the simulated problems; 28 of them make another slip
in a line that an earlier entry also edits, each replacing a text of that line that no earlier entry replaces, and
the other 15 edit lines that no earlier entry edits (among them the first joint frame of problem 24, the recursion's
call of the joint function and the unpacking of the successor's Jacobians in ``tree.py``, the recursive sum of
``dynamics.DynamicBody``, the declared order of the parameters of problem 42's ``ball_ode`` and of problem 44's event
builder, and the explicit ``<inertial>`` of the Exercise I link builder).  Its slips are spread over 14 families, none
above nine entries (the family ``order``, 21% of the set).  Four entries name a second family (``also``), decided from
the slip alone: problem 24's first joint frame typed by columns is a transpose and a sign, problem 17's
representations built from ``np.linalg.eig`` are unsorted and not made proper rotations (an order and a sign),
problem 37's computed torques given the measured and the desired state in each other's places are an order and a sign
(the feedback reversed), and problem 46's constrained state unpacked with its halves exchanged is a state row and an
order slip.  Of 295 candidates tried (330 gradings: a slip that differed from an earlier entry's in the same replaced
text was tried again with another span of its line, and is counted by its last try), 252 were dropped: 199 repeated
an earlier entry (132 the same planted text, 67 the same replaced text), 39 failed no check, 8 erred in their first
failing check, and 6 were left out for the spread (the family ``order`` within its share: a third exchange of sine and
cosine, problem 6's ``R2``, and five exchanges of arguments, angles or indices in problems 8, 27, 31, 34 and 39, each
of which keeps other entries).  The whole set takes about a minute on a two-core machine (59 s graded, 62 s in all, in
the recording run).

``--set fresh15`` is a fifteenth held-out set (``tests/diagnosis/fresh15/``), written like the fourteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit d6adb7a, the commit the set's branch started
from, an empty string where the check names nothing; every entry's check failed in that run, so none was dropped
after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the fourteen
earlier sets, their named companions, the engine's own tests or the planted suite (the same file and replaced text,
the same planted text, or the same slip written otherwise) was dropped.  It holds 40 entries in 26 problems, at most
three of one problem (problems 34 and 46; 7.5% of the set), 13 of them in the simulated problems; 33 of them make
another slip in a line that an earlier entry also edits, each replacing a text of that line that no earlier entry
replaces, and the other 7 edit lines that no earlier entry edits (among them the declared order of the parameters
of problem 2's ``pendulum`` and problem 39's ``inertia_aligned``, the loop of problem 24's builder that advances the
predecessor, problem 34's hip amplitude, the default gravity of problem 44's ``simulate`` and the impact's
constraint Jacobian of problem 46).  Many of its slips are in arguments, returns and the plumbing between functions
(a tuple returned in another order, an argument left for a module constant or for its neighbour, a body hung on the
wrong predecessor) and in NumPy, SciPy, sympy and MJCF habits (``np.rad2deg`` for ``np.deg2rad``, a row vector
times a matrix, ``np.inner`` for ``np.outer``, a ``weld`` for a ``connect``, the attributes of an event assigned in
each other's places).  Its slips are spread over 14 families, none above eight entries (the family ``order``, 20%
of the set).  Three entries name a second family (``also``), decided from the slip alone: problem 12's constructor
that sets the angular velocity from the angular acceleration starts from a wrong state and ignores an argument,
problem 27's revolute column with the joint and the end effector in each other's places is an order and a sign
slip, and problem 42's apex event whose ``terminal`` and ``direction`` are assigned in each other's places is an
event and an order slip.  Of 162 candidates tried (177 tries: a slip whose replaced text an earlier entry had
replaced was tried again with a narrower span of its line, and is counted by its last try), 122 were dropped: 72
repeated an earlier entry (37 the same planted text, 32 the same replaced text, 3 the same name), 2 more were the
same slip as an earlier entry written otherwise (gravity along another wrong axis of problem 24, the gravity
compensation of problem 37 handed ``-g``), 33 failed no check (among them all 10 tried in the problem modules of
problems 9, 11, 14, 19 and 20, whose helpers no check calls), 10 erred in their first failing check (or left it
not implemented), 1 was left out before grading (its text occurred twice in the reference), and 4 were left out
for the spread (a third slip of problem 34, a second of problem 38 of the family ``scale``, and two of the family
``order`` in problems 31 and 37).  The whole set takes under a minute on a two-core machine (43 s graded, 45 s in
all, in the recording run).

``--set fresh16`` is a sixteenth held-out set (``tests/diagnosis/fresh16/``), written like the fifteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 9910883, the commit the set's branch started from,
an empty string where the check names nothing; every entry's check failed in that run, so none was dropped after it).
Its check is the first of its problem's checks that it fails; a slip that repeats one of the fifteen earlier sets, their
named companions, the engine's own tests or the planted suite (the same file and replaced text, the same planted text,
or the same slip written otherwise) was dropped.  It holds 38 entries in 25 problems, at most three of one problem
(problems 3, 12, 25 and 46; 8% of the set), 13 of them in the simulated problems; 36 of them make another slip in a line
that an earlier entry also edits, each replacing a text of that line that no earlier entry replaces, and the other 2
edit lines that no earlier entry edits (the return of problem 34's ``gait`` and of problem 46's ``constrained_ode``).
Many of its slips are in NumPy, SciPy, sympy and MJCF habits (``np.sinc``, the normalised sinc, for sin(x)/x in
``expm_skew``, a ``<velocity>`` servo for an ``<intvelocity>``, the half edges of MJCF's box size handed to problem 3's
``link_inertia``, a symbolic Jacobian returned transposed) and in the plumbing between functions (a tuple returned or
unpacked in another order, an argument passed as a constant or as its neighbour: the support event of problem 44 built
with ``d = 0``, the rolling joint of problem 25 given the leg length as its radius), and some in indices and sampling
(problem 37's desired state held at a knot, its output one sample short of ``t_end``) and in units (the triple
pendulum's gravity normalised to one).  Its slips are spread over 13 families, none above six entries (the families
``scale`` and ``state_row``, 16% of the set each).  Five entries name a second family (``also``), decided from the slip
alone: the body-frame angular velocity read from ``dA^T A`` (``rotations.py``, problem 7) and problem 35's virtual joint
turned by ``R3(gamma).T`` are a sign and a transpose slip, problem 12's body that starts at its velocity argument starts
from a wrong state and reads a wrong state entry, problem 42's negated apex residual is a sign and an event slip, and
problem 46's constrained derivative returned as ``(qdd, qd)`` is a state row and an order slip.  Of 263 candidates tried
(296 tries: a slip whose replaced text an earlier entry had replaced was tried again with a narrower span of its line,
and is counted by its last try; 107 gradings), 225 were dropped: 149 repeated an earlier entry (134 the same planted
text, 14 the same replaced text, 1 the same name), 20 more were the same slip as an earlier entry written otherwise
(among them problem 37's interpolation weights from the wrong end, which exchange the weights as an earlier entry does,
the gravity-compensation controller handed the desired and the measured states in each other's places, the residual of
problem 4's Newton loop negated, its loop cut to six iterations, problem 7's symbolic ``c, s`` exchanged, and problem
3's driven model started without its rate), 35 failed no check (among them 5 of the 6 tried in problem 4's ``balanced``,
the sixth erred, and problem 34's ``frame_time``), 12 erred in their first failing check (or left it not implemented), 4
were left out before grading (their text did not occur once in the reference as written), and 5 were left out after
grading (3 for Exercise VII's share: problem 44's ``bar_ode`` declaring theta before m and returning its accelerations
twice, and problem 47's inverse mass matrix with theta on the y row; a third slip of problem 31, another angular
acceleration read for a velocity; and a made-up apex residual of problem 42 that no reading of the sheet gives).  The
whole set takes under a minute on a two-core machine (34 s graded, 36 s in all, in the recording run).

``--set fresh17`` is a seventeenth held-out set (``tests/diagnosis/fresh17/``), written like the sixteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 1130799, the commit the set's branch started from,
an empty string where the check names nothing; every entry's check failed in that run).  One entry recorded in that
run, problem 27's governor Jacobian evaluated at gamma = 30, was found afterwards to plant the same text as an entry of
the third set and was dropped; a slip of ``integrate_piecewise`` (``dynamics.py``) that keeps the output times up to
each piece's end, so that a time on a break is recorded twice (problem 37), took its place and its ``today`` was
recorded by a run of that entry alone, at the same commit.  Its check is the first of its problem's checks that it
fails; a slip that repeats one of the sixteen earlier sets, their named companions, the engine's own tests or the
planted suite (the same file and replaced text, the same planted text, or the same slip written otherwise) was
dropped.  It holds 30 entries in 23 problems, at most three of one problem (problem 24; 10% of the set), 11 of them
in the simulated problems (14 in Exercise I's MuJoCo problems and the runs of problems 7, 34, 37, 38, 42, 44, 46 and
47); it is smaller than the sets before it because the earlier sets had taken nearly every slip of the graded
functions that was tried.  Many of its slips are in plumbing and API habits: an MJCF attribute written as a constant
instead of its argument (the hinge's damping, the geom's density), ``mujoco`` left out of problem 1's package tuple,
a joint of the four-bar model turned by its neighbour's entry of q, arguments handed to ``solve_ivp`` in another
order (problem 44's ``args``), the walker's kinematics handed (gamma, alpha), problem 38's output grid built with
``np.arange`` for ``np.linspace``, problem 24's output step defaulted to 0.1, the triple pendulum's ODE returning
(qdd, qd), a symbolic sigma differentiated by the rates instead of the positions, the ellipsoid's function called
for the cuboid's edges; others leave a factor out (``np.eye(3)`` in the parallel-axis term, the drag's ``|v|``, the
centripetal term of a joint's successor acceleration, ``@ qd`` of a symbolic relative velocity).  Its slips are spread
over 12 families, none above six entries (the family ``missing_term``, 20% of the set).  Two entries name a second
family (``also``), decided from the slip alone: problem 3's third principal moment written with height^2 for width^2
leaves one term out and puts another in (``extra_term``, also ``missing_term``), and problem 24's ODE returning
(qdd, qd) is a state row and an order slip.  Of 363 candidates tried (a slip whose replaced text an earlier entry had
replaced was tried again with a narrower span of its line, and is counted by its last try; about 170 gradings), 333
were dropped: 225 repeated an earlier entry by its text (182 the same planted text, 14 the same replaced text, 28 more
found to repeat an earlier planted or replaced text after they were graded, and problem 27's governor after the
recording), 17 more were the same slip as an earlier entry written otherwise (among them problem 47's negated
impulse, problem 43's multiplier read from entry 2, problem 38's output rows exchanged, problem 42's landing speed
read from the height row, the Newton loop of problem 4 cut to two iterations, and ``set_transform`` storing the
transpose), 74 failed no check (most of them in the problems' own scripts, which the checks do not call, such as
problem 12's point Q written ``3 // 16`` and problem 15's bodies built with the identity inertia), 12 erred in their
first failing check (or left it not implemented), 2 were left out before grading (their text did not occur once in
the reference as written), 2 were left out for their family, which the set's families do not hold (problem 1's
version read as ``platform.python_version_tuple()``, a typed value, and problem 36's TweedleDum named TweedleDee, a
wrong constant), and 1 for Exercise I's share (a third slip of problem 4).  The whole set takes under a minute on a
two-core machine (30 s graded, 32 s in all, in the recording run); it was written in about 35 minutes.

``--set fresh18`` is an eighteenth held-out set (``tests/diagnosis/fresh18/``), written like the seventeenth and kept
from the engine's builders until they were done: from the sheet, the problem data and the reference alone, every
realistic mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine
switched off; ``today`` recorded from one run after the set was chosen, at commit cd32a04, the commit the set's branch
started from, an empty string where the check names nothing; every entry's check failed in that run, so none was
dropped after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the
seventeen earlier sets, their named companions, the engine's own tests or the planted suite (the same file and replaced
text, the same planted text, or the same slip written otherwise) was dropped.  It holds 29 entries in 22 problems, at
most three of one problem (problem 37; 10% of the set), 11 of them in the simulated problems (16 in Exercise I's MuJoCo
problems and the runs of problems 8, 34, 37, 38, 42, 44, 46 and 47); like the seventeenth it is smaller than the
earlier sets, because they had taken nearly every slip of the graded functions that was tried (more than half of this
set's candidates planted an earlier entry's text).  25 of its entries make another slip in a line that an earlier
entry also edits, each replacing a text of that line that no earlier entry replaces; the other 4 edit lines that no
earlier entry edits (the series threshold of ``expm_skew``, problem 36's Red Queen's foe, and the edges of the pieces
of ``integrate_piecewise`` in two ways).  Many of its slips are in plumbing and API habits: ``integrate_piecewise``
(``dynamics.py``) asking each piece for its output times only and not for the break, so that the next piece starts
from an earlier state, dropping the output times on the breaks, leaving out the last piece, or keeping the breaks
before the span's start, so that problem 46's run after the impact restarts at t = 0; the attributes of problem 42's
landing event assigned in the other order, problem 46's end-effector position and velocity unpacked in each other's
places, problem 4's fixed point read as ``[1:]`` and its bisection keeping the wrong end, problem 3's link mass taken
from the module's constants instead of the arguments, problem 34's hips both placed at the loop's first z, problem
38's rates read one row early, a relative rotation that inverts the wrong matrix, the gyroscopic term written as
``np.cross`` with its factors in the other order, ``np.linalg.norm(r)`` for ``r @ r`` in the parallel-axis term, and
the children's bias forces left out of the recursive sum of the equations of motion.  Its slips are spread over 12
families, none above five entries (the family ``missing_term``, 17% of the set).  Four entries name a second family
(``also``), decided from the slip alone: problem 9's relative rotation built with the wrong inverse is a transpose and
an order slip, the gyroscopic cross product with its factors exchanged a sign and an order slip, the pieces of
``integrate_piecewise`` started from the state at their last output time a time-shift and an initial-state slip, and
the landing event's attributes assigned in the other order an event and an order slip.  Of 268 candidates tried (a
slip whose replaced text an earlier entry had replaced was tried again with a narrower span of its line, and is
counted by its last try; 130 gradings), 239 were dropped: 162 repeated an earlier entry by its text (125 the same
planted text, 37 the same replaced text, among them two that are also the same slip as an earlier entry written
otherwise: problem 17's handedness fixed on a row and problem 44's ODE handed the default gravity), 52 failed no check
(most of them in the problems' own scripts and constants, which the checks do not call, such as problem 15's run
stepping before its dynamics, problem 19's blocks and problem 24's default configuration, and some in tolerances,
such as ``solve_ivp`` left at its default ``rtol`` in problems 24, 38 and 42), 13 erred in their first failing check
(or left it not implemented), 4 were left out before grading (their text did not occur once in the reference as
written), 1 was left out for its family, which the set's families do not hold (problem 47's impact returning the
argument ``q_minus`` itself, a typed value), 1 failed its check but repeats an earlier entry written otherwise
(problem 3's driven model started without its rate), and 6 were left out for the spread (a third slip of problem 4,
a third and a fourth of problem 46 and a second of problem 42, for Exercise VII's share and the family ``order``,
problem 38's swing leg given a retyped inertia with its axes permuted, and a contrived start of problem 44, replaced
by its contact residual without the bar's angle).  The whole set takes under half a minute on a two-core machine
(20 s graded, 21 s in all, in the recording run); it was written in about 20 minutes.

``--set fresh19`` is a nineteenth held-out set (``tests/diagnosis/fresh19/``), written like the eighteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded from one run after the set was chosen, at commit 396e0c2, the commit the set's branch started from,
an empty string where the check names nothing; every entry's check failed in that run, so none was dropped after
it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the eighteen earlier
sets, their named companions, the engine's own tests or the planted suite (the same file and replaced text, the same
planted text, or the same slip written otherwise) was dropped.  It holds 35 entries in 26 problems, at most two of one
problem (problems 3, 4, 8, 12, 31, 34, 37, 46 and 47), 12 of them in the simulated problems (17 in Exercise I's MuJoCo
problems and the runs of problems 8, 34, 37, 38, 42, 44, 46 and 47); like the two before it, it is smaller than the
earlier sets, because they had taken nearly every slip of the graded functions that was tried (more than half of this
set's candidates planted an earlier entry's text).  31 of its entries make another slip in a line that an earlier entry
also edits, each replacing a text of that line that no earlier entry replaces; the other 4 edit lines that no earlier
entry edits (problem 4's limit of joint targets and its Newton iterations' start, problem 34's gait coefficients
returned in the other order, and the walker's stance leg built without its inertia).  Many of its slips are in plumbing,
class designs and API habits: problem 3's keyframe setting the actuator's activation (``act``) for its control and its
drive declared as a ``<position>`` servo, an ``integrate_piecewise`` that keeps each piece's output times before its end
also in the last piece, or that returns the last output sample for the state at the event, problem 37's runs all handed
the controller ``"pd"``, problem 46's constrained run handed its ODE without the wire's anchor and length, the gait's
coefficient tables returned in each other's places, the double pendulum of points with its coordinates stacked in
reverse, ``BoundVector`` storing its start offset as its vector, ``float32`` for ``float`` in problem 21's layout and
problem 39's misaligned inertia, the angular velocity of problem 7 built as a row (``sp.Matrix([[...]])``), the start
angles of problem 24 converted with ``np.deg2rad`` a second time, the contact event unpacking the state as ``(x, phi,
height)``, and ``len(t_land) > 1`` for a landing; others leave a term or factor out (``P_r_PDp`` in the lever of the
Jacobian recursion, ``qd_minus`` in the velocity after the pin's impact, ``theta`` in its impulse, the stance leg's
inertia) or put one in the wrong frame or sign (the tangential and centripetal terms of a point's acceleration left in
body coordinates, ``W.T`` in the sine term of Rodrigues' formula).  Its slips are spread over 14 families, none above
five entries (the family ``sign``, 14% of the set).  Three entries name a second family (``also``), decided from the
slip alone: the transposed skew matrix in Rodrigues' formula is a sign and a transpose slip, the leaf of problem 28
printing its color for 'Sandwich' puts a line in and leaves one out (``extra_term``, also ``missing_term``), and the
contact event's state unpacked as ``(x, phi, height)`` is a state row and an order slip.  Of 290 candidates tried (a
slip whose replaced text an earlier entry had replaced was tried again with a narrower span of its line, and is counted
by its last try: 323 tries; about 90 gradings), 255 were dropped: 179 repeated an earlier entry by its text (170 the
same planted text, 9 the same replaced text), 14 more were the same slip as an earlier entry written otherwise (among
them problem 24's ODE handed gravity along -z, an earlier entry's ``I_GRAV`` along z, and the rotation step
``expm_skew(-dt * I_Om)``, an earlier entry's transposed exponential, both found after they were graded), 29 failed no
check (most of them in the problems' own scripts or in functions the checks replace with their own, such as problem 32's
desired trajectory, problem 9's chain of frames and problem 37's robot inertia, and some in tolerances and steps, such
as ``solve_ivp`` given its default or looser tolerances in problems 24, 38, 44 and 46, problem 37's run without its
breaks and the four-bar's 10 ms step), 12 erred in their first failing check (or left it not implemented), 4 were left
out before grading (their text did not occur once in the reference as written), and 17 were left out for realism, family
or spread (contrived or equivalent edits, such as a control range clipping problem 2's input, whose family the set's
families do not tell, a second problem 38 leg without inertia, a third slip of problem 34 and a third ``float32``
slip).  The whole set takes about half a minute on a two-core machine (30 s graded, 32 s in all, in the recording run);
it was written in about 25 minutes.

``--set fresh20`` is a twentieth held-out set (``tests/diagnosis/fresh20/``), written like the nineteenth and kept from
the engine's builders until they were done: from the sheet, the problem data and the reference alone, every realistic
mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine switched off;
``today`` recorded after the set was chosen, at commit f228ad2, the commit the set's branch started from, an empty
string where the check names nothing).  Its check is the first of its problem's checks that it fails; a slip that
repeats one of the nineteen earlier sets, their named companions, the engine's own tests or the planted suite (the same
file and replaced text, the same planted text, or the same slip written otherwise) was dropped.  It holds 35 entries
in 21 problems of all seven exercises (I 5, II 2, III 5, IV 6, V 5, VI 5, VII 7), at most three of one problem (four
problems hold three), 14 of them in the problems of ``SIMULATED`` and 16 in Exercise I's MuJoCo problems and the runs;
29 of its entries make another slip in a line that an earlier entry also edits, each replacing a text of that line
that no earlier entry replaces, the other 6 edit lines that no earlier entry edits.  Its slips are spread over 12
families: order 7, scale 6, state_row 5, missing_term 3, and offset, frame, step_size, time_shift, ignored_argument
and sign 2 each, initial_state and precision 1 each (no family above 20% of the set).  Three entries name a second
family (``also``), decided from the slip alone: one each of order, offset and scale.  Of about 205 candidates tried
(a slip retried with a narrower span of its line is counted once, by its last try; about 130 gradings), about 170 were
dropped: 104 repeated an earlier entry by its text (the same replaced or planted text), 14 of them found only by this
file's repeat test after a first recording run, on a version of the set that held them, so they were dropped and
replaced and the recording run was made again on the set as it stands (every entry's check failed in both runs), 12
more were the same slip as an earlier entry written otherwise, 41 failed no check (most in the problems' own scripts,
which the checks replace with their own, and some in tolerances, steps and defaults), 4 erred in their first failing
check (or left it not implemented), 2 were left out before grading (their text did not occur once in the reference as
written), and 7 were left out for realism or spread (contrived or equivalent edits, a fourth entry of one problem).
The whole set takes about half a minute on a two-core machine (28 s graded, 30 s in all, in the recording run); it was
written in about 25 minutes.

``--set fresh21`` is a twenty-first held-out set (``tests/diagnosis/fresh21/``), written like the twentieth and kept
from the engine's builders until they were done: from the sheet, the problem data and the reference alone, every
realistic mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine
switched off; ``today`` recorded from one run after the set was chosen, at commit fd81b66, the commit the set's branch
started from, an empty string where the check names nothing; every entry's check failed in that run, so none was
dropped after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the twenty
earlier sets, their named companions, the engine's own tests or the planted suite (the same file and replaced text,
the same planted text, or the same slip written otherwise) was dropped.  It holds 27 entries in 20 problems of all
seven exercises (I 3, II 2, III 4, IV 4, V 5, VI 4, VII 5), at most two of one problem (seven problems hold two), 11
of them in the problems of ``SIMULATED`` and 13 in Exercise I's MuJoCo problems and the runs; it is smaller than the
sets before it because the earlier sets had taken nearly every slip tried (more than three in five candidates repeated
an earlier entry's text), and Exercise VII's share of the set bounds its size with the entries the other exercises
gave.  Its slips are spread over 12 families: order 5, precision 4, scale 3, and missing_term, extra_term, frame,
transpose, step_size and time_shift 2 each, sign, ignored_argument and initial_state 1 each (no family above 20% of
the set).  One entry names a second family (``also``), decided from the slip alone: order.  Of 232 candidates tried
(each counted once; about 20 screening runs), 205 were dropped: 148 repeated an earlier entry by its text (90 the same
replaced and planted text, 29 the same replaced text only, 29 the same planted text only), all of them found before
the recording run, 40 failed no check (most in the problems' own scripts and constants, which the checks replace with
their own, and some in helpers the checks do not call), 10 erred in their first failing check (or left it not
implemented), 3 were left out for proportion and spread (Exercise VII above its share, a sixth entry of the family
``order``), and 4 were left out before grading (no family of the grammar fits them, or contrived).  None was dropped as
the same slip as an earlier entry written otherwise.  The whole set takes well under a minute on a two-core machine
(37 s graded, 40 s in all, in the recording run); it was written in about 20 minutes.

``--set fresh22`` is a twenty-second held-out set (``tests/diagnosis/fresh22/``), written like the twenty-first and
kept from the engine's builders until they were done: from the sheet, the problem data and the reference alone, every
realistic mistake whose check fails, whatever the grader of the day said of it (chosen with the diagnosis engine
switched off; ``today`` recorded from one run after the set was chosen, at commit 307961c, the commit the set's branch
started from, an empty string where the check names nothing; every entry's check failed in that run, so none was
dropped after it).  Its check is the first of its problem's checks that it fails; a slip that repeats one of the
twenty-one earlier sets, their named companions, the engine's own tests or the planted suite (the same file and
replaced text, the same planted text, or the same slip written otherwise) was dropped.  It holds 26 entries in 20
problems of all seven exercises (I 2, II 4, III 4, IV 4, V 4, VI 3, VII 5), at most two of one problem (six problems
hold two), 10 of them in the problems of ``SIMULATED`` and 14 in Exercise I's MuJoCo problems and the runs (12 without
problem 24's run); it is smaller than the sets before it because the earlier sets had taken nearly every slip tried
(six in ten candidates repeated an earlier entry's text), and Exercise VII's share of the set bounds its size with the
entries the other exercises gave.  Its slips are spread over 12 families: frame 5, precision 5, time_shift 3,
transpose 3, inverse 2, order 2, and extra_term, sign, scale, missing_term, state_row and ignored_argument 1 each (no
family above 20% of the set).  One entry names a second family (``also``), decided from the slip alone: transpose.
Of 232 candidates tried (a slip whose replaced text an earlier entry had replaced was tried again with a narrower or
wider span of its line, and is counted once, by its last try; about 25 screening runs), 206 were dropped: 138
repeated an earlier entry by its text (the same replaced or planted text), all of them found before the recording
run, 38 failed no check (most in the problems' own scripts and in library code that the checks replace with their
own), 16 erred in their first failing check (or left it not implemented), 11 failed their check but were the same
slip as an earlier entry written otherwise (found by comparing each with the earlier entries on the same line), 1 was
left out for proportion and realism (Exercise VII above its share, a contrived edit), 1 was left out before grading
(contrived) and 1 was left out before grading (its text did not occur once in the reference as written).  The whole
set takes about half a minute on a two-core machine (28 s graded, 30 s in all, in the recording run); it was written
in about 25 minutes.

``--set fresh23``, the twenty-third held-out set (``tests/diagnosis/fresh23/``), follows the rules of the twenty-second
and was kept from the engine's builders until they were done.  Its writer worked from the sheet, the problem data and
the reference alone and kept every realistic mistake whose check fails, whatever the grader of the day said of it: the
candidates were graded with the diagnosis engine switched off, and ``today`` was recorded from a single run once the
set was chosen (at commit 734e1e7, where the set's branch started; an empty string where the check names nothing).
Every entry's check failed in that run, so no entry was dropped after it.  Each entry's check is the first of its
problem's checks that it fails, and a slip that repeats one of the twenty-two earlier sets, their named companions,
the engine's own tests or the planted suite (by its file and replaced text, by its planted text, or as the same slip
written otherwise) was dropped.  It holds 31 entries in 22
problems of all seven exercises (I 3, II 3, III 4, IV 5, V 5, VI 5, VII 6), at most three of one problem (one problem
holds three, seven hold two), 14 of them in the problems of ``SIMULATED`` and 17 in Exercise I's MuJoCo problems and
the problems with runs; the earlier sets had again taken most slips tried (six in ten candidates repeated an earlier
entry's text), and Exercises VI and VII's shares of the set bound its size with the entries the other exercises gave.
Its slips are spread over 13 families: missing_term 4, order 4, precision 4, state_row 4, sign 3, extra_term 2, frame
2, time_shift 2, transpose 2, and event, ignored_argument, initial_state and scale 1 each (no family above 20% of the
set).  One entry names a second family (``also``), decided from the slip alone: state_row.  Of 279 candidates tried (a
slip whose replaced text an earlier entry had replaced was tried again with a narrower or wider span of its line, and
is counted once, by its last try; 13 screening runs), 248 were dropped: 174 repeated an earlier entry by its text (the
same replaced or planted text, or its name), all of them found before the recording run, 47 failed no check (most in
the problems' own scripts and in library code that the checks replace with their own), 13 erred in their first
failing check (or left it not implemented), 6 were the same slip as an earlier entry written otherwise (found by
comparing each with the earlier entries on the same line), 3 failed their check but were left out for proportion and
spread (Exercises VI and VII above their shares), 4 were left out before grading (contrived or unfinished) and 1 was
left out before grading (its text did not occur once in the reference as written).  The whole set takes well under a
minute on a two-core machine (37 s graded, 38 s in all, in the recording run); it was written in about 25 minutes.

``--set fresh24``, the twenty-fourth held-out set (``tests/diagnosis/fresh24/``), follows the rules of the
twenty-third and was kept from the engine's builders until they were done.  Its writer worked from the sheet, the
problem data and the reference alone and kept every realistic mistake whose check fails, whatever the grader of the day
said of it: the candidates were graded with the diagnosis engine switched off, and ``today`` was recorded from a single
run once the set was chosen (at commit 66e8e66, where the set's branch started; an empty string where the check names
nothing).  Every entry's check failed in that run, so no entry was dropped after it.  Each entry's check is the first
of its problem's checks that it fails, and a slip that repeats one of the twenty-three earlier sets, their named
companions, the engine's own tests or the planted suite (by its file and replaced text, by its planted text, by its
name, or as the same slip written otherwise) was dropped.  It holds 26 entries in 19 problems of all seven exercises
(I 4, II 2, III 3, IV 6, V 4, VI 2, VII 5), at most three of one problem (two problems hold three, three hold two), 12
of them in the problems of ``SIMULATED`` and 12 in Exercise I's MuJoCo problems and the problems with runs (15
counting problem 24's run); the earlier sets had taken most slips tried (more than six in ten candidates repeated an
earlier entry's text), and Exercises IV and VII's shares of the set bound its size with the entries the other
exercises gave.  Its slips are spread over 12 families: order 5, scale 3, state_row 3, time_shift 3, extra_term 2,
missing_term 2, precision 2, sign 2, and ignored_argument, initial_state, offset and transpose 1 each (no family above
20% of the set).  One entry names a second family (``also``), decided from the slip alone: order.  Of 228 candidates
tried (a slip whose replaced text an earlier entry had replaced was tried again with a narrower span of its line, and
is counted once, by its last try; 13 screening runs), 202 were dropped: 145 repeated an earlier entry by its text (the
same replaced or planted text, or its name), all of them found before the recording run, 37 failed no check (most in
the problems' own scripts and in functions that the checks do not call), 8 erred in their first failing check (or left
it not implemented), 1 was the same slip as an earlier entry written otherwise (found by comparing it with the earlier
entries on the same line), 5 failed their check but were left out for proportion and spread (Exercises IV and VII
above their shares, at most three of one problem, and the spread of the families), 4 were left out because their text
did not occur exactly once in the reference as written, and 2 were left out before grading (contrived, or changing
nothing that is graded).  The whole set takes about half a minute on a two-core machine (28 s in all in the
recording run); it was written in about 20 minutes.

``--set fresh25``, the twenty-fifth held-out set (``tests/diagnosis/fresh25/``), follows the rules of the
twenty-fourth and was kept from the engine's builders until they were done.  Its writer worked from the sheet, the
problem data and the reference alone and kept every realistic mistake whose check fails, whatever the grader of the day
said of it: the candidates were graded with the diagnosis engine switched off, and ``today`` was recorded from a single
run once the set was chosen (at commit 3d59502, where the set's branch started; an empty string where the check names
nothing).  Every entry's check failed in that run, so no entry was dropped after it.  Each entry's check is the first
of its problem's checks that it fails, and a slip that repeats one of the twenty-four earlier sets, their named
companions, the engine's own tests or the planted suite (by its file and replaced text, by its planted text, by its
name, or as the same slip written otherwise) was dropped.  It holds 28 entries in 21 problems of all seven exercises
(I 3, II 4, III 5, IV 3, V 4, VI 4, VII 5), at most two of one problem (seven problems hold two), 11 of them in the
problems of ``SIMULATED`` and 15 in Exercise I's MuJoCo problems and the problems with runs (17 counting problem 24's
run); the earlier sets had taken most slips tried (a third of the candidates repeated an earlier entry's text, and
most of the others failed no check or erred), and Exercises II and VI's shares of the set bound its size with the
entries the other exercises gave.  Its slips are spread over 13 families: order 5, sign 4, transpose 4, extra_term 3,
ignored_argument 2, missing_term 2, precision 2, and event, frame, inverse, scale, state_row and time_shift 1 each (no
family above 20% of the set).  Three entries name a second family (``also``), decided from the slip alone: sign 2 and
state_row 1.  Of 125 candidates tried (a slip whose replaced text an earlier entry had replaced was tried again with a
narrower or wider span of its line, and is counted once, by its last try; 14 screening runs), 97 were dropped: 41
repeated an earlier entry by its text (the same replaced or planted text, or its name), all of them found before the
recording run, 38 failed no check (most in the problems' own scripts outside the graded functions, and in library
code that the checks do not reach with the problems' data), 11 erred in their first failing check (or left it not
implemented), 1 was the same slip as an earlier entry written otherwise (found by comparing it with the earlier entries
on the same line), 3 failed their check but were left out for proportion and spread (Exercise VI above its share, and
two families above a fifth of the set), and 3 were left out before grading (contrived, or changing nothing that is
graded).  The whole set takes about half a minute on a two-core machine (30 s in all in the recording run); it was
written in about 25 minutes.

``--set fresh26``, the twenty-sixth held-out set (``tests/diagnosis/fresh26/``), follows the rules of the
twenty-fifth and was kept from the engine's builders until they were done.  Its writer worked from the sheet, the
problem data and the reference alone and kept every realistic mistake whose check fails, whatever the grader of the day
said of it: the candidates were graded with the diagnosis engine switched off, and ``today`` was recorded from a single
run once the set was chosen (at commit 6178771, where the set's branch started; an empty string where the check names
nothing).  Every entry's check failed in that run, so no entry was dropped after it.  Each entry's check is the first
of its problem's checks that it fails, and a slip that repeats one of the twenty-five earlier sets, their named
companions, the engine's own tests or the planted suite (by its file and replaced text, by its planted text, by its
name, or as the same slip written otherwise) was dropped.  It holds 30 entries in 22 problems of all seven exercises
(I 4, II 5, III 7, IV 3, V 4, VI 3, VII 4), at most three of one problem (one problem holds three, six hold two), 10
of them in the problems of ``SIMULATED`` and 16 in Exercise I's MuJoCo problems and the problems with runs (17
counting problem 24's run); the earlier sets had taken most slips tried (more than half of the candidates repeated an
earlier entry's text, and most of the others failed no check or erred), and Exercises IV and VI's shares of the set
bound its size with the entries the other exercises gave.  Its slips are spread over 12 families: order 6, precision
5, scale 4, transpose 3, extra_term 2, ignored_argument 2, missing_term 2, offset 2, and frame, initial_state, sign
and state_row 1 each (no family above 20% of the set).  Three entries name a second family (``also``), decided from
the slip alone: initial_state, order and sign 1 each.  Of 261 candidates tried (a slip whose replaced text an earlier
entry had replaced was tried again with a narrower or wider span of its line, and is counted once, by its last try; 19
screening runs), 231 were dropped: 135 repeated an earlier entry by its text (the same replaced or planted text, or its
name), all of them found before the recording run, 57 failed no check (most in the problems' own scripts and data
outside the graded functions, in the runs' options that the checks' bands allow, and in library code that the checks
do not reach with the problems' data), 17 erred in their first failing check (or left it not implemented), 5 were the
same slip as an earlier entry written otherwise (found by comparing each with the earlier entries on the same line),
1 failed its check but was left out (contrived, its answer's form rather than a cause), and 16 were left out before
grading (contrived, or changing nothing that is graded).  The whole set takes about half a minute on a two-core
machine (29 s in all in the recording run); it was written in about 25 minutes.

``--set fresh27``, the twenty-seventh held-out set (``tests/diagnosis/fresh27/``), follows the rules of the
twenty-sixth and was kept from the engine's builders until they were done.  Its writer worked from the sheet, the
problem data and the reference alone and kept every realistic mistake whose check fails, whatever the grader of the
day said of it: the candidates were graded with the diagnosis engine switched off, and ``today`` was recorded from a
single run once the set was chosen (at commit 6a209c6, where the set's branch started; an empty string where the check
names nothing).  Every entry's check failed in that run, so no entry was dropped after it.  Each entry's check is the
first of its problem's checks that it fails, and a slip that repeats one of the twenty-six earlier sets, their named
companions, the engine's own tests or the planted suite (by its file and replaced text, by its planted text, by its
name, or as the same slip written otherwise) was dropped.  It holds 33 entries in 24 problems of all seven exercises
(I 2, II 2, III 6, IV 7, V 5, VI 5, VII 6), at most two of one problem (nine problems hold two), 11 of them in the
problems of ``SIMULATED`` and 15 in Exercise I's MuJoCo problems and the problems with runs (16 counting problem 24's
run); the earlier sets had taken most slips tried (more than seven in ten candidates repeated an earlier entry's text,
and most of the others failed no check), and Exercises IV and VI's shares of the set bound its size with the entries
the other exercises gave.  Its slips are spread over 12 families: order 6, sign 4, state_row 4, extra_term 3,
missing_term 3, scale 3, transpose 3, ignored_argument 2, step_size 2, and frame, initial_state and time_shift 1 each
(no family above 20% of the set).  Two entries name a second family (``also``), decided from the slip alone:
state_row and time_shift 1 each.  Of 348 candidates tried (a slip whose replaced text an earlier entry had replaced
was tried again with a narrower or wider span of its line, and is counted once, by its last try; 15 grading runs,
each after a screen of the texts), 315 were dropped: 251 repeated an earlier entry by its text (the same replaced or
planted text, or its name), all of them found before the recording run, 39 failed no check (most in the problems'
own scripts and data outside the graded functions, in the runs' options and defaults that the checks' bands or calls
allow, and in code that the checks reach only with the problems' own data), 10 erred in their first failing check (or
left it not implemented), 3 were left out because their text did not occur exactly once in the reference as written,
7 failed their check but were left out (3 for Exercise IV's share and a fifth of the set in one family, 1 the same
slip as an earlier entry written otherwise, 1 a second slip of the same kind in one problem, 1 whose cause no family
fits, and 1 that proved no mistake on a closer reading), and 5 were left out before grading (1 changing nothing
that is graded, 1 contrived, 1 the same slip as an earlier entry written otherwise, and 2 that were not graded before
the set was chosen).  The whole set takes about a minute on a two-core machine (55 s graded, 58 s in all in the
recording run); it was written in about 30 minutes.

``--set fresh28``, the twenty-eighth held-out set (``tests/diagnosis/fresh28/``), was written, chosen and checked for
repeats (of the twenty-seven earlier sets as well) by the twenty-seventh's rules above, with ``today`` recorded at
commit 58e2536, where its branch started; no entry was dropped after that run.  It holds 31 entries in 27 problems of
all seven exercises (I 2, II 3, III 6, IV 6, V 5, VI 3, VII 6), at most two of one problem (four problems hold two), 10
of them in the problems of ``SIMULATED`` and 10 in Exercise I's MuJoCo problems and the runs of problems 8, 37, 38, 42,
44, 46 and 47 (11 counting problem 24's run); the earlier sets had taken most slips tried (more than eight in ten
candidates repeated an earlier entry's text, and most of the others failed no check), and Exercise I's few untaken slips
and Exercise VII's share of the set (at most a fifth) bound its size with the entries the other exercises gave.  Its
slips are spread over 12 families: missing_term 5, order 5, precision 4, frame 3, state_row 3, ignored_argument 2, scale
2, sign 2, transpose 2, and extra_term, offset and step_size 1 each (no family above 20% of the set).  Two entries name
a second family (``also``), decided from the slip alone: frame and inverse 1 each.  Of 478 candidates tried (a slip
whose replaced text an earlier entry had replaced was tried again with a narrower or wider span of its line, and is
counted once, by its last try; 16 grading runs, each after a screen of the texts), 447 were dropped: 392 repeated an
earlier entry by its text (the same replaced or planted text, or its name), all of them found before the recording run,
13 were the same slip as an earlier entry written otherwise (found by comparing each with the earlier entries on the
same line; 8 of them after they had failed their check), 28 failed no check (most in the problems' own scripts outside
the graded functions, in the runs' options and output grids that the checks' bands or calls allow, and in code that the
checks reach only with the problems' own data), 7 erred in their first failing check, 1 was left out because its text
did not occur exactly once in the reference as written, and 6 failed their check but were left out for proportion and
spread (3 for Exercise VII's share, 2 for the share of the precision family and Exercise II, and 1 a third entry of one
problem).  The whole set takes under a minute on a two-core machine (41 s graded, 43 s in all in the recording run); it
was written in about 30 minutes.

``--set fresh29``, the twenty-ninth held-out set (``tests/diagnosis/fresh29/``), was written, chosen and checked for
repeats (of the twenty-eight earlier sets as well) by the twenty-seventh's rules above, with ``today`` recorded at
commit 9bbe3a1, where its branch started; every entry's check failed in that run, so no entry was dropped after it.  It
holds 32 entries in 24 problems of all seven exercises (I 3, II 3, III 5, IV 6, V 4, VI 5, VII 6), at most two of one
problem (eight problems hold two), 13 of them in the problems of ``SIMULATED`` and 13 in Exercise I's MuJoCo problems
and the runs of problems 8, 37, 38, 42, 44, 46 and 47 (15 counting problem 24's run); the earlier sets had taken most
slips tried (more than seven in ten candidates repeated an earlier entry's text), and the candidates that failed their
check outnumbered the set in Exercises IV and VII, whose shares (at most six entries of VII) and the limit of two
entries of one problem bound the set with the entries the other exercises gave.  Its slips are spread over 13 families:
missing_term 6, order 5, transpose 5, sign 3, state_row 3, inverse 2, scale 2, and event, extra_term, frame,
initial_state, precision and step_size 1 each (no family above 20% of the set).  Two entries name a second family
(``also``), decided from the slip alone: sign and transpose 1 each.  Of 513 candidates tried (58 of them tried again
with a narrower or wider span of their line after an earlier entry had replaced the same text, each counted once, by its
last try; 38 of them taken from a mechanical screen of the solutions' lines for edits that no earlier entry had planted,
and kept where the slip was one a student makes; 10 grading runs, each after a screen of the texts), 481 were dropped:
368 repeated an earlier entry by its text (the same replaced or planted text, or its name), all of them found before the
recording run, 21 were the same slip as an earlier entry written otherwise (one of them the same as another candidate;
found by comparing each with the earlier entries on the same line, all before they were graded), 32 failed no check
(most in the problems' own scripts and test data that the checks do not read, in arguments that the checks pass as their
defaults, and in changes that the answers do not feel, such as a sign under a square or a rounding within the checks'
bands), 10 erred in their first failing check, 5 were left out because their text did not occur exactly once in the
reference as written, and 45 failed their check but were left out for proportion and spread (16 a third entry of a
problem that held two, and 29 for the shares of Exercises VII 12, IV 10, II 3, I 2 and VI 2 and of the missing_term
family).  The whole set takes under a minute and a half on a two-core machine beside another long test run (82 s graded,
84 s in all in the recording run); it was written in about 25 minutes.

``--set fresh30``, the thirtieth held-out set (``tests/diagnosis/fresh30/``), was written, chosen and checked for
repeats (of the twenty-nine earlier sets as well) by the twenty-seventh's rules above, with the diagnosis engine
switched off for the choice and ``today`` recorded from one run at commit 75d6243, where its branch started; every
entry's check failed in that run, so no entry was dropped after it.  It holds 32 entries in 25 problems of all seven
exercises (I 3, II 3, III 5, IV 6, V 4, VI 5, VII 6), at most two of one problem (seven problems hold two), 13 of them
in the problems of ``SIMULATED`` and 13 in Exercise I's problems and the runs of problems 8, 37, 38, 42, 44, 46 and 47
(15 counting problem 24's run); the earlier sets had taken many of the slips tried (about a third of the candidates
repeated an earlier entry's text), and problem 42 gave a single slip that failed its check in 22 tries.  Its slips are
spread over 12 families: sign 5, missing_term 4, order 4, state_row 4, ignored_argument 3, scale 3, transpose 3,
initial_state 2, and extra_term, frame, offset and precision 1 each (no family above 20% of the set).  Three entries
name a second family (``also``), decided from the slip alone: missing_term 2 and transpose 1.  Of 248 candidates tried
(4 of them tried again with a narrower or wider span of their line after an earlier entry had replaced the same text,
each counted once, by its last try; 138 of them taken from a mechanical screen of the solutions' lines for edits that no
earlier entry had planted, and kept where the slip was one a student makes, which gave 26 of the entries; 15 grading
runs, each after a screen of the texts), 216 were dropped: 79 repeated an earlier entry by its text (the same replaced
or planted text, or its name), all of them found before the recording run, 7 were the same slip as an earlier entry
written otherwise (one found before it was graded, six after, by comparing each with the earlier entries on the same
line, all before the recording run), 74 failed no check (16 of them in the reference-only code of problems 2 and 3 that
the checks do not read, most others in the problems' own scripts and in changes that the answers do not feel within the
checks' bands), 30 erred in their first failing check, 1 was left out because its text did not occur exactly once in the
reference as written, 2 failed their check but were left out as slips no student makes (a typo that turns a square into
a power and a mass matrix term of the wrong units), and 23 failed their check but were left out for proportion and
spread (6 a third entry of a problem that held two, and 17 for the shares of Exercises III 7, II 3, IV 2, VI 2, I 1, V 1
and VII 1).  The whole set takes over two minutes on a two-core machine beside other work (129 s graded, 131 s in all in
the recording run); it was written in about 30 minutes.

``--set fresh31``, the thirty-first held-out set (``tests/diagnosis/fresh31/``), was written, chosen and checked for
repeats (of the thirty earlier sets as well) by the twenty-seventh's rules above, with the diagnosis engine switched
off for the choice and ``today`` recorded from one run of the whole set at commit 8943590, where its branch started;
every entry's check failed in that run, so no entry was dropped after it (an earlier recording run of a draft was set
aside when the tests of the set found no entry of problems 24 and 38, whose slips had all erred or repeated; two
entries, of problems 3 and 39, were exchanged for one of each, chosen with the engine off like the others, before the
run recorded here).  It holds 32 entries in 24 problems of all seven exercises (I 3, II 3, III 5, IV 6, V 4, VI 5,
VII 6), at most two of one problem (eight problems hold two), 11 of them in the problems of ``SIMULATED`` (every one
but problem 5); the earlier sets had taken most of the slips tried (more than half of the candidates repeated an
earlier entry's text), and the simulated problems' runs gave few slips whose first failing check failed rather than
erred.  Its slips are spread over 12 families: order 6, sign 5, transpose 4, extra_term 3, scale 3, state_row 3,
ignored_argument 2, missing_term 2, and initial_state, inverse, offset and precision 1 each (no family above 20% of
the set).  One entry names a second family (``also``), decided from the slip alone: order 1.  Of 317 candidates tried
(a slip whose replaced text an earlier entry had replaced was tried with a narrower or wider span of its line, and is
counted once; 98 of them taken from a mechanical screen of the solutions' lines for edits that no earlier entry had
planted, and kept where the slip was one a student makes, which gave 27 of the entries; 12 grading runs, each after a
screen of the texts), 285 were dropped: 169 repeated an earlier entry by its text (the same replaced or planted text,
or its name), all of them found before grading, 18 were the same slip as an earlier entry written otherwise (found by
comparing each with the earlier entries on the same line, all before the recording run), 27 failed no check (most in
the runs' tolerances, methods and output grids and the MuJoCo models' options that the checks' bands allow, and in
event directions the runs do not feel), 14 erred in their first failing check (most of them outputs of the wrong
shape and calls that raise), 3 were left out
because their text did not occur exactly once in the reference as written, 4 were left out before grading (clean
texts not graded before the set was chosen), 18 failed their check but were left out as slips no student makes
(mechanical edits that garble an expression, stray signs on whole rotations and contrived extra terms), and 32 failed
their check but were left out for proportion and spread (the shares of the families sign and order, a third entry of
a problem that held two, the shares of the exercises, and the two entries exchanged for problems 24 and 38).  The
whole set takes about a minute and a half on a two-core machine beside other work (94 s graded, 96 s in all in the
recording run); it was written in about 30 minutes.

``--set fresh32``, the thirty-second held-out set (``tests/diagnosis/fresh32/``), was written, chosen and checked for
repeats (of the thirty-one earlier sets as well) by the twenty-seventh's rules above, with the diagnosis engine
switched off for the choice and ``today`` recorded from one run of the whole set at commit 2cae369, where its branch
started; every entry's check failed in that run, so no entry was dropped after it (the replaced text of one entry, of
problem 19, was widened by the line before it after the tests of the set found the bare line replaced by an earlier
entry; it plants the same file, so its grading is unchanged).  Unlike the thirtieth and thirty-first sets, no slip
was taken from a mechanical screen of the solutions' lines: every candidate was written by hand from the sheet, the
problem data and the reference, as a student of the course slips (a convention misread, a formula of the lecture in
the other frame, a value taken from the wrong line or column, a term forgotten, a library call used wrongly, a
number rounded or converted once too often, a wrong choice in answers.toml), many of them spanning or restructuring a
line, and a slip whose replaced text an earlier entry had replaced with another slip was tried again with a wider
span of its lines.  It holds 26 entries in 21 problems of all seven exercises (I 2, II 3, III 3, IV 5, V 4, VI 4,
VII 5), at most two of one problem (five problems hold two), 10 of them in the problems of ``SIMULATED`` (every one
but problem 5, two in each of problems 37 and 47); the earlier sets had taken most slips tried (three in four
candidates repeated an earlier entry's text), the shares of Exercises VI and VII (at most a sixth and a fifth of the
set) bound the simulated entries of those exercises, and the few untaken slips of Exercises I, III and V bound the
set's size.  Its slips are spread over 12 families: scale 5, order 4, missing_term 3, precision 3, extra_term 2,
frame 2, sign 2, and initial_state, inverse, offset, step_size and transpose 1 each (no family above 20% of the set).
One entry names a second family (``also``), decided from the slip alone: state_row 1.  Of 309 candidates tried (a
slip tried again with a wider span is counted once, by its last try; 15 grading runs, each after a screen of the
texts), 283 were dropped: 235 repeated an earlier entry by its text (the same replaced or planted text, or its name),
all of them found before grading, 11 were the same slip as an earlier entry written otherwise (found by comparing
each with the earlier entries on the same lines, all before the recording run; 4 of them after they had failed their
check), 21 failed no check (most in the MuJoCo models' and the runs' options and outputs that the checks' bands or
calls allow, in the choice among balanced configurations of problem 4, and in problem 14's run, whose checks test the
screw's properties rather than the start values), 9 erred in their first failing check (outputs of the wrong shape,
a None where an object was needed, and a symbolic solve that raised), 2 were left out before grading as slips no
student makes (a halved acceleration and a run cut by a row), and 5 failed their check but were left out for
proportion and spread (3 for the shares of Exercises VI and VII, 1 a second entry of problem 19 that would have put
the family scale above a fifth of the set, and 1 a second entry of problem 24 that would have left Exercise III at the
edge of its share).  The whole set takes about a minute on a two-core machine beside other work (62 s graded, 64 s in
all in the recording run); it was written in about 30 minutes.

``--set fresh33``, the thirty-third held-out set (``tests/diagnosis/fresh33/``), was written, chosen and checked for
repeats (of the thirty-two earlier sets as well) by the twenty-seventh's rules above, with the diagnosis engine switched
off for the choice and ``today`` recorded from one run of the whole set at commit 886067f, where its branch started;
every entry's check failed in that run, so no entry was dropped after it.  Like the thirty-second set, and unlike the
thirtieth and thirty-first, no slip was taken from a mechanical screen of the solutions' lines: every candidate was
written by hand from the sheet, the problem data and the reference, as a student of the course slips (a convention
misread, a formula of the lecture in the other frame, a unit converted once too often or a constant typed rounded, a
term forgotten or added, a loop or a recursion written otherwise, a library call used wrongly, a value read from the
wrong place), many of them spanning or restructuring a line, and a slip whose replaced text an earlier entry had
replaced with another slip was tried again with a wider span of its lines.  It holds 29 entries in 23 problems of all
seven exercises (I 2, II 2, III 7, IV 5, V 4, VI 4, VII 5), at most two of one problem (six problems hold two), 11 of
them in the problems of ``SIMULATED`` (every one but problem 5, two in each of problems 24, 38 and 47); the earlier sets
had taken most slips tried (more than four in five candidates repeated an earlier entry's text), and the few untaken
slips of Exercises I and II, which bound the set's size, leave them at two entries each.  Its slips are spread over 13
families: missing_term 5, scale 5, frame 4, extra_term 3, order 3, precision 2, and ignored_argument, initial_state,
inverse, offset, state_row, step_size and time_shift 1 each (no family above 20% of the set).  One entry names a second
family (``also``), decided from the slip alone: initial_state 1.  Of 353 candidates tried (a slip tried again with a
wider span is counted once, by its last try; 11 grading runs, each after a screen of the texts), 324 were dropped: 287
repeated an earlier entry by its text (the same replaced or planted text, or its name), all of them found before
grading, 22 were the same slip as an earlier entry written otherwise (found by comparing each with the earlier entries
on the same lines, all before the recording run; 2 of them after they had failed their check), 10 failed no check (most
in the MuJoCo models' options and inertias that the checks' bands allow, in the choice among balanced configurations of
problem 4, in outputs of the runs that the checks do not compare, and in rotations about one axis, which commute), 4
erred or were not implemented in their first failing check (3 erred, in answers that raised or had the wrong shape, and
1 in problem 7's symbolic check, which is not implemented), and 1 failed its check but was left out for spread (a second
entry of problem 42, whose other slip gave the set a family it lacked).  The whole set takes about a minute on a
two-core machine beside other work (66 s graded, 71 s in all in the recording run); it was written in about 30 minutes.

``--set fresh34``, the thirty-fourth held-out set (``tests/diagnosis/fresh34/``), was written, chosen and checked for
repeats (of the thirty-three earlier sets as well) by the twenty-seventh's rules above, with the diagnosis engine
switched off for the choice and ``today`` recorded from one run of the set at commit 44a5c82, where its branch started;
every entry's check failed in that run, and two entries graded in it were dropped after it, found by the tests of the
set (one replaced the same text as an earlier entry and, widened by the line before it, was the same slip as an earlier
entry written otherwise; the other planted the same text as the planted suite, having been screened against the wrong
file), so the set holds the other 25 with the diagnosis that run gave them. Like the thirty-second and thirty-third
sets, and unlike the thirtieth and thirty-first, no slip was taken from a mechanical screen of the solutions' lines:
every candidate was written by hand from the sheet, the problem data and the reference, as a student of the course
slips (a convention misread, a formula of the lecture in the other frame, a term forgotten or carried over from another
part of the sheet, a loop or a slice written otherwise, a library call or an argument used wrongly, a value read from
the wrong place, a number rounded), many of them spanning or restructuring a line, and a slip whose replaced text an
earlier entry had replaced with another slip was tried again with a wider span of its lines; unlike the earlier sets'
screens, this one also left out every slip in code that the student template gives (its constants and given functions),
which a student does not write. It holds 25 entries in 19 problems of all seven exercises (I 2, II 2, III 3, IV 4, V 5,
VI 4, VII 5), at most two of one problem (six problems hold two), 10 of them in the problems of ``SIMULATED`` (every
one but problem 5, two in each of problems 38 and 47); the earlier sets had taken most slips tried (more than three in
five candidates repeated an earlier entry's text), and the few untaken slips written in the student's own code of
Exercises I, II and III bound the set's size. Its slips are spread over 13 families: missing_term 4, frame 3, sign 3,
extra_term 2, ignored_argument 2, order 2, precision 2, scale 2, and event, inverse, offset, state_row and transpose 1
each (no family above 20% of the set). One entry names a second family (``also``), decided from the slip alone:
initial_state 1. Of 298 candidates tried (a slip tried again with a wider span is counted once, by its last try; 7
grading runs, each after a screen of the texts), 273 were dropped: 192 repeated an earlier entry by its text (the same
replaced or planted text, or its name), 191 of them found before grading and 1 by the tests after the recording run, 40
changed code that the student template gives (constants typed from the problem data and given functions; 11 of them
graded before that screen was added), 24 were the same slip as an earlier entry written otherwise (found by comparing
each with the earlier entries on the same lines, 23 before grading and 1 after the recording run), 2 were left out
before grading as slips no student makes (a least-squares solve of part of a system and a mass matrix inverted by
halves), 9 failed no check (most in the runs' tolerances, start rows and output rows that the checks' bands or calls
allow, in problem 4's balanced configurations and wrapping of angles, and in rotations about one axis, which commute),
5 erred in their first failing check (outputs of the wrong shape and ports whose prints raise), and 1 failed its check
but was left out for spread (a third entry of problem 31, exchanged for two that gave the set the families state_row
and transpose). The whole set takes about a minute and a quarter on a two-core machine beside other work (75 s graded,
76 s in all in the recording run); it was written in about 20 minutes.

**Two classifications.**  Every run classifies each diagnosis twice: *strictly* (right only when a told family is
the entry's ``family``, as above) and *leniently* (right when a told family is its ``family`` or its ``also``;
wrong only when the told families include neither).  Both are reported, per mistake (``-v``) and in the totals;
an entry without ``also`` is classified alike both ways, so the sets without it read exactly as before.
"""

from __future__ import annotations

import argparse
import importlib
import json
import shutil
import sys
import tempfile
import time
import tomllib
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:  # grade with the checks of the tree this script belongs to
    sys.path.insert(0, str(ROOT))

__all__ = [
    "FAMILIES",
    "EXERCISES",
    "FALLBACK",
    "FRESH",
    "NAMED",
    "FRESH2",
    "NAMED2",
    "FRESH3",
    "NAMED3",
    "FRESH4",
    "FRESH5",
    "FRESH6",
    "FRESH7",
    "FRESH8",
    "FRESH9",
    "FRESH10",
    "FRESH11",
    "FRESH12",
    "FRESH13",
    "FRESH14",
    "FRESH15",
    "FRESH16",
    "FRESH17",
    "FRESH18",
    "FRESH19",
    "FRESH20",
    "FRESH21",
    "FRESH22",
    "FRESH23",
    "FRESH24",
    "FRESH25",
    "FRESH26",
    "FRESH27",
    "FRESH28",
    "FRESH29",
    "FRESH30",
    "FRESH31",
    "FRESH32",
    "FRESH33",
    "FRESH34",
    "SETS",
    "HELD_OUT",
    "SYMPTOMS",
    "SEED",
    "VERDICTS",
    "READINGS",
    "SAMPLED",
    "Fresh",
    "Graded",
    "Naming",
    "fresh_mistakes",
    "defects",
    "plant",
    "exercise_of",
    "naming",
    "candidate_families",
    "classify",
    "grade_all",
    "summary",
    "main",
]

FRESH = ROOT / "tests" / "diagnosis" / "fresh"
#: mistakes written for the fresh set that today's catalogues already name rightly: not in the set, kept to measure
#: the whole pool of candidates (``--set pool``) and to see that a new diagnosis keeps naming them (``--set named``)
NAMED = ROOT / "tests" / "diagnosis" / "named"
#: the second held-out set, written apart from the engine and from the first set, and its candidates already named
FRESH2 = ROOT / "tests" / "diagnosis" / "fresh2"
NAMED2 = ROOT / "tests" / "diagnosis" / "named2"
#: the third held-out set, written apart from the engine and kept from its builders, and its candidates already named
FRESH3 = ROOT / "tests" / "diagnosis" / "fresh3"
NAMED3 = ROOT / "tests" / "diagnosis" / "named3"
#: the fourth held-out set, written apart from the engine: every realistic mistake whose check fails, named or not
FRESH4 = ROOT / "tests" / "diagnosis" / "fresh4"
#: the fifth held-out set, written like the fourth apart from the engine: every realistic mistake whose check fails
FRESH5 = ROOT / "tests" / "diagnosis" / "fresh5"
#: the sixth held-out set, written like the fifth apart from the engine: every realistic mistake whose check fails
FRESH6 = ROOT / "tests" / "diagnosis" / "fresh6"
#: the seventh held-out set, written like the sixth apart from the engine, with a second family (``also``) where a
#: slip is as truly of two
FRESH7 = ROOT / "tests" / "diagnosis" / "fresh7"
#: the eighth held-out set, written like the seventh apart from the engine
FRESH8 = ROOT / "tests" / "diagnosis" / "fresh8"
#: the ninth held-out set, written like the eighth apart from the engine
FRESH9 = ROOT / "tests" / "diagnosis" / "fresh9"
#: the tenth held-out set, written like the ninth apart from the engine
FRESH10 = ROOT / "tests" / "diagnosis" / "fresh10"
#: the eleventh held-out set, written like the tenth apart from the engine
FRESH11 = ROOT / "tests" / "diagnosis" / "fresh11"
#: the twelfth held-out set, written like the eleventh apart from the engine
FRESH12 = ROOT / "tests" / "diagnosis" / "fresh12"
#: the thirteenth held-out set, written like the twelfth apart from the engine
FRESH13 = ROOT / "tests" / "diagnosis" / "fresh13"
#: the fourteenth held-out set, written like the thirteenth apart from the engine
FRESH14 = ROOT / "tests" / "diagnosis" / "fresh14"
#: the fifteenth held-out set, written like the fourteenth apart from the engine
FRESH15 = ROOT / "tests" / "diagnosis" / "fresh15"
#: the sixteenth held-out set, written like the fifteenth apart from the engine
FRESH16 = ROOT / "tests" / "diagnosis" / "fresh16"
#: the seventeenth held-out set, written like the sixteenth apart from the engine
FRESH17 = ROOT / "tests" / "diagnosis" / "fresh17"
#: the eighteenth held-out set, written like the seventeenth apart from the engine
FRESH18 = ROOT / "tests" / "diagnosis" / "fresh18"
#: the nineteenth held-out set, written like the eighteenth apart from the engine
FRESH19 = ROOT / "tests" / "diagnosis" / "fresh19"
#: the twentieth held-out set, written like the nineteenth apart from the engine
FRESH20 = ROOT / "tests" / "diagnosis" / "fresh20"
#: the twenty-first held-out set, written like the twentieth apart from the engine
FRESH21 = ROOT / "tests" / "diagnosis" / "fresh21"
#: the twenty-second held-out set, written like the twenty-first apart from the engine
FRESH22 = ROOT / "tests" / "diagnosis" / "fresh22"
#: the twenty-third held-out set, written like the twenty-second apart from the engine
FRESH23 = ROOT / "tests" / "diagnosis" / "fresh23"
#: the twenty-fourth held-out set, written like the twenty-third apart from the engine
FRESH24 = ROOT / "tests" / "diagnosis" / "fresh24"
#: the twenty-fifth held-out set, written like the twenty-fourth apart from the engine
FRESH25 = ROOT / "tests" / "diagnosis" / "fresh25"
#: the twenty-sixth held-out set, written like the twenty-fifth apart from the engine
FRESH26 = ROOT / "tests" / "diagnosis" / "fresh26"
#: the twenty-seventh held-out set, written like the twenty-sixth apart from the engine
FRESH27 = ROOT / "tests" / "diagnosis" / "fresh27"
#: the twenty-eighth held-out set, written like the twenty-seventh apart from the engine
FRESH28 = ROOT / "tests" / "diagnosis" / "fresh28"
#: the twenty-ninth held-out set, written like the twenty-eighth apart from the engine
FRESH29 = ROOT / "tests" / "diagnosis" / "fresh29"
#: the thirtieth held-out set, written like the twenty-ninth apart from the engine
FRESH30 = ROOT / "tests" / "diagnosis" / "fresh30"
#: the thirty-first held-out set, written like the thirtieth apart from the engine
FRESH31 = ROOT / "tests" / "diagnosis" / "fresh31"
#: the thirty-second held-out set, written like the thirty-first apart from the engine
FRESH32 = ROOT / "tests" / "diagnosis" / "fresh32"
#: the thirty-third held-out set, written like the thirty-second apart from the engine
FRESH33 = ROOT / "tests" / "diagnosis" / "fresh33"
#: the thirty-fourth held-out set, written like the thirty-third apart from the engine
FRESH34 = ROOT / "tests" / "diagnosis" / "fresh34"
SETS = {"fresh": (FRESH,), "named": (NAMED,), "pool": (FRESH, NAMED),
        "fresh2": (FRESH2,), "named2": (NAMED2,), "pool2": (FRESH2, NAMED2),
        "fresh3": (FRESH3,), "named3": (NAMED3,), "pool3": (FRESH3, NAMED3),
        "fresh4": (FRESH4,), "fresh5": (FRESH5,), "fresh6": (FRESH6,), "fresh7": (FRESH7,),
        "fresh8": (FRESH8,), "fresh9": (FRESH9,), "fresh10": (FRESH10,),
        "fresh11": (FRESH11,), "fresh12": (FRESH12,), "fresh13": (FRESH13,),
        "fresh14": (FRESH14,), "fresh15": (FRESH15,), "fresh16": (FRESH16,),
        "fresh17": (FRESH17,), "fresh18": (FRESH18,), "fresh19": (FRESH19,),
        "fresh20": (FRESH20,), "fresh21": (FRESH21,), "fresh22": (FRESH22,),
        "fresh23": (FRESH23,), "fresh24": (FRESH24,),
        "fresh25": (FRESH25,), "fresh26": (FRESH26,),
        "fresh27": (FRESH27,), "fresh28": (FRESH28,),
        "fresh29": (FRESH29,), "fresh30": (FRESH30,),
        "fresh31": (FRESH31,), "fresh32": (FRESH32,),
        "fresh33": (FRESH33,), "fresh34": (FRESH34,)}
#: the held-out sets, on which the issue's target is read: the first three hold only mistakes whose cause was not told
#: when they were written, the fourth to the thirty-fourth every realistic mistake whose check fails
HELD_OUT = ("fresh", "fresh2", "fresh3", "fresh4", "fresh5", "fresh6", "fresh7", "fresh8", "fresh9", "fresh10",
            "fresh11", "fresh12", "fresh13", "fresh14", "fresh15", "fresh16", "fresh17", "fresh18", "fresh19",
            "fresh20", "fresh21", "fresh22", "fresh23", "fresh24", "fresh25", "fresh26", "fresh27", "fresh28",
            "fresh29", "fresh30", "fresh31", "fresh32", "fresh33", "fresh34")
#: the held-out sets that sample every realistic mistake whose check fails (the issue's measure: ``--unlisted``)
SAMPLED = ("fresh4", "fresh5", "fresh6", "fresh7", "fresh8", "fresh9", "fresh10", "fresh11", "fresh12",
           "fresh13", "fresh14", "fresh15", "fresh16", "fresh17", "fresh18", "fresh19", "fresh20",
           "fresh21", "fresh22", "fresh23", "fresh24", "fresh25", "fresh26", "fresh27", "fresh28", "fresh29",
           "fresh30", "fresh31", "fresh32", "fresh33", "fresh34")
#: the live seed of the planted suite (``tests/kit_support.SEED``)
SEED = 12345

#: the families of true causes (issue 27's grammar)
FAMILIES = (
    "transpose", "sign", "order", "scale", "frame", "missing_term", "extra_term", "ignored_argument",
    "initial_state", "time_shift", "offset", "step_size", "event", "state_row", "inverse", "precision",
)

#: the vocabulary's families that say what an answer shows rather than what the slip did (a reflection, a run that
#: diverges) and its verdicts on an answer that does nothing (zeros or one constant, the identity, nothing returned,
#: credit resting on such results): a name of one names no cause, whatever ``FALLBACK`` read it as when the first
#: set was written.  A slip of any family may leave an answer constant (a body started at rest, an argument or a
#: term never used), so saying that it is constant says what the answer is, not what made it so
SYMPTOMS = ("handedness", "orientation", "diverged", "constant", "identity", "stub", "degenerate_input")

#: the course's exercises and their problems
EXERCISES = {"I": range(1, 6), "II": range(6, 11), "III": range(11, 21), "IV": range(21, 29),
             "V": range(29, 37), "VI": range(37, 42), "VII": range(42, 48)}

#: The families of the diagnosis names in use when the set was written (in checks/ and grader/, and every diagnosis
#: the planted suite asserts), by the cause that each name's hint tells the student.  ``None``: the name states a
#: symptom or a verdict and no cause (a shape, a load error, a false statement, an answer that does nothing, a motion
#: that does not sag).  Where a hint offers two causes, the family is the one it leads with: ``energy_drift`` ("the
#: energy of your own pendulum drifts ... use solve_ivp") and ``diverged`` ("a timestep far too large, ...") are
#: read as the integration's step.
FALLBACK: dict[str, str | None] = {
    **dict.fromkeys("""transpose orientation""".split(), "transpose"),
    **dict.fromkeys("""sign_flip axis_sign jacobian_sign impulse_sign sigma_sign gravity_sign f_sign
        constraint_force_sign constraint_sign d_sign centripetal_sign gyroscopic_sign omega_dot_sign outer_sign
        rolling_sign rolling_wrong_way rotation_sense baumgarte_sign offset_sign omega_x_r_sign omega_x_v_sign
        parallel_axis_sign slope_sign reflection inequality_reversed support_side rotation_side""".split(), "sign"),
    **dict.fromkeys("""rotation_order swapped swapped_names swapped_columns rows_swapped argument_order axis_order
        column_order state_order joint_order coordinate_order sin_cos_swapped beta_sin_cos phi_sin_cos reversed
        wrong_axis wrong_axes column_offset unsorted order gravity_axis inertia_position lever_arm""".split(),
                    "order"),
    **dict.fromkeys("""degrees rate_degrees one_third factor_two coriolis_factor mass_per_particle positions
        density_as_mass box_full_size full_length_offset com_full_length joint_at_centre semi_axes not_divided
        damping_per_degree damping_wrong_conversion unit_gear wrong_rate normalization elastic no_mass
        omega_squared cuboid_formula soft_servo mass_not_small pd_through_mass_matrix""".split(), "scale"),
    **dict.fromkeys("""wrong_frame body_coordinates inertial_coordinates inertial_frame body_frame inertial
        gravity_body_frame omega_frame offset_frame offset_not_rotated not_rotated""".split(), "frame"),
    **dict.fromkeys("""missing_centripetal centripetal coriolis no_centripetal no_gyroscopic no_gravity
        missing_omega_x_r missing_omega_x_v missing_tangential missing_outer_product no_parallel_axis missing_sigma
        missing_f missing_baumgarte missing_rotation missing_translation missing_torque missing_qdd no_bias
        no_offset no_rotation no_final_link missing_mass euler_component_form transport lever radius
        absolute_position one_sided level_ground no_actuator no_connect""".split(), "missing_term"),
    **dict.fromkeys("""about_the_joint rotation joint_extras""".split(), "extra_term"),
    **dict.fromkeys("""ignores_parent earth_gravity ignored_frame stale built_straight leftover_input
        unweighted""".split(), "ignored_argument"),
    **dict.fromkeys("""initial_state starts_at_rest not_horizontal acceleration_not_reset""".split(),
                    "initial_state"),
    **dict.fromkeys("""previous_sample nearest_sample omega_before_rotation update_order
        velocity_first""".split(), "time_shift"),
    **dict.fromkeys("""com_at_joint centre_pivot about_origin foot_offset contact_height horizontal""".split(),
                    "offset"),
    **dict.fromkeys("""integration integrator explicit_euler euler_not_exponential lost_orthonormality energy_drift
        step_count diverged""".split(), "step_size"),
    **dict.fromkeys("""no_event event_direction event_sign not_terminal apex_terminal first_support""".split(),
                    "event"),
    **dict.fromkeys("""velocity_of_B orientation_before""".split(), "state_row"),
    **dict.fromkeys("""no_inverse multiplied_not_solved ratio_inverted principal_axes_only""".split(), "inverse"),
    **dict.fromkeys("""typed_numbers""".split(), "precision"),
    **dict.fromkeys("""shape format not_finite none not_orthonormal not_symmetric not_positive_definite load_error
        refused joints contacts structure type versions install mujoco_broken identity no_motion unchanged no_error
        wrong_error no_message not_assembled no_swing mutates_argument shared_result state_between_calls
        wrong_choice wrong_column correct_statement false_statement class_names missing_class multiple_inheritance
        indirect far_from_figure wrong_matrix wrong_values chain_wrong no_recursion shallow_recursion
        leaf_prints_color past_leaf missing_prompt missing_foe_story typo_corrected sheet_misprint free_symbols
        missing plate_rejected definite_on_diagonal forgot_positive_definite forgot_symmetry
        forgot_triangle_inequality triangle_on_diagonal has_a non_holonomic total_derivative joints_changed
        unvisited_branch always_raises always_zero constant_answer density_matters energy_gain no_sag
        position_wrong""".split(), None),
}

#: the engine's family labels that are spelt otherwise than ours
_ALIASES = {"missing term": "missing_term", "extra term": "extra_term", "integration": "step_size",
            "step": "step_size", "argument": "ignored_argument", "ignored argument": "ignored_argument",
            "initial state": "initial_state", "time shift": "time_shift", "state row": "state_row",
            "row": "state_row", "permutation": "order", "float32": "precision", "rounding": "precision"}


# ---------------------------------------------------------------------------------------------- the set


@dataclass(frozen=True)
class Fresh:
    """One mistake of the fresh set: a text replacement in ``file`` of a reference copy, the check it must fail,
    the family of its true cause, what the student did, and the diagnosis the grader gave when it was written;
    ``also``: the second family of a slip that is as truly of two ("" for most)."""

    name: str
    problem: int
    file: str
    old: str
    new: str
    check: str
    family: str
    cause: str
    today: str = ""
    also: str = ""

    @property
    def exercise(self) -> str:
        return exercise_of(self.problem)


def exercise_of(problem: int) -> str:
    return next(name for name, problems in EXERCISES.items() if problem in problems)


def fresh_mistakes(folder: Path = FRESH) -> list[Fresh]:
    """Every ``[[mistake]]`` of ``folder/problem_NN.toml``, in problem order; an entry with an unknown field or
    family raises ``ValueError``."""
    mistakes = []
    for path in sorted(folder.glob("problem_*.toml")):
        number = int(path.stem.removeprefix("problem_"))
        for entry in tomllib.loads(path.read_text()).get("mistake", []):
            try:
                mistake = Fresh(problem=number, **entry)
            except TypeError as exc:
                raise ValueError(f"{path.name}: {entry.get('name', '?')}: {exc}") from None
            for field in ("family", "also"):
                label = getattr(mistake, field)
                if (label or field == "family") and label not in FAMILIES:
                    raise ValueError(f"{mistake.name}: unknown {field} {label!r}; one of {', '.join(FAMILIES)}")
            mistakes.append(mistake)
    return mistakes


def defects(mistakes: list[Fresh]) -> list[str]:
    """What is wrong with the set itself: a name used twice, a text that does not occur exactly once in its file
    of the reference, a check that is not its problem's, a family or second family (``also``) that is not one of
    ``FAMILIES``, or a second family that repeats the first."""
    found = []
    names = Counter(m.name for m in mistakes)
    found += [f"{name}: the name is used {count} times" for name, count in names.items() if count > 1]
    for mistake in mistakes:
        path = ROOT / "reference" / mistake.file
        count = path.read_text().count(mistake.old) if path.is_file() else 0
        if count != 1:
            found.append(f"{mistake.name}: its text occurs {count} times in reference/{mistake.file}")
        if not mistake.check.startswith(f"p{mistake.problem:02d}."):
            found.append(f"{mistake.name}: {mistake.check} is not a check of problem {mistake.problem}")
        if mistake.family not in FAMILIES:
            found.append(f"{mistake.name}: unknown family {mistake.family!r}")
        if mistake.also and mistake.also not in FAMILIES:
            found.append(f"{mistake.name}: unknown second family (also) {mistake.also!r}")
        if mistake.also and mistake.also == mistake.family:
            found.append(f"{mistake.name}: its second family (also) repeats its family {mistake.family!r}")
    return found


def plant(mistake: Fresh, dest: Path) -> Path:
    """A copy of the reference with ``mistake`` planted; its text must occur exactly once in its file."""
    shutil.copytree(ROOT / "reference", dest, ignore=shutil.ignore_patterns("__pycache__", "answers_*.toml"))
    target = dest / mistake.file
    text = target.read_text()
    if text.count(mistake.old) != 1:
        raise ValueError(f"{mistake.name}: its text occurs {text.count(mistake.old)} times in {mistake.file}")
    target.write_text(text.replace(mistake.old, mistake.new))
    return dest


# ---------------------------------------------------------------------------------------------- families


@dataclass(frozen=True)
class Naming:
    """How diagnosis names are mapped to families: ``family_of(name)`` gives a family of ``FAMILIES``, ``None``
    for a name that tells no cause, or ``"?"`` for a name it does not know; ``source`` says which table it is."""

    family_of: Callable[[str], str | None]
    source: str


def _normalized(label) -> str | None:
    if label is None:
        return None
    label = str(label).strip().lower()
    label = _ALIASES.get(label, label).replace(" ", "_")
    return label if label in FAMILIES else "?"


def _engine_table():
    """The family function of ``checks/_diagnoses.py``, or None when the module (or a table in it) is missing."""
    try:
        module = importlib.import_module("checks._diagnoses")
    except ModuleNotFoundError as exc:
        if exc.name != "checks._diagnoses":
            raise
        return None
    if callable(getattr(module, "family_of", None)):
        return module.family_of
    for name in ("FAMILIES", "DIAGNOSES", "TABLE", "VOCABULARY"):
        table = getattr(module, name, None)
        if isinstance(table, dict):
            return lambda diagnosis, table=table: _label(table[diagnosis])
    return None


def _label(entry):
    """The family of an entry of the engine's table: a string, or an object or dict with a ``family``."""
    if isinstance(entry, dict):
        return entry.get("family")
    return getattr(entry, "family", entry)


def naming(prefer_engine: bool = True) -> Naming:
    """The engine's table when ``checks/_diagnoses.py`` provides one (a name it does not hold is looked up in
    ``FALLBACK``), else ``FALLBACK``.  The vocabulary also has families for symptoms and verdicts (``shape``,
    ``format``, ``not_orthonormal``, ...), which are none of the grammar's causes: a name in one of those that
    ``FALLBACK`` reads as a symptom counts as naming no cause, as the module's docstring says; any other name whose
    family is not the grammar's stays unknown (wrong)."""
    engine = _engine_table() if prefer_engine else None

    def fallback(name: str):
        return FALLBACK[name] if name in FALLBACK else "?"

    if engine is None:
        return Naming(fallback, "the fallback table of tests/diagnosis/score.py (checks/_diagnoses.py has no table)")

    def family_of(name: str):
        try:
            if str(engine(name)) in SYMPTOMS:
                return None
            family = _normalized(engine(name))
        except Exception:  # noqa: BLE001 - a name the table does not hold (or refuses) is looked up in the fallback
            return fallback(name)
        if family == "?" and name in FALLBACK and FALLBACK[name] is None:
            return None  # a family of the vocabulary outside the grammar's (a shape, a format, ...): a symptom
        return family

    return Naming(family_of, "the table of checks/_diagnoses.py (names it lacks: the fallback table)")


def candidate_families(diagnosis: str, family_of) -> tuple[list[str], list[str]]:
    """``(families, unknown)``: the distinct families that a diagnosis ("x", "x or y") names, in order, and the
    names whose family is unknown.  Names that tell no cause are left out."""
    families, unknown = [], []
    for name in (part.strip() for part in diagnosis.split(" or ")):
        if not name:
            continue
        family = family_of(name)
        if family == "?":
            unknown.append(name)
        elif family is not None and family not in families:
            families.append(family)
    return families, unknown


def classify(diagnosis: str, family: str, family_of, also: str = "") -> str:
    """"right", "wrong" or "none" for the diagnosis of a mistake whose true cause is of ``family``.  Strict by
    default; with ``also`` (the second family of a slip that is as truly of two) lenient: a told family that is
    either one counts as the true one, and the diagnosis is wrong only when it tells neither."""
    families, unknown = candidate_families(diagnosis, family_of)
    true = any(f in families for f in (family, also) if f)
    if true and len(families) + len(unknown) <= 2:
        return "right"
    if true or not (families or unknown):
        return "none"  # the true family among more than two candidates, or no cause at all
    return "wrong"


# ---------------------------------------------------------------------------------------------- grading


@dataclass(frozen=True)
class Graded:
    """The grading of one mistake: the status and diagnosis of its check, and the class of the diagnosis
    ("right", "wrong", "none", or "not caught" when the check did not fail), strict (``verdict``) and lenient
    (``lenient``: right also when the told family is the mistake's ``also``)."""

    mistake: Fresh
    status: str
    diagnosis: str
    hint: str
    verdict: str
    failed: tuple[str, ...]
    #: named rightly by the check itself with the diagnosis engine switched off (None: not graded so)
    listed: bool | None = None
    #: the lenient class ("" where not classified: the strict one stands for it)
    lenient: str = ""
    #: named rightly by the check itself with the engine off, read leniently (None: not graded so)
    listed_lenient: bool | None = None

    @property
    def lenient_verdict(self) -> str:
        return self.lenient or self.verdict


def _graded(mistake: Fresh, report, family_of) -> Graded:
    results = {r.check_id: r for r in report.results}
    if mistake.check not in results:
        raise ValueError(f"{mistake.name}: problem {mistake.problem} has no check {mistake.check}")
    result = results[mistake.check]
    failed = tuple(r.check_id for r in report.results if r.status.value not in ("passed", "skipped"))
    if result.status.value != "failed":
        verdict = lenient = "not caught"
    else:
        verdict = classify(result.diagnosis, mistake.family, family_of)
        lenient = classify(result.diagnosis, mistake.family, family_of, mistake.also)
    return Graded(mistake, result.status.value, result.diagnosis, result.hint, verdict, failed, lenient=lenient)


def grade_all(mistakes: list[Fresh], family_of, progress=None, unlisted: bool = False) -> list[Graded]:
    """Grade every mistake (its problem only) on workers forked from one batch slot's warm process; with
    ``unlisted``, grade it with the diagnosis engine switched off first, to tell whether it is ``listed``."""
    import dataclasses

    import grader.diagnosis as engine
    from grader import grade_problem
    from grader.workers import Forked
    from grader.sandbox import Limits, sandbox_mode
    from grader.sandbox.zygote import Zygote, warm_modules

    problems = sorted({m.problem for m in mistakes})
    graded = []
    with tempfile.TemporaryDirectory(prefix="fresh-") as scratch, \
            Zygote(Limits(), sandbox_mode(), warm_modules(problems)) as slot:
        slot.start()
        for index, mistake in enumerate(mistakes):
            _mark_trace(mistake)
            submission = plant(mistake, Path(scratch) / f"{index:03d}")
            listed = listed_lenient = None
            if unlisted:
                engine.ENABLED = False
                try:
                    off = grade_problem(mistake.problem, submission, seed=SEED, workers=Forked(slot))
                finally:
                    engine.ENABLED = True
                off_graded = _graded(mistake, off, family_of)
                listed, listed_lenient = off_graded.verdict == "right", off_graded.lenient_verdict == "right"
            report = grade_problem(mistake.problem, submission, seed=SEED, workers=Forked(slot))
            graded.append(dataclasses.replace(_graded(mistake, report, family_of), listed=listed,
                                              listed_lenient=listed_lenient))
            shutil.rmtree(submission)
            if progress is not None:
                progress(graded[-1])
    return graded


def _mark_trace(mistake: Fresh) -> None:
    """Where the engine's trace is written (``GRADER_DIAGNOSIS_TRACE``), a line that says which mistake the
    explanations after it belong to."""
    import os

    from grader.diagnosis.trace import VARIABLE

    if os.environ.get(VARIABLE):
        with open(os.environ[VARIABLE], "a", encoding="utf-8") as out:
            out.write(json.dumps({"mistake": mistake.name, "check": mistake.check, "family": mistake.family}) + "\n")


# ---------------------------------------------------------------------------------------------- the report

#: the classes of a graded mistake
VERDICTS = ("right", "wrong", "none", "not caught")


#: the two readings of a diagnosis: strict (the told family is the entry's ``family``) and lenient (it is its
#: ``family`` or its ``also``)
READINGS = ("strict", "lenient")


def _verdict(g: Graded, reading: str) -> str:
    return g.lenient_verdict if reading == "lenient" else g.verdict


def _row(label: str, graded: list[Graded], reading: str = "strict") -> str:
    counts = Counter(_verdict(g, reading) for g in graded)
    total = len(graded)
    cells = "".join(f"{counts[v]:>5} {100 * counts[v] / total:>4.0f}%  " if total else f"{'-':>12}  "
                    for v in VERDICTS)
    return f"  {label:<10}{total:>8}    {cells}"


def _target(graded: list[Graded], what: str, reading: str = "strict") -> str:
    counts = Counter(_verdict(g, reading) for g in graded)
    right, wrong = 100 * counts["right"] / len(graded), 100 * counts["wrong"] / len(graded)
    met = right >= 60 and wrong <= 2
    prefix = "" if reading == "strict" else "lenient "
    return (f"{prefix}target (issue 27: right >= 60%, wrong <= 2%): {'met' if met else 'not met'} "
            f"(right {right:.0f}%, wrong {wrong:.0f}%; {what})")


def _table(graded: list[Graded], reading: str, weak: bool = False) -> list[str]:
    """The counts per exercise and in all (and of Exercises I, VI and VII together with ``weak``)."""
    lines = [f"  {'exercise':<10}{'mistakes':>8}    " + "".join(f"{v:>12}  " for v in VERDICTS)]
    for exercise in EXERCISES:
        mine = [g for g in graded if g.mistake.exercise == exercise]
        if mine:
            lines.append(_row(exercise, mine, reading))
    if weak:
        lines.append(_row("I+VI+VII", [g for g in graded if g.mistake.exercise in ("I", "VI", "VII")], reading))
    lines.append(_row("all", graded, reading))
    return lines


def _unlisted(graded: list[Graded]) -> list[str]:
    """The issue's measure: the mistakes whose check does not name their cause with the engine switched off, read
    strictly and then leniently (a mistake is listed in each reading by that reading of its engine-off diagnosis)."""
    lines = []
    for reading in READINGS:
        listed = (lambda g: g.listed) if reading == "strict" else (lambda g: g.listed_lenient)
        rest = [g for g in graded if not listed(g)]
        head = "listed" if reading == "strict" else "lenient reading: listed"
        lines += ["", f"{head} (named rightly with the diagnosis engine off): {len(graded) - len(rest)}; "
                      f"the issue's measure is read on the other {len(rest)}, graded with the engine on:",
                  *_table(rest, reading)]
        if rest:
            lines.append(_target(rest, "mistakes that no check names rightly without the engine", reading))
    return lines


def _line(g: Graded, family_of) -> str:
    told = g.diagnosis or "nothing"
    families, unknown = candidate_families(g.diagnosis, family_of)
    read = ", ".join(families + [f"{n}: unknown family" for n in unknown]) or "no cause"
    true = g.mistake.family + (f" (also {g.mistake.also})" if g.mistake.also else "")
    line = (f"  {g.mistake.name} [{g.mistake.check}, {g.status}] true: {true}; told: {told} ({read})\n"
            f"      {g.mistake.cause}")
    if g.verdict == "wrong" and g.hint:
        line += f"\n      the hint: {g.hint.splitlines()[0][:160]}"
    return line


def summary(graded: list[Graded], naming_: Naming, seconds: float | None = None, verbose: bool = False,
            which: str = "fresh") -> str:
    """The counts and percentages overall and per exercise, read strictly and leniently, the target, every wrong
    diagnosis, every mistake not caught, and the diagnoses that differ from those recorded with the set."""
    seconds_family = sum(1 for g in graded if g.mistake.also)
    lines = [f"diagnosis of the {which} set: {len(graded)} mistakes, graded live on workers forked from a batch "
             f"slot's warm process (seed {SEED})",
             f"families of diagnosis names: {naming_.source}", "", *_table(graded, "strict", weak=True), "",
             f"lenient reading (right also when the told family is the entry's second family, also; "
             f"{seconds_family} entries have one):", *_table(graded, "lenient", weak=True), ""]
    if graded and which in HELD_OUT:
        what = ("every mistake of the set, also those a check names without the engine (the issue's measure: "
                "--unlisted)" if which in SAMPLED else
                "the set holds only mistakes whose cause was not told when it was written")
        lines += [_target(graded, what, reading) for reading in READINGS]
    if graded and all(g.listed is not None for g in graded):
        lines += _unlisted(graded)
    for verdict, title in (("wrong", "told a wrong cause"), ("not caught", "not caught (the check did not fail)")):
        some = [g for g in graded if g.verdict == verdict]
        if some:
            lines += ["", f"{title}: {len(some)}", *(_line(g, naming_.family_of) for g in some)]
    changed = [g for g in graded if g.diagnosis != g.mistake.today]
    if changed:
        lines += ["", f"diagnosis changed since the set was recorded: {len(changed)}",
                  *(f"  {g.mistake.name}: recorded {g.mistake.today or 'nothing'!r}, now {g.diagnosis or 'nothing'!r}"
                    f" ({g.verdict}; lenient {g.lenient_verdict})" for g in changed)]
    if verbose:
        lines += ["", "every mistake (strict, lenient):"]
        for g in graded:
            others = ", ".join(c for c in g.failed if c != g.mistake.check) or "none"
            lines += [f"  {g.verdict:<10} {g.lenient_verdict:<10} {_line(g, naming_.family_of)[2:]}",
                      f"      other checks not passed: {others}"]
    if seconds is not None:
        lines += ["", f"graded in {seconds:.0f} s"]
    return "\n".join(lines)


def _select(mistakes: list[Fresh], args) -> list[Fresh]:
    if args.exercises:
        wanted = {e.strip() for e in args.exercises.split(",")}
        unknown = wanted - set(EXERCISES)
        if unknown:
            raise SystemExit(f"unknown exercise(s): {', '.join(sorted(unknown))}")
        mistakes = [m for m in mistakes if m.exercise in wanted]
    if args.problems:
        wanted_problems = {int(p) for p in args.problems.split(",")}
        mistakes = [m for m in mistakes if m.problem in wanted_problems]
    if args.names:
        names = set(args.names.split(","))
        mistakes = [m for m in mistakes if m.name in names]
    if args.per_exercise:
        taken: Counter = Counter()
        chosen = []
        for mistake in mistakes:
            if taken[mistake.exercise] < args.per_exercise:
                taken[mistake.exercise] += 1
                chosen.append(mistake)
        mistakes = chosen
    return mistakes


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--set", choices=sorted(SETS), default="fresh", help="fresh (default): the mistakes today's "
                        "catalogues do not name rightly; named: those they do; pool: both; fresh2, named2, pool2 and "
                        "fresh3, named3, pool3: the same of the second and third held-out sets; fresh4 ... fresh10: "
                        "the held-out sets of every realistic mistake whose check fails")
    parser.add_argument("--exercises", help="only these exercises, e.g. VI,VII")
    parser.add_argument("--problems", help="only these problems, e.g. 42,44")
    parser.add_argument("--names", help="only the mistakes of these names")
    parser.add_argument("--per-exercise", type=int, default=0, help="only the first N mistakes of each exercise")
    parser.add_argument("--fallback", action="store_true", help="map names with the fallback table even when "
                        "checks/_diagnoses.py has one")
    parser.add_argument("--unlisted", action="store_true", help="also grade each mistake with the diagnosis engine "
                        "off, and read the target on those that no check names rightly without it (twice the time)")
    parser.add_argument("-v", "--verbose", action="store_true", help="one line per mistake")
    parser.add_argument("--json", metavar="PATH", help="also write every mistake's grading to PATH (JSON)")
    args = parser.parse_args(argv)
    mistakes = _select([m for folder in SETS[args.set] for m in fresh_mistakes(folder)], args)
    problems = defects(mistakes)
    if problems:
        print("the fresh set has defects:", *problems, sep="\n  ", file=sys.stderr)
        return 2
    if not mistakes:
        print("no mistake selected")
        return 2
    naming_ = naming(prefer_engine=not args.fallback)
    started = time.monotonic()

    def progress(g: Graded) -> None:
        print(f"  graded {g.mistake.name}: {g.verdict}", file=sys.stderr, flush=True)

    graded = grade_all(mistakes, naming_.family_of, progress if args.verbose else None, args.unlisted)
    print(summary(graded, naming_, time.monotonic() - started, args.verbose, args.set))
    if args.json:
        rows = [{"name": g.mistake.name, "exercise": g.mistake.exercise, "check": g.mistake.check,
                 "family": g.mistake.family, "also": g.mistake.also, "status": g.status, "diagnosis": g.diagnosis,
                 "today": g.mistake.today, "verdict": g.verdict, "lenient": g.lenient_verdict,
                 "failed": list(g.failed), "listed": g.listed, "listed_lenient": g.listed_lenient} for g in graded]
        Path(args.json).write_text(json.dumps({"naming": naming_.source, "seed": SEED, "mistakes": rows}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
