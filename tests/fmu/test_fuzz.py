"""Fuzz of every input and parameter of every FMU (tests/fmu/fuzz.py drives the FMU in a fresh process).

Per variable, values derived from the declared range in modelDescription.xml: NaN, +-inf, just below and
just above the range, +-1e30, 1e-300, -300; per String parameter: empty, unknown, a printf format, a name
too long for a file, near-misses of an allowed value. Required of every case:

- the host survives (the fuzz process exits 0);
- no value outside the declared range (or NaN) is accepted: an input is refused by fmi2DoStep
  (fmi2Discard or fmi2Error), a parameter by fmi2ExitInitializationMode (fmi2Error);
- no silent NaN: whenever a step is accepted every output is finite;
- a refusal logs an error naming the variable, its value and what is allowed;
- a refused input, set in initialisation mode or during the run, recovers: with the input back at its
  start value the step is accepted (the thermal FMUs as the bearing FMUs).

test_fuzz_fast (CI) takes NaN and just-above-range for each Real and two Strings; test_fuzz_full (slow,
tests/_markers.py) every case. test_fuzz_inside (slow) takes values inside the declared ranges (its docstring).
"""

import json
import re
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest

from spindle.all_fmus import all_variables

FUZZ = Path(__file__).with_name("fuzz.py")
TIMEOUT = {"fast": 900, "full": 900, "inside": 7200}  # s per FMU: the inside cases step the models
FIXTURES = {
    "BearingAnalytic": "analytic_fmu",
    "Bearing": "bearing_fmu",
    "BearingDisp": "bearing_disp_fmu",
    "BearingFixed": "bearing_fixed_fmu",
    "BearingDEM": "dem_fmu",
    "BearingDEMDisp": "dem_disp_fmu",
    "SpindleThermal": "spindle_thermal_fmu",
    "SpindleThermalFixed": "spindle_thermal_fixed_fmu",
    "SpindleShaft": "spindle_shaft_fmu",
    "SpindleShaftTransient": "spindle_shaft_transient_fmu",
}
FUZZED = [
    (name, v.name)
    for name, _, _, parameters, inputs, *_ in all_variables()
    for v in (*parameters, *inputs)
    if v.kind in ("real", "string")  # a Boolean's only wrong values are C ints, refused by the FMI layer itself
]


INSIDE = [
    (name, v.name)
    for name, _, _, parameters, *_ in all_variables()
    for v in parameters
    if v.kind in ("real", "integer")
]
PARAMETERS = {name: tuple(v.name for v in parameters) for name, _, _, parameters, *_ in all_variables()}
# a lubricant law's constant is 0 when its law is not chosen (its start value in an FMU that starts with another law):
# its 0 is accepted with another law, refused with its own
UNUSED_ZERO = {
    v.name for _, _, _, parameters, *_ in all_variables() for v in parameters if "law is not chosen" in v.description
}


@pytest.fixture(scope="session")
def dem_fmu():
    from tests.conftest import _fmu

    return _fmu("BearingDEM", "dem.toml")


@cache
def fuzz(path, which):
    """The case reports of one FMU (one fresh process), by variable name; fails if the host died."""
    proc = subprocess.run(
        [sys.executable, str(FUZZ), str(path), which], capture_output=True, text=True, timeout=TIMEOUT[which]
    )
    lines = [json.loads(line) for line in proc.stdout.splitlines() if line.startswith("{")]
    running = lines[-1] if lines and lines[-1].get("running") else None
    assert proc.returncode == 0, (proc.returncode, running, proc.stderr[-3000:])
    by_variable = {}
    for line in lines:
        if not line.get("running"):
            by_variable.setdefault(line["variable"], []).append(line)
    return by_variable


def problems(case):
    """What is wrong with one case report (an empty list if nothing)."""
    out = []
    real = case["min"] is not None
    if case["causality"] == "input":
        refusals = [case["step"] != 0, case["run_step"] != 0]
        accepted = not all(refusals)
        if not refusals[0] and not case["finite"] or not refusals[1] and not case["run_finite"]:
            out.append("silent NaN: a step accepted with a non-finite output")
        if refusals[0] and not case["recovered"]:
            out.append("no recovery after the value was refused at initialisation")
        if refusals[1] and not case["run_recovered"]:
            out.append("no recovery after the value was refused during the run")
    else:
        accepted = case["exit_init"] == 0
        refusals = [not accepted]
        if accepted and case["step"] == 0 and not case["finite"]:
            out.append("silent NaN: a step accepted with a non-finite output")
    if accepted and real and not (case["min"] <= float(case["value"]) <= case["max"]):
        out.append(f"accepted outside the declared range [{case['min']}, {case['max']}]")
    if any(refusals):
        value = case["value"]
        # a message shows a float as Python prints it (repr) or to 6 digits; the FMI logger gets '%' as '%%'
        shown = (value, f"{float(value):.6g}") if real else (value.replace("%", "%%"),)
        allowed = ("allowed", "catalogue name (")  # a name or path: the refusal lists the catalogue
        if not any(
            case["variable"] in e and any(s in e for s in shown) and any(a in e.lower() for a in allowed)
            for e in case["errors"]
        ):
            out.append(f"no error naming variable, value and allowed range: {case['errors']}")
    return out


def names(text, variable):
    """True if `text` names the FMU variable `variable` (not as part of a longer name such as bearing_data.Pd)."""
    return re.search(rf"(?<![\w.]){re.escape(variable)}(?![\w.\[])", text) is not None


def names_value(case):
    """True if an error of the case names its variable and its value, followed by a reason."""
    value = case["value"]
    shown = {value, f"{float(value):.6g}", f"{float(value):g}"}
    return any(
        names(e, case["variable"]) and any(f"{case['variable']} = {s}" in e for s in shown) for e in case["errors"]
    )


def inside_problems(fmu_name, case):
    """What is wrong with one value inside the declared range (an empty list if nothing)."""
    refused = case["exit_init"] > 1 or case["steps"][0] > 1  # at initialisation or the first step (fmi2Warning: runs)
    if refused:  # say why
        if not names_value(case):
            return [f"refused without naming {case['variable']} and its value: {case['errors']}"]
        others = [n for n in PARAMETERS[fmu_name] if n != case["variable"] and any(names(e, n) for e in case["errors"])]
        unused = case["variable"] in UNUSED_ZERO and float(case["value"]) == 0.0
        if case["label"] in ("min", "max") and not others and not unused:
            return [f"the declared {case['label']} is refused whatever the other parameters: {case['errors']}"]
        return []
    out = [f"absurd output: {text}" for text in case["absurd"][:3]]
    if not case["finite"]:
        out.append("silent NaN: a step accepted with a non-finite output")
    if any(status > 1 for status in case["steps"]):  # refused at the operating point: an input or the parameter
        inputs = ("omega", "F_", "x =", "y =", "z =", "Q_", "K_axial")
        if not (names_value(case) or any(e.split(": ", 1)[-1].startswith(inputs) for e in case["errors"])):
            out.append(f"a step refused without naming {case['variable']} or an input: {case['errors']}")
    return out


def check(request, fmu_name, variable, which):
    path = request.getfixturevalue(FIXTURES[fmu_name])
    cases = fuzz(path, which)[variable]
    assert cases, f"{fmu_name}.{variable}: no case ran"
    wrong = {case["label"]: problems(case) for case in cases}
    assert not any(wrong.values()), {label: p for label, p in wrong.items() if p}


@pytest.mark.parametrize("fmu_name,variable", FUZZED, ids=[f"{f}.{v}" for f, v in FUZZED])
def test_fuzz_fast(request, fmu_name, variable):
    """NaN and a value just above the declared range for each Real input and parameter, two bad values for each
    String, of every FMU: refused with the variable's name, value and range, the host survives, no silent NaN, and
    the FMU recovers with the value back at its start (module docstring)."""
    check(request, fmu_name, variable, "fast")


@pytest.mark.parametrize("fmu_name,variable", FUZZED, ids=[f"{f}.{v}" for f, v in FUZZED])
def test_fuzz_full(request, fmu_name, variable):
    check(request, fmu_name, variable, "full")


@pytest.mark.parametrize("fmu_name,variable", INSIDE, ids=[f"{f}.{v}" for f, v in INSIDE])
def test_fuzz_inside(request, fmu_name, variable):
    """Every Real and Integer parameter of every FMU at values inside its declared range (both ends, just inside
    each, interior points; tests/fmu/fuzz.py inside_values), one at a time from the FMU's start values with the
    switch that puts it in effect, then a few steps at an operating point (a speed and a load). Each value either
    runs (every output finite, no absurd output: a negative film, contact load, pressure or loss, a thermal growth
    beyond the part) or is refused at initialisation or the first step by a message naming the FMU variable, its
    value and why; a declared end is not refused whatever the other parameters are (the declared range is the
    accepted range); a step refused later names the parameter or the input the bearing cannot take."""
    path = request.getfixturevalue(FIXTURES[fmu_name])
    cases = fuzz(path, "inside")[variable]
    assert cases, f"{fmu_name}.{variable}: no case ran"
    wrong = {f"{case['label']} = {case['value']}": inside_problems(fmu_name, case) for case in cases}
    assert not any(wrong.values()), {label: p for label, p in wrong.items() if p}


def test_every_input_and_real_parameter_declares_its_range():
    """The declarations give every Real input and parameter a range holding its start value, and the reason."""
    missing = [
        (name, v.name)
        for name, _, _, parameters, inputs, *_ in all_variables()
        for v in (*parameters, *inputs)
        if v.kind == "real" and not (v.min is not None and v.min <= v.start_in(None) <= v.max and v.limits)
    ]
    assert not missing


@pytest.mark.parametrize(
    "fixture,name,value,message",
    [
        ("analytic_fmu", "bearing", "62O8", "unknown bearing '62O8'"),
        ("bearing_fmu", "race_control", "", "race_control = '' is not allowed"),
        ("spindle_thermal_fmu", "T_initial", "-300", "T_initial = -300.0 K is outside the allowed range [0, 1000] K"),
    ],
)
def test_fmpy_simulate_command_exits_non_zero_with_the_fmu_message(request, fixture, name, value, message):
    """`fmpy simulate` (fmpy's command line, no debug logging) with a refused parameter."""
    path = request.getfixturevalue(fixture)
    fmpy = Path(sys.executable).with_name("fmpy")
    command = [str(fmpy), "simulate", str(path), "--start-values", name, value, "--stop-time", "2"]
    proc = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert proc.returncode != 0
    assert message in proc.stdout + proc.stderr, (proc.stdout, proc.stderr[-2000:])
    assert "fmi2ExitInitializationMode failed with status 3 (error)" in proc.stderr


@pytest.mark.parametrize("arguments", all_variables(), ids=lambda a: a[0])
def test_model_description_declares_the_checked_ranges(request, arguments):
    """min/max in modelDescription.xml are the declarations' numbers, the ones the models check against."""
    from fmpy import read_model_description

    name, _, _, parameters, inputs, *_ = arguments
    md = read_model_description(str(request.getfixturevalue(FIXTURES[name])))
    xml = {v.name: v for v in md.modelVariables if v.causality in ("input", "parameter")}
    for var in (*parameters, *inputs):
        declared = (var.min, var.max) if var.kind in ("real", "integer") else (None, None)
        written = tuple(None if x is None else float(x) for x in (xml[var.name].min, xml[var.name].max))
        assert written == declared, var.name
