"""Probes of problem 5: the repaired model (and the given broken one), loaded by MuJoCo in the sandbox."""

from . import _mjcf, module, probe


@probe(returns=_mjcf.RESULT_OF_DESCRIBE, says="fixed_model()")
def fixed(pkg, qpos=None):
    """What ``fixed_model()`` declares, at the joint configuration ``qpos`` when it has the model's size."""
    xml = module(pkg, "problem_05").fixed_model()
    return _mjcf.guarded(lambda: _mjcf.describe(*_mjcf.posed(*_mjcf.load(xml), qpos)))


@probe(returns=_mjcf.RESULT_OF_DESCRIBE, says="BROKEN_MODEL")
def broken(pkg):
    xml = module(pkg, "problem_05").BROKEN_MODEL
    return _mjcf.guarded(lambda: _mjcf.describe(*_mjcf.load(xml)))
