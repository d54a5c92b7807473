"""What the integrator's monitor stops on and what the facade says then: the thresholds packed for the kernel, the
bound of the kinetic energy of a call, and the DemUnstableError that names the cause and a step that would work."""

import math

from ...kernels.ball_dynamics import state as s
from ...kernels.ball_dynamics.monitor import kinetic_energy
from ...kernels.ball_dynamics.outputs import contact_loads
from ...kernels.geometry import rolling_kinematics
from ..limits import InputError

# consecutive slipping reversals of one spring that count as chatter: sustained chatter (6208 at 3 kN,
# 500 rad/s, dt >= 7 us) reverses for hundreds of steps and multiplies the torque; a lightly loaded ball
# entering the load zone during a start-up reverses for up to ~15 steps without changing the results
# (cage speed and torque equal within 0.05 % at half the step)
CHATTER_STEPS = 50
# the normal damping of a ball (its loaded contacts' C_n) times the step over its mass: the automatic step keeps
# it at or below DAMPING_PLAN, the monitor stops above DAMPING_STOP (a film that thickened into full film
# within the call); measured on the B7214C entering full film at 10 rad/s: correct up to 0.43, a spurious
# dissipation from 0.48 (docs/dem.md)
DAMPING_PLAN = 0.25
DAMPING_STOP = 0.35
# what the advised step also keeps, whatever film the contacts reach
FILM_WORDS = f"(c_i + c_o) dt / m <= {DAMPING_PLAN} up to the squeeze damping of the thinnest full film"
ENERGY_FACTOR = 10.0  # kinetic-energy bound: this factor x (pure-rolling energy + load x groove clearance)

STATUS_WORDS = {
    s.STATUS_NOT_FINITE: "a force became NaN or infinite",
    s.STATUS_PENETRATION: "a ball-race penetration passed the physical limit (Hertz pressure above the material limit)",
    s.STATUS_ENERGY: "the kinetic energy grew beyond the bound of the inputs (energy growth without input)",
    s.STATUS_CHATTER: "a tangential spring chattered against its Coulomb limit (slip direction reversing every step)",
    s.STATUS_DAMPING: "a ball's normal damping is beyond what the step integrates ((c_i + c_o) dt / m above "
    f"{DAMPING_STOP}; e.g. a contact that entered full film at low speed, whose squeeze damping overdamps the ball)",
}


class DemUnstableError(InputError):
    """The monitor stopped the integration; the message names the cause and a time step that would work."""


def energy_limit(bearing, par, balls, cage, ring, Q, omega, loads):
    """Bound (J) of the kinetic energy over a call: ENERGY_FACTOR x (pure-rolling kinetic energy at omega + load x
    groove clearance A (a moment M counts as the force M / rho_i, rho_i the radius of the inner groove's
    curvature-centre circle: it tilts the ring by about A / rho_i) + the mechanical energy the state already holds:
    its kinetic energy and the elastic energy of its ball-race contacts, 0.4 Q delta each for Q = K_h delta^1.5).
    Without input the kinetic energy cannot exceed the energy held plus the work of the drive and the loads, so an
    unstable integration passes the bound within a few steps and a physical run never does, also when a load is
    released (its elastic energy turns into motion) or the ring stops while the balls still roll.
    Q (2, Z) takes the contact loads (N)."""
    b, p = bearing, par
    cage_speed, ball_rel, _, _ = rolling_kinematics(omega, b.D, b.dm, p[s.P_ALPHA0])
    v = 0.5 * b.dm * cage_speed
    rolling = b.Z * (0.5 * (p[s.P_M_BALL] + p[s.P_M_CAGE]) * v * v + 0.5 * p[s.P_I_BALL] * ball_rel**2)
    A = (b.f_i + b.f_o - 1.0) * b.D
    F_x, F_y, F_z, M_x, M_y = loads
    force = math.sqrt(F_x**2 + F_y**2 + F_z**2) + math.hypot(M_x, M_y) / p[s.P_RHO_I]
    held = kinetic_energy(balls, cage, ring, p) + elastic_energy(balls, ring, p, Q)
    return ENERGY_FACTOR * (rolling + force * A + held) + 1e-6


def elastic_energy(balls, ring, par, Q):
    """Elastic energy (J) of the current ball-race contacts: sum of the integral of K_h delta^1.5 d delta,
    0.4 Q delta with delta = (Q / K_h)^(2/3); Q (2, Z) takes the contact loads (N)."""
    contact_loads(balls, ring, par, Q)
    K_h = par[[s.P_KH_I, s.P_KH_O]][:, None]
    return float(0.4 * (Q * (Q / K_h) ** (2.0 / 3.0)).sum())


def unstable_error(status, time, dt, Z, trib, m_ball, fixed_step, safety, stable_time_step, film_step):
    """The DemUnstableError of a monitor stop: status the monitor's (code, step, index), time (s) where it stopped,
    dt (s) the step it stopped at, Z balls of mass m_ball (kg), trib the stopped state's tribology, fixed_step whether
    the step was the user's, safety the automatic step's factor; stable_time_step(include_state) the stability limit
    (s) at the call's inputs, with (True) or without the stopped state's contact loads; film_step (s) a step whose
    damping check holds whatever film the contacts reach at the call's inputs (time_step.film_damping_step). The
    step advised is the smallest of them: one that holds only for the films of the stopped state is stopped again
    as the film thickens (the B7214C at 10 000 rpm and 2 kN, 0.1 ms later)."""
    code, step, index = (int(v) for v in status)
    where = ""
    # a fixed step that works at these inputs can be stopped again when the film or the loads change (a
    # start-up: the film thickens, the cage's load grows): the automatic step follows them
    alternative = (
        "; or use dt = 0 (automatic: the step follows the loads and the film as they change)" if fixed_step else ""
    )
    if code == s.STATUS_DAMPING:
        # the stopped state's film; a ball's other contact may still follow into full film: 2 x the largest
        c_max = float(trib[s.T_C_N][trib[s.T_Q] > 0.0].max())
        return DemUnstableError(
            f"DEM stopped at t = {time:.9g} s (step {step} of the interval) on ball {index}: "
            f"{STATUS_WORDS[code]}. dt = {dt:.3g} s is too large here; use dt <= "
            f"{min(DAMPING_PLAN * m_ball / (2.0 * c_max), film_step):.3g} s (largest contact damping "
            f"{c_max:.4g} N.s/m, {FILM_WORDS}){alternative}"
        )
    if index >= 0:
        race = "inner" if index < Z else "outer"
        where = f" at the {race} contact of ball {index % Z}"
    # the state at the stop is already disturbed: judge from the inputs alone, or, when they load no
    # contact (no load, no speed), from the contact loads of the stopped state (larger: a safe side)
    limit = stable_time_step(False)
    basis = "at these inputs"
    if not math.isfinite(limit):
        limit = stable_time_step(True)
        basis = "at the contact loads where the run stopped"
    if math.isfinite(limit):
        suggestion = min(0.5 * dt, safety * limit, film_step)
        reason = f"stability limit of the stiffest contact pair {basis} {limit:.3g} s, {FILM_WORDS}"
    else:
        suggestion = min(0.5 * dt, film_step)
        reason = f"no contact is loaded, so no contact sets a stability limit; {FILM_WORDS}"
    return DemUnstableError(
        f"DEM stopped at t = {time:.9g} s (step {step} of the interval){where}: "
        f"{STATUS_WORDS[code]}. dt = {dt:.3g} s is too large here; use dt <= {suggestion:.3g} s ({reason})"
        f"{alternative}"
    )
