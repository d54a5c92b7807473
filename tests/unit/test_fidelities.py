"""The fidelity registry (bearing_fmu.fidelities): every fidelity the scene knows has one contract, the FMU classes
and the scene files use it, and the FMU layer, the build and the scene loop over it instead of branching on a
fidelity's name (docs/architecture.md, Fidelities)."""

import ast
import tomllib
from pathlib import Path

import pytest

from bearing_fmu import fmu as slaves
from bearing_fmu.build import make_model, scene_files
from bearing_fmu.fidelities import FIDELITIES
from bearing_fmu.scene import FIDELITY_RULES, Scene, SceneError

ROOT = Path(__file__).resolve().parents[2]
# the layers that must not know a fidelity by name (the facades themselves may check their own)
LOOPING_LAYERS = (
    "bearing_fmu/fmu.py",
    "bearing_fmu/build.py",
    "bearing_fmu/scene.py",
    "bearing_fmu/fmu_files.py",
    "spindle/all_fmus.py",
    "spindle/configured.py",
    "spindle/cli.py",
    "spindle/check.py",
)


def fidelity_branches(source):
    """Line numbers of comparisons of something named `fidelity` with a string (fidelity == 'dem', != , in (...))."""

    def names_fidelity(node):
        return (isinstance(node, ast.Attribute) and node.attr == "fidelity") or (
            isinstance(node, ast.Name) and node.id == "fidelity"
        )

    def is_text(node):
        return (isinstance(node, ast.Constant) and isinstance(node.value, str)) or (
            isinstance(node, (ast.Tuple, ast.List, ast.Set)) and all(is_text(e) for e in node.elts)
        )

    lines = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            if any(names_fidelity(s) for s in sides) and any(is_text(s) for s in sides):
                lines.append(node.lineno)
    return lines


def test_the_branch_finder_finds_branches():
    found = fidelity_branches(
        "if scene.fidelity == 'dem':\n    pass\nx = fidelity in ('a', 'b')\ny = f.name == 'dem'\n"
    )
    assert found == [1, 3]


@pytest.mark.parametrize("path", LOOPING_LAYERS)
def test_no_layer_branches_on_a_fidelity_name(path):
    assert fidelity_branches((ROOT / path).read_text()) == []


def test_every_fidelity_has_scene_rules_and_a_contract():
    assert list(FIDELITIES) == list(FIDELITY_RULES)
    assert all(name == fidelity.name for name, fidelity in FIDELITIES.items())


@pytest.mark.parametrize("scene_file", scene_files(), ids=lambda p: p.stem)
def test_each_fmu_class_takes_its_facade_and_parameters_from_its_fidelity(scene_file):
    with open(scene_file, "rb") as fh:
        doc = tomllib.load(fh)
    scene = Scene.from_dict(doc["scene"])
    slave = getattr(slaves, doc["fmu"]["slave"])
    assert slave.fidelity is FIDELITIES[scene.fidelity]
    assert slave.parameters is slave.fidelity.parameters
    assert slave.scene.fidelity == scene.fidelity


def test_a_choice_the_fidelity_does_not_take_is_left_out():
    """The build's configured FMUs pass a race control to every fidelity's facade; only the quasi-static one takes it
    (the others would refuse an unknown keyword)."""
    analytic = make_model(Scene(), {"bearing": "6208", "race_control": "inner"})
    assert analytic.bearing.name == "6208"
    quasi_static = make_model(Scene(name="qs", fidelity="quasi_static"), {"race_control": "inner"})
    assert quasi_static.race_control == "inner"


def test_a_fidelitys_rules_refuse_what_it_cannot_do():
    with pytest.raises(SceneError, match="torque = true needs fidelity = 'quasi_static'"):
        Scene(fidelity="analytic", torque=True).validate()
    with pytest.raises(SceneError, match="drive = 'fixed_axial' is not a DEM drive: allowed 'load' or 'displacement'"):
        Scene(name="d", fidelity="dem", drive="fixed_axial").validate()
    with pytest.raises(SceneError, match="lubrication = 'oil_bath' is not in the DEM yet"):
        Scene(name="d", fidelity="dem", lubrication="oil_bath").validate()
    Scene(name="q", fidelity="quasi_static", torque=True, drive="displacement", lubrication="oil_bath").validate()


def test_an_option_refused_everywhere_is_reported_once():
    with pytest.raises(SceneError) as refused:
        Scene(name="d", fidelity="dem", lubrication="mist").validate()
    assert str(refused.value).count("lubrication") == 1
