"""The gradebook now lives in ``grader.batch.gradebook``; this name stays for the code that imports it here."""

from .batch.gradebook import *  # noqa: F401,F403
from .batch.gradebook import __all__  # noqa: F401
