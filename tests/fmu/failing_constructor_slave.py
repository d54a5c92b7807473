"""A test slave whose constructor fails on demand (tests/fmu/test_native_runtime.py builds it into an FMU
with the product's FMI layer): from the N-th construction in a process on, N read from
resources/fail_from.txt of the extracted FMU (no such file: never). N = 1 fails fmi2Instantiate, N = 2
the first fmi2Reset."""

import os

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real

FAIL_FROM = "fail_from.txt"
REASON = "the constructor refuses on purpose (construction {n}, 100% planned)"


class FailingConstructor(Fmi2Slave):
    """y = the end time of the last step."""

    constructions = 0  # in this process (the layer imports the module once per process)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        cls = type(self)
        cls.constructions += 1
        path = os.path.join(self.resources or "", FAIL_FROM)
        if os.path.isfile(path):
            with open(path) as fh:
                if cls.constructions >= int(fh.read()):
                    raise RuntimeError(REASON.format(n=cls.constructions))
        self.y = 0.0
        self.register_variable(
            Real("y", causality=Fmi2Causality.output, variability=Fmi2Variability.continuous, description="time")
        )

    def do_step(self, current_time, step_size):
        self.y = current_time + step_size
        return True
