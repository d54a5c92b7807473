"""A test slave whose getters return values that cannot be converted to their FMI type
(tests/fmu/test_native_runtime.py builds it into an FMU with the product's FMI layer).

Each getter returns, for value references 0, 1 and 2: a good value, a bad one, a good one. The bad ones: a str for
a Real, an int beyond 32 bits for an Integer, an object whose truth cannot be told for a Boolean, bytes for a
String. The variables are registered so that the model description has them; the getters bypass them.
"""

from pythonfmu import Boolean, Fmi2Causality, Fmi2Slave, Fmi2Variability, Integer, Real, String


class Undecided:
    def __bool__(self):
        raise ValueError("this value is neither true nor false")


VALUES = {
    "real": [1.5, "not a number", 2.5],
    "integer": [7, 2**40, 8],
    "boolean": [True, Undecided(), True],
    "string": ["first", b"bytes", "third"],
}


class BadValues(Fmi2Slave):
    """Outputs of every type whose second value is bad."""

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        for kind, cls in (("real", Real), ("integer", Integer), ("boolean", Boolean), ("string", String)):
            for k in range(3):
                setattr(self, f"{kind}_{k}", VALUES[kind][0])
                variability = Fmi2Variability.continuous if cls is Real else Fmi2Variability.discrete
                self.register_variable(cls(f"{kind}_{k}", causality=Fmi2Causality.output, variability=variability))

    def _values(self, kind, vrs):
        return [VALUES[kind][vr % 3] for vr in vrs]

    def get_real(self, vrs):
        return self._values("real", vrs)

    def get_integer(self, vrs):
        return self._values("integer", vrs)

    def get_boolean(self, vrs):
        return self._values("boolean", vrs)

    def get_string(self, vrs):
        return self._values("string", vrs)

    def do_step(self, current_time, step_size):
        return True
