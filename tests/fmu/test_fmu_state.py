"""fmi2DeSerializeFMUstate of the built FMUs accepts only a state this FMU and version saved
(docs/fmu_runtime.md, "FMU state"); the round trips themselves are in each FMU's own tests.

- a state of BearingAnalytic.fmu given to Bearing.fmu, or one whose header names another version, is refused
  with fmi2Error and a message naming both FMUs or both versions;
- truncated bytes and a pickle are refused the same way, and the pickle's code is not run;
- the instance then restores a good state and steps on.
"""

import pickle
import shutil
from contextlib import contextmanager

import pytest
from fmpy import extract, fmi2, read_model_description
from fmpy.fmi1 import FMICallException

from bearing_fmu import __version__
from bearing_fmu_common.runtime import fmi2_layer as layer
from tests.fmu.harness import PickleMarker

FMI2_ERROR = 3


@contextmanager
def logged(fmu_path, name):
    """An initialised instance of fmu_path whose log messages are collected: (fmu, value references, messages);
    freed on exit."""
    md = read_model_description(str(fmu_path))
    messages = []
    callbacks = fmi2.fmi2CallbackFunctions()
    callbacks.logger = fmi2.fmi2CallbackLoggerTYPE(lambda c, i, status, cat, text: messages.append(text.decode()))
    callbacks.allocateMemory = fmi2.fmi2CallbackAllocateMemoryTYPE(fmi2.calloc)
    callbacks.freeMemory = fmi2.fmi2CallbackFreeMemoryTYPE(fmi2.free)
    unzip = extract(str(fmu_path))
    fmu = fmi2.FMU2Slave(
        guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name
    )
    try:
        fmu.instantiate(callbacks=callbacks)
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        yield fmu, {v.name: v.valueReference for v in md.modelVariables}, messages
    finally:  # no fmi2Terminate: a refused state leaves the instance in the error state, which allows only freeing
        fmu.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)


def refusal(fmu, messages, data):
    """The message of the fmi2Error that deserialising `data` returns."""
    del messages[:]
    with pytest.raises(FMICallException) as error:
        fmu.deSerializeFMUstate(data)
    assert error.value.status == FMI2_ERROR
    assert len(messages) == 1, messages
    return messages[0]


def saved_state(analytic_fmu):
    with logged(analytic_fmu, "saver") as (fmu, vr, _):
        fmu.setReal([vr["omega"], vr["F_y"]], [500.0, 3000.0])
        fmu.doStep(0.0, 1.0)
        state = fmu.getFMUstate()
        data = fmu.serializeFMUstate(state)
        fmu.freeFMUstate(state)
    return data


def test_a_state_of_another_fmu_is_refused_naming_both(analytic_fmu, bearing_fmu):
    data = saved_state(analytic_fmu)
    with logged(bearing_fmu, "other") as (fmu, _, messages):
        why = refusal(fmu, messages, data)
    assert f"saved by BearingAnalytic version {__version__}" in why
    assert f"this FMU is Bearing version {__version__}" in why


def test_refused_states_other_version_truncated_pickle_then_a_good_one(analytic_fmu, tmp_path):
    data = saved_state(analytic_fmu)
    header, _ = layer._header(data)
    identity = {key: header[key] for key in ("model", "version", "variables")}
    older = layer.pack(layer.unpack(data), {**identity, "version": "0.0.9"})
    marker = tmp_path / "pickle-ran"
    with logged(analytic_fmu, "restorer") as (fmu, vr, messages):
        why = refusal(fmu, messages, older)
        assert "restorer: fmi2DeSerializeFMUstate: the state was saved by BearingAnalytic version 0.0.9" in why
        assert f"this FMU is BearingAnalytic version {__version__}" in why
        assert "SHA-256 checksum" in refusal(fmu, messages, data[:-10])
        why = refusal(fmu, messages, pickle.dumps((4, 0.0, {"omega": PickleMarker(marker)})))
        assert "not a serialised FMU state of this product" in why
        assert not marker.exists()
        state = fmu.deSerializeFMUstate(data)  # the instance is in the error state: a good state restores it
        fmu.setFMUstate(state)
        fmu.freeFMUstate(state)
        fmu.setReal([vr["omega"], vr["F_y"]], [600.0, 2000.0])
        fmu.doStep(1.0, 1.0)
        assert fmu.getReal([vr["Lambda_outer"]])[0] > 0.0
