/* A minimal native FMI 2.0 co-simulation importer (what a C/C++ master does), used by
 * tests/fmu/test_native_runtime.py. It dlopens the FMU binary with nothing preloaded, runs
 * RUNS times: instantiate, set the given variables in initialisation mode, N steps of size H,
 * a serialised state round trip (the step after restoring must repeat the first step's outputs
 * bit for bit), read the outputs, free. It prints the outputs of the last run as "VR=value"
 * lines and the FMU's messages on stderr, formatted as printf formats (FMI 2.0 logger).
 *
 * usage: native_importer LIBRARY RESOURCE_URI GUID RUNS N H [r:VR=REAL] [s:VR=TEXT] [b:VR=0|1] [o:VR] ...
 * exit: 0 all calls OK, 2 usage or loading problem, 3 an FMI call failed, 4 state round trip differs
 */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define MAX_VARS 64

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    (void)env;
    va_list args;
    va_start(args, message);
    fprintf(stderr, "[%d] %s (%s): ", (int)status, name, category);
    vfprintf(stderr, message, args);
    fputc('\n', stderr);
    va_end(args);
}

#define LOAD(name)                                                                                 \
    name##TYPE *name = (name##TYPE *)dlsym(lib, #name);                                            \
    if (name == NULL) {                                                                            \
        fprintf(stderr, "missing %s\n", #name);                                                    \
        return 2;                                                                                  \
    }

#define CHECK(call)                                                                                \
    do {                                                                                           \
        fmi2Status s__ = (call);                                                                   \
        if (s__ != fmi2OK) {                                                                       \
            fprintf(stderr, "%s returned status %d\n", #call, (int)s__);                           \
            return 3;                                                                              \
        }                                                                                          \
    } while (0)

int main(int argc, char **argv)
{
    if (argc < 7) {
        fprintf(stderr, "usage: %s LIBRARY RESOURCE_URI GUID RUNS N H [r:VR=REAL|s:VR=TEXT|b:VR=0|1|o:VR] ...\n",
                argv[0]);
        return 2;
    }
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (lib == NULL) {
        fprintf(stderr, "dlopen: %s\n", dlerror());
        return 2;
    }
    LOAD(fmi2Instantiate);
    LOAD(fmi2SetupExperiment);
    LOAD(fmi2EnterInitializationMode);
    LOAD(fmi2ExitInitializationMode);
    LOAD(fmi2SetReal);
    LOAD(fmi2SetString);
    LOAD(fmi2SetBoolean);
    LOAD(fmi2GetReal);
    LOAD(fmi2DoStep);
    LOAD(fmi2GetFMUstate);
    LOAD(fmi2SetFMUstate);
    LOAD(fmi2FreeFMUstate);
    LOAD(fmi2SerializedFMUstateSize);
    LOAD(fmi2SerializeFMUstate);
    LOAD(fmi2DeSerializeFMUstate);
    LOAD(fmi2Terminate);
    LOAD(fmi2FreeInstance);

    int runs = atoi(argv[4]), steps = atoi(argv[5]);
    double h = atof(argv[6]);
    fmi2ValueReference out_vr[MAX_VARS];
    fmi2Real out[MAX_VARS], first[MAX_VARS], again[MAX_VARS];
    size_t n_out = 0;
    for (int i = 7; i < argc; i++)
        if (strncmp(argv[i], "o:", 2) == 0 && n_out < MAX_VARS)
            out_vr[n_out++] = (fmi2ValueReference)strtoul(argv[i] + 2, NULL, 10);

    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    for (int run = 0; run < runs; run++) {
        fmi2Component c = fmi2Instantiate("native", fmi2CoSimulation, argv[3], argv[2], &callbacks, fmi2False,
                                          fmi2False);
        if (c == NULL) {
            fprintf(stderr, "fmi2Instantiate failed\n");
            return 3;
        }
        CHECK(fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
        CHECK(fmi2EnterInitializationMode(c));
        for (int i = 7; i < argc; i++) {
            char kind = argv[i][0], *eq = strchr(argv[i], '=');
            if (eq == NULL)
                continue;
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(argv[i] + 2, NULL, 10);
            if (kind == 'r') {
                fmi2Real value = strtod(eq + 1, NULL);
                CHECK(fmi2SetReal(c, &vr, 1, &value));
            } else if (kind == 's') {
                fmi2String value = eq + 1;
                CHECK(fmi2SetString(c, &vr, 1, &value));
            } else if (kind == 'b') {
                fmi2Boolean value = atoi(eq + 1) != 0;
                CHECK(fmi2SetBoolean(c, &vr, 1, &value));
            }
        }
        CHECK(fmi2ExitInitializationMode(c));

        /* state round trip through bytes: the first step, repeated after restoring, is bit-exact */
        fmi2FMUstate saved = NULL, restored = NULL;
        size_t size = 0;
        CHECK(fmi2GetFMUstate(c, &saved));
        CHECK(fmi2DoStep(c, 0.0, h, fmi2True));
        CHECK(fmi2GetReal(c, out_vr, n_out, first));
        CHECK(fmi2SerializedFMUstateSize(c, saved, &size));
        fmi2Byte *bytes = malloc(size);
        CHECK(fmi2SerializeFMUstate(c, saved, bytes, size));
        CHECK(fmi2DeSerializeFMUstate(c, bytes, size, &restored));
        free(bytes);
        CHECK(fmi2SetFMUstate(c, restored));
        CHECK(fmi2DoStep(c, 0.0, h, fmi2False));
        CHECK(fmi2GetReal(c, out_vr, n_out, again));
        if (n_out > 0 && memcmp(first, again, n_out * sizeof first[0]) != 0) {
            fprintf(stderr, "outputs after restoring a deserialised state differ\n");
            return 4;
        }
        CHECK(fmi2FreeFMUstate(c, &saved));
        CHECK(fmi2FreeFMUstate(c, &restored));

        for (int n = 1; n < steps; n++)
            CHECK(fmi2DoStep(c, n * h, h, fmi2True));
        CHECK(fmi2GetReal(c, out_vr, n_out, out));
        CHECK(fmi2Terminate(c));
        fmi2FreeInstance(c);
    }
    for (size_t i = 0; i < n_out; i++)
        printf("%u=%.17g\n", (unsigned)out_vr[i], out[i]);
    return 0;
}
