"""ShaftTransient: the time-domain mode of the reduced shaft model (docs/shaft.md, "Time-domain mode").

The reduced model of a ShaftModel (Craig-Bampton: the seat and tool-tip nodes keep their physical dof) is integrated
in time under the bearings' forces at its seats, so that bearings computing their forces from the inner ring's motion
(a displacement-driven bearing, a DEM with the ring's motion prescribed) can be coupled to it:

    M q'' + (C + Omega G) q' + K q = f(t),

K and M the shaft's alone (the bearings supply their forces through the inputs; a linear seat stiffness and damping
may be added for tests and for a damping the bearings do not model), f linear over each communication step. The
scheme is Newmark's (Newmark 1959, ASCE J. Eng. Mech. Div. 85, 67-94; Geradin & Rixen, Mechanical Vibrations,
ch. 7) with beta = (gamma + 1/2)^2 / 4, unconditionally stable for a linear system for every gamma >= 1/2:
gamma = 1/2 is the average acceleration (the trapezoidal rule: no numerical damping, energy conserved to rounding
without damping and with the gyroscopic term alone); gamma > 1/2 damps the modes the step does not resolve, their
amplitude multiplied per step by at most (3/2 - gamma) / (gamma + 1/2) as omega h grows (Hughes, The Finite Element
Method, 1987, section 9.1), at the price of a numerical damping ratio of about (gamma - 1/2) omega h / 2 on the
resolved ones. That is what a bearing whose reaction carries its contacts' vibration (a DEM's mean over the step)
needs: the average acceleration leaves the unresolved seat modes undamped, the velocity they take goes back to the
bearing's contact damping, and the loop grows (docs/shaft.md, "Coupled with displacement-driven bearings"). numpy
only.

Signs and frames. A seat's forces arrive as the bearing outputs them, in the bearing's own frame (docs/
conventions.md): F_x, F_y, F_z, M_x, M_y are the load on the inner ring needed to hold it at its displacement,
K d for a linear bearing (a positive F_y goes with a positive y). The balls push the inner ring with the opposite
force, and the inner ring is fixed to the shaft, so the shaft's seat receives -F (turned into the shaft's frame).
The seat's displacement and velocity go back in the bearing's frame: the inner ring's motion relative to the
outer ring, which is fixed to the housing.
"""

import math

import numpy as np

from bearing_fmu_common.blas_threads import single_blas_thread

from . import beam
from .model import ShaftInputError

FORCE_MAX = 1.0e7  # N (moments N.m): far above a spindle bearing's load limit; a finite bound on an input
STEP_MAX = 1.0  # s: a communication step of the shaft's dynamics (its first periods are milliseconds)
SUBSTEPS_MAX = 100_000
GAMMA_RANGE = (0.5, 1.0)  # Newmark's gamma: 1/2 is the trapezoidal rule, 1 the most damping scheme of the family


class ShaftTransient:
    """Time integration of a ShaftModel's reduced model at the constant speed omega (rad/s, 0 to 1e4).

    K_seats, C_seats (n_seats, 5, 5, in the bearings' frames, as ShaftModel.evaluate takes them; None: none): a linear
    seat stiffness and damping kept inside the model, for tests and for a damping the bearings do not supply; a
    bearing coupled through the seat forces must not also be given here. substeps: Newmark steps per
    communication step (1 to 1e5). gamma: Newmark's gamma (0.5 to 1; beta = (gamma + 1/2)^2 / 4): 0.5 the
    average acceleration, above it a numerical damping of the modes the step does not resolve (module docstring).
    The state starts at rest, undeformed (set_state to change it)."""

    def __init__(self, model, omega, K_seats=None, C_seats=None, substeps=1, gamma=0.5):
        self.model = model
        self.omega = model._check_omega(omega)
        if not (isinstance(substeps, int | np.integer) and 1 <= substeps <= SUBSTEPS_MAX):
            raise ShaftInputError(
                f"substeps = {substeps} is outside the allowed range [1, {SUBSTEPS_MAX}] (an integer)"
            )
        if not GAMMA_RANGE[0] <= gamma <= GAMMA_RANGE[1]:
            raise ShaftInputError(f"gamma = {gamma} is outside the allowed range [{GAMMA_RANGE[0]}, {GAMMA_RANGE[1]}]")
        self.substeps = int(substeps)
        self.gamma = float(gamma)
        self.beta = 0.25 * (self.gamma + 0.5) ** 2
        self.K, self._C = model.matrices(K_seats, C_seats)
        self.M = model._M
        self.D = self._C + self.omega * model._G
        self._t = model.seat_signs()
        self._seat_dofs = model._seat_dofs
        self._tip = model._tip
        self._solver = (None, None)  # ((substep h, stiffness), inverse of M + h/2 D + h^2/4 K)
        n = self.K.shape[0]
        self.q, self.v = np.zeros(n), np.zeros(n)
        self.time = 0.0

    def set_speed(self, omega):
        """Change the speed (rad/s, 0 to 1e4) from the next step on: the gyroscopic term follows it, the state is
        kept (a run-up as a sequence of constant speeds)."""
        self.omega = self.model._check_omega(omega)
        self.D = self._C + self.omega * self.model._G
        self._solver = (None, None)

    # ------------------------------------------------------------------------------------------ frames
    def to_shaft(self, seat_values):
        """Seat vectors (n_seats, 5) from the bearings' frames into the shaft's (or back: T is its own inverse)."""
        return np.asarray(seat_values, dtype=float) * self._t

    to_bearing = to_shaft

    # ------------------------------------------------------------------------------------------ inputs
    def _seat_forces(self, name, value):
        n = len(self.model.shaft.seat_nodes)
        F = np.asarray(value, dtype=float)
        if F.shape != (n, beam.NDOF):
            raise ShaftInputError(
                f"{name}: shape {F.shape}, expected ({n}, 5) (F_x, F_y, F_z, M_x, M_y per seat "
                f"{self.model.shaft.seat_names})"
            )
        for s, k in zip(*np.nonzero(~(np.abs(F) <= FORCE_MAX)), strict=True):
            raise ShaftInputError(
                f"{name}[{s}][{k}] = {F[s, k]} is outside the allowed range [-{FORCE_MAX:g}, {FORCE_MAX:g}] "
                f"(N or N.m; seat '{self.model.shaft.seat_names[s]}')"
            )
        return F

    def _tip_force(self, value):
        if value is None:
            return np.zeros(beam.NDOF)
        F = np.asarray(value, dtype=float)
        if F.shape != (beam.NDOF,):
            raise ShaftInputError(f"external_tip_force: shape {F.shape}, expected (5,) (F_x, F_y, F_z, M_x, M_y)")
        for k in np.nonzero(~(np.abs(F) <= FORCE_MAX))[0]:
            raise ShaftInputError(
                f"external_tip_force[{k}] = {F[k]} is outside the allowed range [-{FORCE_MAX:g}, {FORCE_MAX:g}] "
                "(N or N.m)"
            )
        return F

    def load_vector(self, seat_forces, tip_force=None):
        """The reduced model's force vector f: at each seat -F turned into the shaft's frame (F as the bearing outputs
        it: the load holding its inner ring, the reverse of the balls' push on the ring and so on the shaft), at
        the tool tip the external force (N, N.m; shaft's frame, on the shaft)."""
        f = np.zeros(self.K.shape[0])
        f[self._seat_dofs] -= self.to_shaft(seat_forces)
        f[self._tip : self._tip + beam.NDOF] += tip_force if tip_force is not None else 0.0
        return f

    # ------------------------------------------------------------------------------------------ state
    def set_state(self, q, v):
        """Set the reduced model's displacement q and velocity v (the first 5 n_interface entries are the seat and
        tool-tip nodes' physical dof, m and rad; then the fixed-interface modal amplitudes)."""
        n = self.K.shape[0]
        q, v = np.array(q, dtype=float), np.array(v, dtype=float)
        for name, x in (("q", q), ("v", v)):
            if x.shape != (n,) or not np.all(np.isfinite(x)):
                raise ShaftInputError(f"{name}: shape {x.shape}, expected ({n},) finite values")
        self.q, self.v = q, v

    def energy(self):
        """Kinetic plus strain energy (J) of the model's own K (with the internal seat stiffness): constant without
        damping and external forces (the gyroscopic forces do no work)."""
        return 0.5 * float(self.v @ self.M @ self.v) + 0.5 * float(self.q @ self.K @ self.q)

    def outputs(self):
        """Each seat's displacement and velocity (n_seats, 5: x, y, z, theta_x, theta_y in the bearing's own frame; m,
        rad, m/s, rad/s) and the tool tip's displacement (5, shaft's frame)."""
        d = self._seat_dofs
        return {
            "seat_displacement": self.to_bearing(self.q[d]),
            "seat_velocity": self.to_bearing(self.v[d]),
            "tip_displacement": self.q[self._tip : self._tip + beam.NDOF].copy(),
        }

    # ------------------------------------------------------------------------------------------ step
    def _effective_inverse(self, h, K):
        """Inverse of M + gamma h D + beta h^2 K, kept while the substep and the stiffness stay the same."""
        key = (h, K.tobytes())
        if self._solver[0] != key:
            self._solver = (key, np.linalg.inv(self.M + self.gamma * h * self.D + self.beta * h * h * K))
        return self._solver[1]

    def _coupled_stiffness(self, seat_stiffness):
        """The bearings' stiffness over the step in the reduced model's dof (shaft's frame), 0 without it."""
        Kc = np.zeros_like(self.K)
        if seat_stiffness is not None:
            A = self.model.seat_frame(self.model._seat_matrices("seat_stiffness", seat_stiffness))
            beam.add_seats(self._seat_dofs, A, Kc)
        return Kc

    def step(self, h, seat_forces_start, seat_forces_end, external_tip_force=None, seat_stiffness=None):
        """Advance the state by the communication step h (s, 0 to 1) in `substeps` Newmark steps and return outputs()
        at its end. The seat forces go linearly from seat_forces_start to seat_forces_end ((n_seats, 5) each, as the
        bearings output them, in their frames); the external force on the tool tip (5, shaft's frame; None: none)
        holds over the step. seat_stiffness (n_seats, 5, 5, the bearings' K in their frames, as they output it;
        None: none) adds each bearing's linearisation about the step's start, K (d(t) - d_start), to its force and
        integrates it with the shaft (implicitly): a master that knows the forces at the step's start only passes
        them as both ends with the bearings' K, and a linear bearing is then followed without lag."""
        h = float(h)
        if not 0.0 < h <= STEP_MAX:
            raise ShaftInputError(f"h = {h} s is outside the allowed range (0, {STEP_MAX:g}]")
        tip = self._tip_force(external_tip_force)
        Kc = self._coupled_stiffness(seat_stiffness)
        hold = Kc @ self.q  # -K (d - d_start) on the shaft: -Kc q + Kc q_start
        f0 = self.load_vector(self._seat_forces("seat_forces_start", seat_forces_start), tip) + hold
        f1 = self.load_vector(self._seat_forces("seat_forces_end", seat_forces_end), tip) + hold
        with single_blas_thread():  # tens of unknowns: BLAS threads cost more than they bring
            self._advance(h / self.substeps, f0, f1, self.K + Kc)
        self.time += h
        return self.outputs()

    def _advance(self, dt, f0, f1, K):
        """Newmark's scheme over the substeps for M q'' + D q' + K q = f: a_n from the equation of motion at the
        start (so that a force that jumps between communication steps enters consistently), then, with the
        predictors q* = q + dt v + (1/2 - beta) dt^2 a and v* = v + (1 - gamma) dt a,
        (M + gamma dt D + beta dt^2 K) a_{n+1} = f_{n+1} - D v* - K q*,
        q = q* + beta dt^2 a_{n+1}, v = v* + gamma dt a_{n+1}."""
        S_inv = self._effective_inverse(dt, K)
        g, b = self.gamma, self.beta
        q, v = self.q, self.v
        a = self.model._Minv @ (f0 - self.D @ v - K @ q)
        for i in range(1, self.substeps + 1):
            f = f0 + (f1 - f0) * (i / self.substeps)
            q_star = q + dt * v + (0.5 - b) * dt * dt * a
            v_star = v + (1.0 - g) * dt * a
            a = S_inv @ (f - self.D @ v_star - K @ q_star)
            q = q_star + b * dt * dt * a
            v = v_star + g * dt * a
        self.q, self.v = q, v

    # ------------------------------------------------------------------------------------------ coupling
    def held_force_step(self, K_seats, C_seats):
        """Estimate (s) of the largest stable communication step when the bearings' forces are held over the step
        (computed from the seat's motion at its start, no seat_stiffness passed): min over seats and dof of
        2 c_ii / k_ii. A held spring force lags the motion by half a step, a negative damping ratio omega h / 4 with
        omega = sqrt(k / m), m = 1 / (M^-1)_ii the mass the seat's dof moves at high frequency; the average-
        acceleration scheme is stable where the seat's damping ratio c / (2 sqrt(k m)) outweighs it,
        h < 4 zeta / omega = 2 c / k (a mass on a spring and damper; exact for zeta <= 1). An estimate: it ignores
        the coupling between dof and the shaft's flexibility (on the default shaft the motion starts growing at 2.5
        to 3 times it)."""
        k = np.diagonal(self.model._seat_matrices("K_seats", K_seats), axis1=1, axis2=2)
        c = np.diagonal(self.model._seat_matrices("C_seats", C_seats), axis1=1, axis2=2)
        with np.errstate(divide="ignore", invalid="ignore"):
            limits = np.where(k > 0.0, 2.0 * c / k, math.inf)
        return float(np.min(limits))
