"""Problem 24's bands hold for every solve_ivp method at its default tolerances: the run released from a start of
its own (drawn angles, speeds and output step) stays within ``SIMULATION_BAND`` of the reference's tight run, and
the sheet's run conserves its energy within ``SIMULATION_ENERGY``.  The worst errors are printed (``-s``)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from checks.problem_24 import (
    OWN_T_END,
    SIMULATION_BAND,
    SIMULATION_ENERGY,
    SIMULATION_T_END,
    draw_start,
)
from probes._dynamics import energies
from reference import problem_24 as p24
from reference.dynamics import DynamicBody

METHODS = ("RK45", "RK23", "DOP853", "LSODA")
DRAWS = 50


def _run(method, t_end, q0, qd0, t_eval, tree):
    y0 = np.concatenate([np.asarray(q0, dtype=float), np.asarray(qd0, dtype=float)])
    result = solve_ivp(p24.pendulum_ode, (0.0, t_end), y0, method=method, t_eval=t_eval, args=(tree,))
    return result.y[:3].T, result.y[3:].T


@pytest.mark.slow
def test_every_method_at_its_defaults_stays_within_the_band_of_a_drawn_run():
    tree = p24.build_triple_pendulum(DynamicBody)
    worst = {method: {"q": 0.0, "qd": 0.0} for method in METHODS}
    for seed in range(DRAWS):
        q0, qd0, dt = draw_start(np.random.default_rng(seed))
        tight = p24.simulate(OWN_T_END, np.array(q0), np.array(qd0), dt)
        for method in METHODS:
            q, qd = _run(method, OWN_T_END, q0, qd0, tight["t"], tree)
            for key, value in (("q", q), ("qd", qd)):
                worst[method][key] = max(worst[method][key], float(np.abs(value - tight[key]).max()))
    for method, errors in worst.items():
        print(f"{method}: " + ", ".join(f"{key} {error:.3g} ({error / SIMULATION_BAND[key].atol:.0%} of the band)"
                                        for key, error in errors.items()))
    assert all(errors[key] <= SIMULATION_BAND[key].atol for errors in worst.values() for key in errors), worst


@pytest.mark.slow
@pytest.mark.parametrize("method", METHODS)
def test_every_method_at_its_defaults_conserves_the_energy_of_the_sheets_run(method):
    tree = p24.build_triple_pendulum(DynamicBody)
    t_eval = np.linspace(0.0, SIMULATION_T_END, 201)
    q, qd = _run(method, SIMULATION_T_END, p24.Q, np.zeros(3), t_eval, tree)
    E = np.array([sum(energies(tree, a, b, p24.I_GRAV)) for a, b in zip(q, qd)])
    drift = float(np.abs(E - E[0]).max())
    print(f"{method}: energy drift {drift:.3g} J of {SIMULATION_ENERGY.atol:g} J allowed")
    assert drift <= SIMULATION_ENERGY.atol
