"""Reference solution of the multibody-dynamics course.

The package is a small multibody library (rotations, coordinate systems, rigid bodies, inertia, kinematic trees)
plus one ``problem_NN`` module per problem of the exercise sheet.  Student-editable regions are marked with
``# BEGIN SOLUTION problem N`` / ``# END SOLUTION``; ``python -m tools.make_template`` turns this package into
``student_template/``.

Notation (see ``conventions``): ``A_XY`` maps Y-coordinates to X-coordinates, ``B_r_IB`` is the position of B
from I expressed in B, adjacent frame letters cancel (``A_IB @ A_BC == A_IC``).  SI units, radians.

All imports inside the package are relative, so the same code runs whether it is imported as ``reference`` or as
a student's copy under another name.
"""
