"""The shaft's time-domain mode as SpindleShaftTransient.fmu steps it (spindle.shaft.fmu): inputs in declaration order
in, outputs in declaration order out, every refusal naming the FMU variable, its value and the allowed range.

ShaftTransient.step takes the seats' forces and stiffness as arrays; this layer builds them from the flat FMU inputs
(omega, then per seat F_x ... M_y and the 25 K entries, then the tool tip's force), checks the declared ranges first
(so that a message names `F_x_1` or `K_2[3,3]`, not an array index) and couples them as docs/shaft.md section 10
says: the bearings' forces, computed from the seat's motion at the step's start, held over the step, with their K
integrated implicitly (`implicit_coupling`). A speed that changed since the last step goes through
ShaftTransient.set_speed, which keeps the state.
"""

import numpy as np

from bearing_fmu_common.variables import InputLimits

from . import beam
from .declarations import NEWMARK_GAMMA, transient_input_declarations, transient_output_declarations
from .model import ShaftModel
from .params import DEFAULT_SHAFT
from .transient import ShaftTransient

PER_SEAT = 30  # inputs per seat: F_x, F_y, F_z, M_x, M_y, then the 25 entries of K


class TransientStepper:
    """Outputs of the shaft's time-domain mode for the FMU's inputs (transient_input_declarations order) in
    transient_output_declarations order. configure() sets the parameters and starts from rest."""

    def __init__(self, shaft=DEFAULT_SHAFT):
        self.model = ShaftModel(shaft)
        self.inputs = transient_input_declarations(self.model.shaft)
        self.outputs = transient_output_declarations(self.model.shaft)
        self._limits = InputLimits(self.inputs)
        self._seats = len(self.model.shaft.seat_nodes)
        self.implicit = True
        self.transient = None
        self.configure(1, np.zeros((self._seats, 3)), True, NEWMARK_GAMMA)

    def configure(self, substeps, damping, implicit, gamma):
        """Substeps per communication step, the shaft's own damping per seat ((n_seats, 3): radial N.s/m, axial
        N.s/m, tilt N.m.s/rad), whether the bearings' K is used and Newmark's gamma; the state at rest, undeformed."""
        damping = np.asarray(damping, dtype=float).reshape(self._seats, 3)
        C = np.zeros((self._seats, beam.NDOF, beam.NDOF))
        for i, column in enumerate((0, 0, 1, 2, 2)):  # x, y radial; z axial; theta_x, theta_y tilt
            C[:, i, i] = damping[:, column]
        self.transient = ShaftTransient(self.model, 0.0, C_seats=C, substeps=int(substeps), gamma=float(gamma))
        self.implicit = bool(implicit)

    def split(self, u):
        """(omega, seat forces (n_seats, 5), seat stiffness (n_seats, 5, 5), tool-tip force (5,)) of the inputs u."""
        u = np.asarray(u, dtype=float)
        rows = u[1 : 1 + PER_SEAT * self._seats].reshape(self._seats, PER_SEAT)
        return float(u[0]), rows[:, :5].copy(), rows[:, 5:].reshape(self._seats, 5, 5).copy(), u[-5:].copy()

    def check(self, u):
        """Raise InputError naming the first input of u outside its declared range (or NaN)."""
        self._limits.check(u)

    def start(self, u):
        """The outputs at the state now for the inputs u (checked; the speed taken)."""
        self.check(u)
        self._speed(u[0])
        return self.values()

    def _speed(self, omega):
        if float(omega) != self.transient.omega:
            self.transient.set_speed(omega)

    def step(self, h, u):
        """Advance by the communication step h (s) under the inputs u and return the outputs (a list): the seat
        forces held over the step, each bearing's K passed when implicit (ShaftTransient.step)."""
        self.check(u)
        omega, forces, stiffness, tip = self.split(u)
        self._speed(omega)
        self.transient.step(h, forces, forces, tip, stiffness if self.implicit else None)
        return self.values()

    def values(self):
        """The outputs (a list in declaration order) of the state now."""
        out = self.transient.outputs()
        per_seat = np.concatenate([out["seat_displacement"], out["seat_velocity"]], axis=1)
        return [*per_seat.ravel().tolist(), *out["tip_displacement"].tolist()]

    def get_state(self):
        """The state (reduced displacement q, velocity v, time, speed) as plain values."""
        t = self.transient
        return {"q": t.q.tolist(), "v": t.v.tolist(), "time": t.time, "omega": t.omega}

    def set_state(self, state):
        self.transient.set_state(state["q"], state["v"])
        self.transient.time = float(state["time"])
        self._speed(state["omega"])
