"""The one vocabulary of diagnoses: every name a check or the diagnosis engine may give a failure, once, with its
family, its phrase for students and its phrase for the class summary.

* A *diagnosis* names the cause of a failure (``transpose``, ``gravity_sign``, ``time_shift``); a failure whose cause
  is not known has none.  Several causes that give the student's value alike are joined by " or "
  (``"transpose or angle_sign"``: "could be X or Y").
* A *family* groups the names of one kind of slip (``sign``: ``sign_flip``, ``gravity_sign``, ``angle_sign``, ...);
  the class summary counts mistakes by family, and ``family_of`` maps a diagnosis (or an "X or Y") to its family.
* The student phrase completes "looks like ...": a noun phrase ("a transposed matrix (A_BI for A_IB)"); the summary
  phrase completes "35% of students ...": a verb phrase ("transposed a matrix (A_BI for A_IB)").

A name's family is decided by what the slip did to the right formula, in the words of the grammar of common slips,
never by the quantity it concerns or by its symptom:

* a factor left out, doubled, halved or of the wrong unit (a mass, a length, g, a gain, degrees) is ``scale``;
* a term left out of a sum is ``missing_term``, a term added is ``extra_term`` (a value taken about another point
  than asked adds the parallel-axis term: ``about_origin``, ``about_the_joint``; an absolute position where a lever
  arm belongs leaves out the position subtracted);
* a sign of a term, an axis, a residual, an inequality is ``sign``;
* things in each other's place within one expression (arguments, factors, entries) is ``order``; an update of a
  step that reads a value the step has already changed (or the other way round) takes a value of another time and
  is ``time_shift``;
* a rotation left out, on one side only or the other frame's is ``frame``; a reference point moved, or a term that
  is the same on every input (a radius, a height) left out or added, puts every value off by the same amount and
  is ``offset``;
* an argument whose value has no effect (a given gravity replaced by the Earth's) is ``ignored_argument``;
* a state read from another row or column of the state or the solution is ``state_row``;
* what the integration does (the step, the tolerance) is ``step_size``; when an event fires and whether it ends the
  run is ``event``: an event's residual that reads another row of the state watches another quantity, and fires
  elsewhere (``event_quantity``), as one of another support does (``first_support``).

A name that says what the answer shows rather than what the slip did, where slips of several families show it
alike, has a family of its own among the symptoms, beside ``shape`` and ``not_orthonormal``, and its hint says what
differs and what may cause it: a reflection (``handedness``: one axis reversed, or two exchanged), a body with the
right moments in the wrong orientation (``orientation``), a run that diverges (``diverged``).

``grader.checking`` refuses a name that is not in the table (``Mistake``, ``fail``, ``CheckFailure``): a grader
fault, never the student's.  The table checks itself when it is imported: every name once, every family known,
no phrase empty.  This module imports nothing of the grader.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass

__all__ = [
    "Family",
    "Diagnosis",
    "FAMILIES",
    "DIAGNOSES",
    "TERMS",
    "names_of",
    "family_of",
    "families_of",
    "is_known",
    "unknown_names",
    "student_phrase",
    "summary_phrase",
    "DIAGNOSIS_PARAMETERS",
    "literal_diagnoses",
]


@dataclass(frozen=True)
class Family:
    """A kind of slip: its name, its phrase for students ("looks like ...") and for the class summary."""

    name: str
    student: str
    summary: str


@dataclass(frozen=True)
class Diagnosis:
    """One name of the vocabulary."""

    name: str
    family: str
    student: str
    summary: str


_FAMILIES = (
    # slips of the grammar of common mistakes (the diagnosis engine names these too)
    Family("transpose", "a transposed matrix (A_BI for A_IB)", "transposed a matrix (A_BI for A_IB)"),
    Family("inverse", "an inverse confused with its matrix", "confused a matrix with its inverse"),
    Family("sign", "a sign slip", "flipped a sign"),
    Family("order", "things in the wrong order (arguments, factors, rows, columns)",
           "put arguments, factors or entries in the wrong order"),
    Family("scale", "a wrong factor or unit (2, 1/2, degrees for radians, a constant or a factor left out)",
           "were off by a factor or a unit (2, 1/2, degrees, a constant, a factor left out)"),
    Family("frame", "coordinates of the wrong frame (body for inertial)", "mixed up the frames of coordinates"),
    Family("missing_term", "a missing term", "left out a term"),
    Family("extra_term", "an extra term", "added a term that does not belong"),
    Family("ignored_argument", "an argument that is ignored", "ignored an argument"),
    Family("initial_state", "a wrong initial state", "started the motion from a wrong state"),
    Family("time_shift", "a value of another time (a motion shifted in time, an update out of order)",
           "took values of another time (a motion shifted, updates out of order)"),
    Family("offset", "a constant offset", "were off by a constant offset"),
    Family("step_size", "an integration error that grows with the step (a step too large)",
           "integrated too coarsely (a step too large)"),
    Family("event", "an event missed, found late or not ending the run", "mishandled an event"),
    Family("state_row", "a state read from the wrong row", "read a state from the wrong row or column"),
    Family("precision", "a loss of precision (rounding, float32)", "lost precision (rounding, float32)"),
    # slips the catalogues of the checks name
    Family("formula", "a wrong formula", "used a wrong formula"),
    Family("model", "a slip in building the model (geometry, mass, joints)", "built the model wrongly"),
    Family("recursion", "a recursion that does not recurse as it should", "got the recursion wrong"),
    Family("side_effect", "a function that changes its arguments or keeps state",
           "wrote functions with side effects"),
    Family("choice", "a wrong choice among the options", "chose a wrong option"),
    Family("text", "a wrong line of the predicted output or diagram", "predicted the output or diagram wrongly"),
    Family("installation", "an installation that is incomplete", "had an incomplete installation"),
    # structure: what is returned is not the kind of thing asked for
    Family("shape", "a value of the wrong shape", "returned values of the wrong shape"),
    Family("format", "an answer in the wrong format", "answered in the wrong format"),
    Family("not_finite", "NaN or infinite values", "returned NaN or infinite values"),
    Family("not_orthonormal", "a matrix that is not orthonormal", "returned a matrix that is not orthonormal"),
    Family("handedness", "a reflection instead of a rotation (det = -1: one axis reversed, or two exchanged)",
           "returned a reflection instead of a rotation (det = -1)"),
    Family("orientation", "a body with the right principal moments in the wrong orientation",
           "built a body with the right moments in the wrong orientation"),
    Family("diverged", "a run that diverges (a mass near zero, a step far too large, a servo too stiff)",
           "built models whose runs diverge"),
    Family("not_spd", "a matrix that is not symmetric positive-definite",
           "returned a matrix that is not symmetric positive-definite"),
    Family("typed_numbers", "the sheet's printed numbers typed in", "typed in the sheet's printed numbers"),
    Family("identity", "an answer that leaves everything as it was (the identity, no motion)",
           "returned something that does nothing (the identity, no motion)"),
    Family("constant", "an answer that does nothing (all zeros, one constant, the same for every input)",
           "returned answers that do nothing (zeros, a constant)"),
    Family("degenerate_input", "credit resting on earlier results of yours that do nothing",
           "built on earlier results that do nothing"),
    Family("stub", "a function that returns nothing", "returned nothing (a missing return)"),
)

#: the terms of a formula that probes declare (``probes.probe(terms=...)``); each has the names ``missing_<term>``,
#: ``<term>_sign`` and ``extra_<term>`` (where the table lists them)
TERMS = {
    "gyroscopic": "the gyroscopic term omega x (I omega)",
    "gravity": "the gravity term",
    "coriolis": "the Coriolis term 2 omega x v_rel",
    "centripetal": "the centripetal term omega x (omega x r)",
    "tangential": "the tangential term omegaDot x r",
    "bias": "the bias accelerations (sigma, the accelerations at qdd = 0)",
    "baumgarte": "the Baumgarte stabilisation P_B c + D_B c_dot",
    "torque": "the joint torques tau",
    "omega_x_r": "the transport term omega x r",
    "omega_x_v": "the transport term omega x v",
    "pd": "the PD torques P (q_des - q) + D (qd_des - qd)",
    "f": "the velocity terms f (Coriolis, centripetal, gyroscopic)",
    "mass_matrix": "the mass-matrix torques M qdd_des",
}


def _terms() -> tuple:
    """``missing_<term>`` (missing_term), ``<term>_sign`` (sign), ``extra_<term>`` and ``<term>_twice`` (extra_term)
    of each term."""
    rows = []
    for term, words in TERMS.items():
        rows.append(Diagnosis(f"missing_{term}", "missing_term", f"{words} missing", f"left out {words}"))
        rows.append(Diagnosis(f"{term}_sign", "sign", f"{words} with the wrong sign",
                              f"gave {words} the wrong sign"))
        rows.append(Diagnosis(f"extra_{term}", "extra_term", f"{words} added where it does not belong",
                              f"added {words} where it does not belong"))
        rows.append(Diagnosis(f"{term}_twice", "extra_term", f"{words} counted twice", f"counted {words} twice"))
    return tuple(rows)


_D = Diagnosis

_TABLE = (
    # ---------------------------------------------------------------- transpose
    _D("transpose", "transpose", "a transposed matrix (A_BI for A_IB)", "transposed a matrix (A_BI for A_IB)"),
    # ---------------------------------------------------------------- inverse
    _D("inverse", "inverse", "the inverse of the expected matrix", "returned the inverse of the matrix asked for"),
    _D("no_inverse", "inverse", "a matrix used where its inverse belongs", "forgot to invert a matrix"),
    _D("inverse_left_out", "inverse", "an inverse factor of a product left out (J.T Lam for M^-1 J.T Lam)",
       "left an inverse out of a product"),
    _D("reciprocal_argument", "inverse", "a number used as its reciprocal (1/x where x belongs, or the reverse)",
       "used a number's reciprocal in its place"),
    _D("ratio_inverted", "inverse", "a ratio upside down", "turned a ratio upside down"),
    _D("multiplied_not_solved", "inverse", "a product with M where M qdd = ... is to be solved",
       "multiplied by the mass matrix instead of solving with it"),
    # ---------------------------------------------------------------- sign
    _D("sign_flip", "sign", "a sign slip (the value, a row, a column or entries with the wrong sign)",
       "flipped a sign"),
    _D("angle_sign", "sign", "an angle with the wrong sign (a rotation the wrong way)",
       "turned an angle the wrong way"),
    _D("axis_sign", "sign", "an axis pointing the wrong way", "let an axis point the wrong way"),
    _D("impulse_sign", "sign", "an impulse with the wrong sign", "gave the impulse the wrong sign"),
    _D("jacobian_sign", "sign", "a Jacobian with the wrong sign", "gave a Jacobian the wrong sign"),
    _D("sigma_sign", "sign", "the bias acceleration sigma with the wrong sign", "gave sigma the wrong sign"),
    _D("event_sign", "sign", "an event residual with the wrong sign", "gave an event residual the wrong sign"),
    _D("constraint_sign", "sign", "a constraint with the wrong sign", "gave the constraint the wrong sign"),
    _D("constraint_force_sign", "sign", "constraint forces with the wrong sign",
       "gave the constraint forces the wrong sign"),
    _D("d_sign", "sign", "the offset d with the wrong sign", "gave the offset d the wrong sign"),
    _D("offset_sign", "sign", "an offset vector with the wrong sign", "added an offset that must be subtracted"),
    _D("omega_dot_sign", "sign", "omega_dot with the wrong sign", "gave omega_dot the wrong sign"),
    _D("outer_sign", "sign", "the outer product r r^T with the wrong sign", "added the outer product r r^T"),
    _D("parallel_axis_sign", "sign", "the parallel-axis shift with the wrong sign",
       "subtracted the parallel-axis shift"),
    _D("rolling_sign", "sign", "a rolling motion the wrong way", "rolled the wrong way"),
    _D("rotation_sense", "sign", "a rotation the wrong way round", "turned the wrong way round"),
    _D("slope_sign", "sign", "a slope the wrong way", "tilted the slope the wrong way"),
    _D("reflection", "handedness", "a reflection instead of a rotation (det = -1)",
       "built a reflection instead of a rotation (det = -1)"),
    # ---------------------------------------------------------------- order
    _D("argument_order", "order", "arguments in the wrong order", "swapped the arguments"),
    _D("swapped", "order", "entries, rows or columns swapped", "swapped entries, rows or columns"),
    _D("rotation_order", "order", "rotations multiplied in the wrong order",
       "multiplied the rotations in the wrong order"),
    _D("axis_order", "order", "the axes in the wrong order", "took the axes in the wrong order"),
    _D("column_order", "order", "columns in the wrong order", "put the columns in the wrong order"),
    _D("coordinate_order", "order", "coordinates in the wrong order", "took the coordinates in the wrong order"),
    _D("joint_order", "order", "joints in the wrong order", "applied the joints in the wrong order"),
    _D("state_order", "order", "the state derivative in the wrong order ((qdd, qd) for (qd, qdd))",
       "returned the state derivative in the wrong order"),
    _D("rotation_side", "order", "a rotation multiplied from the wrong side", "multiplied from the wrong side"),
    _D("factor_order", "order", "the factors of a product in the wrong order", "multiplied factors in the wrong order"),
    _D("sibling_matrix", "order", "a matrix where its sibling belongs (J_R for J_S)",
       "used a matrix where its sibling belongs"),
    _D("wrong_angle", "order", "one angle read where another belongs (cos(beta) for cos(phi))",
       "read one angle where another belongs"),
    _D("wrong_parameter", "order", "one argument read where another belongs (the width for the height)",
       "read one argument where another belongs"),
    _D("sin_cos_swapped", "order", "sin and cos swapped", "swapped sin and cos"),
    _D("beta_sin_cos", "order", "sin and cos of beta swapped", "swapped sin and cos of beta"),
    _D("phi_sin_cos", "order", "sin and cos of phi swapped", "swapped sin and cos of phi"),
    # ---------------------------------------------------------------- scale
    _D("degrees", "scale", "degrees and radians confused", "used degrees where radians are expected"),
    _D("rate_degrees", "scale", "a rate converted as if it were in degrees", "converted a rate as if in degrees"),
    _D("damping_per_degree", "scale", "damping per degree where MuJoCo wants it per radian",
       "gave the damping per degree instead of per radian"),
    _D("damping_wrong_conversion", "scale", "a damping converted the wrong way",
       "converted the damping the wrong way"),
    _D("factor_two", "scale", "a value twice the expected one", "were off by a factor of 2"),
    _D("factor_half", "scale", "a value half the expected one", "were off by a factor of 1/2"),
    _D("constant_factor", "scale", "a value off by a constant of the problem (a mass, g, a length)",
       "multiplied or divided by a wrong constant (a mass, g, a length)"),
    _D("wrong_factor", "scale", "a value off by a constant factor (3, 1/4, sqrt(2), pi, ...)",
       "were off by a constant factor (3, 1/4, sqrt(2), pi, ...)"),
    _D("scaled_argument", "scale", "an argument used at twice or half its value (a full length for a half, ...)",
       "used an argument at twice or half its value"),
    _D("one_third", "scale", "1/3 where 1/12 belongs", "used 1/3 instead of 1/12"),
    _D("semi_axes", "scale", "full axes where semi-axes belong", "confused full axes and semi-axes"),
    _D("mass_per_particle", "scale", "the whole mass at each particle", "put the whole mass at each particle"),
    _D("mass_per_point", "scale", "the whole mass at each point", "put the whole mass at each point"),
    _D("positions", "scale", "particles at the wrong distance", "placed the particles at the wrong distance"),
    _D("density_as_mass", "scale", "the density used as the mass", "used the density as the mass"),
    _D("missing_mass", "scale", "a missing factor m (an acceleration where a force belongs)",
       "left out the mass m"),
    _D("gravity_9_81", "scale", "g = 9.81 in a model normalised to g = 1", "used g = 9.81 in a normalised model"),
    _D("coriolis_factor", "scale", "the Coriolis term without its factor 2", "left out the factor 2 of Coriolis"),
    _D("not_divided", "scale", "a sum not divided by the total mass", "forgot to divide by the total mass"),
    _D("unweighted", "scale", "points not weighted by their masses", "did not weight by the masses"),
    _D("unit_gear", "scale", "a motor gear of 1", "left the motor's gear at 1"),
    _D("omega_squared", "scale", "omega squared where omega belongs", "returned omega squared"),
    _D("normalization", "scale", "a vector normalised (or not) where it should not be",
       "normalised a vector wrongly"),
    _D("soft_servo", "scale", "a servo too soft to follow its setpoint", "used a servo too soft"),
    _D("missing_factor", "scale", "a factor left out of a product", "left a factor out of a product"),
    # ---------------------------------------------------------------- frame
    _D("wrong_frame", "frame", "coordinates of the wrong frame (body for inertial, or the reverse)",
       "mixed up body and inertial coordinates"),
    _D("gravity_body_frame", "frame", "gravity taken as body coordinates", "took gravity as body coordinates"),
    _D("omega_frame", "frame", "an angular velocity in the wrong frame", "used omega in the wrong frame"),
    _D("offset_frame", "frame", "an offset added in the wrong frame", "added an offset in the wrong frame"),
    _D("offset_not_rotated", "frame", "an offset not rotated into the frame", "did not rotate an offset"),
    _D("ignored_frame", "frame", "a coordinate system ignored", "ignored a coordinate system"),
    _D("not_rotated", "frame", "a body not turned into its frame", "did not turn the body into its frame"),
    _D("one_sided", "frame", "a rotation applied on one side only (A I, not A I A.T)",
       "rotated an inertia on one side only"),
    _D("velocity_of_B", "state_row", "the velocity of B where another point's is asked",
       "gave the velocity of the wrong point"),
    # ---------------------------------------------------------------- missing terms
    *_terms(),
    _D("missing_term", "missing_term", "a term left out of a sum", "left a term out of a sum"),
    _D("missing_matrix_factor", "missing_term", "a matrix or vector factor of a matrix product left out (J for J "
       "@ qd)", "left a matrix factor out of a product"),
    _D("missing_identity", "missing_term", "the identity matrix left out of a product (a number added to every "
       "entry, not to the diagonal alone)", "left the identity matrix out"),
    _D("missing_rotation", "missing_term", "the rotational part J_R.T I J_R missing", "left out the rotation"),
    _D("missing_translation", "missing_term", "the translational part J_S.T m J_S missing",
       "left out the translation"),
    _D("missing_sigma", "missing_term", "the bias acceleration sigma missing", "left out sigma"),
    _D("missing_qdd", "missing_term", "the qdd terms missing", "left out the qdd terms"),
    _D("missing_outer_product", "missing_term", "the outer product r r^T missing",
       "left out the outer product r r^T"),
    _D("no_parallel_axis", "missing_term", "the parallel-axis shift missing", "left out the parallel-axis shift"),
    _D("no_offset", "missing_term", "an offset missing", "left out an offset"),
    _D("transport", "missing_term", "the transport term omega x omega_rel missing",
       "left out the transport term omega x omega_rel"),
    _D("lever", "missing_term", "the lever of the predecessor's rotation missing", "left out a lever arm"),
    _D("no_rotation", "missing_term", "the rotation of a revolute joint missing", "left out a joint's rotation"),
    _D("absolute_position", "missing_term", "an absolute position where a lever arm belongs",
       "used an absolute position instead of a lever arm"),
    _D("extra_term", "extra_term", "a term added where it does not belong", "added a term that does not belong"),
    _D("samples_repeated", "extra_term", "output times kept twice (a sample on a boundary kept by both pieces that "
       "meet there)", "kept output times twice"),
    _D("rotation", "extra_term", "a rotation where a prismatic joint has none", "added a prismatic joint's rotation"),
    _D("acceleration_not_reset", "extra_term", "an acceleration left where none acts",
       "left an acceleration where none acts"),
    _D("about_origin", "extra_term", "a value about the origin instead of the centre of gravity",
       "measured about the origin instead of the centre of gravity"),
    _D("about_the_joint", "extra_term", "an inertia about the joint instead of the centre of mass",
       "gave the inertia about the joint"),
    # ---------------------------------------------------------------- ignored argument
    _D("ignored_argument", "ignored_argument", "an argument that your function ignores", "ignored an argument"),
    _D("ignores_parent", "ignored_argument", "the parent frame ignored", "ignored the parent frame"),
    _D("baumgarte_ignored", "ignored_argument", "the baumgarte flag ignored (stabilisation always on or always off)",
       "ignored the baumgarte flag"),
    _D("stale", "ignored_argument", "a value stored once instead of computed when asked",
       "stored a value instead of computing it"),
    _D("earth_gravity", "ignored_argument", "the Earth's gravity where another is given", "used the Earth's gravity"),
    _D("value_unused", "ignored_argument", "one value read where another belongs, which is then never used",
       "read one value where another belongs, leaving that one unused"),
    # ---------------------------------------------------------------- motions
    _D("initial_state", "initial_state", "a run that starts from a wrong state", "started from a wrong state"),
    _D("start_value", "initial_state", "the value at the start read where the value computed from it belongs (the "
       "start returned for the end)", "returned the start for the end"),
    _D("starts_at_rest", "initial_state", "a run that starts at rest where it should move",
       "started at rest instead of in motion"),
    _D("not_horizontal", "initial_state", "a start that is not horizontal", "did not start horizontal"),
    _D("initial_pose", "initial_state", "a model built in another configuration (a body turned about its joint)",
       "built the model in another configuration"),
    _D("time_shift", "time_shift", "a motion shifted in time", "shifted the motion in time"),
    _D("step_count", "time_shift", "one step too many or too few", "ran a step too many or too few"),
    _D("nearest_sample", "time_shift", "the nearest table row instead of an interpolation",
       "took the nearest row instead of interpolating"),
    _D("previous_sample", "time_shift", "the previous table row instead of an interpolation",
       "took the row before instead of interpolating"),
    _D("offset", "offset", "a constant offset", "were off by a constant offset"),
    _D("from_origin", "offset", "a position measured from the origin where it is measured from a point",
       "measured a position from the origin instead of from its point"),
    _D("step_size", "step_size", "an integration error that grows with the step (a step too large)",
       "integrated with a step too large"),
    _D("step_typed", "step_size", "a step or a count of steps typed otherwise (the run takes steps of another size)",
       "typed the step or the number of steps otherwise"),
    _D("step_left_out", "step_size", "the step left out of an update (a whole unit of time taken for one step)",
       "left the step out of an update"),
    _D("output_step", "step_size", "an output step too long (every m-th output time alone)",
       "sampled a run with too long a step"),
    _D("integration", "step_size", "an integration too coarse (a loose integrator or a step too large)",
       "integrated too coarsely"),
    _D("energy_drift", "step_size", "energy that drifts in a conservative run", "let the energy drift"),
    _D("event_late", "event", "an event found late (or a run that goes past it)", "found an event late"),
    _D("event_early", "event", "an event found too early", "found an event too early"),
    _D("state_before_event", "event", "the state at an event read from the last output before it (not solve_ivp's "
       "y_events)", "read the state at an event from the output before it"),
    _D("event_direction", "event", "an event with the wrong direction", "gave an event the wrong direction"),
    _D("no_event", "event", "an event that never fires", "never detected the event"),
    _D("event_appended", "event", "the state at an event appended to a run's output (a sample off the output times)",
       "appended the state at an event to a run"),
    _D("not_terminal", "event", "an event that does not end the run", "did not end the run at the event"),
    _D("apex_terminal", "event", "an event that ends the run where it should only mark a point",
       "ended the run at an event that only marks a point"),
    _D("extremum_from_steps", "event", "an extremum (an apex) read from the solver's steps instead of located by "
       "an event", "read an extremum from the solver's steps instead of an event"),
    _D("event_quantity", "event", "an event that watches the wrong quantity (another row of the state)",
       "watched the wrong quantity in an event"),
    _D("event_residual", "event", "an event function that returns a test or a magnitude (height > 0, abs(gap)) "
       "where a residual belongs that changes sign at the event", "returned a test or a magnitude from an event "
       "function instead of a residual"),
    _D("state_row", "state_row", "a state read from the wrong row (or column) of the solution",
       "read a state from the wrong row"),
    _D("wrong_index", "state_row", "an entry read from the wrong index (a neighbouring row or column)",
       "read an entry from the wrong index"),
    _D("omega_before_rotation", "time_shift", "an update in the wrong order (omega before the rotation)",
       "updated omega before the rotation"),
    _D("update_order", "time_shift", "B_omega_B updated before the step used its old value",
       "updated B_omega_B before the step used it"),
    _D("velocity_first", "time_shift", "the velocity updated before the position update used it",
       "updated the velocity before the position"),
    _D("orientation_before", "time_shift", "an orientation updated before it is used",
       "updated an orientation before using it"),
    _D("grid_off_by_one", "time_shift", "an output grid of one sample too many or too few (every sample after the "
       "first at another time)", "built an output grid one sample off"),
    _D("weights_left_out", "ignored_argument", "a weighted sum taken unweighted (the weights, the masses, ignored)",
       "left the weights out of a weighted sum"),
    _D("solver_steps", "ignored_argument", "the output times asked for left out (a run returned at the solver's own "
       "steps: t_eval not passed)", "left the output times out of a run"),
    _D("span_short", "time_shift", "a run that ends too early (the span of its integration shorter than the one "
       "asked for)", "ended a run too early"),
    _D("piece_left_out", "missing_term", "a piece of a run left out (its last piece, between the last break and the "
       "end, never integrated)", "left a piece of a run un-integrated"),
    _D("samples_left_out", "time_shift", "output times left out (a boundary of the span or of a piece taken with < "
       "where <= belongs)", "left output times out of a run"),
    # ---------------------------------------------------------------- precision
    _D("float32", "precision", "values computed in single precision (float32)", "computed in single precision"),
    _D("rounded", "precision", "values rounded to a few decimals", "rounded the values"),
    _D("integer_truncated", "precision", "values cut to whole numbers (an integer dtype where floats belong)",
       "cut values to whole numbers"),
    _D("absolute_tolerance", "precision", "a tolerance not relative to the size of the values",
       "compared with an absolute tolerance"),
    _D("event_interpolated", "precision", "the state at an event interpolated between a run's output samples (not "
       "solve_ivp's y_events, the state at the event itself)", "interpolated the state at an event between samples"),
    # ---------------------------------------------------------------- integration schemes
    _D("euler_not_exponential", "step_size", "an Euler step where the matrix exponential belongs",
       "used Euler instead of the matrix exponential"),
    _D("explicit_euler", "step_size", "an explicit Euler step where the exponential belongs",
       "used explicit Euler for the rotation"),
    _D("lost_orthonormality", "step_size", "a rotation that loses orthonormality as it is integrated",
       "let the rotation lose orthonormality"),
    _D("euler_component_form", "missing_term", "Euler's equations in components with a full inertia matrix",
       "used Euler's equations in components off the principal axes"),
    _D("principal_axes_only", "inverse", "a division by the diagonal that holds in principal axes only",
       "divided by the diagonal of the inertia"),
    # ---------------------------------------------------------------- formulas
    _D("wrong_axis", "order", "a rotation about another axis", "rotated about the wrong axis"),
    _D("cuboid_formula", "scale", "the cuboid's formula for another body", "used the cuboid's formula"),
    _D("wrong_axes", "order", "the formula of other axes", "used the formula of other axes"),
    _D("horizontal", "offset", "angles measured from the horizontal instead of the vertical",
       "measured the angles from the horizontal"),
    _D("radius", "missing_term", "the wrong radius of the circle", "used the wrong radius"),
    _D("lever_arm", "order", "the lever arm where the velocity perpendicular to it belongs",
       "used the lever arm itself"),
    _D("missing_class", "text", "a class missing from the diagram", "left a class out of the diagram"),
    _D("first_support", "event", "the first support's constraint for the second's",
       "used the first support for the second"),
    _D("support_side", "sign", "the support on the wrong side", "put the support on the wrong side"),
    _D("elastic", "scale", "an elastic impact where it is plastic", "made the impact elastic"),
    _D("energy_gain", "formula", "an impact that gains energy", "let an impact gain energy"),
    _D("unchanged", "identity", "velocities the impact leaves unchanged", "left the velocities unchanged"),
    _D("inequality_reversed", "sign", "an inequality the wrong way", "reversed an inequality"),
    _D("inertia_position", "order", "the inertia in the wrong place of M", "put the inertia in the wrong place"),
    _D("wrong_column", "formula", "a wrong column of the Jacobian", "built a wrong Jacobian column"),
    _D("column_offset", "order", "Jacobian columns in the wrong place", "put Jacobian columns in the wrong place"),
    _D("total_derivative", "formula", "a partial derivative where the total one belongs",
       "took a partial derivative instead of the total one"),
    _D("non_holonomic", "formula", "a constraint taken for holonomic", "took a non-holonomic constraint"),
    _D("pd_through_mass_matrix", "scale", "the PD torques passed through M", "passed the PD torques through M"),
    _D("chain_wrong", "formula", "a derivative of a wrong position", "differentiated a wrong position"),
    _D("wrong_ode", "formula", "a run of a right-hand side that is wrong (its own check says how)",
       "simulated a wrong right-hand side"),
    _D("position_wrong", "formula", "a derivative of a wrong position", "differentiated a wrong position"),
    _D("sheet_misprint", "formula", "the sheet's misprinted value", "copied the sheet's misprint"),
    _D("no_sag", "formula", "a controller that does not sag as PD alone must", "gave the PD controller no sag"),
    _D("wrong_rate", "scale", "a servo driven at the wrong rate", "drove the servo at the wrong rate"),
    _D("free_symbols", "formula", "symbols the expression should not contain", "left stray symbols in"),
    _D("orientation", "orientation", "a body with the wrong orientation", "oriented the body wrongly"),
    _D("unsorted", "order", "principal moments out of order", "left the principal moments unsorted"),
    # ---------------------------------------------------------------- models (Exercise I, trees)
    _D("box_full_size", "scale", "a box with full edges where MuJoCo wants half", "gave MuJoCo full box sizes"),
    _D("full_length_offset", "scale", "a body a full length from its pivot", "placed the body a full length away"),
    _D("centre_pivot", "offset", "the pivot at the centre of the link", "put the pivot at the link's centre"),
    _D("joint_at_centre", "scale", "a joint at the centre of the link", "put the joint at the centre"),
    _D("com_at_joint", "offset", "the centre of mass at the joint", "put the centre of mass at the joint"),
    _D("com_full_length", "scale", "the centre of mass a full length away", "put the centre of mass too far"),
    _D("gravity_axis", "order", "gravity along the wrong axis", "pointed gravity along the wrong axis"),
    _D("level_ground", "missing_term", "a level ground where a slope is asked", "left out the slope"),
    _D("contact_height", "offset", "a rolling joint's frame at the wrong height", "placed the rolling frame wrongly"),
    _D("foot_offset", "offset", "the foot's offset of another point", "used the wrong foot offset"),
    _D("no_final_link", "missing_term", "a chain without its last link", "left out the last link"),
    _D("built_straight", "ignored_argument", "a model built straight instead of in its configuration",
       "built the model straight"),
    _D("structure", "model", "bodies nested in the wrong structure", "nested the bodies wrongly"),
    _D("joints", "model", "the wrong joints in the model", "declared the wrong joints"),
    _D("joint_extras", "extra_term", "joint settings that change the motion", "added joint settings"),
    _D("joints_changed", "model", "joints changed that were right", "changed joints that were right"),
    _D("contacts", "model", "contacts that touch where nothing should", "left contacts on"),
    _D("mass_not_small", "scale", "a massless body left without a small mass", "left a body massless"),
    _D("inertia_not_small", "scale", "a small added mass given a large inertia",
       "gave the added small mass a large inertia"),
    _D("no_actuator", "missing_term", "a model without its actuator", "left out the actuator"),
    _D("actuator_joint", "model", "an actuator on the wrong joint", "put the actuator on the wrong joint"),
    _D("leftover_input", "extra_term", "an input left in the model that should be zero", "left an input in"),
    _D("no_connect", "missing_term", "a loop not closed by a connect", "did not close the loop"),
    _D("weld_for_connect", "extra_term", "a loop closed by a weld where a connect belongs (its orientation locked "
       "too)", "closed a loop with a weld where a connect belongs"),
    _D("not_assembled", "model", "a linkage that is not assembled", "did not assemble the linkage"),
    _D("no_swing", "model", "a link that does not swing", "built a link that does not swing"),
    _D("diverged", "diverged", "a model whose run diverges", "built a model whose run diverges"),
    _D("load_error", "model", "a model that MuJoCo cannot load", "wrote a model MuJoCo cannot load"),
    _D("refused", "model", "a model the grader refuses (files, includes)", "wrote a model that was refused"),
    _D("density_matters", "model", "a model in which the density changes the motion",
       "let the density change the motion"),
    _D("no_error", "model", "no error where an impossible model must raise one",
       "raised no error for an impossible model"),
    _D("wrong_error", "model", "the wrong kind of error", "raised the wrong kind of error"),
    _D("no_message", "model", "an error without a message", "raised an error without a message"),
    # ---------------------------------------------------------------- recursion
    _D("no_recursion", "recursion", "a function that does not call itself", "did not recurse"),
    _D("shallow_recursion", "recursion", "a recursion that handles several steps per call",
       "recursed too shallowly"),
    _D("wrong_values", "recursion", "a recursion that does not compute the values",
       "recursed without computing the values"),
    _D("unvisited_branch", "recursion", "a branch of the tree never visited", "left a branch of the tree out"),
    _D("past_leaf", "recursion", "a recursion that goes on past the leaf", "recursed past the leaf"),
    # ---------------------------------------------------------------- side effects
    _D("mutates_argument", "side_effect", "a function that changes its arguments in place",
       "changed the caller's arrays in place"),
    _D("shared_result", "side_effect", "one array returned on every call", "returned the same array on every call"),
    _D("state_between_calls", "side_effect", "state kept between calls", "kept state between calls"),
    _D("stale_mass_matrix", "side_effect", "a mass matrix computed once and reused at later states",
       "reused a mass matrix computed at another state"),
    # ---------------------------------------------------------------- choices and texts
    _D("wrong_choice", "choice", "a wrong option", "chose a wrong option"),
    _D("correct_statement", "choice", "a correct statement taken for the wrong one",
       "took a correct statement for the wrong one"),
    _D("false_statement", "choice", "a false statement taken for a correct one",
       "took a false statement for a correct one"),
    _D("wrong_matrix", "choice", "the wrong matrix", "chose the wrong matrix"),
    _D("far_from_figure", "choice", "a matrix far from the figure", "read the figure wrongly"),
    _D("forgot_symmetry", "choice", "a test that forgets symmetry", "forgot to test symmetry"),
    _D("forgot_positive_definite", "choice", "a test that forgets positive definiteness",
       "forgot to test positive definiteness"),
    _D("forgot_triangle_inequality", "choice", "a test that forgets the triangle inequality",
       "forgot the triangle inequality"),
    _D("definite_on_diagonal", "choice", "positive definiteness read off the diagonal",
       "read positive definiteness off the diagonal"),
    _D("triangle_on_diagonal", "choice", "the triangle inequality tested on the diagonal",
       "tested the triangle inequality on the diagonal"),
    _D("plate_rejected", "choice", "a flat plate rejected", "rejected a flat plate's inertia"),
    _D("order", "order", "lines in the wrong order", "printed the lines in the wrong order"),
    _D("reversed", "order", "pairs the wrong way round", "wrote the pairs the wrong way round"),
    _D("class_names", "text", "class names spelt differently", "misspelt the class names"),
    _D("indirect", "text", "an indirect base class listed as direct", "listed an indirect base class"),
    _D("multiple_inheritance", "text", "a class with several bases", "gave a class several bases"),
    _D("has_a", "text", "a has-a relation taken for inheritance", "took has-a for inheritance"),
    _D("leaf_prints_color", "text", "a leaf that prints its colour", "let the leaf print its colour"),
    _D("missing_prompt", "text", "a missing prompt line", "left out the prompt"),
    _D("missing_foe_story", "text", "a missing line of the story", "left out a line of the story"),
    _D("typo_corrected", "text", "the script's typo corrected", "corrected the script's typo"),
    # ---------------------------------------------------------------- installation
    _D("install", "installation", "a package that is not installed", "had a package missing"),
    _D("mujoco_broken", "installation", "a MuJoCo that does not run", "had a broken MuJoCo"),
    _D("versions", "installation", "versions that are not read as asked", "reported the versions wrongly"),
    _D("versions_left_out", "missing_term", "packages left out of the versions", "left packages out of the versions"),
    _D("versions_cut", "precision", "versions cut short", "cut the versions short"),
    _D("versions_of_one", "ignored_argument", "one package's version reported for others",
       "reported one package's version for others"),
    _D("type", "format", "a value of the wrong type", "returned a value of the wrong type"),
    # ---------------------------------------------------------------- structure
    _D("shape", "shape", "a value of the wrong shape", "returned an array of the wrong shape"),
    _D("format", "format", "an answer in the wrong format", "answered in the wrong format"),
    _D("not_finite", "not_finite", "NaN or infinite values", "returned NaN or infinite values"),
    _D("not_orthonormal", "not_orthonormal", "a matrix that is not orthonormal",
       "returned a matrix that is not orthonormal"),
    _D("not_symmetric", "not_spd", "a matrix that is not symmetric", "returned a matrix that is not symmetric"),
    _D("not_positive_definite", "not_spd", "a matrix that is not positive definite",
       "returned a matrix that is not positive definite"),
    _D("typed_numbers", "typed_numbers", "the sheet's printed numbers typed in", "typed in the sheet's numbers"),
    _D("identity", "identity", "the identity matrix (no rotation)", "returned the identity"),
    _D("no_motion", "identity", "a step that does not move anything", "wrote a step that does not move"),
    _D("constant_answer", "constant", "the same answer for every input", "returned the same answer for every input"),
    _D("always_zero", "constant", "zeros for every input", "returned zeros for every input"),
    _D("always_raises", "constant", "an error raised for every input", "raised for every input"),
    _D("degenerate", "constant", "a value that does nothing (all zeros, one constant everywhere)",
       "returned a value that does nothing (all zeros, a constant)"),
    _D("degenerate_input", "degenerate_input",
       "a value judged on earlier results of yours that do nothing (zeros, a constant, not a rotation)",
       "had their own earlier results do nothing, so nothing could be carried forward"),
    _D("none", "stub", "nothing returned (a missing return)", "returned nothing (a missing return)"),
)

FAMILIES: dict[str, Family] = {}
DIAGNOSES: dict[str, Diagnosis] = {}

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")


def _build() -> None:
    """Fill ``FAMILIES`` and ``DIAGNOSES``, refusing a table that names something twice, a family that does not
    exist, a name that is not one word, or an empty phrase."""
    for family in _FAMILIES:
        if family.name in FAMILIES:
            raise ValueError(f"diagnosis family {family.name!r} is listed twice")
        if not (family.student and family.summary):
            raise ValueError(f"diagnosis family {family.name!r} needs both phrases")
        FAMILIES[family.name] = family
    for diagnosis in _TABLE:
        if diagnosis.name in DIAGNOSES:
            raise ValueError(f"diagnosis {diagnosis.name!r} is listed twice")
        if not _NAME.match(diagnosis.name):
            raise ValueError(f"diagnosis {diagnosis.name!r} is not one snake_case word")
        if diagnosis.family not in FAMILIES:
            raise ValueError(f"diagnosis {diagnosis.name!r} has an unknown family {diagnosis.family!r}")
        if not (diagnosis.student and diagnosis.summary):
            raise ValueError(f"diagnosis {diagnosis.name!r} needs both phrases")
        DIAGNOSES[diagnosis.name] = diagnosis


_build()


def names_of(diagnosis: str) -> tuple[str, ...]:
    """The names of a diagnosis: ``()`` for none, one name, or the names of "X or Y"."""
    return tuple(name.strip() for name in diagnosis.split(" or ")) if diagnosis.strip() else ()


def is_known(diagnosis: str) -> bool:
    """True for "" (no diagnosis), a name of the table, or names of the table joined by " or "."""
    return all(name in DIAGNOSES for name in names_of(diagnosis))


def unknown_names(diagnosis: str) -> list[str]:
    return [name for name in names_of(diagnosis) if name not in DIAGNOSES]


def families_of(diagnosis: str) -> tuple[str, ...]:
    """The families of the names of a diagnosis, each once, in the order of the names."""
    families: list[str] = []
    for name in names_of(diagnosis):
        if name not in DIAGNOSES:
            raise KeyError(f"unknown diagnosis {name!r}")
        family = DIAGNOSES[name].family
        if family not in families:
            families.append(family)
    return tuple(families)


def family_of(diagnosis: str) -> str:
    """The family of a diagnosis: ``"sign"`` for ``"gravity_sign"``; for "X or Y", the family they share, or
    their families joined by " or " (``"transpose or sign"``); ``""`` for no diagnosis.  An unknown name raises
    ``KeyError``."""
    return " or ".join(families_of(diagnosis))


def student_phrase(diagnosis: str) -> str:
    """What a diagnosis looks like, for students: "a transposed matrix (A_BI for A_IB)"; for "X or Y", the phrases
    joined by " or "."""
    return " or ".join(DIAGNOSES[name].student for name in names_of(diagnosis))


def summary_phrase(diagnosis: str) -> str:
    """What the students did, for the class summary: "transposed a matrix (A_BI for A_IB)"; for "X or Y", the
    phrases joined by " or "."""
    return " or ".join(DIAGNOSES[name].summary for name in names_of(diagnosis))


# ---------------------------------------------------------------------------------------------- literals in code

#: callables that take a diagnosis, and the index of that argument: ``Mistake(name, ...)``, the trees' ``Model(name,
#: ...)``, ``fail(message, hint, diagnosis)``, ``CheckFailure(message, hint, diagnosis)``, the diagnosis engine's
#: ``Hypothesis(key, name, ...)``; any other callable is found by a parameter named ``diagnosis``
#: (``literal_diagnoses``'s ``helpers``), and any call by a ``diagnosis=`` keyword
DIAGNOSIS_PARAMETERS = {"Mistake": 0, "Model": 0, "fail": 2, "CheckFailure": 2, "Hypothesis": 1}


def _strings(node, constants: dict) -> list[str]:
    """The string constants an expression can evaluate to: a constant, a name the module binds to one
    (``constants``), either branch of ``a if c else b``, the operands of ``a or b``."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, ast.Name) and node.id in constants:
        return [constants[node.id]]
    if isinstance(node, ast.IfExp):
        return _strings(node.body, constants) + _strings(node.orelse, constants)
    if isinstance(node, ast.BoolOp):
        return [text for value in node.values for text in _strings(value, constants)]
    return []


def _module_constants(module: ast.Module) -> dict:
    """The names a module binds once, at its top level, to a string (``DEGENERATE = "degenerate"``)."""
    bound: dict = {}
    for statement in module.body:
        targets = statement.targets if isinstance(statement, ast.Assign) else \
            [statement.target] if isinstance(statement, ast.AnnAssign) and statement.value is not None else []
        for target in targets:
            if isinstance(target, ast.Name):
                value = statement.value
                text = value.value if isinstance(value, ast.Constant) and isinstance(value.value, str) else None
                bound[target.id] = text if target.id not in bound else None
    return {name: text for name, text in bound.items() if text is not None}


def _called(node) -> str | None:
    func = node.func
    return func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else None


def literal_diagnoses(source: str, helpers: dict | None = None) -> list[tuple[int, str]]:
    """``(line, name)`` of every diagnosis written as a string literal in ``source`` (or as a name the module binds
    to one at its top level, ``DEGENERATE = "degenerate"``): the diagnosis argument of the
    callables of ``DIAGNOSIS_PARAMETERS``, of ``helpers`` (callable name -> index of its diagnosis parameter) and of
    the functions ``source`` defines with a parameter named ``diagnosis``, and every ``diagnosis=`` keyword.  A name
    that is not in the table is a defect of the checks (a test holds every check module to the table); names
    computed at run time are refused when the failure or the mistake is made."""
    module = ast.parse(source)
    constants = _module_constants(module)
    nodes = list(ast.walk(module))
    positions = {**DIAGNOSIS_PARAMETERS, **(helpers or {})}
    for node in nodes:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            arguments = [a.arg for a in (*node.args.posonlyargs, *node.args.args)]
            if "diagnosis" in arguments:
                positions.setdefault(node.name, arguments.index("diagnosis"))
    found = []
    for node in nodes:
        if not isinstance(node, ast.Call):
            continue
        values = [keyword.value for keyword in node.keywords if keyword.arg == "diagnosis"]
        index = positions.get(_called(node))
        if index is not None and len(node.args) > index:
            values.append(node.args[index])
        if _called(node) in ("Mistake", "Model"):
            values += [keyword.value for keyword in node.keywords if keyword.arg == "name"]
        for value in values:
            for text in _strings(value, constants):
                found += [(node.lineno, name) for name in names_of(text)]
    return found
