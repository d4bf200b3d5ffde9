"""Every test of the diagnosis engine runs it strict: a defect of the engine fails the test instead of naming no
cause."""

from tests.kit_support import strict  # noqa: F401 (an autouse fixture)
