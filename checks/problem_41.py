"""Checks of problem 41: three multiple-choice questions on dynamics (answers.toml ``[problem_41] a, b, c``).

The keys are computed by the reference (each statement or option turned into a numerical identity on a random
motion, tree or configuration) and stay with the instructor: the checks are secret.  A wrong choice is explained
by what the computation shows about the chosen option, without naming the key.
"""

from checks._answers import choice
from grader.checking import STAGE_VALUES, check, fail
from probes import problem_41 as p41

TITLE = "Understanding Dynamics"

QUESTIONS = {
    "a": "(a) the true law of angular momentum",
    "b": "(b) the projection of the force F_P that is NOT correct",
    "c": "(c) the partial mass matrix of one ball of the flyball governor",
}
#: a statement holds when its residual is below this
HOLDS = 1e-5
#: (c) is compared for a ball of this length and mass (any values give the same key)
L, M = 1.3, 0.7


def _choice(ctx, key):
    return choice(ctx, key, (1, 2, 3, 4), QUESTIONS[key])


def _key(ctx, key):
    return int(ctx.reference(p41.keys, persist=True)[key])


def _residual(ctx, key, choice):
    return ctx.reference(p41.residuals, L, M, persist=True)[key][str(choice)]


@check(1, title="(a) the chosen law of angular momentum holds", stage=STAGE_VALUES, group="a", secret=True)
def check_choice_a(ctx):
    choice, key = _choice(ctx, "a"), _key(ctx, "a")
    residual = _residual(ctx, "a", choice)
    if choice != key:
        fail(f"{QUESTIONS['a']}: statement {choice} does not hold: on a random motion of a rigid body its two sides "
             f"differ by {residual:.2g} (relative).",
             "Euler's law dL/dt = M holds about the centre of gravity or a fixed point, with the derivative taken "
             "in an inertial frame; about a moving point, or for the derivative of coordinates in a moving frame, "
             "extra terms appear.", "false_statement")


@check(1, title="(b) the chosen projection is the one that does NOT give the generalized force", stage=STAGE_VALUES,
       group="b", secret=True)
def check_choice_b(ctx):
    choice, key = _choice(ctx, "b"), _key(ctx, "b")
    residual = _residual(ctx, "b", choice)
    if choice != key:
        fail(f"{QUESTIONS['b']}: option {choice} does give the generalized force: on a random tree it equals the "
             f"virtual work (d I_r_P / dq).T I_F_P to {residual:.1e}.",
             "The question asks for the projection that is NOT correct: a force at P projects with P's own "
             "Jacobian alone, or with the Jacobians of B plus the moment r_BP x F_P, not with both P's Jacobian and "
             "the moment.", "correct_statement")


@check(1, title="(c) the chosen matrix is the ball's partial mass matrix m J.T J at phi = 0, gamma = 30 deg",
       stage=STAGE_VALUES, group="c", secret=True)
def check_choice_c(ctx):
    choice, key = _choice(ctx, "c"), _key(ctx, "c")
    difference = _residual(ctx, "c", choice)
    if choice != key:
        fail(f"{QUESTIONS['c']}: option {choice} is not m J.T J of the ball: for l = {L}, m = {M} an entry differs "
             f"by {difference:.3g}.",
             "Write the ball's position as a function of (phi, gamma), take J = d r / d(phi, gamma) at phi = 0, "
             "gamma = 30 deg (the Jacobian of problem 27(d)) and form m J.T J: its columns are orthogonal.",
             "wrong_matrix")
