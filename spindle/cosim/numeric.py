"""The numeric parameters that carry a bearing FMU's String choices (docs/parameters.md, "Numeric parameters"),
for the SSP export (spindle.cosim.ssp), which writes them so that a master importing no String values
(OMSimulator) runs the same bearing, lubricant, race control and lubrication method.

`numeric_parameters()` computes them in a child process (`python -m spindle.cosim.numeric`): the exporting
process runs the FMUs, and importing `bearing_fmu` there would make a bearing FMU run on the source tree's
package instead of the one it carries (docs/fmu_runtime.md, "The master"). The values are those the FMU's own
readers give: `bearing_fmu.models.file_parameters`, which a configured FMU also uses for its start values.
"""

import json
import subprocess
import sys

# String parameter -> the parameter that says whether it is in effect (the switch, or the Integer that wins)
SWITCHES = {
    "bearing": "bearing_from_file",
    "lubricant": "lubricant_from_file",
    "race_control": "race_control_mode",
    "lubrication": "lubrication_mode",
}


def _values(choices):
    """name -> value of the numeric parameters standing for `choices` (String parameter -> value)."""
    from bearing_fmu.models.file_parameters import bearing_values, lubricant_values
    from bearing_fmu.scene import LUBRICATION_METHODS, RACE_CONTROLS

    out = {}
    if "bearing" in choices:
        out.update({"bearing_from_file": False, **bearing_values(choices["bearing"])})
    if "lubricant" in choices:
        out.update({"lubricant_from_file": False, **lubricant_values(choices["lubricant"])})
    if "race_control" in choices:
        out["race_control_mode"] = RACE_CONTROLS.index(choices["race_control"])
    if "lubrication" in choices:
        out["lubrication_mode"] = LUBRICATION_METHODS.index(choices["lubrication"])
    return out


def numeric_parameters(choices):
    """The numeric parameters (name -> value: the switches false, bearing_data.*, lubricant_data.*,
    race_control_mode, lubrication_mode) of `choices` (String parameter of SWITCHES -> its value: a catalogue
    name or a file), computed in a child process. Raises ValueError with the child's message if a choice
    cannot be read."""
    if not choices:
        return {}
    proc = subprocess.run(
        [sys.executable, "-m", __name__, json.dumps(choices)], capture_output=True, text=True, check=False, timeout=300
    )
    if proc.returncode != 0:
        raise ValueError(f"numeric parameters of {choices}: {proc.stderr.strip().splitlines()[-1:]}")
    return json.loads(proc.stdout)


if __name__ == "__main__":
    print(json.dumps(_values(json.loads(sys.argv[1]))))  # floats as repr: exact on the way back
