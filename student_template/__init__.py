"""Your multibody-dynamics package: the student template of the course.

The package is a small multibody library (rotations, coordinate systems, rigid bodies, inertia, kinematic trees)
plus one ``problem_NN`` module per problem of the exercise sheet.  Fill in every function that raises
``NotImplementedError("Problem N: ...")``, and the answers in ``answers.toml``; keep the names and signatures, which
the grader calls.  ``grade problem-6`` in this folder grades problem 6.

Notation (see ``conventions``): ``A_XY`` maps Y-coordinates to X-coordinates, ``B_r_IB`` is the position of B
from I expressed in B, adjacent frame letters cancel (``A_IB @ A_BC == A_IC``).  SI units, radians.

Import inside the package with relative imports (``from .rotations import skew``): the grader imports the package
under another name.
"""
