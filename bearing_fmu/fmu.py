"""pythonfmu slaves of the bearing models: variables from the declarations, calls into the model.

Thin on purpose (docs/architecture.md, FMUs): physics lives in the kernels, input checks in the
models, every variable is declared once in bearing_fmu.models.declarations. The slave registers the
model's inputs and outputs from those declarations and keeps their values in two lists read and
written by precomputed index (bearing_fmu_common.fmi.DeclaredSlave); a step hands the input list to
model.update() and takes the model's output array as the new output list. Bad input never raises out
of an FMI call: it is logged with its allowed range and do_step returns False (fmi2Discard); the
outputs keep their last valid values. A refused parameter makes exit_initialization_mode return False
(fmi2Error). Statuses: docs/fmu_runtime.md.
"""

import os

from pythonfmu.enums import Fmi2Status

from bearing_fmu_common.fmi import DeclaredSlave, check_parameters, declared_parameter
from bearing_fmu_common.variables import select

from .fidelities import FIDELITIES
from .kernels.ball_dynamics.state import ST_CODE
from .models.dem import DemUnstableError
from .models.dem_settings import DEM_SETTINGS
from .models.file_parameters import BEARING_PREFIX, LUBRICANT_PREFIX, bearing_from_values, lubricant_from_values
from .models.film_table import CARRIED_DIR
from .models.limits import InputError
from .params import ParameterError
from .scene import LUBRICATION_METHODS, RACE_CONTROLS, Scene, SceneError

# appended to an input refused at initialisation: the call succeeds (parameters are fine), the step would not
INPUT_NOTE = " (refused at the first doStep unless the input is corrected)"


class _BearingSlave(DeclaredSlave):
    """Common FMI plumbing: parameters, inputs and outputs from the declarations, guarded calls, full state."""

    author = "bearing_fmu developers"
    fidelity = FIDELITIES["analytic"]  # its facade and parameters (models.fidelity)
    scene = Scene()
    parameters = fidelity.parameters  # declarations of the FMU's parameters (models.declarations)

    @classmethod
    def described(cls, scene):
        """The FMU's description text with `scene` (its build's)."""
        return cls.description

    def __init_subclass__(cls, **kwargs):
        """A bearing FMU class names its fidelity; its default scene and its parameters follow from it (a class
        that sets them itself, such as a built FMU's with its scene file, keeps its own)."""
        super().__init_subclass__(**kwargs)
        if "fidelity" in cls.__dict__:
            name = cls.fidelity.name
            cls.scene = cls.__dict__.get("scene", Scene(name=name, fidelity=name))
            cls.parameters = cls.__dict__.get("parameters", cls.fidelity.parameters)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._model = None
        self._built_for = None
        self._ready = False
        self._parameters = select(self.parameters, self.scene)
        self._names = {var.name for var in self._parameters}
        for var in self._parameters:
            self.register_variable(declared_parameter(var, self, self.scene))
        self._build_model()
        self.register_declared(self._model.inputs, self._model.outputs)
        self._update()  # start values of the outputs = the model at the start inputs

    # -- model ---------------------------------------------------------------------------------
    def _model_key(self):
        """The parameters' values: the model is rebuilt when one of them changed."""
        return tuple(getattr(self, var.name) for var in self._parameters)

    def _values(self, prefix):
        return {var.name: getattr(self, var.name) for var in self._parameters if var.name.startswith(prefix)}

    def _bearing(self):
        """The bearing in effect (bearing_from_file): the name or file of `bearing`, or the numeric one."""
        return self.bearing if self.bearing_from_file else bearing_from_values(self._values(BEARING_PREFIX))

    def _lubricant(self):
        """The lubricant in effect (lubricant_from_file): the name or file of `lubricant`, or the numeric one."""
        if self.lubricant_from_file:
            return self.lubricant
        return lubricant_from_values(self._values(LUBRICANT_PREFIX))

    def _clearance(self):
        """The clearance that replaces the bearing's (m), None: the bearing's own (Pd_from_file)."""
        return None if self.Pd_from_file else self.Pd

    def _model_options(self):
        """The facade's keyword arguments beyond bearing, lubricant, scene and clearance (from the parameters)."""
        return {}

    def _film_tables(self):
        """The film tables the FMU carries (resources/film_tables): its models read no other (models.film_table)."""
        return None if self.resources is None else os.path.join(self.resources, CARRIED_DIR)

    def _make_model(self):
        return self.fidelity.model(
            self._bearing(),
            self._lubricant(),
            self.scene,
            Pd=self._clearance(),
            film_tables=self._film_tables(),
            **self._model_options(),
        )

    def _build_model(self):
        check_parameters(self, self._parameters)
        key = self._model_key()
        if self._built_for != key:
            self._model = self._make_model()
            self._built_for = key

    def _update(self):
        values = self._model.update(self._u)
        self._log_warnings()
        self._y = values.tolist()

    def _log_warnings(self):
        for warning in self._model.warnings:
            self.log(warning, Fmi2Status.warning)

    def _guarded(self, action, status=Fmi2Status.error, note=""):
        """Run action(); on bad input or parameters log a clear message (with the FMI status that the calling
        function returns, and `note` appended) and return False."""
        try:
            action()
            return True
        except (InputError, ParameterError, SceneError, DemUnstableError) as exc:
            self.log(f"{self.instance_name}: {exc}{note}", status)
        except Exception as exc:  # logged as the model's own message, not a traceback
            self.log(f"{self.instance_name}: internal error {type(exc).__name__}: {exc}{note}", status)
        return False

    # -- FMI -------------------------------------------------------------------------------------
    def exit_initialization_mode(self):
        # a refused parameter fails initialisation (fmi2Error: parameters are fixed from here on); a
        # bad input is logged and refused again by the first doStep (fmi2Discard): the host may still
        # correct an input (and libcosim 0.11 aborts the process on fmi2Error here, docs/fmu_runtime.md)
        # a fresh model, also when no parameter changed: the first outputs then do not depend on which start
        # values the master wrote (one that writes every start value, one that writes none and one that sets
        # a parameter to its start value all start a solver from the same state)
        self._built_for = None
        self._ready = self._guarded(self._build_model)
        if not self._ready:
            return False  # fmi2Error, logged as such
        # an input refused now is logged once as a warning (fmi2Warning returned) and refused by the first doStep
        if not self._guarded(self._update, Fmi2Status.warning, INPUT_NOTE):
            return Fmi2Status.warning
        return True

    def do_step(self, current_time, step_size):
        if not self._ready:
            # the model could not be built (a refused parameter, logged then: e.g. restored by
            # _set_fmu_state); try again rather than step without a model
            self._ready = self._guarded(self._build_model, Fmi2Status.discard)
            if not self._ready:
                return False
        return self._guarded(self._update, Fmi2Status.discard)  # False: fmi2Discard

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


class BearingAnalytic(_BearingSlave):
    """Analytic ball-bearing model (Stribeck/Sjovall + Hertz + EHL film + capacitance)."""

    description = (
        "Radially loaded deep-groove ball bearing, analytic fidelity: Sjovall load distribution "
        "with clearance, exact Hertz contacts, Hamrock-Dowson EHL film, film parameter, regime, "
        "capacitance. SI units."
    )


class BearingQuasiStatic(_BearingSlave):
    """Quasi-static 5-DOF ball bearing (Jones/Harris) with film, capacitance, Houpert torque and stiffness."""

    description = (
        "Ball bearing, quasi-static fidelity: 5-DOF inner-ring equilibrium with per-ball "
        "equilibrium (centrifugal force, gyroscopic moment, race control), exact Hertz contacts, "
        "5x5 stiffness, EHL film, regime, capacitance, Houpert friction torque and ring heat. SI units."
    )
    fidelity = FIDELITIES["quasi_static"]
    F_preload = 0.0  # N: no assembly offset unless the scene's drive is fixed_axial (then a parameter)

    def _race_control(self):
        """The race control in effect: race_control_mode's unless it is -1, then the String race_control's."""
        return self.race_control if self.race_control_mode < 0 else RACE_CONTROLS[self.race_control_mode]

    def _lubrication(self):
        """The lubrication method in effect: lubrication_mode's unless it is -1, then the String lubrication's."""
        return self.lubrication if self.lubrication_mode < 0 else LUBRICATION_METHODS[self.lubrication_mode]

    def _model_options(self):
        return {"race_control": self._race_control(), "F_preload": self.F_preload, "lubrication": self._lubrication()}


class BearingDEM(_BearingSlave):
    """DEM (ball dynamics) ball bearing: one doStep integrates the communication step in one jitted call.

    The speed goes linearly from its value at the previous communication point to the input over the
    step; loads, oil temperature and clearance change are held (DemModel.update). With the scene's drive
    'displacement' the inner ring follows the cubic from its state to the inputs x ... theta_y and their rates at
    the step's end, and the reaction loads F_x ... M_y, means over the step, are outputs. A step the stability
    monitor stops returns fmi2Discard with the monitor's message, the instance back at the start of
    the step and `monitor_status` naming the cause; the master may retry with a smaller step."""

    # per drive (scene option): the inner ring integrated under the loads, or moved along the master's path
    DESCRIPTIONS = {
        drive: f"Ball bearing, DEM fidelity: {bodies}, per-contact EHL film, regime, friction and damping, Houpert "
        "resistances, capacitance; torque and ring heat from the energy dissipated over the step. SI units."
        for drive, bodies in (
            ("load", "6-DOF balls, cage balls and a translating inner ring integrated in time"),
            (
                "displacement",
                "6-DOF balls and cage balls integrated in time, the inner ring moved along the master's path "
                "(x ... theta_y and their rates in, reaction loads out)",
            ),
        )
    }
    description = DESCRIPTIONS["load"]
    fidelity = FIDELITIES["dem"]

    def __init_subclass__(cls, **kwargs):
        """A built FMU's class (with its scene) takes the description of its scene's drive."""
        super().__init_subclass__(**kwargs)
        cls.description = cls.described(cls.scene)

    @classmethod
    def described(cls, scene):
        return cls.DESCRIPTIONS[scene.drive]

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._monitor_slot = self._model.output_names.index("monitor_status")

    def _model_options(self):
        return {
            "dt": None if self.dt == 0.0 else self.dt,  # 0 = automatic
            "refresh_interval": self.refresh_interval,
            "averaged": bool(self.average_outputs),
            "averaged_state": bool(self.average_state_outputs),
            # each by its own name; those the scene's drive has not (a prescribed ring has no support) stay out
            **{setting.name: getattr(self, setting.name) for setting in DEM_SETTINGS if setting.name in self._names},
        }

    def _advance(self, step_size):
        self._y = self._model.update(self._u, step_size).tolist()
        self._log_warnings()  # p_max above the ISO 76 limit, as Bearing.fmu

    def do_step(self, current_time, step_size):
        if not self._ready:
            self._ready = self._guarded(self._build_model, Fmi2Status.discard)
            if not self._ready:
                return False
        if self._guarded(lambda: self._advance(step_size), Fmi2Status.discard):
            return True
        self._y[self._monitor_slot] = int(self._model.status[ST_CODE])  # the cause of a monitor stop, else 0
        return False
