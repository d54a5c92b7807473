r"""Stiff thermal network with large steps (tiny thermal capacities next to huge conductances).

The stiff spindle is the default one (spindle/thermal/params/b7214c_x_pair.toml) with one extra node, `film_1`,
between outer ring 1 and the housing: capacity 1e-3 of a ring's (0.1467 J/K) and a conductance 1e4 times
the bearing's internal one (1.5e5 W/K) to the outer ring; the ring-housing contact now starts at the
film. Its time constant C/G ~ 1e-6 s is 1e9 times shorter than the slowest (~650 s).

Why the step size does not matter for the implicit schemes. A = C^-1 L is similar to the symmetric
S = C^-1/2 L C^-1/2, so its eigenvalues lambda are real and > 0 (L positive definite). Over a step h
each eigenmode is multiplied by
    forward Euler   1 - h lambda         (|.| < 1 only if h < 2/lambda: here h < 2e-6 s)
    backward Euler  1 / (1 + h lambda)   (in ]0, 1[ for every h: A-stable; -> 0 as h lambda -> inf:
                                          L-stable, the stiff mode is removed in one step, without
                                          the sign flip of the trapezoidal rule)
    exponential     exp(-h lambda)       (in ]0, 1[, exact for inputs held over the step)
Monotonicity in node space (no overshoot after a heat step from a uniform start) follows from the
M-matrix structure of L (off-diagonals <= 0): -A is a Metzler matrix, so exp(-A t) >= 0 elementwise
and dT/dt = exp(-A t) C^-1 P >= 0 for P >= 0; for backward Euler (C/dt + L)^-1 >= 0 (inverse of an
M-matrix), and the residual r_n = f - L T_n obeys r_{n+1} = (C/dt)(C/dt + L)^-1 r_n >= 0, so every
increment T_{n+1} - T_n = (C/dt + L)^-1 r_n >= 0 and T_n never passes T_ss.
"""

import math

import numpy as np
import pytest

from spindle.thermal import network as nk
from spindle.thermal.model import CATALOGUE, SpindleThermalModel

OMEGA = 10000.0 * 2.0 * math.pi / 60.0
HEATS = dict(Q_inner_ring_1=300.0, Q_outer_ring_1=200.0, Q_inner_ring_2=300.0, Q_outer_ring_2=200.0)
RUN = dict(omega=OMEGA, T_ambient=293.15, T_coolant=293.15, **HEATS)
C_FILM = 1e-3 * 146.7  # J/K, 1e-3 of a bearing ring's capacity
G_FILM = 1e4 * 15.0  # W/K, 1e4 x the bearing's internal ball/oil-ring conductance
G_CONTACT = 2000.0 * 9.425e-3  # W/K, outer ring 1 - housing contact of the default file
OLD_LINK = '''between = ["outer_ring_1", "housing"]
kind = "contact"'''
NEW_NODE = '''[[node]]
name = "housing"'''


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """(stiff, reference) TOML paths. The reference merges the film into outer ring 1 (capacity added) and
    replaces the two links by their exact series conductance: same physics without the fast mode."""
    folder = tmp_path_factory.mktemp("stiff")
    text = (CATALOGUE / "b7214c_x_pair.toml").read_text()
    assert OLD_LINK in text and NEW_NODE in text
    stiff = text.replace(
        NEW_NODE,
        f"""[[node]]
name = "film_1"
capacity = {{ value = {C_FILM!r}, unit = "J/K", source = "stiff test node" }}

{NEW_NODE}""",
    ).replace(
        OLD_LINK,
        f'''between = ["outer_ring_1", "film_1"]
kind = "conductance"
G = {{ value = {G_FILM!r}, unit = "W/K", source = "stiff test link" }}

[[link]]
between = ["film_1", "housing"]
kind = "contact"''',
    )
    G_series = 1.0 / (1.0 / G_FILM + 1.0 / G_CONTACT)
    block_end = text.index("[[link]]", text.index(OLD_LINK))
    reference = (
        text[: text.index(OLD_LINK)]
        + f"""between = ["outer_ring_1", "housing"]
kind = "conductance"
G = {{ value = {G_series!r}, unit = "W/K", source = "series film + contact" }}

"""
        + text[block_end:]
    ).replace(
        'capacity = { value = 224.9, unit = "J/K", source = "B7214C outer ring',
        f'capacity = {{ value = {224.9 + C_FILM!r}, unit = "J/K", source = "B7214C outer ring',
        1,
    )
    paths = folder / "stiff.toml", folder / "reference.toml"
    paths[0].write_text(stiff)
    paths[1].write_text(reference)
    return paths


def run(path, integrator, h, t_end, substeps=1):
    m = SpindleThermalModel(path, integrator=integrator, substeps=substeps)
    m.initialize(**RUN)
    names = [f"T_{n}" for n in m.net.nodes]
    rows = [[m.outputs_values()[k] for k in names]]
    for _ in range(int(round(t_end / h))):
        out = m.step(h)
        rows.append([out[k] for k in names])
    return m, names, np.array(rows)


def test_the_network_is_stiff(files):
    """Fastest/slowest time constant ratio of the stiff network > 1e8 (vs ~230 for the default one)."""
    tau = SpindleThermalModel(files[0]).time_constants(OMEGA)
    assert tau[-1] < 2e-6 and tau[0] / tau[-1] > 1e8


@pytest.mark.parametrize("integrator", ["exponential", "implicit_euler"])
@pytest.mark.parametrize("h", [1.0, 10.0])
def test_step_heat_monotone_no_overshoot(files, integrator, h):
    """Heat step (1 kW) from a uniform 293.15 K: every node rises monotonically and never passes its
    steady state (module docstring: both schemes preserve the sign structure). Allowance 1e-9 K for
    rounding of ~350 K values (ulp 6e-14 K) accumulated over the steps."""
    m, names, T = run(files[0], integrator, h, 3600.0)
    ss = m.steady_state()
    T_ss = np.array([ss[k] for k in names])
    assert np.all(np.isfinite(T))
    assert np.all(np.diff(T, axis=0) >= -1e-9), "a node temperature decreased"
    assert np.all(T <= T_ss + 1e-9), "overshoot past the steady state"
    assert np.all(T[-1] > 293.15 + 1.0)  # and it does heat up (no frozen solution)


@pytest.mark.parametrize("integrator", ["exponential", "implicit_euler"])
def test_steady_state_equals_direct_solve(files, integrator):
    """After 1 h at h = 10 s, then 20 steps of 1e5 s (large steps are safe), both schemes sit on the
    direct solve of L T = B T_b + P (numpy.linalg.solve, independent of the Cholesky kernel) to 1e-9 of
    the rise: T_ss is the exact fixed point of both; the slowest mode is reduced by
    1/(1 + 1e5/914)^20 < 1e-40 (backward Euler) or exp(-2e6/914) (exponential)."""
    m = SpindleThermalModel(files[0], integrator=integrator)
    m.initialize(**RUN)
    for _ in range(360):
        m.step(10.0)
    for _ in range(20):
        out = m.step(1e5)
    op = m._operator(OMEGA)
    P, Tb, _ = m._vectors(m._u)
    T_direct = np.linalg.solve(op["L"], op["B"] @ Tb + P)
    T = np.array([out[f"T_{n}"] for n in m.net.nodes])
    assert np.max(np.abs(T - T_direct)) <= 1e-9 * np.max(T_direct - 293.15)
    assert abs(out["P_out"] - out["P_in"]) <= 1e-9 * out["P_in"]


@pytest.mark.parametrize("integrator", ["exponential", "implicit_euler"])
@pytest.mark.parametrize("h", [1.0, 10.0])
def test_same_trajectory_as_non_stiff_reference(files, integrator, h):
    """Physics: the film follows outer ring 1 within 1e-6 s and passes the ring-housing flow through
    1.5e5 W/K. Eliminating it (capacity merged into the ring, exact series conductance) gives the same
    steady state and, in transients, moves only the share G_c/(G_film + G_c) = 1.3e-4 of the film's
    storage flow C_film dT/dt from the ring to the housing side: a relative perturbation of
    (C_film/C_ring) x 1.3e-4 = 8e-8 of the ring's rise (~50 K), i.e. <= 4e-6 K. With the same scheme and
    step both networks must then agree to that bound over 1 h; measured 4-5e-7 K, largest at ~20 s when
    the ring heats fastest. Backward Euler is stiffly accurate (L-stable): its limit for a vanishing film
    time constant is backward Euler on the reduced network, so the same bound applies to it."""
    _, names_s, T_s = run(files[0], integrator, h, 3600.0)
    _, names_r, T_r = run(files[1], integrator, h, 3600.0)
    common = [names_s.index(k) for k in names_r]
    diff = np.max(np.abs(T_s[:, common] - T_r))
    print(f"{integrator} h = {h} s: max |stiff - reference| = {diff:.2e} K")
    bound = (C_FILM / 224.9) * G_CONTACT / (G_FILM + G_CONTACT) * 50.0
    assert diff < bound


def forward_euler(C, L, f, T, h, steps):
    """Explicit Euler C (T_new - T)/h = f - L T: the contrast (not part of the product)."""
    out = [T]
    for _ in range(steps):
        T = T + h * (f - L @ T) / C
        out.append(T)
    return np.array(out)


def test_forward_euler_blows_up_at_these_steps(files):
    """Contrast, computed: forward Euler multiplies the film mode by 1 - h lambda_max; at h = 1 s that is
    ~ -1e6, so 6 steps amplify it by ~1e36 (growth asserted > 1e20 K, alternating signs). On the
    non-stiff reference at the same h = 1 s (lambda_max = 1/2.8 s^-1, |1 - h lambda| = 0.64 < 1) it stays
    bounded, and on the stiff network it is stable again once h < 2/lambda_max (~2e-6 s): the stiff node,
    not the heat input, limits the explicit step, while the implicit schemes above take h = 10 s."""
    growth = {}
    for key, path in zip(("stiff", "reference"), files):
        m = SpindleThermalModel(path)
        m.initialize(**RUN)
        op = m._operator(OMEGA)
        P, Tb, _ = m._vectors(m._u)
        f = nk.source_vector(op["B"], Tb, P)
        lam_max = 1.0 / m.time_constants(OMEGA)[-1]
        T = forward_euler(m.net.C, op["L"], f, m.T.copy(), 1.0, 6)
        growth[key] = np.max(np.abs(T[-1] - T[0]))
        if key == "stiff":
            assert abs(1.0 - lam_max) > 1e5
            # from step 2 on (step 1 only adds h P/C), the film deviation flips sign every step
            signs = np.sign(T[2:, m.net.nodes.index("film_1")] - T[0, m.net.nodes.index("film_1")])
            assert np.all(signs[1:] * signs[:-1] < 0), "the unstable mode alternates in sign"
            small = forward_euler(m.net.C, op["L"], f, m.T.copy(), 1.0 / lam_max, 2000)
            assert np.all(np.isfinite(small)) and np.max(np.abs(small - 293.15)) < 1.0
        else:
            assert abs(1.0 - lam_max) < 1.0
    print(
        f"forward Euler at h = 1 s, 6 steps: max change stiff {growth['stiff']:.2e} K, "
        f"reference {growth['reference']:.2e} K"
    )
    assert growth["stiff"] > 1e20
    assert growth["reference"] < 10.0
