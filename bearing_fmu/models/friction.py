"""What friction a quasi-static solution assumes, said to the user (docs/quasistatic.md, section 2).

A race-control hypothesis (outer, inner, hybrid) fixes the balls' kinematics and lets the contacts carry whatever
tangential force the ball's balance then needs: its share of the gyroscopic moment. The traction coefficient that
asks of a contact, mu_required = |lam M_g / D| / Q (kernels.jones_harris BQ_MU_REQ_*), can exceed what the film
carries (the lubricant's limiting traction coefficient); the solution then describes balls the oil cannot hold, and
the race control "traction" is the answer that follows from the traction the oil gives. FrictionWatch warns once per
entry into that state, refuses a state whose loads friction carries (every inner contact open under a load: an
infinite required coefficient; or one above MU_IMPOSSIBLE), and warns when the solution jumps to another branch.
"""

import math

import numpy as np

from ..kernels import jones_harris
from .limits import InputError

RACES = ("inner", "outer")
BRANCH_JUMP = math.radians(10.0)  # rad: a change of the most loaded ball's inner contact angle between two evaluations
# (-): a required coefficient above it is friction carrying the load, not the contacts: no lubricated contact, nor dry
# bearing steel (0.4-0.8 in air, Bowden & Tabor 1950, The Friction and Lubrication of Solids), transmits it
MU_IMPOSSIBLE = 1.0
SMALL_STEP = 0.05  # ... whose inputs changed by less than this share of their values: a jump, not a large input step


class FrictionWatch:
    """Warnings and refusals about the friction a race-control hypothesis assumes.

    race_control: the model's ('outer' | 'inner' | 'hybrid' | 'traction'); mu_limit: the lubricant's limiting
    traction coefficient (-); lubricant: its name, for the messages."""

    def __init__(self, race_control, mu_limit, lubricant):
        self.race_control = race_control
        self.mu_limit = mu_limit
        self.lubricant = lubricant
        self.exceeded = [False, False]  # per race: the required coefficient was above the limit at the last solution
        self.alpha_inner = None  # the most loaded ball's inner contact angle of the last solution (rad)
        self.inputs = None  # the inputs of the last solution (SI)

    def refuse_friction_alone(self, balls, applied, control, shown):
        """Raise InputError when the solution's loads are carried by friction: every inner contact open under a load
        (the hypothesis then holds the ring by the friction of its share of the gyroscopic moment alone: an infinite
        required coefficient), or a required coefficient above MU_IMPOSSIBLE. balls: per-ball rows of
        kernels.jones_harris; applied, control: the load-controlled loads (N, N.m) and their flags; shown: a callable
        giving the inputs for the message (formatted only for one). Lists, not numpy reductions: for a few dozen
        balls a fraction of numpy's fixed cost per call, paid at every step."""
        if self.race_control == "traction":
            return
        mu = (max(balls[jones_harris.BQ_MU_REQ_I].tolist()), max(balls[jones_harris.BQ_MU_REQ_O].tolist()))
        if max(balls[jones_harris.BQ_Q_I].tolist()) <= 0.0 and any(
            control[i] > 0.5 and applied[i] != 0.0 for i in range(5)
        ):
            why = "no ball touches the inner race under these loads, which only the friction of the balls' gyroscopic "
            why += "moment would carry (its required traction coefficient is infinite)"
        elif max(mu) > MU_IMPOSSIBLE:
            race = 0 if mu[0] >= mu[1] else 1
            j = int(np.argmax(balls[jones_harris.BQ_MU_REQ_I + race]))
            why = (
                f"it asks a traction coefficient of {mu[race]:.4g} of ball {j + 1}'s {RACES[race]} contact (load "
                f"{balls[jones_harris.BQ_Q_I + race, j]:.4g} N), above {MU_IMPOSSIBLE:g}: friction, not the contact "
                f"loads, would carry the bearing's load"
            )
        else:
            return
        raise InputError(
            f"race control '{self.race_control}': {why}; no bearing carries a load that way. Allowed: loads that press "
            f"the balls on both races (more thrust or preload), or race_control = 'traction' (race_control_mode = 3), "
            f"which takes only the traction the oil gives. Inputs: {shown()}"
        )

    def warnings(self, mu_required, alpha_inner, balls, u):
        """Warnings for this solution: the races whose required coefficient (mu_required: inner, outer; -) has just
        passed the limit (once per entry), and a jump of the most loaded ball's inner contact angle (alpha_inner,
        rad; None when no ball touches the inner race) by more than BRANCH_JUMP since the last solution while no
        input (u, SI) changed by SMALL_STEP of its value. balls: per-ball rows of kernels.jones_harris, for the
        message."""
        out = []
        for race in range(2):
            above = bool(mu_required[race] > self.mu_limit)  # a Python bool: the state holds plain values
            if above and not self.exceeded[race]:
                j = int(np.argmax(balls[jones_harris.BQ_MU_REQ_I + race]))
                out.append(
                    f"race control '{self.race_control}' asks a traction coefficient of {mu_required[race]:.4g} of "
                    f"ball {j + 1}'s {RACES[race]} contact, above the limiting traction coefficient "
                    f"{self.mu_limit:.4g} of lubricant '{self.lubricant}': the oil cannot carry the friction this "
                    f"hypothesis assumes (the balls would slide; cage speed, contact angles and torque differ). "
                    f"race_control = 'traction' (race_control_mode = 3) solves the balls' kinematics from the "
                    f"traction the oil gives (outputs mu_required_{RACES[race]})"
                )
            self.exceeded[race] = above
        previous, previous_inputs = self.alpha_inner, self.inputs
        self.alpha_inner = alpha_inner
        self.inputs = [float(v) for v in u]
        if alpha_inner is None or previous is None or abs(alpha_inner - previous) <= BRANCH_JUMP:
            return out
        if all(abs(a - b) <= SMALL_STEP * max(abs(a), abs(b), 1e-300) for a, b in zip(self.inputs, previous_inputs)):
            out.append(
                f"the solution jumped to another branch: the most loaded ball's inner contact angle went from "
                f"{math.degrees(previous):.1f} deg to {math.degrees(alpha_inner):.1f} deg since the last evaluation "
                f"(race control '{self.race_control}'); a small change of the inputs can cross such a jump"
            )
        return out

    def state(self):
        return {"exceeded": list(self.exceeded), "alpha_inner": self.alpha_inner, "inputs": self.inputs}

    def set_state(self, state):
        self.exceeded[:] = state.get("exceeded", (False, False))
        self.alpha_inner = state.get("alpha_inner")
        self.inputs = state.get("inputs")
