/* A minimal native FMI 2.0 co-simulation importer (what a C/C++ master does), used by
 * tests/fmu/test_native_runtime.py. It dlopens the FMU binary with nothing preloaded. Three modes:
 *
 * native_importer LIBRARY RESOURCE_URI GUID RUNS N H [r:VR=REAL] [s:VR=TEXT] [b:VR=0|1] [o:VR] ...
 *     RUNS times: instantiate, set the given variables in initialisation mode, N steps of size H, a
 *     serialised state round trip (the step after restoring must repeat the first step's outputs bit for
 *     bit), read the outputs, free. Prints the outputs of the last run as "VR=value" lines.
 *     exit: 0 all calls OK, 2 usage or loading problem, 3 an FMI call failed, 4 state round trip differs
 * native_importer --calls LIBRARY RESOURCE_URI GUID CALL ...
 *     makes the calls in order on one instance and prints "CALL STATUS" per call (STATUS: the fmi2Status
 *     number; for instantiate "ok" or "null"), whatever they return: the caller judges the sequence.
 *     CALL: instantiate, guid:TEXT (the GUID of the next instantiate), setup, enter, exit, step (doStep
 *     of 0.1 s from the last accepted step's end), terminate, reset, getReal:VR, setReal:VR=REAL,
 *     getState, setState, cancel, free, null (every function with a NULL instance, one line each),
 *     nullargs (NULL array or state arguments, one line each; nullargs:LABEL only the one of that label, e.g.
 *     nullargs:fmi2SetReal(value)), empty (every getter and setter with
 *     nvr = 0 and NULL arrays, one line each), reals:VR,VR,... (likewise integers,
 *     booleans, strings: one get of those variables into an array filled with -7 (strings: "unset")
 *     before, printed as "CALL STATUS|value|value|..."), signals (how SIGINT and SIGPIPE are handled:
 *     "signals SIGINT=default,SIGPIPE=default"; "host" for the handler hostsigint installs for SIGINT).
 *     exit: 0 (2 usage or loading problem)
 * native_importer --threads LIB1 URI1 GUID1 LIB2 URI2 GUID2
 *     two threads, released together, each instantiate, initialise, step twice, terminate and free
 *     one of the two FMUs: what a host that sets up two FMUs at once does.
 *     exit: 0 all calls OK, 2 usage or loading problem, 3 an FMI call failed
 * native_importer --stack KB LIBRARY RESOURCE_URI GUID CALL ...
 *     the --calls mode on a thread whose stack is KB kB (below it a page that faults), filled with a pattern
 *     beforehand; then prints "stack-used BYTES", the depth of stack the calls used (where the pattern was
 *     overwritten). A stack too small for the calls crashes the process (SIGSEGV).
 *     exit: 0 (2 usage or loading problem)
 * native_importer --logger-lock LIBRARY RESOURCE_URI GUID VR
 *     a host whose logger takes a lock of its own: thread 1 holds that lock while it reads Real VR of one
 *     instance; thread 2 meanwhile makes a call the FMU refuses on a second instance, whose message goes
 *     to the logger, which waits for the lock. Prints "logger-lock S1 S2" (the two calls' statuses).
 *     exit: 0, 2 usage or loading problem, 3 an FMI call failed, 5 the threads did not finish within 60 s
 * native_importer --logger-lock-instantiate LIBRARY RESOURCE_URI GUID LOGGING
 *     the same logger; thread 1 holds its lock, thread 2 makes the process's first fmi2Instantiate (loggingOn
 *     = LOGGING), whose messages wait for the lock, and thread 1 then calls fmi2Instantiate too. Prints
 *     "logger-lock-instantiate waited|no-wait ok|null ok|null" (whether thread 2's logger was waiting when
 *     thread 1 called; what thread 2's and thread 1's fmi2Instantiate returned).
 *     exit: 0, 2 usage or loading problem, 5 the threads did not finish within 180 s
 *
 * The FMU's messages go to stderr, formatted as printf formats (FMI 2.0 logger).
 */
#define _GNU_SOURCE /* pthread_timedjoin_np */
#include <dlfcn.h>
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include "fmi2_function_list.h" /* bearing_fmu_common/runtime: the FMI 2.0 functions a host looks up */

#define MAX_VARS 64

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    (void)env;
    va_list args;
    va_start(args, message);
    flockfile(stderr); /* one message per line, also with two threads logging */
    fprintf(stderr, "[%d] %s (%s): ", (int)status, name, category);
    vfprintf(stderr, message, args);
    fputc('\n', stderr);
    funlockfile(stderr);
    va_end(args);
}

/* The FMU's functions (dlsym), one table per loaded library. */
typedef struct {
    FMI2_FUNCTIONS(FMI2_POINTER)
} Api;

static int load(const char *path, Api *api)
{
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (lib == NULL) {
        fprintf(stderr, "dlopen: %s\n", dlerror());
        return 0;
    }
#define LOOKUP(name)                                                                               \
    if ((api->name = (name##TYPE *)dlsym(lib, #name)) == NULL) {                                   \
        fprintf(stderr, "missing %s\n", #name);                                                    \
        return 0;                                                                                  \
    }
    FMI2_FUNCTIONS(LOOKUP)
    return 1;
}

static fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};

#define CHECK(call)                                                                                \
    do {                                                                                           \
        fmi2Status s__ = (call);                                                                   \
        if (s__ != fmi2OK) {                                                                       \
            fprintf(stderr, "%s returned status %d\n", #call, (int)s__);                           \
            return 3;                                                                              \
        }                                                                                          \
    } while (0)

/* -- default mode: runs of a whole simulation --------------------------------------------------- */

static int runs_mode(const Api *api, int argc, char **argv)
{
    if (argc < 7) {
        fprintf(stderr, "usage: %s LIBRARY RESOURCE_URI GUID RUNS N H [r:VR=REAL|s:VR=TEXT|b:VR=0|1|o:VR] ...\n",
                argv[0]);
        return 2;
    }
    int runs = atoi(argv[4]), steps = atoi(argv[5]);
    double h = atof(argv[6]);
    fmi2ValueReference out_vr[MAX_VARS];
    fmi2Real out[MAX_VARS], first[MAX_VARS], again[MAX_VARS];
    size_t n_out = 0;
    for (int i = 7; i < argc; i++)
        if (strncmp(argv[i], "o:", 2) == 0 && n_out < MAX_VARS)
            out_vr[n_out++] = (fmi2ValueReference)strtoul(argv[i] + 2, NULL, 10);

    for (int run = 0; run < runs; run++) {
        fmi2Component c = api->fmi2Instantiate("native", fmi2CoSimulation, argv[3], argv[2], &callbacks, fmi2False,
                                               fmi2False);
        if (c == NULL) {
            fprintf(stderr, "fmi2Instantiate failed\n");
            return 3;
        }
        CHECK(api->fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
        CHECK(api->fmi2EnterInitializationMode(c));
        for (int i = 7; i < argc; i++) {
            char kind = argv[i][0], *eq = strchr(argv[i], '=');
            if (eq == NULL)
                continue;
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(argv[i] + 2, NULL, 10);
            if (kind == 'r') {
                fmi2Real value = strtod(eq + 1, NULL);
                CHECK(api->fmi2SetReal(c, &vr, 1, &value));
            } else if (kind == 's') {
                fmi2String value = eq + 1;
                CHECK(api->fmi2SetString(c, &vr, 1, &value));
            } else if (kind == 'b') {
                fmi2Boolean value = atoi(eq + 1) != 0;
                CHECK(api->fmi2SetBoolean(c, &vr, 1, &value));
            }
        }
        CHECK(api->fmi2ExitInitializationMode(c));

        /* state round trip through bytes: the first step, repeated after restoring, is bit-exact */
        fmi2FMUstate saved = NULL, restored = NULL;
        size_t size = 0;
        CHECK(api->fmi2GetFMUstate(c, &saved));
        CHECK(api->fmi2DoStep(c, 0.0, h, fmi2True));
        CHECK(api->fmi2GetReal(c, out_vr, n_out, first));
        CHECK(api->fmi2SerializedFMUstateSize(c, saved, &size));
        fmi2Byte *bytes = malloc(size);
        CHECK(api->fmi2SerializeFMUstate(c, saved, bytes, size));
        CHECK(api->fmi2DeSerializeFMUstate(c, bytes, size, &restored));
        free(bytes);
        CHECK(api->fmi2SetFMUstate(c, restored));
        CHECK(api->fmi2DoStep(c, 0.0, h, fmi2False));
        CHECK(api->fmi2GetReal(c, out_vr, n_out, again));
        if (n_out > 0 && memcmp(first, again, n_out * sizeof first[0]) != 0) {
            fprintf(stderr, "outputs after restoring a deserialised state differ\n");
            return 4;
        }
        CHECK(api->fmi2FreeFMUstate(c, &saved));
        CHECK(api->fmi2FreeFMUstate(c, &restored));

        for (int n = 1; n < steps; n++)
            CHECK(api->fmi2DoStep(c, n * h, h, fmi2True));
        CHECK(api->fmi2GetReal(c, out_vr, n_out, out));
        CHECK(api->fmi2Terminate(c));
        api->fmi2FreeInstance(c);
    }
    for (size_t i = 0; i < n_out; i++)
        printf("%u=%.17g\n", (unsigned)out_vr[i], out[i]);
    return 0;
}

/* -- --calls: a call sequence, each status printed ---------------------------------------------- */

#define SHOW(label, call) printf("%s %d\n", label, (int)(call))

/* The getters and setters, each with the local variable (r, i, b, s) of its value type. */
#define ACCESSORS(X)                                                                               \
    X(fmi2GetReal, r) X(fmi2GetInteger, i) X(fmi2GetBoolean, b) X(fmi2GetString, s)                \
    X(fmi2SetReal, r) X(fmi2SetInteger, i) X(fmi2SetBoolean, b) X(fmi2SetString, s)

/* Every function that takes an instance, called with NULL. */
static void null_instance(const Api *api)
{
    fmi2ValueReference vr = 0;
    fmi2Real r = 0.0;
    fmi2Integer i = 0;
    fmi2Boolean b = fmi2False;
    fmi2String s = "";
    fmi2FMUstate state = NULL;
    size_t size = 0;
    fmi2Byte byte = 0;
    fmi2Status status = fmi2OK;
    api->fmi2FreeInstance(NULL); /* no status: it must simply return */
    SHOW("null:fmi2SetDebugLogging", api->fmi2SetDebugLogging(NULL, fmi2True, 0, NULL));
    SHOW("null:fmi2SetupExperiment", api->fmi2SetupExperiment(NULL, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    SHOW("null:fmi2EnterInitializationMode", api->fmi2EnterInitializationMode(NULL));
    SHOW("null:fmi2ExitInitializationMode", api->fmi2ExitInitializationMode(NULL));
    SHOW("null:fmi2Terminate", api->fmi2Terminate(NULL));
    SHOW("null:fmi2Reset", api->fmi2Reset(NULL));
#define NULL_INSTANCE(name, value) SHOW("null:" #name, api->name(NULL, &vr, 1, &value));
    ACCESSORS(NULL_INSTANCE)
    SHOW("null:fmi2GetFMUstate", api->fmi2GetFMUstate(NULL, &state));
    SHOW("null:fmi2SetFMUstate", api->fmi2SetFMUstate(NULL, state));
    SHOW("null:fmi2FreeFMUstate", api->fmi2FreeFMUstate(NULL, &state));
    SHOW("null:fmi2SerializedFMUstateSize", api->fmi2SerializedFMUstateSize(NULL, state, &size));
    SHOW("null:fmi2SerializeFMUstate", api->fmi2SerializeFMUstate(NULL, state, &byte, 1));
    SHOW("null:fmi2DeSerializeFMUstate", api->fmi2DeSerializeFMUstate(NULL, &byte, 1, &state));
    SHOW("null:fmi2GetDirectionalDerivative", api->fmi2GetDirectionalDerivative(NULL, &vr, 1, &vr, 1, &r, &r));
    SHOW("null:fmi2SetRealInputDerivatives", api->fmi2SetRealInputDerivatives(NULL, &vr, 1, &i, &r));
    SHOW("null:fmi2GetRealOutputDerivatives", api->fmi2GetRealOutputDerivatives(NULL, &vr, 1, &i, &r));
    SHOW("null:fmi2DoStep", api->fmi2DoStep(NULL, 0.0, 0.1, fmi2True));
    SHOW("null:fmi2CancelStep", api->fmi2CancelStep(NULL));
    SHOW("null:fmi2GetStatus", api->fmi2GetStatus(NULL, fmi2DoStepStatus, &status));
    SHOW("null:fmi2GetRealStatus", api->fmi2GetRealStatus(NULL, fmi2LastSuccessfulTime, &r));
    SHOW("null:fmi2GetIntegerStatus", api->fmi2GetIntegerStatus(NULL, fmi2DoStepStatus, &i));
    SHOW("null:fmi2GetBooleanStatus", api->fmi2GetBooleanStatus(NULL, fmi2Terminated, &b));
    SHOW("null:fmi2GetStringStatus", api->fmi2GetStringStatus(NULL, fmi2PendingStatus, &s));
}

/* NULL where the instance's functions expect an array or a state (nvr > 0); `only`: that one call (its label
 * without "nullargs:"), or every one if empty. */
#define SHOW_IF(label, call)                                                                       \
    if (only[0] == '\0' || strcmp(only, label) == 0)                                               \
    SHOW("nullargs:" label, call)

static void null_arguments(const Api *api, fmi2Component c, const char *only)
{
    fmi2ValueReference vr = 0;
    fmi2Real r = 0.0;
    fmi2Integer i = 0;
    fmi2Boolean b = fmi2False;
    fmi2String s = "";
#define NULL_ARRAYS(name, value)                                                                   \
    SHOW_IF(#name "(vr)", api->name(c, NULL, 1, &value));                                          \
    SHOW_IF(#name "(value)", api->name(c, &vr, 1, NULL));
    ACCESSORS(NULL_ARRAYS)
    SHOW_IF("fmi2GetFMUstate", api->fmi2GetFMUstate(c, NULL));
    SHOW_IF("fmi2SetFMUstate", api->fmi2SetFMUstate(c, NULL));
    SHOW_IF("fmi2SerializedFMUstateSize", api->fmi2SerializedFMUstateSize(c, NULL, NULL));
    SHOW_IF("fmi2GetRealStatus", api->fmi2GetRealStatus(c, fmi2LastSuccessfulTime, NULL));
}

/* nvr = 0 with NULL arrays (allowed: FMI 2.0), every getter and setter. */
static void empty_arrays(const Api *api, fmi2Component c)
{
#define EMPTY_ARRAYS(name, value) SHOW("empty:" #name, api->name(c, NULL, 0, NULL));
    ACCESSORS(EMPTY_ARRAYS)
}

static void host_handler(int number) { (void)number; }

/* How the process handles signal `number`: "default", "ignored", "host" (host_handler) or "handler". */
static const char *disposition(int number)
{
    struct sigaction action;
    if (sigaction(number, NULL, &action) != 0)
        return "unknown";
    if (!(action.sa_flags & SA_SIGINFO) && action.sa_handler == host_handler)
        return "host";
    if (!(action.sa_flags & SA_SIGINFO) && action.sa_handler == SIG_DFL)
        return "default";
    if (!(action.sa_flags & SA_SIGINFO) && action.sa_handler == SIG_IGN)
        return "ignored";
    return "handler";
}

/* reals:VR,VR,... and the like: one get into an array filled beforehand, printed whole with the status. */
__attribute__((noinline)) /* its arrays stay off the stack of the other calls */
static void get_many(const Api *api, fmi2Component c, const char *call, const char *list)
{
    fmi2ValueReference vr[MAX_VARS];
    size_t n = 0;
    for (const char *p = list; *p && n < MAX_VARS; p = strchr(p, ',') ? strchr(p, ',') + 1 : p + strlen(p))
        vr[n++] = (fmi2ValueReference)strtoul(p, NULL, 10);
    fmi2Real r[MAX_VARS];
    fmi2Integer i[MAX_VARS];
    fmi2Boolean b[MAX_VARS];
    fmi2String s[MAX_VARS];
    for (size_t k = 0; k < MAX_VARS; k++)
        r[k] = -7.0, i[k] = -7, b[k] = -7, s[k] = "unset";
    fmi2Status status = call[0] == 'r'   ? api->fmi2GetReal(c, vr, n, r)
                        : call[0] == 'i' ? api->fmi2GetInteger(c, vr, n, i)
                        : call[0] == 'b' ? api->fmi2GetBoolean(c, vr, n, b)
                                         : api->fmi2GetString(c, vr, n, s);
    printf("%s %d", call, (int)status);
    for (size_t k = 0; k < n; k++) {
        if (call[0] == 'r')
            printf("|%.17g", r[k]);
        else if (call[0] == 'i')
            printf("|%d", i[k]);
        else if (call[0] == 'b')
            printf("|%d", b[k]);
        else
            printf("|%s", s[k]);
    }
    printf("\n");
}

static int calls_mode(const Api *api, int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: %s --calls LIBRARY RESOURCE_URI GUID CALL ...\n", argv[0]);
        return 2;
    }
    const char *uri = argv[3], *guid = argv[4];
    fmi2Component c = NULL;
    fmi2FMUstate state = NULL;
    fmi2Real t = 0.0, h = 0.1;
    for (int k = 5; k < argc; k++) {
        const char *call = argv[k], *arg = strchr(call, ':');
        arg = arg ? arg + 1 : "";
        if (strcmp(call, "instantiate") == 0) {
            c = api->fmi2Instantiate("native", fmi2CoSimulation, guid, uri, &callbacks, fmi2False, fmi2False);
            printf("%s %s\n", call, c ? "ok" : "null");
        } else if (strncmp(call, "guid:", 5) == 0) {
            guid = arg;
        } else if (strcmp(call, "setup") == 0) {
            SHOW(call, api->fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
        } else if (strcmp(call, "enter") == 0) {
            SHOW(call, api->fmi2EnterInitializationMode(c));
        } else if (strcmp(call, "exit") == 0) {
            SHOW(call, api->fmi2ExitInitializationMode(c));
        } else if (strcmp(call, "step") == 0) {
            fmi2Status s = api->fmi2DoStep(c, t, h, fmi2True);
            if (s <= fmi2Warning)
                t += h;
            SHOW(call, s);
        } else if (strcmp(call, "terminate") == 0) {
            SHOW(call, api->fmi2Terminate(c));
        } else if (strcmp(call, "reset") == 0) {
            t = 0.0;
            SHOW(call, api->fmi2Reset(c));
        } else if (strncmp(call, "getReal:", 8) == 0) {
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(arg, NULL, 10);
            fmi2Real value = 0.0;
            SHOW(call, api->fmi2GetReal(c, &vr, 1, &value));
        } else if (strncmp(call, "setReal:", 8) == 0) {
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(arg, NULL, 10);
            const char *eq = strchr(arg, '=');
            fmi2Real value = eq ? strtod(eq + 1, NULL) : 0.0;
            SHOW(call, api->fmi2SetReal(c, &vr, 1, &value));
        } else if (strcmp(call, "getState") == 0) {
            SHOW(call, api->fmi2GetFMUstate(c, &state));
        } else if (strcmp(call, "setState") == 0) {
            SHOW(call, api->fmi2SetFMUstate(c, state));
        } else if (strcmp(call, "cancel") == 0) {
            SHOW(call, api->fmi2CancelStep(c));
        } else if (strcmp(call, "free") == 0) {
            if (state != NULL)
                api->fmi2FreeFMUstate(c, &state);
            api->fmi2FreeInstance(c);
            c = NULL;
            printf("%s done\n", call);
        } else if (strncmp(call, "reals:", 6) == 0 || strncmp(call, "integers:", 9) == 0 ||
                   strncmp(call, "booleans:", 9) == 0 || strncmp(call, "strings:", 8) == 0) {
            get_many(api, c, call, arg);
        } else if (strcmp(call, "hostsigint") == 0) {
            struct sigaction action = {.sa_handler = host_handler};
            sigemptyset(&action.sa_mask);
            SHOW(call, sigaction(SIGINT, &action, NULL));
        } else if (strcmp(call, "signals") == 0) {
            printf("%s SIGINT=%s,SIGPIPE=%s\n", call, disposition(SIGINT), disposition(SIGPIPE));
        } else if (strcmp(call, "null") == 0) {
            null_instance(api);
        } else if (strncmp(call, "nullargs", 8) == 0) {
            null_arguments(api, c, arg);
        } else if (strcmp(call, "empty") == 0) {
            empty_arrays(api, c);
        } else {
            fprintf(stderr, "unknown call %s\n", call);
            return 2;
        }
        fflush(stdout);
    }
    return 0;
}

/* -- --threads: two FMUs set up at once --------------------------------------------------------- */

typedef struct {
    Api api;
    const char *uri, *guid, *name;
    pthread_barrier_t *start;
    int result;
} Job;

static int simulate(const Api *api, const char *name, const char *uri, const char *guid)
{
    fmi2Component c = api->fmi2Instantiate(name, fmi2CoSimulation, guid, uri, &callbacks, fmi2False, fmi2False);
    if (c == NULL) {
        fprintf(stderr, "%s: fmi2Instantiate failed\n", name);
        return 3;
    }
    CHECK(api->fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    CHECK(api->fmi2EnterInitializationMode(c));
    CHECK(api->fmi2ExitInitializationMode(c));
    CHECK(api->fmi2DoStep(c, 0.0, 0.1, fmi2True));
    CHECK(api->fmi2DoStep(c, 0.1, 0.1, fmi2True));
    CHECK(api->fmi2Terminate(c));
    api->fmi2FreeInstance(c);
    return 0;
}

static void *job_main(void *arg)
{
    Job *job = arg;
    pthread_barrier_wait(job->start);
    job->result = simulate(&job->api, job->name, job->uri, job->guid);
    return NULL;
}

static int threads_mode(int argc, char **argv)
{
    if (argc != 8) {
        fprintf(stderr, "usage: %s --threads LIB1 URI1 GUID1 LIB2 URI2 GUID2\n", argv[0]);
        return 2;
    }
    pthread_barrier_t start;
    pthread_barrier_init(&start, NULL, 2);
    Job jobs[2];
    pthread_t threads[2];
    for (int k = 0; k < 2; k++) {
        jobs[k] = (Job){.uri = argv[3 + 3 * k], .guid = argv[4 + 3 * k], .name = k ? "second" : "first",
                        .start = &start, .result = 3};
        if (!load(argv[2 + 3 * k], &jobs[k].api))
            return 2;
    }
    for (int k = 0; k < 2; k++)
        pthread_create(&threads[k], NULL, job_main, &jobs[k]);
    for (int k = 0; k < 2; k++)
        pthread_join(threads[k], NULL);
    pthread_barrier_destroy(&start);
    return jobs[0].result ? jobs[0].result : jobs[1].result;
}

/* -- --logger-lock: a logger that takes a lock another thread holds while it calls into the FMU ------ */

/* e.g. the host's log file; recursive: a thread that holds it may log */
static pthread_mutex_t host_lock = PTHREAD_RECURSIVE_MUTEX_INITIALIZER_NP;
static volatile int logger_waiting;                           /* the locking logger is waiting for host_lock */

static void locking_logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                           fmi2String message, ...)
{
    (void)env;
    __atomic_store_n(&logger_waiting, 1, __ATOMIC_SEQ_CST);
    pthread_mutex_lock(&host_lock);
    va_list args;
    va_start(args, message);
    flockfile(stderr);
    fprintf(stderr, "[%d] %s (%s): ", (int)status, name, category);
    vfprintf(stderr, message, args);
    fputc('\n', stderr);
    funlockfile(stderr);
    va_end(args);
    pthread_mutex_unlock(&host_lock);
}

typedef struct {
    const Api *api;
    fmi2Component reader, refused; /* thread 1 reads from the first, thread 2 makes a refused call on the second */
    fmi2ValueReference vr;         /* the Real thread 1 reads */
    volatile int holding;          /* thread 1 holds host_lock */
    fmi2Status status;
} LockJob;

static void *reader_main(void *arg)
{
    LockJob *job = arg;
    pthread_mutex_lock(&host_lock);
    __atomic_store_n(&job->holding, 1, __ATOMIC_SEQ_CST);
    for (int k = 0; k < 10000 && !__atomic_load_n(&logger_waiting, __ATOMIC_SEQ_CST); k++)
        usleep(1000); /* until thread 2 is in the logger, waiting for host_lock (10 s at most) */
    fmi2Real value = 0.0;
    job->status = job->api->fmi2GetReal(job->reader, &job->vr, 1, &value); /* needs the GIL */
    pthread_mutex_unlock(&host_lock);
    return NULL;
}

static void *refused_main(void *arg)
{
    LockJob *job = arg;
    while (!__atomic_load_n(&job->holding, __ATOMIC_SEQ_CST))
        usleep(1000);
    job->status = job->api->fmi2DoStep(job->refused, 0.0, 0.1, fmi2True); /* before initialisation: refused */
    return NULL;
}

/* Join both threads within `seconds`, or print "<label> deadlock" and exit 5 (the threads are stuck: no orderly
 * exit). */
static void join_both(pthread_t threads[2], int seconds, const char *label)
{
    struct timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_sec += seconds;
    for (int k = 0; k < 2; k++)
        if (pthread_timedjoin_np(threads[k], NULL, &deadline) == ETIMEDOUT) {
            printf("%s deadlock\n", label);
            fflush(stdout);
            _exit(5);
        }
}

static int logger_lock_mode(const Api *api, int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: %s --logger-lock LIBRARY RESOURCE_URI GUID VR\n", argv[0]);
        return 2;
    }
    static fmi2CallbackFunctions locking = {locking_logger, calloc, free, NULL, NULL};
    fmi2Component reader = api->fmi2Instantiate("reader", fmi2CoSimulation, argv[4], argv[3], &locking, fmi2False,
                                                fmi2False);
    fmi2Component refused = api->fmi2Instantiate("refused", fmi2CoSimulation, argv[4], argv[3], &locking, fmi2False,
                                                 fmi2False);
    if (reader == NULL || refused == NULL) {
        fprintf(stderr, "fmi2Instantiate failed\n");
        return 3;
    }
    CHECK(api->fmi2SetupExperiment(reader, fmi2False, 0.0, 0.0, fmi2False, 0.0));
    CHECK(api->fmi2EnterInitializationMode(reader));
    CHECK(api->fmi2ExitInitializationMode(reader));
    LockJob first = {.api = api, .reader = reader, .vr = (fmi2ValueReference)strtoul(argv[5], NULL, 10),
                     .status = fmi2Fatal};
    LockJob second = {.api = api, .refused = refused, .status = fmi2Fatal};
    pthread_t threads[2];
    __atomic_store_n(&logger_waiting, 0, __ATOMIC_SEQ_CST); /* a message of the set-up does not count */
    pthread_create(&threads[0], NULL, reader_main, &first);
    pthread_create(&threads[1], NULL, refused_main, &second);
    /* thread 2 starts its call once thread 1 holds the lock */
    while (!__atomic_load_n(&first.holding, __ATOMIC_SEQ_CST))
        usleep(1000);
    __atomic_store_n(&second.holding, 1, __ATOMIC_SEQ_CST);
    join_both(threads, 60, "logger-lock");
    printf("logger-lock %d %d\n", (int)first.status, (int)second.status);
    api->fmi2FreeInstance(reader);
    api->fmi2FreeInstance(refused);
    return 0;
}

/* --logger-lock-instantiate: thread 2 makes the process's first fmi2Instantiate, whose messages go to the
 * locking logger, while thread 1 holds the lock and then calls fmi2Instantiate itself. */
typedef struct {
    const Api *api;
    const char *uri, *guid;
    int logging;
    volatile int holding; /* thread 1 holds host_lock */
    int waited;           /* thread 1 saw thread 2's logger waiting before it called */
    fmi2Component got;
} SetupJob;

static fmi2Component instantiate_locked(const SetupJob *job, const char *name)
{
    static fmi2CallbackFunctions locking = {locking_logger, calloc, free, NULL, NULL};
    return job->api->fmi2Instantiate(name, fmi2CoSimulation, job->guid, job->uri, &locking, fmi2False,
                                     job->logging ? fmi2True : fmi2False);
}

static void *holder_main(void *arg)
{
    SetupJob *job = arg;
    pthread_mutex_lock(&host_lock);
    __atomic_store_n(&job->holding, 1, __ATOMIC_SEQ_CST);
    for (int k = 0; k < 120000 && !__atomic_load_n(&logger_waiting, __ATOMIC_SEQ_CST); k++)
        usleep(1000); /* until thread 2 is in the logger (120 s at most: it starts Python) */
    job->waited = __atomic_load_n(&logger_waiting, __ATOMIC_SEQ_CST);
    job->got = instantiate_locked(job, "holder");
    pthread_mutex_unlock(&host_lock);
    return NULL;
}

static void *first_main(void *arg)
{
    SetupJob *job = arg;
    job->got = instantiate_locked(job, "first");
    return NULL;
}

static int logger_lock_instantiate_mode(const Api *api, int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: %s --logger-lock-instantiate LIBRARY RESOURCE_URI GUID LOGGING\n", argv[0]);
        return 2;
    }
    SetupJob holder = {.api = api, .uri = argv[3], .guid = argv[4], .logging = atoi(argv[5])};
    SetupJob first = holder;
    pthread_t threads[2];
    pthread_create(&threads[0], NULL, holder_main, &holder);
    while (!__atomic_load_n(&holder.holding, __ATOMIC_SEQ_CST))
        usleep(1000);
    pthread_create(&threads[1], NULL, first_main, &first);
    join_both(threads, 180, "logger-lock-instantiate");
    printf("logger-lock-instantiate %s %s %s\n", holder.waited ? "waited" : "no-wait", first.got ? "ok" : "null",
           holder.got ? "ok" : "null");
    if (first.got)
        api->fmi2FreeInstance(first.got);
    if (holder.got)
        api->fmi2FreeInstance(holder.got);
    return 0;
}

/* -- --stack: the calls on a thread with a small stack, and how much of it they used ------------------ */

typedef struct {
    const Api *api;
    int argc;
    char **argv;
    int result;
} CallsJob;

static void *calls_main(void *arg)
{
    CallsJob *job = arg;
    job->result = calls_mode(job->api, job->argc, job->argv);
    fflush(stdout);
    return NULL;
}

static int stack_mode(int argc, char **argv)
{
    if (argc < 6) {
        fprintf(stderr, "usage: %s --stack KB LIBRARY RESOURCE_URI GUID CALL ...\n", argv[0]);
        return 2;
    }
    Api api;
    if (!load(argv[3], &api))
        return 2;
    size_t size = (size_t)atoi(argv[2]) * 1024, page = (size_t)sysconf(_SC_PAGESIZE);
    unsigned char *region = mmap(NULL, page + size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_STACK,
                                 -1, 0);
    if (region == MAP_FAILED || mprotect(region, page, PROT_NONE) != 0) { /* the stack grows down to the guard */
        perror("mmap");
        return 2;
    }
    unsigned char *stack = region + page;
    memset(stack, 0xA5, size);
    setvbuf(stderr, NULL, _IOFBF, 1 << 16); /* an unbuffered stream formats in an 8 kB buffer on the stack */
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstack(&attr, stack, size);
    /* argv + 1: --stack KB LIBRARY URI GUID CALL ..., the layout calls_mode reads (URI argv[3], GUID argv[4]) */
    CallsJob job = {.api = &api, .argc = argc - 1, .argv = argv + 1, .result = 2};
    pthread_t thread;
    if (pthread_create(&thread, &attr, calls_main, &job) != 0) {
        fprintf(stderr, "pthread_create failed\n");
        return 2;
    }
    pthread_join(thread, NULL);
    size_t untouched = 0;
    while (untouched < size && stack[untouched] == 0xA5)
        untouched++;
    printf("stack-used %zu\n", size - untouched);
    return job.result;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--stack") == 0)
        return stack_mode(argc, argv);
    if (argc > 1 && strcmp(argv[1], "--threads") == 0)
        return threads_mode(argc, argv);
    if (argc > 2 && strcmp(argv[1], "--logger-lock") == 0) {
        Api api;
        return load(argv[2], &api) ? logger_lock_mode(&api, argc, argv) : 2;
    }
    if (argc > 2 && strcmp(argv[1], "--logger-lock-instantiate") == 0) {
        Api api;
        return load(argv[2], &api) ? logger_lock_instantiate_mode(&api, argc, argv) : 2;
    }
    int calls = argc > 1 && strcmp(argv[1], "--calls") == 0;
    if (argc < 2 + calls) {
        fprintf(stderr, "usage: see the head of native_importer.c\n");
        return 2;
    }
    Api api;
    if (!load(argv[1 + calls], &api))
        return 2;
    return calls ? calls_mode(&api, argc, argv) : runs_mode(&api, argc, argv);
}
