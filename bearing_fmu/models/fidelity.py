"""The contract of a fidelity: what the FMU layer, the build and the documentation need to know of it.

Each fidelity declares one `Fidelity` beside its facade (models.analytic, models.quasi_static, models.dem);
bearing_fmu.fidelities collects them. Whatever loops over fidelities (the FMU classes, the build, the README's
table) reads these fields instead of branching on a fidelity's name. The scene options a fidelity accepts are
declared with the scene (bearing_fmu.scene.FIDELITY_RULES), which the models import and so cannot import back.
"""

from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Fidelity:
    """A fidelity's facade and how it is built and described.

    name: the scene's `fidelity`.
    model: the facade, Model(bearing, lubricant, scene, Pd=..., **options) with `inputs`, `outputs` (declarations),
        update(u), evaluate(**inputs) and get_state()/set_state() (docs/architecture.md, Facades).
    parameters: declarations of its FMU's parameters (models.declarations).
    choices: the configuration choices (`spindle build --config`: catalogue names or files) its facade takes.
    reference_step: communication step (s) of its FMU's reference experiment.
    reference_inputs: scene -> the reference experiment, one dict of inputs (SI) per communication point (with
        "time", s, the end of the step, where the points are not one step apart from 0).
    build_options: scene -> keyword arguments of the facade for the scene's reference model (e.g. the assembly
        preload of a fixed-preload scene).
    summary: scene -> a few words on what its FMU models (the README's table of FMUs).
    """

    name: str
    model: type
    parameters: tuple
    choices: tuple
    reference_step: float
    reference_inputs: Callable
    summary: Callable
    build_options: Callable = lambda scene: {}

    def make_model(self, scene, choices=None):
        """The facade for `scene` with its FMU's default parameters, or those `choices` sets (catalogue names or
        files); the choices the fidelity does not take (a race control in the analytic one) are left out."""
        chosen = {key: value for key, value in (choices or {}).items() if key in self.choices}
        return self.model(scene=scene, **self.build_options(scene), **chosen)
