"""Every jitted kernel has a plain-Python twin and a test that compares them.

The mechanism, explicit on both sides:
- each twin module tests/reference/ref_<x>.py declares KERNEL_MODULE (the kernel module it twins) and
  TWINS = {kernel name: twin function};
- a comparison test is a test function (in tests/) that calls the kernel and its twin, directly or through
  helper functions and module-level tables of its own module; it is found by reading the test modules'
  source (imports resolved: `from bearing_fmu.kernels import hertz as hk` makes `hk.hertz_contact` the
  kernel; `from tests.reference import ref_hertz as rh` makes `rh.hertz_contact` the twin).
A few small helpers have no twin of their own: COVERED_THROUGH names, for each, the kernel that calls it
(checked: the caller's source names the helper, or the caller was built around it, as jones_harris'
line searches are), on a chain that ends at a twinned kernel, and says why that comparison covers it.
A package of kernels (kernels/ball_dynamics/) has one twin module per kernel module it twins.
The walk covers every numba dispatcher defined in bearing_fmu.kernels (packages included), bearing_fmu_common,
spindle.thermal.network and spindle.shaft.beam, and fails naming each kernel without a twin or without a comparison
test.
"""

import ast
import importlib
import inspect
import pkgutil
from pathlib import Path

from numba.core.registry import CPUDispatcher

import bearing_fmu.kernels
import bearing_fmu_common
import tests.reference

TESTS = Path(__file__).resolve().parent.parent
KERNEL_MODULES = (
    [m.name for m in pkgutil.walk_packages(bearing_fmu.kernels.__path__, "bearing_fmu.kernels.")]
    + [f"bearing_fmu_common.{m.name}" for m in pkgutil.iter_modules(bearing_fmu_common.__path__)]
    + ["spindle.thermal.network", "spindle.shaft.beam"]
)
JH = "bearing_fmu.kernels.jones_harris."
ES = "bearing_fmu.kernels.ehl_solver."
BD = "bearing_fmu.kernels.ball_dynamics."
# helper -> (twinned caller, why the caller's comparison covers it)
BT = "bearing_fmu.kernels.ball_traction."
BC = "bearing_fmu.kernels.ball_coupled_newton."
RB = "bearing_fmu.kernels.radial_bearing."
CO = "bearing_fmu.kernels.contact_outputs."
EC = "bearing_fmu.kernels.ehl_contact."
COVERED_THROUGH = {
    "bearing_fmu.kernels.lubricant.wlf_constants": (
        "bearing_fmu.kernels.lubricant.lubricant_state",
        "the WLF constants of the array, read for the compared viscosity and pressure-viscosity coefficient",
    ),
    "bearing_fmu.kernels.roots.illinois_update": (
        "bearing_fmu.kernels.lubrication.inlet_meniscus",
        "the bracket of the compared root (also of capacitance._bound_crossing's)",
    ),
    EC + "oil_state": (CO + "contact_outputs", "the oil's state at its temperature, eta and xi compared as outputs"),
    EC + "lubricated_contact": (
        CO + "_contact",
        "one contact's Hertz, film, film factors, Lambda and capacitance: every contact of both static fidelities "
        "compared (the analytic's through _race_contact)",
    ),
    EC + "contact_method": (CO + "contact_outputs", "the contact constants, read from the parameter array"),
    CO + "_start_sums": (CO + "contact_outputs", "the starting values of the compared sums and extremes"),
    CO + "_contact": (CO + "contact_outputs", "one contact's outputs, every contact's per_contact row compared"),
    CO + "_contact_loss": (CO + "_contact", "one loaded contact's loss, compared per contact and summed"),
    RB + "_ball_contacts": (RB + "analytic_bearing", "every ball's contacts and the races' summaries, all compared"),
    RB + "_race_contact": (RB + "_ball_contacts", "one contact into the ball rows and summaries, both races compared"),
    BT + "_surfaces": (BT + "_contact", "one contact's sliding, spin and entrainment speeds"),
    BT + "_contact": (BT + "_residual", "one contact's forces and moments, both contacts compared"),
    BT + "_residual": (BT + "traction_eval", "the residuals with the contacts' terms given"),
    BT + "_load_terms": (BT + "_terms_at", "a contact's terms of its load"),
    BT + "_film": (BT + "_films_at", "a contact's film terms"),
    BT + "_films_at": (BT + "_terms_at", "both contacts' film terms at the kinematics' entrainment speeds"),
    BT + "_terms_at": (BT + "traction_eval", "every term of both contacts"),
    BT + "solve_from_rolling": (JH + "_traction_grad", "the kinematics from a cold start, with a continuation"),
    BT + "_newton": (BT + "solve_traction_with", "the iteration whose result is the compared kinematics"),
    BT + "solve_traction_with": (BT + "solve_traction", "its body, with the caller's work arrays"),
    BT + "solve_work": (BT + "solve_traction", "the work arrays of a solve"),
    BT + "implicit_derivatives": (
        BT + "parameter_derivatives",
        "its implicit-function step, from the partials the solve leaves",
    ),
    BT + "_residual_d": (
        BT + "parameter_derivatives",
        "the residuals' closed-form partials, also checked against central differences of _residual",
    ),
    BT + "_contact_d": (BT + "_residual_d", "one contact's outputs and their gradients"),
    BT + "_p_column": (BT + "_residual_d", "one column of the partials in the contacts"),
    BT + "_surfaces_grad": (BT + "_contact_d", "gradients of one contact's sliding, spin and entrainment"),
    BT + "_lin": (BT + "_contact_d", "a linear combination of two gradients"),
    BT + "_unit": (BT + "_contact_d", "a gradient along one direction"),
    BT + "_film_load_exponent": (BT + "_film", "the load exponent of the film, checked through d/dQ"),
    BT + "_solve4": (BT + "_newton", "the Newton step of the compared kinematics"),
    BT + "_norm": (BT + "_newton", "the residual norm of the line search"),
    BT + "_marquardt": (BT + "_newton", "the damped step where Newton's does not descend"),
    BC + "coupled_newton": (
        JH + "ball_equilibrium",
        "the start of the nested ball solve, which verifies it in one evaluation: the compared equilibrium is the "
        "nested solve's (test_ball_coupled_newton.py checks that both reach one solution)",
    ),
    BC + "_evaluate": (BC + "coupled_newton", "its residuals, and the Jacobian checked against central differences"),
    BC + "ball_contacts": (JH + "_ball_eval", "a ball's contact loads and directions at its position"),
    BC + "hertz_load": (BC + "ball_contacts", "one contact's load and its derivative"),
    BC + "_norm6": (BC + "coupled_newton", "the residual norm of the line search"),
    BC + "coupled_work": (JH + "traction_work", "the work arrays of the coupled Newton"),
    JH + "_traction_grad": (JH + "_ball_eval", "the traction kinematics' terms, as _kin_grad's for a hypothesis"),
    JH + "traction_work": (JH + "ring_loads", "the work arrays of the traction kinematics"),
    JH + "_cold": (JH + "solve_quasistatic", "whether the traction kinematics start from outer-race control"),
    JH + "_ring_loads": (JH + "ring_loads", "its body, compiled with and without the traction kinematics"),
    JH + "_traction_ball": (JH + "ball_outputs", "the per-ball outputs of the traction kinematics"),
    ES + "_node_residual": (ES + "reynolds_residual", "the residual of one interior node, every node compared"),
    ES + "_eps": (ES + "_node_residual", "the Poiseuille coefficient of a node, four face means per residual"),
    ES + "_flux": (ES + "_node_residual", "the Couette flux of a node, three per upwind difference"),
    ES + "_poiseuille_diagonal": (
        ES + "relaxation_sweep",
        "the derivative of a node's Poiseuille term in its own pressure, the Newton step's denominator",
    ),
    ES + "_point_derivative": (
        ES + "relaxation_sweep",
        "a node's derivative in its own pressure, the point step's denominator and the line system's diagonal",
    ),
    ES + "_line_node": (ES + "line_gauss_seidel", "which nodes a row's line system takes, every row compared"),
    "bearing_fmu.kernels.film_correction._cell": (
        "bearing_fmu.kernels.film_correction.film_ratios",
        "the cell and fraction of one axis of the interpolation, compared inside and beyond every edge of the nodes",
    ),
    "bearing_fmu.kernels.capacitance._gap_integrands": (
        "bearing_fmu.kernels.capacitance._gap_coefficients",
        "the four integrands of the Hertz gap coefficients, Simpson nodes of every cell",
    ),
    "bearing_fmu.kernels.capacitance._gap_coefficients": (
        "bearing_fmu.kernels.capacitance.outside_hertz_capacitance",
        "the gap around the contact (A, B of each ring), compared through the capacitance integrated over it",
    ),
    "bearing_fmu.kernels.capacitance._bound_crossing": (
        "bearing_fmu.kernels.capacitance.outside_hertz_capacitance",
        "where the oil bound first cuts the rings and where it ends, the split points of the compared quadrature",
    ),
    "bearing_fmu.kernels.capacitance._ring_integrals": (
        "bearing_fmu.kernels.capacitance.outside_hertz_capacitance",
        "the angular integral of one ring, summed into the compared capacitance",
    ),
    "bearing_fmu.kernels.hertz._radius_ratio_of_ellipticity": (
        "bearing_fmu.kernels.hertz._ellipticity_exact_major",
        "the printed relation Ry/Rx(k) that the bisection inverts; compared on a grid of Ry/Rx through the exact "
        "coefficients",
    ),
    "bearing_fmu.kernels.hertz._ellipticity_exact_major": (
        "bearing_fmu.kernels.hertz.hertz_coefficients_exact",
        "the bisection for k returned by the exact coefficients (k is one of the compared values)",
    ),
    JH + "_kin_grad": (
        JH + "_ball_eval",
        "complex-step partials of kinematics (itself twinned); they steer the ball Newton whose solution is compared, "
        "and the stiffness they build is checked against central differences (test_quasistatic.py)",
    ),
    JH + "_chain": (JH + "_ball_eval", "chain rule of three kinematic partials, inlined into the ball evaluation"),
    JH + "_ball_eval": (JH + "_ball_newton", "the residual whose zero is the compared ball equilibrium"),
    JH + "_unloaded_ball": (JH + "ball_equilibrium", "the ball-off-both-races branch (compared: balls lifted)"),
    JH + "_static_ball": (JH + "ball_equilibrium", "the closed form at rest (compared: cases at rest)"),
    JH + "_ball_start": (JH + "ball_equilibrium", "the Newton start; the compared solution does not depend on it"),
    JH + "_ball_residual_at": (JH + "_ball_line_search", "one evaluation of the damped step"),
    JH + "_ball_line_search": (JH + "_ball_newton", "the damping of the ball Newton"),
    JH + "_ball_newton": (JH + "ball_equilibrium", "the iteration whose result is the compared ball equilibrium"),
    JH + "_condense": (JH + "ball_equilibrium", "the condensed derivatives; checked through the stiffness"),
    JH + "ball_outputs": (
        JH + "solve_quasistatic",
        "the per-ball rows, compared with the twin's balls after every solve (test_solution_matches_twin)",
    ),
    JH + "_global_newton": (JH + "solve_quasistatic", "the iteration whose result is the compared solution"),
    JH + "_loads_residual_at": (JH + "_global_newton", "one trial of the trust-region iteration"),
    JH + "_damped_newton": (JH + "solve_quasistatic", "the last resort whose result is the compared solution"),
    JH + "_loads_line_search": (JH + "_damped_newton", "the damping of the last-resort Newton"),
    JH + "_newton_system": (JH + "_global_newton", "the scaled, regularised Newton system of both ring solvers"),
    JH + "_max_abs": (JH + "_global_newton", "the size of a Newton step, the small-step convergence test"),
    JH + "_full_step": (JH + "_global_newton", "the five DOFs' step from the scaled step of the load-controlled ones"),
    JH + "_iteration_end": (JH + "_global_newton", "the convergence test of both ring solvers"),
    JH + "_dogleg": (JH + "_global_newton", "the step of the trust-region iteration whose result is compared"),
    JH + "_model_decrease": (JH + "_dogleg", "the quadratic model's decrease, two sums"),
    JH + "_sum_squares": (JH + "_global_newton", "a squared norm"),
    JH + "_residual_norm": (JH + "_newton_start", "largest scaled load error: the compared solution's criterion"),
    JH + "_newton_settings": (JH + "_global_newton", "the solvers' tolerance, cap, scales and stiffness floor"),
    JH + "_newton_start": (JH + "_global_newton", "the first evaluation of the compared iteration"),
    JH + "_mean_ball_load": (JH + "_iteration_end", "load scale of the convergence test, a mean"),
    # the DEM step's pieces: compared through advance over 300 steps of a 6208 in a speed ramp under 3 kN
    # (test_ball_dynamics.py: loaded and open contacts, boundary and mixed regimes, slipping springs, cage
    # balls pressed by the balls and by their channel), three film formulas
    BD + "integrator.verlet_step": (BD + "integrator.run_call", "the step that advance repeats"),
    BD + "tribology.refresh_tribology": (BD + "integrator.run_call", "the refresh every 10 steps (trib compared)"),
    BD + "integrator.ball_capacitances": (
        BD + "integrator.run_call",
        "each ball's series capacitance after a refresh (the integrated capacitance is compared)",
    ),
    BD + "tribology.tribology_constants": (
        BD + "integrator.run_call",
        "the fused film and Houpert constants; their own equality with kernels.ehl and kernels.torque is tested "
        "to 1e-12 in test_ball_dynamics.py",
    ),
    BD + "tribology.race_circle": (BD + "integrator.race_approaches", "the groove-centre circle of each race"),
    BD + "tribology.ring_axis": (
        BD + "integrator.correct_ring",
        "the tilted inner ring's axis: compared through advance with a tilting ring, and against the twin's Rodrigues "
        "rotation from 1e-9 to 0.3 rad in test_ball_dynamics.py",
    ),
    BD + "stiffness._contact_spring": (BD + "stiffness.stiffness_matrix", "the in-plane spring of each loaded contact"),
    BD + "cage.ball_cage_contact": (BD + "integrator.cage_forces", "ball - cage-ball contacts of a step"),
    BD + "cage.cage_guide_contact": (BD + "integrator.cage_forces", "cage ball - channel contacts of a step"),
    BD + "cage.damped_hertz": (BD + "cage.ball_cage_contact", "the damped Hertz law of both cage contacts"),
    BD + "integrator.rigid_cage_torque": (BD + "integrator.verlet_step", "the cage's torque shared by its elements"),
    BD + "integrator.slip_power_correction": (
        BD + "integrator.correct_balls",
        "the slip power at the velocities a step ends with, in the dissipated energy compared every step (the twin "
        "evaluates it from the end velocities directly, ref_ball_dynamics_integrator.slip_power)",
    ),
    BD + "tribology.sample_refresh": (BD + "integrator.run_call", "the averaged state outputs' refresh samples"),
    BD + "tribology.film_losses": (BD + "integrator.run_call", "the film's losses in the power booked every step"),
}


def _pieces(caller, why_by_piece):
    """COVERED_THROUGH entries of the pieces a kernel is written in, each inlined into it (one function body to the
    compiler), so that its comparison covers them as it covered the body: {module.piece: (caller, why)}."""
    module = caller.rsplit(".", 1)[0]
    return {f"{module}.{piece}": (caller, why) for piece, why in why_by_piece.items()}


# compared through advance, every state array after each of the 300 steps (test_ball_dynamics.py)
COVERED_THROUGH |= _pieces(
    BD + "integrator.verlet_step",
    {
        "predict": "the predictor: positions and predicted velocities",
        "race_approaches": "the approaches and normals of every contact",
        "ball_race_forces": "the ball-race contacts' forces, springs, chatter counts and powers",
        "cage_forces": "the cage balls' contacts",
        "correct_ring": "the ring's corrector, translation and tilts",
        "follow_path": "the prescribed ring on its cubic path (test_kernel_matches_twin_with_a_prescribed_ring)",
        "correct_balls": "the balls' and cage balls' corrector and the slip power at the step's end",
    },
)
COVERED_THROUGH |= _pieces(
    BD + "integrator.advance",
    {
        "load_driven_call": "its call with the ring under its loads (every state array after each step)",
        "prescribed_call": "its call with a prescribed ring (test_kernel_matches_twin_with_a_prescribed_ring)",
    },
)
COVERED_THROUGH |= _pieces(
    BD + "integrator.load_driven_call",
    {"run_call": "its body, also prescribed_call's (test_kernel_matches_twin_with_a_prescribed_ring)"},
)
COVERED_THROUGH |= _pieces(BD + "integrator.run_call", {"start_call": "the call's integrals and status cleared"})
# compared through advance's refreshes (trib compared), three film formulas and both tangential laws
COVERED_THROUGH |= _pieces(
    BD + "tribology.refresh_tribology",
    {
        "surface_speeds": "each contact's entrainment, sliding and spin speeds",
        "film_and_rolling": "each contact's films and Houpert rolling force",
        "tangential_law": "each contact's mu, film share and slip scale",
    },
)
# compared through its own twin, every output of random contacts (test_dem_contact_law.py: both races, open and
# closed, sticking and slipping, with and without film)
COVERED_THROUGH |= _pieces(
    BD + "contact_law.ball_race_contact",
    {
        "contact_slip": "the normal and tangential slip speeds",
        "film_traction": "the film's implicit traction",
        "resistance_moments": "the Houpert rolling and pivoting moments",
    },
)


def kernels():
    """{qualified name: dispatcher} of every kernel defined in KERNEL_MODULES."""
    found = {}
    for name in KERNEL_MODULES:
        module = importlib.import_module(name)
        for attr, obj in vars(module).items():
            if isinstance(obj, CPUDispatcher) and obj.py_func.__module__ == name:
                found[f"{name}.{attr}"] = obj
    return found


def twins():
    """{qualified kernel name: (twin module name, twin function name)} from the TWINS declarations."""
    declared = {}
    for info in pkgutil.iter_modules(tests.reference.__path__):
        module = importlib.import_module(f"tests.reference.{info.name}")
        if hasattr(module, "TWINS"):
            for kernel_name, twin in module.TWINS.items():
                assert twin.__module__ == module.__name__, f"{module.__name__}: twin of {kernel_name} is not its own"
                declared[f"{module.KERNEL_MODULE}.{kernel_name}"] = (module.__name__, twin.__name__)
    return declared


def _references(tree):
    """(aliases, per top-level name: the set of (module, attribute) it references and the local names it uses)."""
    aliases = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            for a in node.names:
                aliases[a.asname or a.name] = (node.module, a.name)
        elif isinstance(node, ast.Import):
            for a in node.names:
                aliases[a.asname or a.name] = (a.name, None)
    tops = {}
    for node in tree.body:
        names = []
        if isinstance(node, ast.FunctionDef):
            names = [node.name]
        elif isinstance(node, ast.Assign):
            names = [t.id for t in node.targets if isinstance(t, ast.Name)]
        for name in names:
            tops[name] = node
    refs = {}
    for name, node in tops.items():
        found, used = set(), set()
        for sub in ast.walk(node):
            if isinstance(sub, ast.Attribute) and isinstance(sub.value, ast.Name) and sub.value.id in aliases:
                module, attr = aliases[sub.value.id]
                found.add((f"{module}.{attr}" if attr else module, sub.attr))
            elif isinstance(sub, ast.Name):
                if sub.id in aliases and aliases[sub.id][1]:
                    found.add(aliases[sub.id])
                if sub.id in tops and sub.id != name:
                    used.add(sub.id)
        refs[name] = (found, used)
    return refs


def comparisons():
    """The set of (module, name) pairs called together by some test, for every test function in tests/."""
    pairs = set()
    for path in TESTS.rglob("test_*.py"):
        refs = _references(ast.parse(path.read_text()))
        for name in refs:
            if not name.startswith("test_"):
                continue
            seen, todo, reached = set(), [name], set()
            while todo:
                top = todo.pop()
                if top not in seen:
                    seen.add(top)
                    reached |= refs[top][0]
                    todo += refs[top][1]
            pairs.add(frozenset(reached))
    return pairs


def test_every_kernel_has_a_twin_and_a_comparison_test():
    all_kernels = kernels()
    declared = twins()
    reached_sets = comparisons()
    no_twin, no_test = [], []
    for name in all_kernels:
        if name in COVERED_THROUGH:
            continue
        if name not in declared:
            no_twin.append(name)
            continue
        module, attr = name.rsplit(".", 1)
        wanted = {(module, attr), declared[name]}
        if not any(wanted <= reached for reached in reached_sets):
            no_test.append(f"{name} (twin {'.'.join(declared[name])})")
    assert not no_twin, f"kernels without a twin (declare one in a TWINS table of tests/reference): {no_twin}"
    assert not no_test, f"kernels whose twin no test calls together with them: {no_test}"
    assert len(all_kernels) > 50  # the walk found the kernels (a wrong import path would find none)


def test_covered_helpers_are_called_by_their_twinned_caller():
    all_kernels = kernels()
    declared = twins()
    for helper, (caller, why) in COVERED_THROUGH.items():
        assert helper in all_kernels, f"{helper} is no longer a kernel: remove it from COVERED_THROUGH"
        assert why
        end = caller
        for _ in range(len(COVERED_THROUGH)):  # the chain of callers ends at a twinned kernel
            end = COVERED_THROUGH[end][0] if end in COVERED_THROUGH else end
        assert end in declared, f"{helper}: its chain of callers ends at {end}, which has no twin"
        py_func = all_kernels[caller].py_func
        built_around = any(cell.cell_contents is all_kernels[helper] for cell in py_func.__closure__ or ())
        assert built_around or helper.rsplit(".", 1)[1] in inspect.getsource(py_func), (
            f"{caller} does not call {helper}"
        )
        assert helper not in declared, f"{helper} has a twin: remove it from COVERED_THROUGH"
