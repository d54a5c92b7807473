/* The functions of the FMI 2.0 co-simulation interface (fmi2Functions.h) that an FMU exports and a host looks
 * up, as an X-macro: FMI2_FUNCTIONS(X) expands X(name) for each. The FMU's binary (fmi2_loader.c) looks each up
 * in its Python layer and passes every call on; a C host (tests/fmu/native_importer.c) looks each up in the FMU.
 * fmi2GetTypesPlatform and fmi2GetVersion, which answer without an instance, are not in the list.
 *
 * SPDX-License-Identifier: MIT.
 */
#ifndef BEARING_FMU_FMI2_FUNCTION_LIST_H
#define BEARING_FMU_FMI2_FUNCTION_LIST_H

#include "fmi2Functions.h"

#define FMI2_FUNCTIONS(X)                                                                          \
    X(fmi2Instantiate) X(fmi2FreeInstance) X(fmi2SetupExperiment) X(fmi2EnterInitializationMode)   \
    X(fmi2ExitInitializationMode) X(fmi2Terminate) X(fmi2Reset) X(fmi2SetDebugLogging)             \
    X(fmi2GetReal) X(fmi2GetInteger) X(fmi2GetBoolean) X(fmi2GetString) X(fmi2SetReal)             \
    X(fmi2SetInteger) X(fmi2SetBoolean) X(fmi2SetString) X(fmi2GetFMUstate) X(fmi2SetFMUstate)     \
    X(fmi2FreeFMUstate) X(fmi2SerializedFMUstateSize) X(fmi2SerializeFMUstate)                     \
    X(fmi2DeSerializeFMUstate) X(fmi2GetDirectionalDerivative) X(fmi2SetRealInputDerivatives)      \
    X(fmi2GetRealOutputDerivatives) X(fmi2DoStep) X(fmi2CancelStep) X(fmi2GetStatus)               \
    X(fmi2GetRealStatus) X(fmi2GetIntegerStatus) X(fmi2GetBooleanStatus) X(fmi2GetStringStatus)

/* A struct field holding a pointer to function `name` (FMI2_FUNCTIONS(FMI2_POINTER): the whole table). */
#define FMI2_POINTER(name) name##TYPE *name;

#endif
