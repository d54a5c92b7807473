"""DemModel: the DEM facade's state arrays, its stepping (kernel calls, the automatic step's retries, rollback to the
start of a call) and the FMU protocol (update, evaluate, get_state/set_state); the parts it draws on are its
sibling modules (the package's docstring lists them)."""

import math
from dataclasses import replace

import numpy as np

from bearing_fmu_common.variables import gather_plan, outputs_as_dict, select

from ...kernels import truncation as tk
from ...kernels.ball_dynamics import integrator as dyn
from ...kernels.ball_dynamics import state as s
from ...kernels.ball_dynamics.outputs import bearing_outputs
from ...kernels.ball_dynamics.stiffness import stiffness_matrix
from ...kernels.capacitance import CAP_BACKGROUND
from ...kernels.geometry import pass_frequencies
from ...params import check_roughness, load_bearing, load_lubricant
from ...scene import Scene
from ..declarations import DEM_INPUTS, DEM_OUTPUTS, DEM_PARAMETERS
from ..declarations import DEM_REFRESH_INTERVAL as REFRESH_INTERVAL
from ..dem_settings import settings_doc
from ..fidelity import Fidelity
from ..input_checks import check_clearance
from ..limits import P_MAX_ERROR, InputError, OilTemperatureWatch, pressure_warnings
from . import inputs, outputs, time_step, whirl
from .inputs import T_OIL_DEFAULT
from .monitor import DemUnstableError, energy_limit, unstable_error
from .packing import load_limit, pack_parameters
from .placement import place_bodies
from .time_step import AUTO_STEP_HALVINGS, SAFETY

NO_LOADS = (0.0, 0.0, 0.0, 0.0, 0.0)  # the loads of a prescribed ring (its reaction is an output)


class DemModel:
    """DEM bearing: Z balls + Z cage balls + translating inner ring.

    bearing, lubricant: catalogue name or TOML path (as the other fidelities). scene: Scene with fidelity
    'dem' (film formula, Hertz solution, roughness factor, capacitance on/off, floor, background and
    permittivity pressure). dt: fixed time step (s); None = safety x the
    stability limit of the stiffest contact pair at the loads of each advance() call. refresh: tribology
    refresh interval in steps (>= 1); None = every refresh_interval (s) of simulated time. The defaults
    SAFETY and REFRESH_INTERVAL are chosen from the step study (docs/reports/dem_steps.md, docs/dem.md). Pd: diametral
    clearance (m) overriding the file. ring_mass: inner-ring mass (kg); None = estimated from the bore.
    ring_inertia: its moment of inertia about a diameter through its centre (kg.m^2), for the tilts; None =
    estimated from the same annulus (the polar moment, for the ring's gyroscopic moment, is always the annulus's
    for the ring's mass).
    kt_ratio: tangential/normal stiffness (-) of the asperities' spring; None = params/dem_model.toml's.
    averaged: True (default) reports torque, P_loss, Q_inner_ring,
    Q_outer_ring and C_bearing as means over each advance() interval (what a co-simulation partner integrates:
    the energy of the step), False their values at the interval's last step (docs/dem.md, Outputs).
    averaged_state: False (default) reports the loads, pressure, films and the ring's displacement at the end of
    each interval; True as means over it (the displacement over its steps, the others over its tribology
    refreshes): for masters that sample slower than the ball pass (docs/dem.md, Outputs).
    The numeric settings of models.dem_settings.DEM_SETTINGS are keywords too (the FMU parameters of the same
    names): the traction_limit of the tangential law (docs/dem.md, Tangential force) and the inner ring's support
    (docs/dem.md, Ring support); each is listed below with its unit, range and default.
    film_tables: directory of the film tables an FMU carries (models.film_table); None = this machine's cache.
    drive: None (default: the scene's drive), 'load' (the loads F_x ... M_y move the inner ring on its support) or
    'displacement' (the inner ring's displacement x, y, z and tilts theta_x, theta_y are prescribed: each call gives
    their values and rates at its end and the ring follows the cubic from its state to them; the outputs add the
    reaction loads F_x ... M_y averaged over the call, and the ring has no support of its own, the support settings
    0; docs/dem.md, Prescribed ring). A drive given here replaces the scene's.
    """

    def __init__(
        self,
        bearing="6208",
        lubricant="guessasma_oil",
        scene=None,
        dt=None,
        refresh=None,
        Pd=None,
        ring_mass=None,
        kt_ratio=None,
        ring_inertia=None,
        safety=SAFETY,
        refresh_interval=REFRESH_INTERVAL,
        averaged=True,
        averaged_state=False,
        film_tables=None,
        drive=None,
        **settings,
    ):
        scene = (scene or Scene(name="dem", fidelity="dem")).validate()
        if scene.fidelity != "dem":
            raise InputError(f"scene '{scene.name}' has fidelity {scene.fidelity!r}: DemModel needs 'dem'")
        self.drive = inputs.checked_drive(scene.drive if drive is None else drive)
        self.scene = replace(scene, drive=self.drive)  # its variables follow the drive in effect
        self.bearing = b = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant)
        check_roughness(b.Ra_inner, b.Ra_outer, b.Ra_ball, b.path)  # the reader's check, for a Bearing made by hand
        self.Pd = b.Pd if Pd is None else float(Pd)
        check_clearance(self.Pd, b, Pd is not None)
        # the numeric settings of DEM_SETTINGS by name (checked, the defaults filled in)
        self.settings, kt_ratio = inputs.checked_settings(
            dt, refresh, safety, refresh_interval, settings, kt_ratio, ring_mass, ring_inertia, self.drive
        )
        self.averaged = bool(averaged)
        self.averaged_state = bool(averaged_state)
        self.safety = float(safety)
        self.refresh_interval = float(refresh_interval)
        self.ring_mass_estimated = ring_mass is None
        self.ring_inertia_estimated = ring_inertia is None
        self.cage_radius_estimated = b.cage_ball_radius <= 0.0
        self.dt_fixed = dt
        self.refresh_fixed = None if refresh is None else int(refresh)
        self.omega_max = inputs.speed_limit(b)
        self.par, self._truncation_parameters, self._rest = pack_parameters(
            b, self.scene, self.lubricant, self.Pd, self.settings, kt_ratio, ring_mass, ring_inertia, film_tables
        )
        self.displacement_driven = self.drive == "displacement"
        self.par[s.P_DRIVE] = float(self.displacement_driven)
        self._path_limits = inputs.path_limits(b)
        self._shift_limits = inputs.shift_limits(b)
        # the load that held the prescribed ring over the last call (F_x, F_y, F_z in N, M_x, M_y in N.m), averaged
        self.reaction = np.zeros(5)
        self._path_estimate = 0.0  # N, _path_load_bound of the current call
        self.load_limit = load_limit(self.par, b.Z)
        self._limits = inputs.input_limits(b, self.Pd, self.load_limit, self.omega_max)
        self._rho_outer = float(self.par[s.P_RHO_O])  # at the nominal clearance
        self._allocate(b.Z)
        self._place_bodies()
        self._hold_path()
        self._initialise(0.0, 0.0, 0.0, 0.0, T_OIL_DEFAULT)
        self.orbit_window = whirl.new_window(self.ring)  # the ring-orbit watch's window (models.dem.whirl)
        self.orbit_verdict = None  # whirl.Verdict of the window the last advance() closed, None if it closed none
        self._plan_variables()
        # state at the start of the last kernel call: an automatic-step call is repeated from it, and update()
        # restores it when the call fails
        self._start = self.get_state()
        self.step_halvings = 0  # times the last call's automatic step was halved after a monitor stop
        self._gather()

    # -- set-up --------------------------------------------------------------------------------
    def _allocate(self, Z):
        """The state, output, status and work arrays of Z balls and cage balls (kernels.ball_dynamics.state)."""
        self.balls = np.zeros((s.B_SIZE, Z))
        self.cage = np.zeros((s.C_SIZE, Z))
        self.ring = np.zeros(s.R_SIZE)
        self.spring = np.zeros((s.S_SIZE, Z))
        self.trib = np.zeros((s.T_SIZE, 2, Z))
        self.counters = np.zeros(s.K_SIZE + 2 * Z, dtype=np.int64)
        self.omega = 0.0
        self.out = np.zeros(s.O_SIZE)
        self.status = np.zeros(s.ST_SIZE, dtype=np.int64)
        self._work = np.zeros((s.W_SIZE, Z))
        self._acc = np.zeros(s.A_SIZE)
        self._Q = np.zeros((2, Z))
        self._alpha = np.zeros((2, Z))
        self._signed_alpha = np.zeros((2, Z))
        self.trunc = np.zeros(tk.TR_SIZE)  # shoulder truncation of the last advance() (kernels.truncation TR_*)
        self.truncated = np.zeros(2)  # per race the truncated fraction at its last warning (0: not truncated)
        self.dt = math.nan  # time step of the last advance() call (s)
        self.refresh = 0  # its tribology refresh interval (steps)

    def _plan_variables(self):
        """The FMU interface (update): the scene's variables in declaration order, filled by one copy plan."""
        self.inputs = select(DEM_INPUTS, self.scene)
        self.outputs = select(DEM_OUTPUTS, self.scene)
        self.output_names = tuple(v.name for v in self.outputs)
        self.values = np.zeros(len(self.outputs))
        self.warnings = []  # of the last advance(): p_max above the ISO 76 limit (pressure_warnings)
        self._oil_watch = OilTemperatureWatch(self.lubricant)
        self.K = np.zeros((5, 5))  # condensed stiffness of the last update (scene option stiffness)
        self.frequencies = np.zeros(4)  # FTF, BPFO, BPFI, BSF (Hz) of the last update
        arrays = {
            "out": self.out,
            "ring": self.ring,
            "status": self.status,
            "K": self.K.reshape(-1),
            "freq": self.frequencies,
            "trunc": self.trunc,
            "reaction": self.reaction,
        }
        self._plan = gather_plan(self.outputs, arrays)

    def _groups(self):
        """The arrays of the integrator's kernels in their groups (kernels.ball_dynamics.state, "argument groups"):
        state, params and space."""
        return (
            (self.balls, self.cage, self.ring, self.spring, self.trib, self.counters),
            (self.par, self.lubricant.array),
            (self._work, self._acc, self.status),
        )

    def _place_bodies(self):
        place_bodies(self.balls, self.cage, self.ring, self.spring, self.trib, self.counters, self.par, self._rest)
        self.omega = 0.0

    def _hold_path(self):
        """A prescribed ring's path that holds it where it is (its rates 0) until the first call gives one."""
        if self.displacement_driven:
            current = self._ring_motion()
            self._set_path(1.0, (*current[:5], 0.0, 0.0, 0.0, 0.0, 0.0))

    def _ring_motion(self):
        """The ring's x, y, z (m), theta_x, theta_y (rad) and their rates (m/s, rad/s) in the state."""
        r = self.ring
        return np.concatenate(
            (r[s.R_X : s.R_X + 3], r[s.R_TH : s.R_TH + 2], r[s.R_VX : s.R_VX + 3], r[s.R_VTH : s.R_VTH + 2])
        )

    def _path_load_bound(self, end):
        """Bound (N) of the load the balls put on a ring at the path's end `end` (x ... theta_y first): every ball
        pressed by the whole displacement |(x, y, z)| + |(theta_x, theta_y)| rho_i through its two contacts in
        series (Q = K delta^1.5 each, K^(-2/3) adding), plus the contact loads now. The automatic step and the
        energy bound take it as the load of a call: the drive does work on the bearing the loads do not show."""
        p = self.par
        delta = math.hypot(*end[:3]) + math.hypot(*end[3:5]) * p[s.P_RHO_I]
        K = (p[s.P_KH_I] ** (-2.0 / 3.0) + p[s.P_KH_O] ** (-2.0 / 3.0)) ** -1.5
        return self.bearing.Z * K * delta**1.5 + float(self._Q.sum())

    def _set_path(self, duration, end):
        """The prescribed ring's path of a call of `duration` (s): from its state now to `end` (x ... theta_y, then
        their rates; SI), in the kernel's layout (state.P_PATH)."""
        start = self._ring_motion()
        p = s.P_PATH
        self.par[s.P_PATH_T] = duration
        self.par[p : p + 5] = start[:5]
        self.par[p + 5 : p + 10] = start[5:]
        self.par[p + 10 : p + 20] = end

    def _initialise(self, omega, F_x, F_y, F_z, T_oil, M_x=0.0, M_y=0.0):
        state, params, space = self._groups()
        dyn.initialise_accelerations(state, params, omega, (F_x, F_y, F_z, M_x, M_y), T_oil, space)

    # -- time step -----------------------------------------------------------------------------
    def stable_time_step(self, F_x=0.0, F_y=0.0, F_z=0.0, omega=None, include_state=True, M_x=0.0, M_y=0.0):
        """Stability limit (s) of the stiffest contact pair for the given loads (N, N.m) and speed (rad/s): contact
        loads are an estimate (Stribeck's 5 F_r/Z for the radial load, F_a/(Z sin alpha) for the axial one with alpha >=
        5 deg, 2 M/(Z rho_i sin alpha) for a moment, plus the centrifugal force), or the current ones where larger
        (include_state); the cage-ball load is bounded by the friction force mu Q a ball can transmit (the cage contacts
        are frictionless: only the races' traction pushes a ball against a cage ball), mu the largest mu(Lambda) of the
        loaded contacts at the last tribology refresh (0.1 in the boundary regime, 0.01 in a full film). The normal
        damping C_n of each contact is also that of the last refresh (a cold full film at low speed is overdamped). A
        film that changes within the call is caught by the monitor (the automatic step is then halved)."""
        omega = self.omega if omega is None else omega
        return time_step.stable_time_step(
            self.bearing, self.par, self.balls, self.ring, self.trib, self._Q, F_x, F_y, F_z, omega, include_state,
            M_x, M_y,
        )  # fmt: skip

    def automatic_time_step(self, F_x=0.0, F_y=0.0, F_z=0.0, omega=None, M_x=0.0, M_y=0.0):
        """The automatic step (s) for the given loads (N, N.m) and speed (rad/s; the faster end of a call: the limit
        falls with the centrifugal load): safety x stable_time_step(), and at most DAMPING_PLAN m / c of the ball
        with the largest normal damping c (N.s/m, loaded contacts at the last refresh) or of the ring on its support;
        with a support spring, at most safety x its stability limit 2 / omega_n."""
        stable = self.stable_time_step(F_x, F_y, F_z, omega, M_x=M_x, M_y=M_y)
        return time_step.automatic_time_step(stable, self.safety, self.par, self.trib)

    @property
    def time(self):
        """Simulated time (s)."""
        return float(self.ring[s.R_TIME])

    # -- stepping ------------------------------------------------------------------------------
    def advance(
        self,
        t_end,
        omega=None,
        F_x=0.0,
        F_y=0.0,
        F_z=0.0,
        T_oil=T_OIL_DEFAULT,
        dPd_thermal=0.0,
        M_x=0.0,
        M_y=0.0,
        dz_thermal=0.0,
        **path,
    ):
        """Integrate to t_end (s): inner-ring speed from its current value linearly to omega (rad/s; None =
        hold), loads F_x, F_y, F_z (N) and moments M_x, M_y (N.m, about the ring's centre, that of its
        groove-curvature-centre circle: the quasi-static fidelity's) on the inner ring, oil temperature T_oil (K),
        change of diametral clearance dPd_thermal (m, added to Pd, negative = tighter: the outer groove circle
        moves by half of it; the Hertz constants stay those of the nominal geometry, as in the quasi-static
        fidelity). Returns outputs_dict().

        With drive = 'displacement' the loads stay 0 and `path` gives the inner ring's x, y, z (m), theta_x,
        theta_y (rad) at t_end and their rates x_rate ... theta_y_rate (m/s, rad/s; each absent = 0): the ring
        follows the cubic Hermite curve from its state to them, and the outputs add the load that holds it there,
        F_x, F_y, F_z (N), M_x, M_y (N.m about its centre), averaged over the call. dz_thermal (m) is added to
        z at t_end (not to z_rate: a constant offset, such as a preload position or a thermal growth).

        Raises InputError for inputs out of range, DemUnstableError when the monitor stops the run (the
        state is then left at the offending step: restore a saved state to retry)."""
        omega = self.omega if omega is None else float(omega)
        loads = (float(F_x), float(F_y), float(F_z), float(M_x), float(M_y))
        t_end = float(t_end)
        dz_thermal = float(dz_thermal)
        if (path or dz_thermal) and not self.displacement_driven:  # (refused: inputs of a prescribed ring)
            inputs.path_values(self._path_limits, path, False)
            inputs.shifted((), dz_thermal, self._shift_limits, False)
        if self.displacement_driven:  # (only then: the path's checks are 3 % of a load-driven call)
            end = inputs.path_values(self._path_limits, path, True)
            end = inputs.shifted(end, dz_thermal, self._shift_limits, True)
            inputs.check_no_loads(loads)
            self._prepare_path(t_end, omega, end, float(T_oil), float(dPd_thermal))
        self._advance(t_end, omega, loads, float(T_oil), float(dPd_thermal))
        return self.outputs_dict()

    def _prepare_path(self, t_end, omega, end, T_oil, dPd_thermal):
        """A prescribed ring's call to t_end (s) with the path's end values `end` (x ... theta_y, then their rates; SI,
        checked): the call's other inputs checked (nothing changes on a refusal), then its path set."""
        inputs.check_inputs(self._limits, self.time, t_end, omega, NO_LOADS, T_oil, dPd_thermal)
        self._set_path(t_end - self.time, end)
        self._path_estimate = self._path_load_bound(end)

    def _advance(self, t_end, omega, loads, T_oil, dPd_thermal):
        """advance() without building the output dict (floats in SI units, omega given; loads = (F_x, F_y, F_z,
        M_x, M_y))."""
        inputs.check_inputs(self._limits, self.time, t_end, omega, loads, T_oil, dPd_thermal)
        # the automatic step and the energy bound take the loads the contacts carry: a prescribed ring's are those
        # that held it in the last call
        estimate = loads
        if self.displacement_driven:  # the larger of the last call's reaction and the bound of the path's end
            bound = self._path_estimate
            estimate = (max(math.hypot(*self.reaction[:3]), bound), 0.0, 0.0, 0.0, 0.0)
        F_x, F_y, F_z, M_x, M_y = estimate
        self.par[s.P_RHO_O] = self._rho_outer + 0.5 * dPd_thermal
        interval = t_end - self.time
        self._copy_state(self._start, self.__dict__)
        self._start["omega"] = self.omega
        dt = self.dt_fixed
        automatic = dt is None
        if automatic:
            dt = self.automatic_time_step(F_x, F_y, F_z, max(abs(self.omega), abs(omega)), M_x, M_y)
        n_steps = time_step.step_count(interval, dt)
        self.step_halvings = 0
        while True:
            dt = interval / n_steps  # land exactly on t_end
            omega0, orbit0 = self._run(n_steps, dt, omega, loads, T_oil, estimate)
            if self.status[s.ST_CODE] == s.STATUS_OK:
                break
            if not automatic or self.step_halvings == AUTO_STEP_HALVINGS:
                self._raise_unstable(dt, estimate, T_oil, max(abs(self._start["omega"]), abs(omega)))
            # the step was chosen from the state at the start of the call; the film can change within it (a
            # contact entering full film at low speed takes a squeeze damping that overdamps the ball): repeat
            # the call from its start with half the step, or the step the stopped state's film needs if smaller
            smaller = self.automatic_time_step(F_x, F_y, F_z, max(abs(omega0), abs(omega)), M_x, M_y)
            self._restore_start()
            self.step_halvings += 1
            n_steps = time_step.retry_step_count(interval, n_steps, smaller)
        bearing_outputs(
            self.balls,
            self.cage,
            self.ring,
            self.trib,
            self.par,
            self._acc,
            self.omega,
            interval,
            orbit0,
            self.par[s.P_CAPACITANCE_BLOCK + CAP_BACKGROUND],
            self.averaged,
            self._Q,
            self._alpha,
            self.out,
        )
        outputs.state_outputs(self.out, self._acc, self.ring, interval, self.averaged_state)
        # as the other fidelities: a warning above the ISO 76 limit; beyond the material limit (6 GPa) the
        # monitor has already stopped the step (penetration), so only the warning can apply here
        self.warnings = pressure_warnings(min(self.out[s.O_PMAX], P_MAX_ERROR), "the loads")
        self.warnings += self._oil_watch.warnings(T_oil)
        # the contact ellipses against the shoulders: an output of the interval's end state, not of every step
        self.warnings += outputs.truncation_outputs(
            self.balls, self.ring, self.par, self._truncation_parameters, self._Q, self._signed_alpha, self.trunc,
            self.truncated,
        )  # fmt: skip
        if self.displacement_driven:
            # (the orbit watch judges a ring the contacts move: a prescribed ring's orbit is its caller's)
            self.reaction[:] = self._acc[s.A_REACTION : s.A_REACTION + 5] / interval
        else:
            self.warnings += self._watch_orbit(interval)

    def _watch_orbit(self, interval):
        """The ring-orbit watch (models.dem.whirl) after a call of `interval` (s): closes its window when it is full;
        while the last closed window is a whirl, self.status holds STATUS_WHIRL. Returns the warning of a whirl's
        onset (once per entry), else []."""
        window = self.orbit_window
        whirl.add_call(window, self._acc, interval)
        self.orbit_verdict = None
        warning = []
        if window[whirl.WS_T] >= whirl.WINDOW * (1.0 - 1e-9):
            was_whirling = window[whirl.WS_WHIRL] > 0.0
            o = self.out
            delta = max(
                (self._Q[0].max() / self.par[s.P_KH_I]) ** (2.0 / 3.0),
                (self._Q[1].max() / self.par[s.P_KH_O]) ** (2.0 / 3.0),
            )
            lines = whirl.kinematic_lines(self.omega, o[s.O_OMEGA_CAGE], o[s.O_OMEGA_BALL_REL], self.bearing.Z)
            verdict = whirl.judge(window, self.ring, self.par[s.P_RHO_I], delta, lines)
            self.orbit_verdict = verdict
            if verdict.kind is not None and not was_whirling:
                warning = [self._whirl_warning(verdict)]
        if window[whirl.WS_WHIRL] > 0.0:
            self.status[s.ST_CODE] = s.STATUS_WHIRL
        return warning

    def _whirl_warning(self, v):
        support = self.settings
        return (
            f"the inner ring whirls ({v.kind} orbit at t = {self.time:.6g} s): {v.r * 1e6:.3g} um rms orbit and "
            f"{v.t * 1e3:.3g} mrad rms tilt at {v.f:.4g} Hz, not a shaft, cage, ball or ball-pass frequency; "
            f"{v.e / v.delta:.2g} x the contact deflection {v.delta * 1e6:.3g} um. A self-excited motion of the ring "
            f"driven by the contacts' traction on its support (support_damping = {support['support_damping']:g} N.s/m, "
            f"support_stiffness = {support['support_stiffness']:g} N/m, support_mass = {support['support_mass']:g} "
            "kg): the torque, loads and "
            "films describe the whirling ring. A shaft at the seat damps it: raise support_damping or give the "
            "shaft's modal stiffness and mass (thresholds in docs/dem.md, Ring support)"
        )

    def _run(self, n_steps, dt, omega, loads, T_oil, estimate):
        """One kernel call of n_steps steps of dt (s) to the inner-ring speed omega under `loads`, its energy bound
        from the loads the contacts carry, `estimate`; returns the speed and the sum of the orbital angles at its
        start. self.status holds the monitor's verdict."""
        refresh = time_step.refresh_steps(self.refresh_fixed, self.refresh_interval, dt)
        self.par[s.P_REFRESH] = refresh
        self.dt, self.refresh = dt, refresh
        omega0 = self.omega
        orbit0 = float(self.balls[s.B_ORBIT].sum())
        limit = energy_limit(
            self.bearing, self.par, self.balls, self.cage, self.ring, self._Q, max(abs(omega0), abs(omega)), estimate
        )
        state, params, space = self._groups()
        dyn.advance(state, params, (n_steps, dt, omega0, omega, loads, T_oil, limit), space)
        done = int(self.status[s.ST_STEP])
        self.omega = omega0 + (omega - omega0) * done / n_steps
        return omega0, orbit0

    def _raise_unstable(self, dt, loads, T_oil, omega_max):
        """Raise the DemUnstableError of the monitor's stop (self.status) in a call of step dt (s) at these loads
        (F_x, F_y, F_z, M_x, M_y), oil temperature T_oil (K) and largest speed omega_max (rad/s) of the call."""
        F_x, F_y, F_z, M_x, M_y = loads

        def limit(include_state):
            return self.stable_time_step(F_x, F_y, F_z, self.omega, include_state=include_state, M_x=M_x, M_y=M_y)

        # the films of the rest of the run are not known yet: a step that holds whatever film the contacts reach
        Q = time_step.estimated_load(self.bearing, self.par, F_x, F_y, F_z, omega_max, M_x, M_y)
        film_step = time_step.film_damping_step(self.par, self.lubricant.array, T_oil, Q)
        raise unstable_error(
            self.status, self.time, dt, self.bearing.Z, self.trib, self.par[s.P_M_BALL], self.dt_fixed is not None,
            self.safety, limit, film_step,
        )  # fmt: skip

    # -- outputs -------------------------------------------------------------------------------
    def outputs_dict(self):
        """Bearing-level outputs of the last advance() (names as the quasi-static fidelity), SI units; with drive =
        'displacement' also the reaction loads F_x, F_y, F_z (N), M_x, M_y (N.m), means over the call."""
        result = outputs.outputs_dict(self.out, self.scene.capacitance)
        if self.displacement_driven:
            result.update(zip(("F_x", "F_y", "F_z", "M_x", "M_y"), self.reaction.tolist()))
        return result

    def contacts(self):
        """Per-ball arrays (Z,): azimuth psi (rad, in [0, 2 pi)), orbital and spin speeds (rad/s), and per race
        ('_inner', '_outer') the current load Q (N) and approach delta (m), and the last refresh's film
        h_min, h_c (m), Lambda, regime, mu, normal damping C_n (N.s/m), SRR, entrainment speed u (m/s),
        capacitance C (F) and Hertz semi-axes a, b (m); the current contact angle alpha (rad)."""
        return outputs.contact_arrays(self.balls, self.ring, self.trib, self.par, self._Q, self._alpha)

    def record(self, t_end, interval, omega=None, **held):
        """Advance to t_end (s) in steps of `interval` (s), recording after each: returns a dict of numpy arrays,
        't' (n,) and every bearing output (n,), and under 'contacts' a dict of every per-ball/per-contact
        array of contacts() (n, Z).
        The speed goes linearly from its current value to omega (rad/s; None = hold) over the whole record;
        the other inputs, given by name (F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal), are held."""
        if not (math.isfinite(interval) and interval > 0.0):
            raise InputError(f"interval = {interval} s is outside the allowed range ]0, inf[ s")
        t0, omega0 = self.time, self.omega
        omega = omega0 if omega is None else float(omega)
        n = max(1, math.ceil((float(t_end) - t0) / interval - 1e-9))
        rows = []
        for k in range(1, n + 1):
            t = min(t0 + k * interval, float(t_end))
            out = self.advance(t, omega=omega0 + (omega - omega0) * (t - t0) / (float(t_end) - t0), **held)
            rows.append((t, out, self.contacts()))
        result = {"t": np.array([r[0] for r in rows])}
        for name in rows[0][1]:
            result[name] = np.array([r[1][name] for r in rows])
        result["contacts"] = {name: np.array([r[2][name] for r in rows]) for name in rows[0][2]}
        return result

    def stiffness_matrix(self, K=None):
        """5x5 stiffness dF_i/dd_j of the inner ring in the current state, (F) = (F_x, F_y, F_z, M_x, M_y) in N and
        N.m, (d) = (x, y, z, theta_x, theta_y) in m and rad, the quasi-static fidelity's convention: each ball's
        inner and outer contact tangent stiffnesses condensed in series (kernels.ball_dynamics.stiffness,
        docs/dem.md, Stiffness). Written into K (float64[5, 5]) if given; returned."""
        K = np.zeros((5, 5)) if K is None else K
        stiffness_matrix(self.balls, self.ring, self.par, K)
        return K

    # -- FMU interface ---------------------------------------------------------------------------
    def update(self, u, interval=0.0):
        """Advance by `interval` (s; 0 = only report the current state) with the input values u in self.inputs
        order (omega, F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal; with drive = 'displacement' omega, x ... theta_y,
        x_rate ... theta_y_rate, T_oil, dPd_thermal; SI) as advance() takes them, and fill self.values (self.outputs
        order: the declarations of models.declarations.DEM_OUTPUTS); returns self.values.

        Raises InputError for inputs out of range (nothing changed; also with interval 0) and DemUnstableError when
        the monitor stops the step: the state is then restored to the start of the step and self.status keeps the
        monitor's code."""
        if interval != 0.0:
            self._step_to(self.time + inputs.communication_interval(interval), u)
        else:
            # checked without a step too, as the other fidelities' update: the FMU then names an input its
            # first step would refuse when it leaves initialisation
            if self.displacement_driven:
                omega, end, T_oil, dPd_thermal = self._prescribed_inputs(u)
                self._limits.check((omega, *NO_LOADS, T_oil, dPd_thermal))
            else:
                self._limits.check(tuple(float(v) for v in u))
        self._gather()
        return self.values

    def _step_to(self, t_end, u):
        """update()'s step to t_end (s): advance, or on a monitor stop restore the state and raise."""
        self.status[s.ST_CODE] = s.STATUS_OK  # a refused input leaves no stale monitor code
        self.warnings = []  # nor stale warnings
        if self.displacement_driven:
            omega, end, T_oil, dPd_thermal = self._prescribed_inputs(u)
            loads = NO_LOADS
            self._prepare_path(t_end, omega, end, T_oil, dPd_thermal)
        else:
            omega, F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal = (float(v) for v in u)
            loads = (F_x, F_y, F_z, M_x, M_y)
            inputs.check_inputs(self._limits, self.time, t_end, omega, loads, T_oil, dPd_thermal)
        try:
            self._advance(t_end, omega, loads, T_oil, dPd_thermal)
        except DemUnstableError:
            self._restore_start()
            raise

    def _prescribed_inputs(self, u):
        """A prescribed ring's update() inputs u (omega, x ... theta_y, x_rate ... theta_y_rate, T_oil, dPd_thermal,
        dz_thermal; SI) as omega, the path's end (checked, dz_thermal added to z), T_oil and dPd_thermal."""
        values = tuple(float(v) for v in u)
        end = values[1 : 1 + len(inputs.PATH_NAMES)]
        self._path_limits.check(end)
        end = inputs.shifted(end, values[-1], self._shift_limits, True)
        return values[0], end, values[-3], values[-2]

    def _gather(self):
        if self.scene.stiffness:
            self.stiffness_matrix(self.K)
        o = self.out
        self.frequencies[:] = pass_frequencies(self.omega, o[s.O_OMEGA_CAGE], o[s.O_OMEGA_BALL_REL], self.bearing.Z)
        for src, idx, dst in self._plan:
            self.values[dst] = src[idx]

    def evaluate(self, time, **values):
        """Advance to `time` (s) with the named inputs (missing ones take their start values: 0, T_oil 313.15 K) as
        update() does (update(u, H) is evaluate(self.time + H, ...)); the outputs as a dict name -> SI value
        (integers for integer outputs)."""
        self._step_to(float(time), [values.get(v.name, v.start) for v in self.inputs])
        self._gather()
        return self.as_dict()

    def as_dict(self):
        """The outputs of the last update() as a dict name -> SI value (integers for integer outputs)."""
        return outputs_as_dict(self.outputs, self.values)

    # -- state (FMU get/set state, rollback) ---------------------------------------------------
    STATE_ARRAYS = ("balls", "cage", "ring", "spring", "trib", "counters", "truncated", "orbit_window")

    def get_state(self):
        """Copy of the whole dynamic state (every array and the current inner-ring speed)."""
        state = {name: getattr(self, name).copy() for name in self.STATE_ARRAYS}
        state["omega"] = self.omega
        return state

    def set_state(self, state):
        """Restore a state from get_state() (arrays are copied in place)."""
        for name in self.STATE_ARRAYS:
            getattr(self, name)[...] = state[name]
        self.omega = float(state["omega"])

    def _copy_state(self, target, source):
        for name in self.STATE_ARRAYS:
            np.copyto(target[name], source[name])

    def _restore_start(self):
        """Back to the state at the start of the last kernel call (_advance)."""
        self._copy_state(self.__dict__, self._start)
        self.omega = self._start["omega"]


DemModel.__doc__ = f"{DemModel.__doc__.rstrip()}\n\n{settings_doc()}"

REFERENCE_STEP = 0.5e-3  # s, communication step of the DEM reference experiment


def reference_inputs(scene=None):
    """The DEM reference experiment, one dict per communication point (time = end of the step, s): the 6208
    at 40 C, speed ramp 0 -> 500 rad/s over 5 ms, steady to 6 ms, held to 8 ms (a step of 0.5 ms); load-driven at
    3 kN radial, then a load step to 4 kN; with drive = 'displacement' the inner ring moved along x to 15 um in the
    first step and held there, then moved to 20 um in the step after 6 ms (each end at rest). Each row's inputs hold
    over the step that ends at its time."""
    displacement = scene is not None and scene.drive == "displacement"
    rows = []
    for n in range(1, 17):
        t = n * REFERENCE_STEP
        row = {"time": t, "omega": 500.0 * min(t / 5e-3, 1.0)}
        if displacement:
            row["x"] = 15e-6 if t <= 6e-3 else 20e-6
        else:
            row["F_x"] = 3000.0 if t <= 6e-3 else 4000.0
        rows.append({**row, "T_oil": 313.15})
    return rows


DRIVE_WORDS = {"load": "loads in, displacements out", "displacement": "the inner ring's path in, reaction loads out"}


FIDELITY = Fidelity(
    name="dem",
    model=DemModel,
    parameters=DEM_PARAMETERS,
    choices=("bearing", "lubricant"),
    reference_step=REFERENCE_STEP,
    reference_inputs=reference_inputs,
    summary=lambda scene: f"DEM (ball dynamics) bearing, {DRIVE_WORDS[scene.drive]}",
)
