"""The shaft model as an FMU steps it (spindle.shaft.fmu): inputs in declaration order in, outputs in declaration order
out, every refusal naming the FMU variable, its value and the allowed range.

ShaftModel.evaluate takes the seats' matrices; this layer builds them from the flat FMU inputs (25 K entries and a
radial damping per seat), checks the declared ranges first (so a message names `K_1[3,3]`, not an array index),
refuses a seat stiffness that leaves the shaft free (rigid-body modes: no static compliance) and any non-finite
output, and keeps the critical speeds, a second eigenproblem, until the seats' K or c change.
"""

import math

import numpy as np

from bearing_fmu_common.variables import InputError, InputLimits

from .declarations import input_declarations, output_declarations, seat_stiffness_name
from .model import N_FREQUENCIES, ShaftModel
from .params import DEFAULT_SHAFT

SEAT_CHANGE = 1e-9  # relative change of the seats' K or C (Frobenius norm) below which the critical speeds are kept
PER_SEAT = 26  # inputs per seat: 25 stiffness entries, then the radial damping


def changed(new, old):
    """Whether seat matrices `new` differ from `old` (None: never computed) by more than SEAT_CHANGE of old's norm."""
    return old is None or np.linalg.norm(new - old) > SEAT_CHANGE * np.linalg.norm(old)


class ShaftStepper:
    """Outputs of the shaft model for the FMU's inputs (input_declarations order) in output_declarations order."""

    def __init__(self, shaft=DEFAULT_SHAFT):
        self.model = ShaftModel(shaft)
        self.inputs = input_declarations(self.model.shaft)
        self.outputs = output_declarations()
        self._limits = InputLimits(self.inputs)
        self._seats = len(self.model.shaft.seat_nodes)
        self._critical = None  # (K, C, critical speeds) of the last computation
        self.critical_evaluations = 0  # how many times the critical speeds were computed
        self.tolerance = 0.0  # relative change of the inputs below which evaluate keeps its outputs (moved())
        self._last = None  # (inputs, their bounds (_bounds), outputs) of the last solution
        self.solutions = 0  # how many times the modes were solved

    def configure(self, floating, tolerance):
        """Set the seats' floating flags (ShaftModel.set_floating) and the tolerance; forget the kept solutions."""
        self.model.set_floating(floating)
        self.tolerance = tolerance
        self._critical = self._last = None

    def seat_matrices(self, u):
        """(K, C) of the seats, shape (n_seats, 5, 5), from the inputs u (omega first)."""
        rows = np.asarray(u[1:], dtype=float).reshape(self._seats, PER_SEAT)
        K = rows[:, :25].reshape(self._seats, 5, 5).copy()
        C = np.zeros_like(K)
        C[:, 0, 0] = C[:, 1, 1] = rows[:, 25]
        return K, C

    def seats_changed(self, K, C):
        """Whether the seats' K or C changed (changed()) since the critical speeds were last computed."""
        last = self._critical
        return last is None or changed(K, last[0]) or changed(C, last[1])

    def _refuse_free(self, K, rigid):
        diagonal = ", ".join(
            f"{seat_stiffness_name(s + 1, i, i)} = {K[s, i, i]:g}" for s in range(self._seats) for i in range(5)
        )
        raise InputError(
            f"the seat stiffness leaves the shaft free ({rigid} rigid-body modes, no static compliance): {diagonal}; "
            "allowed: seat stiffness that holds the shaft in x, y, z and in tilt (diagonal entries in [0, 1e13], "
            "radial ones > 0 at two seats, an axial one > 0 at one)"
        )

    def moved(self, u):
        """Whether inputs u moved by more than `tolerance` since the last solution (its bounds: _bounds())."""
        if self._last is None or self.tolerance == 0.0:
            return True
        return bool(np.any(np.abs(np.asarray(u, dtype=float) - self._last[0]) > self._last[1]))

    def _bounds(self, u):
        """Per input, the change from u beyond which a step solves again: an entry of a seat's K by tolerance
        sqrt(K_ii K_jj) (each entry against its own diagonal's scale, so that the tilt entries count as much as the
        radial ones whatever their units), a seat's damping and omega by tolerance of their value (any change
        from 0)."""
        u = np.asarray(u, dtype=float)
        rows = np.abs(u[1:].reshape(self._seats, PER_SEAT))
        diagonal = rows[:, :25].reshape(self._seats, 5, 5).diagonal(axis1=1, axis2=2)
        bounds = np.empty_like(rows)
        bounds[:, :25] = np.sqrt(diagonal[:, :, None] * diagonal[:, None, :]).reshape(self._seats, 25)
        bounds[:, 25] = rows[:, 25]
        return u, self.tolerance * np.concatenate(([abs(u[0])], bounds.ravel()))

    def evaluate(self, u):
        """Outputs (a list) for the inputs u; InputError naming the input when they are refused. With a tolerance,
        the last outputs while the inputs have not moved (moved())."""
        self._limits.check(u)
        if not self.moved(u):
            return list(self._last[2])
        values = self._solve(u)
        self._last = (*self._bounds(u), values)
        self.solutions += 1
        return list(values)

    def _solve(self, u):
        K, C = self.seat_matrices(u)
        # the critical speeds in the same call as the modes when the seats changed: the seats' matrices assembled once
        fresh = self.seats_changed(K, C)
        out = self.model.evaluate(u[0], K, C, critical_speeds=fresh)
        if out["rigid_modes"] or not math.isfinite(out["compliance_radial"] * out["compliance_axial"]):
            self._refuse_free(K, out["rigid_modes"])
        if fresh:
            self._critical = (K, C, out["critical_speeds"])
            self.critical_evaluations += 1
        values = [
            *out["frequencies"].tolist(),
            *out["whirl"].tolist(),
            *out["damping_ratios"].tolist(),
            out["compliance_radial"],
            out["compliance_axial"],
            out["peak_compliance"],
            out["peak_frequency"],
            *self._critical[2].tolist(),
        ]
        if not all(math.isfinite(v) for v in values):
            self._refuse_non_finite(u, values)
        return values

    def _refuse_non_finite(self, u, values):
        missing = [var.name for var, v in zip(self.outputs, values) if not math.isfinite(v)]
        damping = ", ".join(f"c_{s + 1} = {u[1 + PER_SEAT * s + 25]:g} N.s/m" for s in range(self._seats))
        raise InputError(
            f"no finite {', '.join(missing)} with omega = {u[0]:g} rad/s and the seats' K and damping ({damping}): "
            f"fewer than {N_FREQUENCIES} elastic modes, an undamped mode or fewer than two forward critical speeds; "
            "allowed: seats that hold the shaft with damping in [1, 1e8] N.s/m"
        )

    def outputs_values(self, u):
        """The outputs as a dict name -> value (integers for the whirl)."""
        return {v.name: int(x) if v.kind == "integer" else x for v, x in zip(self.outputs, self.evaluate(u))}
