"""SpindleThermalModel facade (spindle/thermal/model.py): variables, stepping, state, steady state, thermo-mechanics,
axial float, parameter and input validation. Expectations come from the model definition
(docs/spindle_thermal.md) and are derived in each docstring."""

import json
import math

import pytest

from bearing_fmu.models.limits import InputError
from bearing_fmu.params import ParameterError
from spindle.thermal import network as nk
from spindle.thermal.model import CATALOGUE, SpindleInputError, SpindleThermalModel
from tests.unit._compare import assert_close

OMEGA = 10000.0 * 2.0 * math.pi / 60.0
HEATS = dict(Q_inner_ring_1=300.0, Q_outer_ring_1=200.0, Q_inner_ring_2=300.0, Q_outer_ring_2=200.0)
RUN = dict(omega=OMEGA, T_ambient=293.15, T_coolant=293.15, **HEATS)
DEFAULT_TOML = (CATALOGUE / "b7214c_x_pair.toml").read_text()


def variant(tmp_path, *replacements, name="variant"):
    """Path of a copy of the default spindle file with (old, new) text replacements (each must match)."""
    text = DEFAULT_TOML
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return path


def test_variables_exactly():
    """Inputs and outputs of the default spindle, in order (docs/spindle_thermal.md)."""
    m = SpindleThermalModel()
    assert [v.name for v in m.inputs] == [
        "Q_inner_ring_1",
        "Q_outer_ring_1",
        "Q_inner_ring_2",
        "Q_outer_ring_2",
        "P_motor",
        "omega",
        "T_ambient",
        "T_coolant",
    ]
    nodes = [
        "shaft",
        "inner_ring_1",
        "inner_ring_2",
        "ball_oil_1",
        "ball_oil_2",
        "outer_ring_1",
        "outer_ring_2",
        "housing",
    ]
    assert [v.name for v in m.outputs] == [f"T_{n}" for n in nodes] + [
        "T_oil_1",
        "dPd_thermal_1",
        "T_oil_2",
        "dPd_thermal_2",
        "dz_thermal",
        "dz_thermal_1",
        "dz_thermal_2",
        "P_in",
        "P_out",
        "E_stored",
    ]
    assert all(v.unit and v.description for v in m.inputs + m.outputs)
    m.initialize()
    assert set(m.outputs_values()) == {v.name for v in m.outputs} | {
        "T_inner_ring_1",
        "T_inner_ring_2",
        "T_outer_ring_1",
        "T_outer_ring_2",
    }


def test_initial_state_and_rest():
    """At initialisation every node sits at T_ambient (default T_initial); at rest and at T_ref nothing
    has grown: dPd = dz = 0, P_out = 0, E_stored = 0 (exactly: every term carries (T - T_ref) or omega^2)."""
    m = SpindleThermalModel()
    out = m.initialize(T_ambient=293.15, T_coolant=290.0)
    assert all(out[f"T_{n}"] == 293.15 for n in m.net.nodes)
    assert out["dPd_thermal_1"] == 0.0 and out["dz_thermal"] == 0.0 and out["E_stored"] == 0.0
    out = SpindleThermalModel(T_initial=300.0).initialize(T_ambient=293.15)
    assert out["T_housing"] == 300.0


def test_steady_state_energy_balance_and_plausibility():
    """Default spindle, 10 000 rpm, 1 kW (300/200 W per bearing): P_out = P_in at steady state (the
    node equations sum to it; 1e-9 relative for the Cholesky solve). Plausibility (Rabreau
    2018 Fig. 8, not tabulated): outer-ring rise in the tens of K (band 10-60 K) and the slowest time
    constant 10-30 min, the design targets of the estimated parameters (docs/spindle_thermal.md)."""
    m = SpindleThermalModel()
    ss = m.steady_state(**RUN)
    assert_close(ss["P_out"], 1000.0, 1e-9, "P_out")
    assert 10.0 < ss["T_outer_ring_1"] - 293.15 < 60.0
    assert 600.0 <= m.time_constants(OMEGA)[0] <= 1800.0
    assert ss["T_inner_ring_1"] > ss["T_outer_ring_1"] and ss["dPd_thermal_1"] < 0.0
    assert ss["dz_thermal"] > 0.0  # X arrangement, shaft hotter than housing: tighter


def test_long_run_reaches_steady_state_both_integrators():
    """Stepping 4 h (exponential: 240 steps of 60 s; implicit Euler: 240 steps of 60 s with 2 substeps)
    reaches the direct steady state: the slowest mode (650 s) decays as exp(-14400/650) ~ 2.4e-10
    (exponential) and as 1/(1 + 30/650)^480 ~ 4e-10 (backward Euler); measured 3.0e-10 and 4.9e-10 of
    the rise. Tolerance 1e-8 of the rise."""
    ss = SpindleThermalModel().steady_state(**RUN)
    for integrator, substeps, tol in (("exponential", 1, 1e-8), ("implicit_euler", 2, 1e-8)):
        m = SpindleThermalModel(integrator=integrator, substeps=substeps)
        m.initialize(**RUN)
        for _ in range(240):
            out = m.step(60.0)
        for node in m.net.nodes:
            key = f"T_{node}"
            assert abs(out[key] - ss[key]) <= tol * (ss[key] - 293.15), (integrator, key)


def test_implicit_euler_matches_exponential_when_refined():
    """1 h in 60 steps of 60 s: backward Euler with 64 substeps (dt ~ 1 s, below the fastest 2.8 s time
    constant) agrees with the exact update within its O(dt) error, measured 6e-4 K (with 1 substep:
    0.04 K); bound 5e-3 K."""
    outs = []
    for integrator, substeps in (("exponential", 1), ("implicit_euler", 64)):
        m = SpindleThermalModel(integrator=integrator, substeps=substeps)
        m.initialize(**RUN)
        for _ in range(60):
            out = m.step(60.0)
        outs.append(out)
    for node in SpindleThermalModel().net.nodes:
        assert abs(outs[0][f"T_{node}"] - outs[1][f"T_{node}"]) < 5e-3


def test_energy_bookkeeping_outputs():
    """E_stored after one backward-Euler step with substeps = 1 equals h (P_in - P_out(T_end)) exactly (the
    scheme's discrete energy balance), 1e-9 relative; for the exponential update E_stored over many steps
    equals the time integral of P_in - P_out (trapezoid over 1 s steps: O(h^2) ~ 1e-4 relative error)."""
    m = SpindleThermalModel(integrator="implicit_euler")
    m.initialize(**RUN)
    out = m.step(30.0)
    assert_close(out["E_stored"], 30.0 * (out["P_in"] - out["P_out"]), 1e-9, "E_stored IE")
    m = SpindleThermalModel()
    prev = m.initialize(**RUN)
    integral = 0.0
    for _ in range(600):
        out = m.step(1.0)
        integral += 0.5 * ((prev["P_in"] - prev["P_out"]) + (out["P_in"] - out["P_out"]))
        prev = out
    assert_close(out["E_stored"], integral, 1e-4, "E_stored exp")


def test_state_round_trip():
    """get_state is JSON-serialisable and set_state restores everything: stepping on from a restored
    state reproduces the outputs bit for bit (same floating-point operations)."""
    m = SpindleThermalModel()
    m.initialize(**RUN)
    for _ in range(5):
        m.step(10.0)
    saved = json.loads(json.dumps(m.get_state()))
    ref = [m.step(10.0, P_motor=50.0) for _ in range(3)]
    m2 = SpindleThermalModel()
    m2.set_state(saved)
    assert m2.time == 50.0
    again = [m2.step(10.0, P_motor=50.0) for _ in range(3)]
    assert ref == again


def test_clearance_sign_and_centrifugal():
    """Hotter inner ring (rest of the bearing at T_ref) -> the inner raceway grows -> clearance shrinks:
    dPd = -alpha d_i dT < 0 (1e-12). At speed with every node at T_ref, dPd = -2 u_c (centrifugal growth of
    the inner raceway, 2.18 um radial at 10 000 rpm, test_network) -> -4.355 um."""
    m = SpindleThermalModel()
    m.initialize(T_ambient=293.15, T_coolant=293.15)
    state = m.get_state()
    state["T"][m.net.nodes.index("inner_ring_1")] = 303.15
    m.set_state(state)
    out = m.outputs_values()
    b = m.net.bearings[0]
    assert out["dPd_thermal_1"] < 0.0
    assert_close(out["dPd_thermal_1"], -11.5e-6 * b["d_i"] * 10.0, 1e-12, "dPd hot inner ring")
    assert out["dPd_thermal_2"] == 0.0
    out = m.steady_state(omega=OMEGA, **{k: 0.0 for k in HEATS})
    assert_close(out["dPd_thermal_1"], -2 * 2.1775e-6, 1e-4, "dPd centrifugal")


def test_axial_sign_X_vs_O(tmp_path):
    """Shaft 10 K hotter than the housing (steel, spacing 0.1 m): its extra growth is
    11.5e-6 x 0.1 x 10 = 11.5 um. X (face-to-face) pair: the shaft pushes the inner rings apart, against
    their outer rings -> both bearings tighter, dz = +11.5 um; O (back-to-back): the same growth
    unloads them, dz = -11.5 um (docs/spindle_thermal.md, sketch). Per bearing dz/2."""
    outs = {}
    for arr in ("X", "O"):
        path = variant(tmp_path, ('arrangement = "X"', f'arrangement = "{arr}"'), name=arr)
        m = SpindleThermalModel(path)
        m.initialize(T_ambient=293.15, T_coolant=293.15)
        state = m.get_state()
        state["T"][m.net.nodes.index("shaft")] = 303.15
        m.set_state(state)
        outs[arr] = m.outputs_values()
    assert_close(outs["X"]["dz_thermal"], 11.5e-6, 1e-12, "X")
    assert_close(outs["O"]["dz_thermal"], -11.5e-6, 1e-12, "O")
    assert outs["X"]["dz_thermal_1"] == outs["X"]["dz_thermal_2"] == 0.5 * outs["X"]["dz_thermal"]


def test_axial_float_equalises_forces(tmp_path):
    """axial_float = true: linear-spring pair F_k = F0_k + K_k dz_k (K_1 = 2e8, K_2 = 1e8 N/m, preloads
    800 and 900 N). The float update s += (F_2 - F_1)/(K_1 + K_2) is one Newton step on F_1 - F_2, exact
    for linear springs: forces equal after the first step (1e-9 of the preload), and stay equal while the
    spindle heats (dz_thermal grows, both bearings equally only if K_1 = K_2: here the mismatch per step is
    (K_1 - K_2) d(dz)/2, so the residual is bounded by the last step's change and the next step removes it)."""
    path = variant(tmp_path, ("axial_float = false", "axial_float = true"))
    m = SpindleThermalModel(path)
    names = [v.name for v in m.inputs]
    assert names[-4:] == ["F_axial_1", "F_axial_2", "K_axial_1", "K_axial_2"]
    K = (2e8, 1e8)
    F0 = (800.0, 900.0)

    def forces(out):
        return [F0[k] + K[k] * out[f"dz_thermal_{k + 1}"] for k in range(2)]

    out = m.initialize(T_ambient=293.15, T_coolant=293.15)
    F = forces(out)
    out = m.step(1.0, F_axial_1=F[0], F_axial_2=F[1], K_axial_1=K[0], K_axial_2=K[1])
    F = forces(out)
    assert abs(F[0] - F[1]) < 1e-9 * 800.0
    assert_close(out["dz_thermal_1"] - out["dz_thermal_2"], 2 * m.s, 1e-12, "float")
    m.step(60.0, omega=OMEGA, **HEATS)  # heating: dz grows between force updates
    for _ in range(5):
        before = m.outputs_values()
        F = forces(before)
        out = m.step(1e4, F_axial_1=F[0], F_axial_2=F[1])  # long steps: temperatures settle
    F = forces(out)
    assert abs(F[0] - F[1]) < 1e-6 * 800.0


def test_bad_inputs_name_the_input():
    """Bad input raises a clear error (an InputError/ValueError) naming the input and its range;
    the state is left unchanged."""
    m = SpindleThermalModel()
    m.initialize(**RUN)
    before = m.get_state()
    cases = [
        (dict(omega=math.nan), "omega"),
        (dict(T_ambient=-5.0), "T_ambient"),
        (dict(T_coolant=math.inf), "T_coolant"),
        (dict(Q_inner_ring_1=math.nan), "Q_inner_ring_1"),
        (dict(P_motor=1e12), "P_motor"),
        (dict(Q_typo=1.0), "Q_typo"),
        (dict(omega="fast"), "omega"),
    ]
    for inputs, name in cases:
        with pytest.raises(SpindleInputError, match=name) as info:
            m.step(1.0, **inputs)
        assert isinstance(info.value, InputError) and isinstance(info.value, ValueError)
    for h in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(SpindleInputError, match="step size h"):
            m.step(h)
    with pytest.raises(SpindleInputError, match=r"node \w+ would reach T = .*non-physical"):
        m.step(1e6, Q_inner_ring_1=-1e7)
    assert m.get_state() == before
    with pytest.raises(SpindleInputError, match="integrator"):
        SpindleThermalModel(integrator="rk4")
    with pytest.raises(SpindleInputError, match="substeps"):
        SpindleThermalModel(integrator="implicit_euler", substeps=0)


def _dimensions(**changes):
    """The default network's main dimensions (the FMU parameters of network_from_file false) with `changes`."""
    from spindle.thermal.declarations import dimension_rows
    from spindle.thermal.model import load_spindle

    values = {name: value for name, *_, value in dimension_rows(load_spindle("b7214c_x_pair"))}
    return {**values, **changes}


def test_ring_modulus_and_clearance_ranges_are_the_bearing_fmus():
    """bearing_k.E_ring and bearing_k.Pd declare the ranges of the bearing FMUs' bearing_data.E_ring and
    bearing_data.Pd (a steel or ceramic ring, 10 GPa to 1 TPa; |Pd| <= 10 mm), and in use the clearance is bounded by
    the groove clearance (f_i + f_o - 1) D = 0.79 mm of the B7214C, as the bearing FMUs bound it. A ring of 1 MPa
    would give dPd_thermal = -0.914 m at 10 000 rpm."""
    from bearing_fmu.models.file_parameters import BEARING_QUANTITIES
    from spindle.thermal.declarations import dimension_declarations
    from spindle.thermal.model import load_spindle

    thermal = {v.name: v for v in dimension_declarations(load_spindle("b7214c_x_pair"))}
    bearing = {q.variable.name: q.variable for q in BEARING_QUANTITIES}
    for k in (1, 2):
        for name in ("E_ring", "Pd"):
            ours, theirs = thermal[f"bearing_{k}.{name}"], bearing[f"bearing_data.{name}"]
            assert (
                (ours.min, ours.max) == (theirs.min, theirs.max) == {"E_ring": (1e10, 1e12), "Pd": (-1e-2, 1e-2)}[name]
            )
    with pytest.raises(
        InputError, match=r"bearing_1.E_ring = 1000000.0 Pa is outside the allowed range \[1e\+10, 1e\+12\]"
    ):
        SpindleThermalModel(dimensions=_dimensions(**{"bearing_1.E_ring": 1e6}))
    with pytest.raises(
        ParameterError,
        match=r"bearing_2.Pd = 0.01 m is outside the allowed range \[-0.0007938, 0.0007938\] m \(\|Pd\| <= "
        r"\(f_i \+ f_o - 1\) D with bearing_2.D = 0.015875 m and the conformities f_i = 0.52, f_o = 0.53",
    ):
        SpindleThermalModel(dimensions=_dimensions(**{"bearing_2.Pd": 0.01}))
    soft = SpindleThermalModel(dimensions=_dimensions(**{"bearing_1.E_ring": 1e10}))
    soft.initialize(**RUN)
    # 21 x the steel ring's centrifugal growth (-4.35 um of clearance at 10 000 rpm, docs/spindle_thermal.md)
    assert -100e-6 < soft.step(1.0)["dPd_thermal_1"] < -80e-6


def test_bore_is_checked_as_the_bearing_files():
    """bearing_k.bore below the inner groove bottom d_m - D - max(Pd, 0)/2 (the B7214C: 81.598 mm), as a bearing
    file's bore (bearing_fmu_common.bearing_file.check_ring_sections)."""
    with pytest.raises(
        ParameterError,
        match=r"bearing_1.bore = 0.0816 m leaves the inner ring no material under its groove: allowed below the inner "
        r"groove bottom d_m - D - max\(P_d, 0\)/2 = 0.081598 m \(bearing_1.d_m = 0.0975 m",
    ):
        SpindleThermalModel(dimensions=_dimensions(**{"bearing_1.bore": 0.0816}))
    SpindleThermalModel(dimensions=_dimensions(**{"bearing_1.bore": 0.0815}))


def test_an_impossible_clearance_change_is_refused_and_the_state_kept():
    """dPd_thermal_k stays within what the bearing FMUs take as their input dPd_thermal: |dPd| <= 1 mm and
    |Pd + dPd| <= (f_i + f_o - 1) D. At 30 000 rad/s (far beyond the bearing's d_m n limit) the B7214C's inner ring
    would grow by 1.8 mm (dPd = -3.57 mm in a step, -3.58 mm at the steady state): refused naming the output, its
    value and the range, as a step, at initialisation and at a steady state; the state is left unchanged."""
    m = SpindleThermalModel()
    m.initialize(**RUN)
    before = m.get_state()
    values = m.values.copy()
    refused = r"dPd_thermal_1 = -0.0035\d* m \(thermal and centrifugal growth at omega = 30000.0 rad/s .*\) is "
    refused += r"outside the allowed range \[-0.0008478, 0.0007397\] m"
    with pytest.raises(SpindleInputError, match=refused):
        m.step(1.0, omega=3e4)
    assert m.get_state() == before and (m.values == values).all()
    with pytest.raises(SpindleInputError, match=refused):
        m.steady_state(omega=3e4)
    with pytest.raises(SpindleInputError, match=refused):
        SpindleThermalModel().initialize(**{**RUN, "omega": 3e4})
    assert m.step(1.0, omega=OMEGA)["dPd_thermal_1"] < 0.0  # the run goes on


def test_parameter_errors(tmp_path):
    """Parameter files are checked: a node cut off from every boundary (L singular) is named; a wrong
    unit, a split not summing to 1, an unknown catalogue name are reported with the key."""
    isolated = variant(
        tmp_path,
        (
            '[[node]]\nname = "housing"',
            '[[node]]\nname = "lonely"\ncapacity = { value = 1.0, unit = "J/K", source = "t" }\n\n'
            '[[node]]\nname = "housing"',
        ),
        name="isolated",
    )
    with pytest.raises(
        ParameterError, match="node lonely has no conductive path to a boundary: steady state undefined"
    ):
        SpindleThermalModel(isolated)
    shaft_only = variant(
        tmp_path,
        ('between = ["shaft", "inner_ring_1"]', 'between = ["inner_ring_2", "inner_ring_1"]'),
        ('between = ["shaft", "inner_ring_2"]', 'between = ["inner_ring_1", "inner_ring_2"]'),
        name="shaft_only",
    )
    with pytest.raises(ParameterError, match="node shaft has no conductive path"):
        SpindleThermalModel(shaft_only)  # only the rotating-shaft convection left: it vanishes at rest
    unit = variant(
        tmp_path, ('h_c  = { value = 2000.0, unit = "W/m^2/K"', 'h_c  = { value = 2000.0, unit = "W/m2K"'), name="unit"
    )
    with pytest.raises(ParameterError, match="h_c"):
        SpindleThermalModel(unit)
    split = variant(
        tmp_path,
        ("split = { inner_ring_1 = 0.5, ball_oil_1 = 0.5 }", "split = { inner_ring_1 = 0.5, ball_oil_1 = 0.4 }"),
        name="split",
    )
    with pytest.raises(ParameterError, match="sum to"):
        SpindleThermalModel(split)
    with pytest.raises(ParameterError, match="unknown spindle"):
        SpindleThermalModel("no_such_spindle")


def test_capacities_from_b7214c_geometry():
    """The ring and ball capacities of the default file follow from the B7214C dimensions and steel
    (rho 7850 kg/m^3, c 460 J/kg/K): inner ring annulus 70 -> 84 mm, outer 111 -> 125 mm, width 24 mm,
    17 balls of 15.875 mm (docs/spindle_thermal.md). 1e-3: the file rounds to 4 digits."""
    rho_c, B = 7850.0 * 460.0, 0.024
    C = dict(zip(SpindleThermalModel().net.nodes, SpindleThermalModel().net.C))
    assert_close(C["inner_ring_1"], rho_c * math.pi / 4 * (0.084**2 - 0.070**2) * B, 1e-3, "inner ring")
    assert_close(C["outer_ring_1"], rho_c * math.pi / 4 * (0.125**2 - 0.111**2) * B, 1e-3, "outer ring")
    assert_close(C["ball_oil_1"], rho_c * 17 * math.pi / 6 * 0.015875**3, 1e-3, "balls")


def test_parameters_summary():
    p = SpindleThermalModel().parameters
    assert set(p["nodes"]) == set(SpindleThermalModel().net.nodes)
    assert p["axial"]["arrangement"] == "X" and p["heat_inputs"]["P_motor"] == {"shaft": 1.0}
    assert any(link["kind"] == "rotating_shaft" and link["G_at_rest"] == 0.0 for link in p["links"])
    assert nk.LINK_ROTATING_SHAFT in SpindleThermalModel().net.kinds


def test_public_api_of_spindle_thermal():
    """`from spindle.thermal import ...` gives the model module's own objects (lazy imports), and an
    unknown name raises AttributeError as a module attribute lookup must."""
    import spindle.thermal as thermal
    from spindle.thermal import model

    for name in thermal.__all__:
        assert getattr(thermal, name) is getattr(model, name)
    with pytest.raises(AttributeError, match="no_such_name"):
        thermal.no_such_name  # noqa: B018
