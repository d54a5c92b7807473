"""pythonfmu slave of the bearing model: a variables table and calls into BearingModel (SPEC 5).

Thin on purpose: physics lives in the kernels, input checks in the model. Bad input never raises
out of an FMI call (a Python exception becomes fmi2Fatal in pythonfmu): it is logged with its
allowed range and reported as fmi2Error; the outputs keep their last valid values.
"""
from pythonfmu import Fmi2Slave
from pythonfmu.enums import Fmi2Status

from .fmi import add_unit_definitions, fmi_escape, input_variable, output_variable, parameter
from .model import INPUTS, BearingModel, InputError
from .params import ParameterError
from .scene import Scene, SceneError

INPUT_START = {"omega": 0.0, "F_y": 0.0, "T_oil": 313.15}


class BearingAnalytic(Fmi2Slave):
    """Analytic ball-bearing model (Stribeck/Sjovall + Hertz + EHL film + capacitance)."""

    author = "bearing_fmu developers"
    description = ("Radially loaded deep-groove ball bearing, analytic fidelity: Sjovall load distribution "
                   "with clearance, exact Hertz contacts, Hamrock-Dowson EHL film, film parameter, regime, "
                   "capacitance. SI units.")
    scene = Scene()

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.bearing = "6208"
        self.lubricant = "guessasma_oil"
        self.Pd = 0.0
        self.register_variable(parameter("bearing", self.bearing,
                                         "bearing catalogue name (6208, 6306) or path of a bearing TOML file"))
        self.register_variable(parameter("lubricant", self.lubricant,
                                         "lubricant catalogue name or path of a lubricant TOML file"))
        self.register_variable(parameter("Pd", self.Pd, "diametral clearance used by the model, overrides the "
                                         "bearing file value (negative = preload), |Pd| <= 0.02 D",
                                         unit="m"))
        for var in INPUTS:
            setattr(self, var.name, INPUT_START[var.name])
            self.register_variable(input_variable(var.name, var.unit, INPUT_START[var.name], var.description))
        self._model = None
        self._built_for = None
        self._ready = False
        self._build_model()
        for var in self._model.outputs:
            setattr(self, var.name, 0 if var.kind == "integer" else 0.0)
            self.register_variable(output_variable(var.name, var.unit, var.description, var.kind == "integer"))
        self._update()  # start values of the outputs = the model at the default inputs

    # -- model ---------------------------------------------------------------------------------
    def _build_model(self):
        key = (self.bearing, self.lubricant, float(self.Pd))
        if self._built_for != key:
            self._model = BearingModel(self.bearing, self.lubricant, self.scene, Pd=self.Pd)
            self._built_for = key

    def _update(self):
        values = self._model.evaluate(self.omega, self.F_y, self.T_oil)
        for warning in self._model.warnings:
            self.log(fmi_escape(warning), Fmi2Status.warning)
        for name, value in values.items():
            setattr(self, name, value)

    def _guarded(self, action):
        """Run action(); log a clear message and return False on bad input or parameters."""
        try:
            action()
            return True
        except (InputError, ParameterError, SceneError) as exc:
            self.log(fmi_escape(f"{self.instance_name}: {exc}"), Fmi2Status.error)
        except Exception as exc:  # never let an exception reach the host as fmi2Fatal
            self.log(fmi_escape(f"{self.instance_name}: internal error {type(exc).__name__}: {exc}"),
                     Fmi2Status.error)
        return False

    # -- FMI -------------------------------------------------------------------------------------
    def exit_initialization_mode(self):
        self._ready = self._guarded(lambda: (self._build_model(), self._update()))

    def do_step(self, current_time, step_size):
        if not self._ready:
            # initialisation failed (logged then); try again so a corrected parameter recovers
            self._ready = self._guarded(self._build_model)
            if not self._ready:
                return False
        return self._guarded(self._update)

    def _set_fmu_state(self, state):
        super()._set_fmu_state(state)
        self._ready = self._guarded(self._build_model)

    def to_xml(self, model_options=dict()):
        return add_unit_definitions(super().to_xml(model_options), self.vars.values())
