"""pythonfmu slave of the spindle shaft's rotor model (docs/shaft.md): SpindleShaft.fmu.

Thin (docs/architecture.md, FMUs): the model is spindle.shaft.model, stepped by spindle.shaft.stepper, and every
variable is declared once in spindle.shaft.declarations. This class registers the inputs and outputs from those
declarations (bearing_fmu_common.fmi.DeclaredSlave) and hands the input list to the stepper in do_step. The shaft is
read from a TOML file (parameter `shaft`: catalogue name or path) whose seats must be those the FMU was built with;
with `shaft_from_file` false its numbers are the parameters shaft_data.* (those of the file the FMU was built with,
for masters that set no String parameter), and the shaft's reduction is done again at initialisation.
As in the thermal FMU, a refused parameter fails fmi2ExitInitializationMode (fmi2Error), a bad input at
initialisation is logged there (fmi2Warning) and refused again by the first doStep (fmi2Discard); the outputs keep
their last accepted values, so the host can correct the input and continue. The outputs hold no history: a step
computes them from the current inputs (the critical speeds are kept while the seats do not change).

SpindleShaftTransient.fmu is the shaft's time-domain mode (spindle.shaft.transient, stepped by
spindle.shaft.transient_stepper): each seat's bearing reaction and K in, each seat's motion out, for bearings driven by
the inner ring's displacement. It has a state (the shaft's displacement and velocity), saved and restored with the FMU
state so that a master can reject a step.
"""

from bearing_fmu_common.fmi import DeclaredSlave, check_parameters, declared_parameter

from .declarations import SEAT_DAMPING, number_name, parameter_declarations, transient_parameter_declarations
from .params import DEFAULT_SHAFT, shaft_numbers, shaft_with_numbers
from .stepper import ShaftStepper
from .transient_stepper import TransientStepper


class ShaftSlave(DeclaredSlave):
    """What the shaft FMUs share: the shaft their seats come from and the registration of their declarations."""

    author = "bearing_fmu developers"
    default_shaft = DEFAULT_SHAFT  # the shaft whose seats become FMI variables (build time)

    def _register(self, stepper, parameters):
        """Register the parameters and the stepper's inputs and outputs; the parameters not yet accepted."""
        self._stepper, self._parameters = stepper, parameters
        for var in parameters:
            self.register_variable(declared_parameter(var, self))
        self._ready = False  # parameters accepted (exit_initialization_mode)
        self.register_declared(stepper.inputs, stepper.outputs)
        self._number_keys = tuple((table, i, key) for table, i, _, key, _ in shaft_numbers(self.default_shaft))

    def _built_shaft(self):
        """Whether the parameters give the shaft the FMU was built with, whose reduction its stepper holds."""
        return self.shaft == self.default_shaft and self.shaft_from_file

    def _shaft(self):
        """The shaft of the parameters: the file named by `shaft`; with shaft_from_file false, that file's structure
        with the numbers shaft_data.* (params.shaft_with_numbers: the file's checks, a refusal naming the parameter).
        """
        if self.shaft_from_file:
            return self.shaft
        keys = tuple((table, i, key) for table, i, _, key, _ in shaft_numbers(self.shaft))
        if keys != self._number_keys:
            raise ValueError(
                f"shaft = {self.shaft!r} has other materials, sections or disks than the shaft this FMU was built "
                f"with ({self.default_shaft!r}), whose numbers the shaft_data.* parameters are; allowed with "
                "shaft_from_file = false: a shaft file with as many materials, sections and disks"
            )
        numbers = {key: getattr(self, number_name(*key)) for key in keys}
        return shaft_with_numbers(self.shaft, numbers, number_name)


class SpindleShaft(ShaftSlave):
    """Rotor finite-element model of a spindle shaft on bearing seats: natural frequencies, whirl, damping, tool-tip
    compliance and critical speeds."""

    description = (
        "Rotor finite-element model of a spindle shaft (Timoshenko beams, disks, Craig-Bampton reduction) on bearing "
        "seats taking a bearing FMU's 5x5 stiffness and a radial damping: first six natural frequencies at speed "
        "with whirl and damping ratio, tool-tip static and peak compliance, first two forward critical speeds. "
        "SI units."
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        stepper = ShaftStepper(self.default_shaft)
        self._register(stepper, parameter_declarations(self.default_shaft, stepper.model.shaft.seat_names))
        self._y = self._stepper.evaluate(self._u)

    def _build(self):
        """The stepper for the parameters (raises on a refused one)."""
        check_parameters(self, self._parameters)
        # the file it was built with: its reduction is done (the costly part of the set-up)
        stepper = self._stepper if self._built_shaft() else ShaftStepper(self._shaft())
        _refuse_other_seats(self.shaft, self.default_shaft, stepper, self._stepper)
        seats = range(1, len(stepper.model.shaft.seat_names) + 1)
        stepper.configure([getattr(self, f"floating_{seat}") for seat in seats], float(self.tolerance))
        self._stepper = stepper

    def _evaluate(self):
        self._y = self._stepper.evaluate(self._u)

    def exit_initialization_mode(self):
        return self._initialised(self._build, self._evaluate)

    def do_step(self, current_time, step_size):
        return self._stepped(self._evaluate)


def _refuse_other_seats(shaft, built_with, stepper, built_stepper):
    """Raise ValueError if the shaft file `shaft` has other seats than the one the FMU was built with."""
    names = stepper.model.shaft.seat_names
    if [v.name for v in stepper.inputs] != [v.name for v in built_stepper.inputs]:
        raise ValueError(
            f"shaft = {shaft!r} has other seats ({', '.join(names)}) than the shaft this FMU was built with "
            f"({built_with!r}: {', '.join(built_stepper.model.shaft.seat_names)}); allowed: a shaft file with as "
            "many seats"
        )


class SpindleShaftTransient(ShaftSlave):
    """Time-domain mode of the spindle shaft's rotor model: the seats' motion under the bearings' reactions."""

    description = (
        "Rotor finite-element model of a spindle shaft (Timoshenko beams, disks, Craig-Bampton reduction) integrated "
        "in time (Newmark's scheme, its gamma a parameter) under the reactions of bearings driven by displacement: "
        "per seat the bearing's F_x, F_y, F_z, M_x, M_y and 5x5 K in, the inner ring's displacement, tilts and their "
        "rates out in the bearing's frame; the tool tip's displacement under an external force. SI units."
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        stepper = TransientStepper(self.default_shaft)
        self._register(stepper, transient_parameter_declarations(self.default_shaft, stepper.model.shaft.seat_names))
        self._y = self._stepper.values()

    def _build(self):
        """The stepper for the parameters, at rest (raises on a refused one)."""
        check_parameters(self, self._parameters)
        stepper = self._stepper if self._built_shaft() else TransientStepper(self._shaft())
        _refuse_other_seats(self.shaft, self.default_shaft, stepper, self._stepper)
        seats = range(1, len(stepper.model.shaft.seat_names) + 1)
        damping = [[getattr(self, f"c_{kind}_{s}") for kind, *_ in SEAT_DAMPING] for s in seats]
        stepper.configure(int(self.substeps), damping, self.implicit_coupling, self.newmark_gamma)
        self._stepper = stepper

    def _start(self):
        self._y = self._stepper.start(self._u)

    def exit_initialization_mode(self):
        return self._initialised(self._build, self._start)

    def do_step(self, current_time, step_size):
        def step():
            self._y = self._stepper.step(step_size, self._u)

        return self._stepped(step)

    def _get_fmu_state(self):
        state = super()._get_fmu_state()
        state["_shaft_state"] = self._stepper.get_state()
        return state

    def _set_fmu_state(self, state):
        state = dict(state)
        shaft = state.pop("_shaft_state", None)
        super()._set_fmu_state(state)
        if shaft is not None:
            self._stepper.set_state(shaft)
