"""Probes of problem 8: the three integration steps, the Cardan-rate matrix, and the three runs."""

from . import module, probe


@probe
def rate_matrix(pkg, alpha, beta, gamma):
    return module(pkg, "rotations").cardan_rate_matrix(alpha, beta, gamma)


@probe
def step(pkg, which, x, I_omega, dt):
    p8 = module(pkg, "problem_08")
    func = {"euler": p8.euler_matrix_step, "cardan": p8.cardan_euler_step, "exp": p8.exponential_step}[which]
    return func(x, I_omega, dt)


@probe
def part(pkg, which):
    return getattr(module(pkg, "problem_08"), f"part_{which}")()
