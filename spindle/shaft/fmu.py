"""pythonfmu slave of the spindle shaft's rotor model (docs/shaft.md): SpindleShaft.fmu.

Thin (docs/architecture.md, FMUs): the model is spindle.shaft.model, stepped by spindle.shaft.stepper, and every
variable is declared once in spindle.shaft.declarations. This class registers the inputs and outputs from those
declarations (bearing_fmu_common.fmi.DeclaredSlave) and hands the input list to the stepper in do_step. The shaft is
read from a TOML file (parameter `shaft`: catalogue name or path) whose seats must be those the FMU was built with.
As in the thermal FMU, a refused parameter fails fmi2ExitInitializationMode (fmi2Error), a bad input at
initialisation is logged there (fmi2Warning) and refused again by the first doStep (fmi2Discard); the outputs keep
their last accepted values, so the host can correct the input and continue. The outputs hold no history: a step
computes them from the current inputs (the critical speeds are kept while the seats do not change).
"""

from bearing_fmu_common.fmi import DeclaredSlave, check_parameters, declared_parameter

from .declarations import parameter_declarations
from .params import DEFAULT_SHAFT
from .stepper import ShaftStepper


class SpindleShaft(DeclaredSlave):
    """Rotor finite-element model of a spindle shaft on bearing seats: natural frequencies, whirl, damping, tool-tip
    compliance and critical speeds."""

    author = "bearing_fmu developers"
    default_shaft = DEFAULT_SHAFT  # the shaft whose seats become FMI variables (build time)
    description = (
        "Rotor finite-element model of a spindle shaft (Timoshenko beams, disks, Craig-Bampton reduction) on bearing "
        "seats taking a bearing FMU's 5x5 stiffness and a radial damping: first six natural frequencies at speed "
        "with whirl and damping ratio, tool-tip static and peak compliance, first two forward critical speeds. "
        "SI units."
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._stepper = ShaftStepper(self.default_shaft)
        self._parameters = parameter_declarations(self.default_shaft, self._stepper.model.shaft.seat_names)
        for var in self._parameters:
            self.register_variable(declared_parameter(var, self))
        self._ready = False  # parameters accepted (exit_initialization_mode)
        self.register_declared(self._stepper.inputs, self._stepper.outputs)
        self._y = self._stepper.evaluate(self._u)

    def _build(self):
        """The stepper for the parameters (raises on a refused one)."""
        check_parameters(self, self._parameters)
        # the file it was built with: its reduction is done (the costly part of the set-up)
        stepper = self._stepper if self.shaft == self.default_shaft else ShaftStepper(self.shaft)
        if [v.name for v in stepper.inputs] != [v.name for v in self._stepper.inputs]:
            raise ValueError(
                f"shaft = {self.shaft!r} has other seats ({', '.join(stepper.model.shaft.seat_names)}) than the shaft "
                f"this FMU was built with ({self.default_shaft!r}: "
                f"{', '.join(self._stepper.model.shaft.seat_names)}); allowed: a shaft file with as many seats"
            )
        seats = range(1, len(stepper.model.shaft.seat_names) + 1)
        stepper.configure([getattr(self, f"floating_{seat}") for seat in seats], float(self.tolerance))
        self._stepper = stepper

    def _evaluate(self):
        self._y = self._stepper.evaluate(self._u)

    def exit_initialization_mode(self):
        return self._initialised(self._build, self._evaluate)

    def do_step(self, current_time, step_size):
        return self._stepped(self._evaluate)
