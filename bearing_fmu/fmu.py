"""pythonfmu slaves of the bearing models: a variables table and calls into the model (SPEC 5).

Thin on purpose: physics lives in the kernels, input checks in the models. The model declares its
inputs and outputs (bearing_fmu.models.analytic.Variable); the slave registers them, so the FMU and the
Python model cannot drift. Bad input never raises out of an FMI call: it is logged with its allowed
range and do_step returns False (fmi2Discard); the outputs keep their last valid values. A refused
parameter makes exit_initialization_mode return False (fmi2Error). Statuses: docs/fmu_runtime.md.
"""

from pythonfmu import Fmi2Slave
from pythonfmu.enums import Fmi2Status

from bearing_fmu_common.fmi import add_unit_definitions, input_variable, output_variable, parameter

from .models.analytic import AnalyticModel
from .models.quasi_static import QuasiStaticModel
from .models.variables import InputError
from .params import ParameterError
from .scene import Scene, SceneError

DEFAULT_FIXED_PRELOAD = 800.0  # N, Rabreau et al. 2018 rig (fixed_axial scenes only)
INPUT_START = {"T_oil": 313.15}  # every other input starts at 0 (at rest, unloaded, centred)


class _BearingSlave(Fmi2Slave):
    """Common FMI plumbing: parameters, inputs and outputs from the model, guarded calls, full state."""

    author = "bearing_fmu developers"
    scene = Scene()

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._model = None
        self._built_for = None
        self._ready = False
        self._values = {}
        self._declare_parameters()
        self._build_model()
        for var in self._model.inputs:
            setattr(self, var.name, INPUT_START.get(var.name, 0.0))
            self.register_variable(input_variable(var.name, var.unit, INPUT_START.get(var.name, 0.0), var.description))
        for var in self._model.outputs:
            self._values[var.name] = 0 if var.kind == "integer" else 0.0
            self.register_variable(
                output_variable(
                    var.name,
                    var.unit,
                    var.description,
                    var.kind == "integer",
                    getter=lambda n=var.name: self._values[n],
                    setter=lambda v, n=var.name: self._values.__setitem__(n, v),
                )
            )
        self._update()  # start values of the outputs = the model at the default inputs

    # -- model ---------------------------------------------------------------------------------
    def _declare_parameters(self):
        raise NotImplementedError

    def _model_key(self):
        raise NotImplementedError

    def _make_model(self):
        raise NotImplementedError

    def _build_model(self):
        key = self._model_key()
        if self._built_for != key:
            self._model = self._make_model()
            self._built_for = key

    def _update(self):
        values = self._model.evaluate(**{v.name: getattr(self, v.name) for v in self._model.inputs})
        for warning in self._model.warnings:
            self.log(warning, Fmi2Status.warning)
        self._values.update(values)

    def _guarded(self, action):
        """Run action(); log a clear message and return False on bad input or parameters."""
        try:
            action()
            return True
        except (InputError, ParameterError, SceneError) as exc:
            self.log(f"{self.instance_name}: {exc}", Fmi2Status.error)
        except Exception as exc:  # logged as the model's own message, not a traceback
            self.log(f"{self.instance_name}: internal error {type(exc).__name__}: {exc}", Fmi2Status.error)
        return False

    # -- FMI -------------------------------------------------------------------------------------
    def exit_initialization_mode(self):
        # a refused parameter fails initialisation (fmi2Error: parameters are fixed from here on); a
        # bad input is logged and refused again by the first doStep (fmi2Discard): the host may still
        # correct an input (and libcosim 0.11 aborts the process on fmi2Error here, docs/fmu_runtime.md)
        self._ready = self._guarded(self._build_model)
        if self._ready:
            self._guarded(self._update)
        return self._ready

    def do_step(self, current_time, step_size):
        if not self._ready:
            # initialisation failed (logged then); try again so a corrected parameter recovers
            self._ready = self._guarded(self._build_model)
            if not self._ready:
                return False
        return self._guarded(self._update)

    def _get_fmu_state(self):
        state = super()._get_fmu_state()
        state["_solver_state"] = self._model.get_state() if self._model is not None else {}
        return state

    def _set_fmu_state(self, state):
        state = dict(state)
        solver = state.pop("_solver_state", {})
        super()._set_fmu_state(state)
        self._ready = self._guarded(self._build_model)
        if self._ready and solver:
            self._model.set_state(solver)

    def to_xml(self, model_options=None):
        return add_unit_definitions(super().to_xml(model_options or {}), self.vars.values())


class BearingAnalytic(_BearingSlave):
    """Analytic ball-bearing model (Stribeck/Sjovall + Hertz + EHL film + capacitance)."""

    description = (
        "Radially loaded deep-groove ball bearing, analytic fidelity: Sjovall load distribution "
        "with clearance, exact Hertz contacts, Hamrock-Dowson EHL film, film parameter, regime, "
        "capacitance. SI units."
    )

    def _declare_parameters(self):
        self.bearing = "6208"
        self.lubricant = "guessasma_oil"
        self.Pd = 0.0
        self.register_variable(
            parameter("bearing", self.bearing, "bearing catalogue name (6208, 6306) or path of a bearing TOML file")
        )
        self.register_variable(
            parameter("lubricant", self.lubricant, "lubricant catalogue name or path of a lubricant TOML file")
        )
        self.register_variable(
            parameter(
                "Pd",
                self.Pd,
                "diametral clearance used by the model, overrides the "
                "bearing file value (negative = preload), |Pd| <= 0.02 D",
                unit="m",
            )
        )

    def _model_key(self):
        return self.bearing, self.lubricant, float(self.Pd)

    def _make_model(self):
        return AnalyticModel(self.bearing, self.lubricant, self.scene, Pd=self.Pd)


class BearingQuasiStatic(_BearingSlave):
    """Quasi-static 5-DOF ball bearing (Jones/Harris) with film, capacitance, Houpert torque and stiffness."""

    description = (
        "Ball bearing, quasi-static fidelity: 5-DOF inner-ring equilibrium with per-ball "
        "equilibrium (centrifugal force, gyroscopic moment, race control), exact Hertz contacts, "
        "5x5 stiffness, EHL film, regime, capacitance, Houpert friction torque and ring heat. SI units."
    )
    scene = Scene(name="quasi_static", fidelity="quasi_static")

    def _declare_parameters(self):
        self.bearing = "B7214C"
        self.lubricant = "iso_vg68_mineral"
        self.Pd = 0.0
        self.Pd_from_file = True
        self.race_control = self.scene.race_control
        self.register_variable(
            parameter(
                "bearing", self.bearing, "bearing catalogue name (6208, 6306, B7214C) or path of a bearing TOML file"
            )
        )
        self.register_variable(
            parameter("lubricant", self.lubricant, "lubricant catalogue name or path of a lubricant TOML file")
        )
        self.register_variable(
            parameter(
                "Pd_from_file",
                self.Pd_from_file,
                "true: diametral clearance from the bearing file; false: from the parameter Pd",
            )
        )
        self.register_variable(
            parameter(
                "Pd",
                self.Pd,
                "diametral clearance used when Pd_from_file is false (negative = preload), |Pd| <= 0.02 D",
                unit="m",
            )
        )
        self.register_variable(
            parameter(
                "race_control", self.race_control, "ball race-control hypothesis: outer | inner | hybrid (Rabreau 2018)"
            )
        )
        self.F_preload = 0.0
        if self.scene.drive == "fixed_axial":  # only a fixed-preload bearing has an assembly offset
            self.F_preload = DEFAULT_FIXED_PRELOAD
            self.register_variable(
                parameter(
                    "F_preload",
                    self.F_preload,
                    "axial preload set at assembly (at rest, "
                    "no thermal change; default: the Rabreau rig's 800 N); the input z is "
                    "added to the axial approach that carries it. 0 = z is the axial "
                    "approach itself",
                    unit="N",
                )
            )

    def _model_key(self):
        return (
            self.bearing,
            self.lubricant,
            bool(self.Pd_from_file),
            float(self.Pd),
            self.race_control,
            float(self.F_preload),
        )

    def _make_model(self):
        Pd = None if self.Pd_from_file else self.Pd
        return QuasiStaticModel(
            self.bearing, self.lubricant, self.scene, Pd=Pd, race_control=self.race_control, F_preload=self.F_preload
        )
