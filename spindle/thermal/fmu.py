"""pythonfmu slave of the lumped thermal spindle (docs/spindle_thermal.md): SpindleThermal.fmu.

Thin (docs/architecture.md, FMUs): the network, its integrator and the thermo-mechanics live in
spindle.thermal.model / spindle.thermal.network, every variable is declared once in
spindle.thermal.declarations. This class registers the model's inputs and outputs from those
declarations, keeps their values in lists read and written by precomputed index
(bearing_fmu_common.fmi.DeclaredSlave) and hands the input list to model.update(h, u) in do_step. The
network is read from a TOML file (parameter `spindle`: catalogue name or path), so a user can describe their own spindle
without rebuilding the FMU. Bad input or parameters are logged with their allowed range and the call
returns Discard/Error; the host never sees an exception. As in the bearing FMUs (docs/fmu_runtime.md), a
refused parameter fails fmi2ExitInitializationMode (fmi2Error), while a bad input at initialisation is
logged there and refused again by the first doStep (fmi2Discard): the network starts from the inputs of
the first doStep that accepts them, so the host can correct an input and continue.
"""

from bearing_fmu_common.fmi import DeclaredSlave, check_parameters, declared_parameter

from .declarations import parameter_declarations
from .model import DEFAULT_SPINDLE, SpindleThermalModel, load_spindle

COMMUNICATION_DIGITS = 12  # the communication step is taken on a grid of 10^-12 s


class SpindleThermal(DeclaredSlave):
    """Lumped thermal network of a spindle with bearing heat inputs and clearance/preload outputs."""

    author = "bearing_fmu developers"
    default_network = DEFAULT_SPINDLE  # the network whose inputs/outputs become FMI variables (build time)
    axial_float = None  # build time: True adds the axial-float inputs (fixed preload)
    description = (
        "Lumped thermal spindle: nodes, capacities, conduction/contact/convection links from a TOML "
        "file, exact exponential (or implicit Euler) integration; outputs node temperatures, ring and "
        "oil temperatures per bearing, thermal/centrifugal change of diametral clearance and axial "
        "interference of a fixed-preload pair. SI units."
    )

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._parameters = parameter_declarations(self.default_network, load_spindle(self.default_network))
        for var in self._parameters:
            self.register_variable(declared_parameter(var, self))
        self._model = SpindleThermalModel(self.spindle, axial_float=self.axial_float)
        self._ready = False  # parameters accepted (exit_initialization_mode)
        self._started = False  # network initialised from accepted inputs
        self.register_declared(self._model.inputs, self._model.outputs)
        self._input_names = tuple(v.name for v in self._model.inputs)
        self._model.initialize(**self._inputs())
        self._y = self._model.values.tolist()

    def _inputs(self):
        return dict(zip(self._input_names, self._u))

    def _build(self):
        """The model for the parameters (raises on a refused one)."""
        check_parameters(self, self._parameters)
        T0 = None if self.T_initial == 0.0 else self.T_initial  # 0 = the ambient input; the model checks the rest
        model = SpindleThermalModel(
            self.spindle,
            integrator=self.integrator,
            T_initial=T0,
            axial_float=self.axial_float,
            dimensions=None if self.network_from_file else self._dimensions(),
        )
        if [v.name for v in model.inputs] != [v.name for v in self._model.inputs] or [
            v.name for v in model.outputs
        ] != [v.name for v in self._model.outputs]:
            raise ValueError(
                f"spindle = {self.spindle!r} has other inputs/outputs than the network this FMU "
                f"was built with ({self.default_network!r}); FMI variables are fixed at build "
                f"time: add an FMU for it in spindle.all_fmus.THERMAL_FMUS"
            )
        self._model = model
        self._started = False

    def _dimensions(self):
        """The main dimensions' parameter values by name (network_from_file false): the structured names
        bearing_<k>.*, expansion.*, axial.* (declarations.dimension_rows)."""
        return {var.name: getattr(self, var.name) for var in self._parameters if "." in var.name}

    def _start(self):
        """Initialise the network from the current inputs (raises on a bad input, nothing changed)."""
        self._model.initialize(**self._inputs())
        self._y = self._model.values.tolist()
        self._started = True

    def exit_initialization_mode(self):
        return self._initialised(self._build, self._start)

    def do_step(self, current_time, step_size):
        def step():
            if not self._started:  # the inputs at initialisation were refused: start from the current ones
                self._start()
            # on a grid of 1 ps, as BearingDEM.fmu: masters that hand the same nominal step in different roundings
            # (libcosim counts integer nanoseconds, fmpy multiplies n H) then integrate the same step, bit for bit
            self._y = self._model.update(round(step_size, COMMUNICATION_DIGITS), self._u).tolist()

        return self._stepped(step)

    def _get_fmu_state(self):
        state = super()._get_fmu_state()
        state["_network_state"] = self._model.get_state() if self._started else None
        return state

    def _set_fmu_state(self, state):
        state = dict(state)
        network = state.pop("_network_state", None)
        super()._set_fmu_state(state)
        if network is not None:
            self._model.set_state(network)
        self._started = network is not None
