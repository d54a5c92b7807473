"""An FMU runs only the code it carries (bearing_fmu_common/runtime/fmi2_layer.py, foreign_code;
docs/fmu_runtime.md, "Its own code"): with its packages or its entry module already imported from elsewhere with
other contents, fmi2Instantiate is refused naming both places; the same code imported from elsewhere (the
host's checkout of this release, another extraction of the FMU) is accepted. Here on directories made for the
purpose; tests/fmu/test_own_code.py does it with a built FMU in a host that imported another bearing_fmu."""

import shutil
import sys
import types

import pytest

from bearing_fmu_common.runtime import fmi2_layer as layer

PACKAGE = "bfmu_own_code_probe"  # a name no other module has
ENTRY = "bfmu_own_code_entry"


def tree(root, files):
    """root (resolved: messages name real paths) with the files {relative path: text}."""
    root = root.resolve()
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


FILES = {
    f"{PACKAGE}/__init__.py": '__version__ = "1.0"\n',
    f"{PACKAGE}/model.py": "def f():\n    return 1\n",
    f"{PACKAGE}/params/brg.toml": "D = 0.012\n",
}


@pytest.fixture
def fmu(tmp_path):
    """resources/ of an FMU carrying PACKAGE, with its entry module and list of own packages."""
    files = {**FILES, f"{ENTRY}.py": "# entry\n", layer.OWN_PACKAGES: f"{PACKAGE}\n", "slavemodule.txt": f"{ENTRY}\n"}
    files[f"{PACKAGE}/__pycache__/model.cpython-311.pyc"] = "compiled"  # caches are not compared
    return tree(tmp_path / "resources", files)


@pytest.fixture(autouse=True)
def fresh_records(monkeypatch):
    """No record of what other tests imported (the records live in a module shared by every copy of the layer)."""
    monkeypatch.setattr(layer, "_imported", {})
    monkeypatch.setattr(layer, "_entries", {})


def imported(monkeypatch, name, file):
    module = types.ModuleType(name)
    module.__file__ = str(file)
    monkeypatch.setitem(sys.modules, name, module)


def test_nothing_imported_yet_is_its_own_code(fmu):
    assert layer.foreign_code(str(fmu), ENTRY) is None


def test_the_same_code_imported_from_elsewhere_is_accepted(fmu, tmp_path, monkeypatch):
    other = tree(tmp_path / "checkout", {**FILES, f"{PACKAGE}/more.py": "x = 1\n"})  # more files: not the FMU's
    imported(monkeypatch, PACKAGE, other / PACKAGE / "__init__.py")
    assert layer.foreign_code(str(fmu), ENTRY) is None


@pytest.mark.parametrize(
    "change, differs",
    [
        ({f"{PACKAGE}/__init__.py": '__version__ = "2.0"\n'}, "__init__.py"),
        ({f"{PACKAGE}/params/brg.toml": "D = 0.013\n"}, "brg.toml"),
    ],
    ids=["version marker", "data file"],
)
def test_other_code_under_the_same_name_is_refused_naming_both_places(fmu, tmp_path, monkeypatch, change, differs):
    other = tree(tmp_path / "elsewhere", {**FILES, **change})
    imported(monkeypatch, PACKAGE, other / PACKAGE / "__init__.py")
    why = layer.foreign_code(str(fmu), ENTRY)
    assert f"package {PACKAGE} from {other / PACKAGE} (1 of its files differ" in why
    assert f"this FMU's {fmu / PACKAGE}" in why and differs in why


def test_a_missing_source_is_a_difference_a_missing_data_file_is_not(fmu, tmp_path, monkeypatch):
    """A package run from a checkout may read a data file from elsewhere (the thermal model reads the bearing
    catalogue from bearing_fmu/params), never a module."""
    without_data = tree(tmp_path / "a", {k: v for k, v in FILES.items() if not k.endswith(".toml")})
    imported(monkeypatch, PACKAGE, without_data / PACKAGE / "__init__.py")
    assert layer.foreign_code(str(fmu), ENTRY) is None
    without_module = tree(tmp_path / "b", {k: v for k, v in FILES.items() if not k.endswith("model.py")})
    imported(monkeypatch, PACKAGE, without_module / PACKAGE / "__init__.py")
    assert "e.g. model.py" in layer.foreign_code(str(fmu), ENTRY)


def test_another_entry_module_of_the_same_name_is_refused(fmu, tmp_path, monkeypatch):
    same = tree(tmp_path / "extraction", {f"{ENTRY}.py": "# entry\n"})
    imported(monkeypatch, ENTRY, same / f"{ENTRY}.py")
    assert layer.foreign_code(str(fmu), ENTRY) is None  # another extraction of the same FMU
    other = tree(tmp_path / "release", {f"{ENTRY}.py": "# entry of another release\n"})
    imported(monkeypatch, ENTRY, other / f"{ENTRY}.py")
    why = layer.foreign_code(str(fmu), ENTRY)
    assert f"its module {ENTRY} from {other / ENTRY}.py (this FMU's is {fmu / ENTRY}.py)" in why


def test_refusal_is_logged_without_a_traceback(fmu, tmp_path, monkeypatch):
    other = tree(tmp_path / "elsewhere", {**FILES, f"{PACKAGE}/model.py": "def f():\n    return 2\n"})
    imported(monkeypatch, PACKAGE, other / PACKAGE / "__init__.py")
    with pytest.raises(layer.Refused) as refused:
        layer.slave_class(str(fmu))
    text = layer.describe(refused.type, refused.value, refused.tb)
    assert "Refused: this FMU runs only the code it carries" in text.splitlines()[0]
    assert "Traceback" not in text


def test_what_a_removed_extraction_imported_is_compared_by_its_record(fmu, tmp_path, monkeypatch):
    """A host may remove an FMU's extraction after running it (fmpy's simulate_fmu does): the next instance
    compares against what was recorded when the first imported it."""
    first = tree(tmp_path / "first", {**FILES, f"{ENTRY}.py": "# entry\n", layer.OWN_PACKAGES: f"{PACKAGE}\n"})
    imported(monkeypatch, ENTRY, first / f"{ENTRY}.py")
    imported(monkeypatch, PACKAGE, first / PACKAGE / "__init__.py")
    layer.remember_code(str(first), ENTRY)
    shutil.rmtree(first)
    assert layer.foreign_code(str(fmu), ENTRY) is None
    (fmu / PACKAGE / "model.py").write_text("def f():\n    return 3\n")  # now this FMU carries other code
    assert f"package {PACKAGE} from {first / PACKAGE} (1 of its files differ" in layer.foreign_code(str(fmu), ENTRY)
