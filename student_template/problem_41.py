"""Problem 41: understanding dynamics, three multiple-choice questions.

Write the number of the option you choose for each question in answers.toml (``[problem_41] a``, ``b``, ``c``).
For (c), the flyball governor is the one of problem 27(d): the ball of mass ``m`` at the distance ``l`` from the
top of the linkage, at the angle ``gamma = 30 deg`` from the spinning axis, ``phi = 0``, ``q = (phi, gamma)``.
"""

__all__ = []


