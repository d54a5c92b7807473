"""A tiny pythonfmu slave that makes a master's algorithm visible (built into a temporary FMU by the tests).

u: input (start 7). y = u + 1, computed by its getter, so it follows u at any time, also in
initialisation mode. x: state, x += u * H in each doStep (so x shows which u a step used).
n_set_inst / n_set_init / n_set: number of fmi2SetReal(u) calls in the instantiated state, in
initialisation mode, in total.
"""

from pythonfmu import Fmi2Slave
from pythonfmu.enums import Fmi2Causality, Fmi2Initial, Fmi2Variability
from pythonfmu.variables import Integer, Real


class ProbeSlave(Fmi2Slave):
    author = "bearing_fmu tests"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._u = 7.0
        self._mode = "instantiated"
        self.x = 0.0
        self.n_set = self.n_set_init = self.n_set_inst = 0
        self.register_variable(
            Real(
                "u",
                causality=Fmi2Causality.input,
                variability=Fmi2Variability.continuous,
                getter=lambda: self._u,
                setter=self._set_u,
            )
        )
        self.register_variable(
            Real(
                "y",
                causality=Fmi2Causality.output,
                variability=Fmi2Variability.continuous,
                initial=Fmi2Initial.exact,
                getter=lambda: self._u + 1.0,
            )
        )
        self.register_variable(
            Real("x", causality=Fmi2Causality.output, variability=Fmi2Variability.continuous, initial=Fmi2Initial.exact)
        )
        for name in ("n_set", "n_set_init", "n_set_inst"):
            self.register_variable(
                Integer(
                    name,
                    causality=Fmi2Causality.output,
                    variability=Fmi2Variability.discrete,
                    initial=Fmi2Initial.exact,
                )
            )

    def _set_u(self, value):
        self._u = value
        self.n_set += 1
        self.n_set_init += self._mode == "init"
        self.n_set_inst += self._mode == "instantiated"

    def enter_initialization_mode(self):
        self._mode = "init"

    def exit_initialization_mode(self):
        self._mode = "step"

    def do_step(self, current_time, step_size):
        self.x += self._u * step_size
        return True
