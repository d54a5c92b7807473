"""A tiny pythonfmu slave that makes the master's time, step sizes and rollback visible (built into a
temporary FMU by tests/cosim/conftest.py; no numpy, no numba).

u: input (start 0). In doStep(t, h): t_start := t, t_end := t + h, x += u * h, n_steps += 1.
n_calls counts every doStep call, also the ones a rollback undoes (its setter ignores restored
states, so a master's setFMUstate cannot reset it); t_start, t_end, x and n_steps are ordinary
registered variables, so they are part of the FMU state and are restored by setFMUstate.
A step is refused (do_step returns False, with an error logged) when h > h_max or t >= fail_at;
the message contains a '%' (escaped for pythonfmu's printf-style log) to check that a master shows
it verbatim.
"""

from pythonfmu import Fmi2Slave
from pythonfmu.enums import Fmi2Causality, Fmi2Initial, Fmi2Status, Fmi2Variability
from pythonfmu.variables import Integer, Real

PARAMETER = {"causality": Fmi2Causality.parameter, "variability": Fmi2Variability.fixed, "initial": Fmi2Initial.exact}


def _output(kind, name, **accessors):
    """An output of kind Real (continuous) or Integer (discrete) that starts at its exact start value."""
    variability = Fmi2Variability.continuous if kind is Real else Fmi2Variability.discrete
    return kind(name, causality=Fmi2Causality.output, variability=variability, initial=Fmi2Initial.exact, **accessors)


class ClockSlave(Fmi2Slave):
    author = "bearing_fmu tests"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.u = 0.0
        self.h_max = 1e300
        self.fail_at = 1e300
        self.t_start = self.t_end = self.x = 0.0
        self.n_steps = 0
        self._n_calls = 0
        self.register_variable(
            Real("u", causality=Fmi2Causality.input, variability=Fmi2Variability.continuous, start=0.0)
        )
        for name in ("h_max", "fail_at"):
            self.register_variable(Real(name, start=1e300, **PARAMETER))
        for name in ("t_start", "t_end", "x"):
            self.register_variable(_output(Real, name))
        self.register_variable(_output(Integer, "n_steps"))
        self.register_variable(_output(Integer, "n_calls", getter=lambda: self._n_calls, setter=lambda value: None))

    def do_step(self, current_time, step_size):
        self._n_calls += 1
        if step_size > self.h_max:
            self.log(
                f"{self.instance_name}: step h = {step_size!r} s > h_max = {self.h_max!r} s: refused "
                f"(100%% of the step)",
                Fmi2Status.error,
            )
            return False
        if current_time >= self.fail_at:
            self.log(f"{self.instance_name}: t = {current_time!r} s >= fail_at: refused (100%% sure)", Fmi2Status.error)
            return False
        self.t_start = current_time
        self.t_end = current_time + step_size
        self.x += self.u * step_size
        self.n_steps += 1
        return True
