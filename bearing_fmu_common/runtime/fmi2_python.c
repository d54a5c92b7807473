/* FMI 2.0 co-simulation layer for Python slaves (pythonfmu's Fmi2Slave protocol).
 *
 * SPDX-License-Identifier: MIT. Written from the FMI 2.0.4 standard (Modelica Association); the
 * fmi2*.h headers come from fmpy's package data at build time. docs/fmu_runtime.md explains the
 * statuses, the environment of native hosts and why Python is never finalised.
 *
 * Built for CPython's stable ABI (Py_LIMITED_API 3.10) and linked with no libpython, so one binary serves
 * every Python from 3.10 on: the interpreter's symbols come from the process (the host's Python, or the
 * libpython the FMU's entry library, fmi2_loader.c, loaded and started). The entry library is the FMU's
 * binaries/linux64/<modelIdentifier>.so; it loads this one (binaries/linux64/fmi2_python.abi3.so) once an
 * interpreter runs (RTLD_LOCAL: its fmi2* functions never enter the global scope) and passes every call
 * on. Nothing here calls its own exported functions, so another library's fmi2* cannot take their place.
 *
 * One library serves every FMU: fmi2Instantiate reads resources/slavemodule.txt (written by
 * pythonfmu's builder), imports that module with resources/ on sys.path (once per process: later
 * instances, from any extraction of the FMU, reuse it and add nothing to sys.path) and instantiates
 * its Fmi2Slave subclass. Every call holds the GIL (PyGILState_Ensure), so a Python host (fmpy, whose
 * ctypes calls release the GIL) and a native host on any thread are served the same way; the host's logger
 * is called with the GIL released (emit).
 *
 * No call can crash the host: a NULL instance gets fmi2Error, and every call is checked against the FMI
 * 2.0 co-simulation call sequence (the states and masks below, as the Modelica Reference-FMUs check it);
 * a call the sequence does not allow, a NULL argument and an instance left without its slave by a failed
 * fmi2Reset get fmi2Error with a message naming the call and the state.
 */
#define PY_SSIZE_T_CLEAN
#define Py_LIMITED_API 0x030A0000 /* Python 3.10: the oldest supported host */
#include <Python.h>

#include <limits.h>
#include <pthread.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2_shared.h"

/* Py_XSETREF is not part of the limited API */
#define SET_REF(target, value)                                                                     \
    do {                                                                                           \
        PyObject *old__ = (PyObject *)(target);                                                    \
        (target) = (value);                                                                        \
        Py_XDECREF(old__);                                                                         \
    } while (0)

#define HELPER_FILE "fmi2_layer.py" /* resources/ file: the layer's Python side (bearing_fmu_common/runtime) */

/* The value references of the last call of one kind, as a Python tuple: a host asks for the same
 * variables every step, so the tuple is built once and handed over again while the references match. */
typedef struct {
    fmi2ValueReference *vr;
    size_t n;
    PyObject *refs;
} References;

enum { GET_REAL, GET_INTEGER, GET_BOOLEAN, GET_STRING, SET_REAL, SET_INTEGER, SET_BOOLEAN, SET_STRING, N_KINDS };

/* The FMI 2.0 co-simulation states (as bits, so that a call's allowed states are one mask). A refused
 * step (fmi2Discard) leaves the instance in STEP_COMPLETE, as in the Reference-FMUs: the host may change an
 * input or restore a state and step again; steps are synchronous, so "step failed" and "step canceled" are
 * never entered. Any call that returns fmi2Error leaves the instance in ERROR_STATE (FMI 2.0: the
 * simulation cannot go on), from which fmi2Reset or fmi2SetFMUstate (a state saved before) recover. */
typedef enum {
    INSTANTIATED = 1 << 0,
    INITIALIZATION_MODE = 1 << 1,
    STEP_COMPLETE = 1 << 2,
    STEP_IN_PROGRESS = 1 << 3,
    TERMINATED = 1 << 4,
    ERROR_STATE = 1 << 5,
    FATAL_STATE = 1 << 6,
} State;

static const char *STATE_NAMES[] = {"instantiated", "initialization mode", "step complete", "step in progress",
                                    "terminated",   "error",               "fatal"};

/* The states in which each call is allowed (FMI 2.0.4, co-simulation state machine). */
#define MASK_SetDebugLogging (INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE | STEP_IN_PROGRESS | TERMINATED | ERROR_STATE)
#define MASK_SetupExperiment INSTANTIATED
#define MASK_EnterInitializationMode INSTANTIATED
#define MASK_ExitInitializationMode INITIALIZATION_MODE
#define MASK_Terminate STEP_COMPLETE
#define MASK_Reset (INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE | TERMINATED | ERROR_STATE)
#define MASK_FreeInstance (MASK_Reset | FATAL_STATE)
#define MASK_Get (INITIALIZATION_MODE | STEP_COMPLETE | TERMINATED | ERROR_STATE) /* in error: diagnostics */
#define MASK_Set (INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE)
#define MASK_GetFMUstate (INSTANTIATED | INITIALIZATION_MODE | STEP_COMPLETE | TERMINATED)
#define MASK_FMUstate MASK_Reset /* set, free, (de)serialise: restoring a state saved before leaves an error */
#define MASK_DoStep STEP_COMPLETE
#define MASK_CancelStep STEP_IN_PROGRESS
#define MASK_Status (STEP_COMPLETE | STEP_IN_PROGRESS | TERMINATED)

typedef struct {
    State state;       /* where the instance is in the FMI call sequence */
    PyObject *cls;     /* the slave class (kept for fmi2Reset) */
    PyObject *kwargs;  /* its constructor arguments */
    PyObject *slave;   /* the Fmi2Slave instance; NULL after a failed fmi2Reset */
    PyObject *strings; /* bytes behind the pointers of the last fmi2GetString */
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
    char *name;
    int logging_on;
    fmi2Real time; /* end of the last accepted step: fmi2LastSuccessfulTime */
    int discarded; /* the last doStep returned fmi2Discard at (discard_t, discard_h) */
    fmi2Real discard_t, discard_h;
    References refs[N_KINDS];
} Instance;

static pthread_mutex_t helper_lock = PTHREAD_MUTEX_INITIALIZER; /* taken before the GIL: see ensure_helper */
static PyObject *helper; /* the module of resources/fmi2_layer.py; lives as long as the process */

/* Names of the slave methods called every step and of its log queue, interned once (ensure_helper):
 * a call by an interned name skips building the name and parsing a format string per call. */
static const char *KIND_METHODS[N_KINDS] = {"get_real",   "get_integer", "get_boolean", "get_string",
                                            "set_real",   "set_integer", "set_boolean", "set_string"};
static PyObject *kind_names[N_KINDS], *name_do_step, *name_log_queue, *name_begin_setup, *name_end_setup;

/* -- the GIL ---------------------------------------------------------------------------------- */

/* How many holds of the GIL this thread has taken through gil_take and not given back: the host's logger is
 * called with the GIL released only by a thread that holds it (PyGILState_Check is not in the stable ABI). */
static __thread int gil_holds;

static PyGILState_STATE gil_take(void)
{
    PyGILState_STATE state = PyGILState_Ensure();
    gil_holds++;
    return state;
}

static void gil_give(PyGILState_STATE state)
{
    gil_holds--;
    PyGILState_Release(state);
}

/* -- logging -------------------------------------------------------------------------------- */

/* Pass a message to the host's logger (warnings and errors always; debug messages only if asked for). The
 * logger runs with the GIL released: a host's logger may wait for a lock of the host (its log file, its
 * console) that another host thread holds while it calls into an FMU, and that thread needs the GIL. The
 * message and category are copied into C memory first, so nothing of Python is touched meanwhile. */
static void emit(const Instance *c, fmi2Status status, const char *category, const char *text)
{
    if (!wanted(c->logger, c->logging_on, status))
        return;
    char *format = printf_safe(text), *cat = strdup(category);
    if (format != NULL && cat != NULL) {
        PyThreadState *saved = gil_holds > 0 ? PyEval_SaveThread() : NULL;
        c->logger(c->env, c->name, status, cat, format);
        if (saved != NULL)
            PyEval_RestoreThread(saved);
    }
    free(format);
    free(cat);
}

static void emitf(const Instance *c, fmi2Status status, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    char *text = wanted_message(c->logger, c->logging_on, status, fmt, args);
    va_end(args);
    if (text != NULL)
        emit(c, status, status >= fmi2Error ? "logStatusError" : "logAll", text);
    free(text);
}

/* Pass the slave's queued log messages (pythonfmu LogMsg: status, category, msg) to the host. They are taken
 * off the queue before the first is passed on (the GIL is released while the logger runs). */
static void flush_log(const Instance *c)
{
    if (c->slave == NULL)
        return;
    PyObject *queue = PyObject_GetAttr(c->slave, name_log_queue);
    if (queue == NULL || !PyList_Check(queue) || PyList_Size(queue) == 0) {
        Py_XDECREF(queue);
        PyErr_Clear();
        return;
    }
    Py_ssize_t n = PyList_Size(queue);
    PyObject *batch = PyList_GetSlice(queue, 0, n);
    if (batch != NULL)
        PyList_SetSlice(queue, 0, n, NULL);
    Py_DECREF(queue);
    PyErr_Clear();
    for (Py_ssize_t i = 0; batch != NULL && i < n; i++) {
        PyObject *entry = PyList_GetItem(batch, i);
        PyObject *status = PyObject_GetAttrString(entry, "status");
        PyObject *category = PyObject_GetAttrString(entry, "category");
        PyObject *msg = PyObject_GetAttrString(entry, "msg");
        PyObject *msg_text = msg ? PyObject_Str(msg) : NULL;
        PyObject *category_text = category && category != Py_None ? PyObject_Str(category) : NULL;
        long level = status ? PyLong_AsLong(status) : fmi2Error;
        const char *text = msg_text ? PyUnicode_AsUTF8AndSize(msg_text, NULL) : NULL;
        const char *cat = category_text ? PyUnicode_AsUTF8AndSize(category_text, NULL) : NULL;
        PyErr_Clear();
        emit(c, level >= fmi2OK && level <= fmi2Pending ? (fmi2Status)level : fmi2Error, cat ? cat : "logAll",
             text ? text : "(unprintable log message)");
        Py_XDECREF(status);
        Py_XDECREF(category);
        Py_XDECREF(msg);
        Py_XDECREF(msg_text);
        Py_XDECREF(category_text);
    }
    Py_XDECREF(batch);
}

/* Log the pending Python exception with its traceback as an fmi2Error message; clears it. */
static void log_exception(const Instance *c, const char *what)
{
    PyObject *kind, *value, *tb;
    PyErr_Fetch(&kind, &value, &tb);
    PyErr_NormalizeException(&kind, &value, &tb);
    flush_log(c); /* what the slave logged came first */
    PyObject *text = NULL;
    if (helper != NULL && kind != NULL)
        text = PyObject_CallMethod(helper, "describe", "(OOO)", kind, value ? value : Py_None, tb ? tb : Py_None);
    const char *utf8 = text ? PyUnicode_AsUTF8AndSize(text, NULL) : NULL;
    PyErr_Clear();
    const char *detail = utf8 ? utf8 : "unknown Python error";
    size_t n = strlen(c->name) + strlen(what) + strlen(detail) + 5;
    char *message = malloc(n);
    if (message != NULL) {
        snprintf(message, n, "%s: %s: %s", c->name, what, detail);
        emit(c, fmi2Error, "logStatusError", message);
        free(message);
    }
    Py_XDECREF(text);
    Py_XDECREF(kind);
    Py_XDECREF(value);
    Py_XDECREF(tb);
}

/* Status of a slave method's result (new reference or NULL), consumed here: None/True -> OK,
 * False -> if_false, an int (pythonfmu's Fmi2Status) -> that status; an exception -> fmi2Error. */
static fmi2Status settle(Instance *c, const char *what, PyObject *result, fmi2Status if_false)
{
    fmi2Status status = fmi2OK;
    if (result == NULL) {
        log_exception(c, what);
        return fmi2Error;
    }
    if (result == Py_False)
        status = if_false;
    else if (PyLong_Check(result) && result != Py_True) {
        long value = PyLong_AsLong(result);
        status = value >= fmi2OK && value <= fmi2Fatal ? (fmi2Status)value : fmi2Error;
    }
    Py_DECREF(result);
    flush_log(c);
    return status;
}

/* -- interpreter ---------------------------------------------------------------------------- */

/* The pending Python exception as "Kind: text" (malloc'ed; NULL if none could be had); clears it. */
static char *exception_text(void)
{
    PyObject *kind, *value, *tb;
    PyErr_Fetch(&kind, &value, &tb);
    PyErr_NormalizeException(&kind, &value, &tb);
    PyObject *name = kind ? PyObject_GetAttrString(kind, "__name__") : NULL;
    PyObject *text = value ? PyObject_Str(value) : NULL;
    const char *name_utf8 = name ? PyUnicode_AsUTF8AndSize(name, NULL) : NULL;
    const char *text_utf8 = text ? PyUnicode_AsUTF8AndSize(text, NULL) : NULL;
    char *out = NULL;
    if (name_utf8 != NULL) {
        size_t n = strlen(name_utf8) + (text_utf8 ? strlen(text_utf8) : 0) + 3;
        if ((out = malloc(n)) != NULL)
            snprintf(out, n, "%s%s%s", name_utf8, text_utf8 && text_utf8[0] ? ": " : "", text_utf8 ? text_utf8 : "");
    }
    PyErr_Clear();
    Py_XDECREF(name);
    Py_XDECREF(text);
    Py_XDECREF(kind);
    Py_XDECREF(value);
    Py_XDECREF(tb);
    return out;
}

/* resources/fmi2_layer.py loaded by file location as a module of its own, not registered in sys.modules (each
 * copy of the layer has its own) and without touching sys.path; new reference, or NULL with an exception set. */
static PyObject *load_helper(const char *resources)
{
    size_t n = strlen(resources) + sizeof HELPER_FILE + 1;
    char *path = malloc(n);
    if (path == NULL)
        return PyErr_NoMemory();
    snprintf(path, n, "%s/%s", resources, HELPER_FILE);
    PyObject *util = PyImport_ImportModule("importlib.util");
    PyObject *spec = util ? PyObject_CallMethod(util, "spec_from_file_location", "(sN)", "bearing_fmu_runtime",
                                                PyUnicode_DecodeFSDefault(path))
                          : NULL;
    free(path);
    if (spec == Py_None) {
        Py_CLEAR(spec);
        PyErr_SetString(PyExc_ImportError, "no loader for " HELPER_FILE);
    }
    PyObject *module = spec ? PyObject_CallMethod(util, "module_from_spec", "(O)", spec) : NULL;
    PyObject *loader = module ? PyObject_GetAttrString(spec, "loader") : NULL;
    PyObject *done = loader ? PyObject_CallMethod(loader, "exec_module", "(O)", module) : NULL;
    if (done == NULL)
        Py_CLEAR(module);
    Py_XDECREF(done);
    Py_XDECREF(loader);
    Py_XDECREF(spec);
    Py_XDECREF(util);
    return module;
}

static char NO_MEMORY[] = "out of memory"; /* what ensure_helper returns when it cannot allocate its message */

/* Make sure this copy of the layer has its helper, the module of resources/fmi2_layer.py (`resources`: the
 * first instance's). The interpreter runs already: the host's, or the one the FMU's entry library started
 * (fmi2_loader.c); it is never finalised (docs/fmu_runtime.md). The helper is made once per copy of the
 * layer; helper_lock is taken before the GIL (never the other way round), so two host threads instantiating
 * at once make it once. NULL if it is there, else what went wrong (malloc'ed, or NO_MEMORY). */
static char *ensure_helper(const char *resources)
{
    if (!Py_IsInitialized()) {
        static const char text[] = "no Python interpreter runs in this process (the FMU's entry library starts one)";
        char *copy = strdup(text);
        return copy ? copy : NO_MEMORY;
    }
    char *error = NULL;
    pthread_mutex_lock(&helper_lock);
    if (helper == NULL) {
        PyGILState_STATE gil = gil_take();
        PyObject *module = load_helper(resources);
        if (module == NULL) {
            char *why = exception_text();
            const char *detail = why ? why : "unknown Python error";
            static const char head[] = "cannot load the layer's Python side, resources/" HELPER_FILE " (an incomplete "
                                       "or altered FMU): ";
            size_t n = sizeof head + strlen(detail);
            error = malloc(n);
            if (error != NULL)
                snprintf(error, n, "%s%s", head, detail);
            else
                error = NO_MEMORY;
            free(why);
        } else {
            helper = module;
            for (int k = 0; k < N_KINDS; k++)
                kind_names[k] = PyUnicode_InternFromString(KIND_METHODS[k]);
            name_do_step = PyUnicode_InternFromString("do_step");
            name_log_queue = PyUnicode_InternFromString("log_queue");
            name_begin_setup = PyUnicode_InternFromString("begin_setup");
            name_end_setup = PyUnicode_InternFromString("end_setup");
        }
        gil_give(gil);
    }
    pthread_mutex_unlock(&helper_lock);
    return error;
}

/* -- instance ------------------------------------------------------------------------------- */

static const char *state_name(State state)
{
    for (int k = 0; k < 7; k++)
        if ((int)state == 1 << k)
            return STATE_NAMES[k];
    return "unknown";
}

/* Is `call` allowed in the instance's state (mask: MASK_<call>)? If not, say so: the call, the state and
 * where the FMI 2.0 call sequence allows it. Holds the GIL. */
static int allowed(Instance *c, int mask, const char *call)
{
    if (c->state & mask)
        return 1;
    char where[256] = "";
    for (int k = 0; k < 7; k++)
        if (mask & (1 << k))
            snprintf(where + strlen(where), sizeof where - strlen(where), "%s%s", where[0] ? ", " : "", STATE_NAMES[k]);
    emitf(c, fmi2Error, "%s: %s is not allowed in state %s (FMI 2.0 co-simulation call sequence; allowed in: %s)%s",
          c->name, call, state_name(c->state), where,
          c->state == ERROR_STATE ? ". An earlier call failed (logged above): fmi2Reset, or fmi2SetFMUstate with a "
                                    "state saved before, makes the instance usable again"
                                  : "");
    return 0;
}

/* A NULL array or pointer argument (FMI: only allowed with nvr = 0) is refused with a message. */
static int given(Instance *c, const void *pointer, const char *call, const char *argument)
{
    if (pointer != NULL)
        return 1;
    emitf(c, fmi2Error, "%s: %s: argument %s is NULL", c->name, call, argument);
    return 0;
}

/* After a failed fmi2Reset the instance has no slave: only fmi2Reset and fmi2FreeInstance can help. */
static int has_slave(Instance *c, const char *call)
{
    if (c->slave != NULL)
        return 1;
    emitf(c, fmi2Error, "%s: %s: the instance has no model since fmi2Reset failed (logged then); call fmi2Reset "
          "again or fmi2FreeInstance", c->name, call);
    return 0;
}

/* Enter a call on instance `component`: NULL gets fmi2Error (there is no logger to tell), then the GIL
 * is taken and the call checked against the state (refused: fmi2Error and the error state). */
#define BEGIN(call, mask)                                                                          \
    Instance *c = component;                                                                       \
    if (c == NULL)                                                                                 \
        return fmi2Error;                                                                          \
    PyGILState_STATE gil__ = gil_take();                                                           \
    State entered__ = c->state;                                                                    \
    if (!allowed(c, (mask), (call)))                                                               \
    RETURN(fmi2Error)

/* Leave the call: an error or fatal status puts the instance into that state (not while a step runs on
 * another thread, nor if one ran when the call came: a call refused meanwhile leaves the step's outcome to
 * decide, also when the step ended while the refusal was being logged); releases the GIL. */
#define RETURN(value)                                                                              \
    do {                                                                                           \
        fmi2Status value__ = (value);                                                              \
        int stepping__ = entered__ == STEP_IN_PROGRESS || c->state == STEP_IN_PROGRESS;            \
        if (value__ == fmi2Error && !stepping__)                                                   \
            c->state = ERROR_STATE;                                                                \
        else if (value__ == fmi2Fatal && !stepping__)                                              \
            c->state = FATAL_STATE;                                                                \
        gil_give(gil__);                                                                           \
        return value__;                                                                            \
    } while (0)

/* The state after a call that succeeded (OK or Warning) moves the instance to `next`. */
#define MOVE_ON(status, next)                                                                      \
    do {                                                                                           \
        if ((status) <= fmi2Warning)                                                               \
            c->state = (next);                                                                     \
    } while (0)

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

/* Call the helper's begin_setup or end_setup (the process-wide set-up lock); holds the GIL. An exception
 * already pending (the slave constructor's) is kept for the caller to log: calling Python with it set
 * would replace it by a SystemError and lose its text. Waiting for the lock releases the GIL. */
static void setup_lock(PyObject *name)
{
    PyObject *kind, *value, *tb;
    PyErr_Fetch(&kind, &value, &tb);
    PyObject *done = PyObject_CallMethodObjArgs(helper, name, NULL);
    if (done == NULL)
        PyErr_Print(); /* cannot happen short of memory exhaustion: say so rather than hide it */
    Py_XDECREF(done);
    PyErr_Restore(kind, value, tb);
}

/* Construct the slave under the set-up lock (a hold of the caller's may be around it); nothing is logged: an
 * exception is left pending. */
static int construct_slave(Instance *c)
{
    PyObject *args = PyTuple_New(0);
    setup_lock(name_begin_setup);
    c->slave = args ? PyObject_Call(c->cls, args, c->kwargs) : NULL;
    setup_lock(name_end_setup);
    Py_XDECREF(args);
    return c->slave != NULL;
}

/* Construct the slave (fmi2Reset) and log what it logged, or its exception, once the set-up lock is released:
 * the host's logger never runs under it (it may wait for a lock of the host whose holder is setting up an
 * FMU). */
static int create_slave(Instance *c)
{
    if (!construct_slave(c)) {
        log_exception(c, "creating the slave");
        return 0;
    }
    flush_log(c);
    return 1;
}

static void release(Instance *c)
{
    for (int k = 0; k < N_KINDS; k++) {
        Py_XDECREF(c->refs[k].refs);
        free(c->refs[k].vr);
    }
    Py_XDECREF(c->slave);
    Py_XDECREF(c->cls);
    Py_XDECREF(c->kwargs);
    Py_XDECREF(c->strings);
    free(c->name);
    free(c);
}

/* Is `guid` the GUID of this FMU's modelDescription.xml (resources/guid.txt, written by the build)? */
static int guid_matches(const Instance *c, const char *resources, const char *guid)
{
    char expected[256];
    if (!read_hint(resources, GUID_FILE, expected, sizeof expected)) {
        emitf(c, fmi2Error, "%s: %s/%s is missing: cannot check the GUID (an incomplete or altered FMU)", c->name,
              resources, GUID_FILE);
        return 0;
    }
    if (guid == NULL || strcmp(guid, expected) != 0) {
        emitf(c, fmi2Error, "%s: fmi2Instantiate: GUID '%s' is not this FMU's ('%s' in its modelDescription.xml): "
              "the host read another FMU's modelDescription.xml, or the FMU's files were mixed", c->name,
              guid ? guid : "(NULL)", expected);
        return 0;
    }
    return 1;
}

/* Free an instance that never ran (fmi2Instantiate failing before the slave exists). */
static fmi2Component refuse(Instance *c, char *resources)
{
    free(resources);
    free(c->name);
    free(c);
    return NULL;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    Instance *c = calloc(1, sizeof *c);
    if (c == NULL)
        return NULL;
    c->name = strdup(instanceName ? instanceName : "");
    if (c->name == NULL) {
        free(c);
        return NULL;
    }
    c->logger = functions ? functions->logger : NULL;
    c->env = functions ? functions->componentEnvironment : NULL;
    c->logging_on = loggingOn;
    char *resources = uri_to_path(fmuResourceLocation);
    if (fmuType != fmi2CoSimulation || resources == NULL) {
        emitf(c, fmi2Error, "%s: only co-simulation with a resource location is supported", c->name);
        return refuse(c, resources);
    }
    if (!guid_matches(c, resources, fmuGUID))
        return refuse(c, resources);
    char *error = ensure_helper(resources);
    if (error != NULL) {
        emitf(c, fmi2Error, "%s: %s", c->name, error);
        if (error != NO_MEMORY)
            free(error);
        return refuse(c, resources);
    }
    PyGILState_STATE gil = gil_take();
    setup_lock(name_begin_setup); /* the class and the slave under one hold: see fmi2_layer.py */
    c->cls = PyObject_CallMethod(helper, "slave_class", "(s)", resources);
    if (c->cls != NULL)
        c->kwargs = Py_BuildValue("{s:s,s:s,s:O}", "instance_name", c->name, "resources", resources, "visible",
                                  visible ? Py_True : Py_False);
    int ok = c->cls != NULL && c->kwargs != NULL && construct_slave(c);
    setup_lock(name_end_setup); /* keeps a pending exception: logged below, the lock released */
    if (!ok) {
        log_exception(c, c->cls == NULL ? "loading the slave class" : "creating the slave");
        release(c);
        c = NULL;
    } else {
        flush_log(c);
        c->state = INSTANTIATED;
    }
    gil_give(gil);
    free(resources);
    return c;
}

void fmi2FreeInstance(fmi2Component component)
{
    Instance *c = component;
    if (c == NULL)
        return;
    PyGILState_STATE gil = gil_take();
    if (!allowed(c, MASK_FreeInstance, "fmi2FreeInstance")) {
        gil_give(gil); /* a step still running on another thread: leave the instance alone */
        return;
    }
    flush_log(c);
    release(c);
    gil_give(gil);
    /* the last instance leaves the interpreter running: docs/fmu_runtime.md */
}

fmi2Status fmi2SetDebugLogging(fmi2Component component, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    (void)nCategories;
    (void)categories; /* categories are not filtered */
    BEGIN("fmi2SetDebugLogging", MASK_SetDebugLogging);
    c->logging_on = loggingOn;
    RETURN(fmi2OK);
}

fmi2Status fmi2SetupExperiment(fmi2Component component, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    BEGIN("fmi2SetupExperiment", MASK_SetupExperiment);
    if (!has_slave(c, "fmi2SetupExperiment"))
        RETURN(fmi2Error);
    c->time = startTime;
    c->discarded = 0;
    PyObject *stop = stopTimeDefined ? PyFloat_FromDouble(stopTime) : Py_NewRef(Py_None);
    PyObject *tol = toleranceDefined ? PyFloat_FromDouble(tolerance) : Py_NewRef(Py_None);
    PyObject *r = PyObject_CallMethod(c->slave, "setup_experiment", "(dOO)", startTime, stop, tol);
    Py_XDECREF(stop);
    Py_XDECREF(tol);
    RETURN(settle(c, "setup_experiment", r, fmi2Error));
}

/* A change of mode by the FMI call `call`: the slave's `method`; if it succeeded the instance moves to `next`
 * (called between BEGIN and RETURN: the GIL is held). */
static fmi2Status change_mode(Instance *c, const char *call, const char *method, State next)
{
    if (!has_slave(c, call))
        return fmi2Error;
    fmi2Status status = settle(c, method, PyObject_CallMethod(c->slave, method, NULL), fmi2Error);
    MOVE_ON(status, next);
    return status;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component component)
{
    BEGIN("fmi2EnterInitializationMode", MASK_EnterInitializationMode);
    RETURN(change_mode(c, "fmi2EnterInitializationMode", "enter_initialization_mode", INITIALIZATION_MODE));
}

fmi2Status fmi2ExitInitializationMode(fmi2Component component)
{
    BEGIN("fmi2ExitInitializationMode", MASK_ExitInitializationMode);
    RETURN(change_mode(c, "fmi2ExitInitializationMode", "exit_initialization_mode", STEP_COMPLETE));
}

fmi2Status fmi2Terminate(fmi2Component component)
{
    BEGIN("fmi2Terminate", MASK_Terminate);
    RETURN(change_mode(c, "fmi2Terminate", "terminate", TERMINATED));
}

fmi2Status fmi2Reset(fmi2Component component)
{
    BEGIN("fmi2Reset", MASK_Reset);
    Py_CLEAR(c->slave);
    c->discarded = 0;
    c->time = 0.0;
    int ok = create_slave(c); /* fails: no slave, error state; only fmi2Reset and fmi2FreeInstance help */
    if (ok)
        c->state = INSTANTIATED;
    RETURN(ok ? fmi2OK : fmi2Error);
}

/* -- variables ------------------------------------------------------------------------------ */

/* The value references vr as a tuple (a new reference), reused from the last call of this kind when the
 * same references are asked for again. */
static PyObject *references(Instance *c, int kind, const fmi2ValueReference vr[], size_t nvr)
{
    References *last = &c->refs[kind];
    if (last->refs != NULL && last->n == nvr && (nvr == 0 || memcmp(last->vr, vr, nvr * sizeof *vr) == 0))
        return Py_NewRef(last->refs);
    PyObject *refs = PyTuple_New((Py_ssize_t)nvr);
    for (size_t i = 0; refs != NULL && i < nvr; i++) {
        PyObject *ref = PyLong_FromUnsignedLong(vr[i]);
        if (ref == NULL) {
            Py_CLEAR(refs);
            break;
        }
        PyTuple_SetItem(refs, (Py_ssize_t)i, ref);
    }
    fmi2ValueReference *copy = refs != NULL && nvr > 0 ? malloc(nvr * sizeof *vr) : NULL;
    if (refs != NULL && (nvr == 0 || copy != NULL)) { /* remembered only if the copy could be made */
        if (nvr > 0)
            memcpy(copy, vr, nvr * sizeof *vr);
        free(last->vr);
        SET_REF(last->refs, Py_NewRef(refs));
        last->vr = copy;
        last->n = nvr;
    }
    return refs;
}

/* The checks every getter and setter makes before touching the slave: the arrays are there (they may be NULL
 * only with nvr = 0: FMI 2.0) and the instance has a slave. A refusal is logged with the argument's name. */
static int arrays_ok(Instance *c, const char *call, const void *vr, const void *value, size_t nvr)
{
    return (nvr == 0 || (given(c, vr, call, "vr") && given(c, value, call, "value"))) && has_slave(c, call);
}

/* slave.<method of kind>(vrs) -> a list of nvr values, or NULL with the problem logged. */
static PyObject *get_values(Instance *c, int kind, const fmi2ValueReference vr[], size_t nvr)
{
    const char *method = KIND_METHODS[kind];
    PyObject *vrs = references(c, kind, vr, nvr);
    PyObject *values = vrs ? PyObject_CallMethodObjArgs(c->slave, kind_names[kind], vrs, NULL) : NULL;
    Py_XDECREF(vrs);
    if (values != NULL && (!PyList_Check(values) || (size_t)PyList_Size(values) != nvr)) {
        Py_DECREF(values);
        values = NULL;
        PyErr_Format(PyExc_TypeError, "%s returned no list of %zu values", method, nvr);
    }
    if (values == NULL)
        log_exception(c, method);
    return values;
}

/* The value of variable vr[i] could not be converted: logged with its value reference. */
static void log_value_error(Instance *c, int kind, fmi2ValueReference vr)
{
    char what[64];
    snprintf(what, sizeof what, "%s, value reference %u", KIND_METHODS[kind], (unsigned)vr);
    log_exception(c, what);
}

/* One FMI variable type: its getter's and setter's names and slave methods (kinds), the size of its C value
 * and the conversions between a C value and a Python object. */
typedef struct {
    const char *get_call, *set_call;
    int get_kind, set_kind;
    size_t size;
    int keeps; /* the C values point into Python objects kept until the next get (String) */
    /* the Python object `item` as the C value at `out`: 0, or -1 with a Python exception set; `keep` (with
     * `keeps`): a list of nvr slots, slot i for what the value points into */
    int (*to_c)(PyObject *item, void *out, PyObject *keep, Py_ssize_t i);
    /* the C value at `in` as a new Python object, or NULL with a Python exception set */
    PyObject *(*to_python)(const void *in);
} VariableType;

static int real_to_c(PyObject *item, void *out, PyObject *keep, Py_ssize_t i)
{
    (void)keep, (void)i;
    double x = PyFloat_AsDouble(item);
    if (x == -1.0 && PyErr_Occurred())
        return -1;
    *(fmi2Real *)out = x;
    return 0;
}

static int integer_to_c(PyObject *item, void *out, PyObject *keep, Py_ssize_t i)
{
    (void)keep, (void)i;
    long x = PyLong_AsLong(item);
    if (x == -1 && PyErr_Occurred())
        return -1;
    if (x < INT_MIN || x > INT_MAX) {
        PyErr_Format(PyExc_OverflowError, "%ld does not fit an fmi2Integer (%d to %d)", x, INT_MIN, INT_MAX);
        return -1;
    }
    *(fmi2Integer *)out = (fmi2Integer)x;
    return 0;
}

static int boolean_to_c(PyObject *item, void *out, PyObject *keep, Py_ssize_t i)
{
    (void)keep, (void)i;
    int truth = PyObject_IsTrue(item);
    if (truth < 0)
        return -1;
    *(fmi2Boolean *)out = truth ? fmi2True : fmi2False;
    return 0;
}

static int string_to_c(PyObject *item, void *out, PyObject *keep, Py_ssize_t i)
{
    PyObject *bytes = PyUnicode_AsUTF8String(item);
    if (bytes == NULL)
        return -1;
    PyList_SetItem(keep, i, bytes); /* the pointer stays valid until the next fmi2GetString */
    *(fmi2String *)out = PyBytes_AsString(bytes);
    return 0;
}

static PyObject *real_to_python(const void *in) { return PyFloat_FromDouble(*(const fmi2Real *)in); }
static PyObject *integer_to_python(const void *in) { return PyLong_FromLong(*(const fmi2Integer *)in); }
static PyObject *boolean_to_python(const void *in) { return PyBool_FromLong(*(const fmi2Boolean *)in); }

static PyObject *string_to_python(const void *in)
{
    const char *text = *(const fmi2String *)in ? *(const fmi2String *)in : ""; /* NULL: the empty string */
    return PyUnicode_DecodeUTF8(text, (Py_ssize_t)strlen(text), "replace");
}

static const VariableType REAL = {"fmi2GetReal", "fmi2SetReal", GET_REAL, SET_REAL, sizeof(fmi2Real), 0,
                                  real_to_c, real_to_python};
static const VariableType INTEGER = {"fmi2GetInteger", "fmi2SetInteger", GET_INTEGER, SET_INTEGER,
                                     sizeof(fmi2Integer), 0, integer_to_c, integer_to_python};
static const VariableType BOOLEAN = {"fmi2GetBoolean", "fmi2SetBoolean", GET_BOOLEAN, SET_BOOLEAN,
                                     sizeof(fmi2Boolean), 0, boolean_to_c, boolean_to_python};
static const VariableType STRING = {"fmi2GetString", "fmi2SetString", GET_STRING, SET_STRING, sizeof(fmi2String), 1,
                                    string_to_c, string_to_python};

/* A getter: slave.get_<type>(vrs), each value converted into value[i]. Stops at the first value that cannot
 * be converted (fmi2Error, logged with its value reference: no C API call with an exception set); the values
 * after it are not written. Holds the GIL. */
static fmi2Status get_variables(Instance *c, const VariableType *type, const fmi2ValueReference vr[], size_t nvr,
                                void *value)
{
    if (!arrays_ok(c, type->get_call, vr, value, nvr))
        return fmi2Error;
    if (nvr == 0)
        return fmi2OK;
    PyObject *values = get_values(c, type->get_kind, vr, nvr);
    if (values == NULL)
        return fmi2Error;
    PyObject *keep = type->keeps ? PyList_New((Py_ssize_t)nvr) : NULL;
    if (type->keeps && keep == NULL) {
        Py_DECREF(values);
        log_exception(c, KIND_METHODS[type->get_kind]);
        return fmi2Error;
    }
    fmi2Status status = fmi2OK;
    for (size_t i = 0; i < nvr; i++) {
        PyObject *item = PyList_GetItem(values, (Py_ssize_t)i);
        if (type->to_c(item, (char *)value + i * type->size, keep, (Py_ssize_t)i) < 0) {
            log_value_error(c, type->get_kind, vr[i]);
            status = fmi2Error;
            break;
        }
    }
    Py_DECREF(values);
    if (keep != NULL)
        SET_REF(c->strings, keep); /* also after an error: the strings given before it stay valid */
    if (status == fmi2OK)
        flush_log(c);
    return status;
}

/* The name of the slave's variable of value reference vr as the model description spells it, with the
 * reference (malloc'ed; NULL if it cannot be had). Holds the GIL; no exception is left set. */
static char *variable_name(Instance *c, fmi2ValueReference vr)
{
    PyObject *name = PyObject_CallMethod(helper, "variable_name", "(Ok)", c->slave, (unsigned long)vr);
    const char *utf8 = name ? PyUnicode_AsUTF8AndSize(name, NULL) : NULL;
    char *copy = utf8 ? strdup(utf8) : NULL;
    PyErr_Clear();
    Py_XDECREF(name);
    return copy;
}

/* FMI 2.0 knows two fmi2Boolean values, fmi2True (1) and fmi2False (0): a call with any other value sets none
 * of its variables (fmi2Error, logged with the variable's name and the value). 1 if every value is one. */
static int booleans_ok(Instance *c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[])
{
    for (size_t i = 0; i < nvr; i++) {
        if (value[i] == fmi2True || value[i] == fmi2False)
            continue;
        char *name = variable_name(c, vr[i]);
        emitf(c, fmi2Error,
              "%s: fmi2SetBoolean: %s = %d is not allowed: allowed values fmi2False (0) and fmi2True (1); no "
              "variable of the call was set",
              c->name, name ? name : "a variable", (int)value[i]);
        free(name);
        return 0;
    }
    return 1;
}

/* A setter: slave.set_<type>(vrs, values) with value[i] converted. A value that cannot be converted stops the
 * call (fmi2Error, logged with its value reference). Holds the GIL. */
static fmi2Status set_variables(Instance *c, const VariableType *type, const fmi2ValueReference vr[], size_t nvr,
                                const void *value)
{
    if (!arrays_ok(c, type->set_call, vr, value, nvr))
        return fmi2Error;
    if (nvr == 0)
        return fmi2OK;
    if (type == &BOOLEAN && !booleans_ok(c, vr, nvr, value))
        return fmi2Error;
    PyObject *values = PyList_New((Py_ssize_t)nvr);
    if (values == NULL) {
        log_exception(c, KIND_METHODS[type->set_kind]);
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        PyObject *item = type->to_python((const char *)value + i * type->size);
        if (item == NULL) {
            Py_DECREF(values);
            log_value_error(c, type->set_kind, vr[i]);
            return fmi2Error;
        }
        PyList_SetItem(values, (Py_ssize_t)i, item);
    }
    PyObject *vrs = references(c, type->set_kind, vr, nvr);
    PyObject *r = vrs ? PyObject_CallMethodObjArgs(c->slave, kind_names[type->set_kind], vrs, values, NULL) : NULL;
    Py_XDECREF(vrs);
    Py_DECREF(values);
    return settle(c, KIND_METHODS[type->set_kind], r, fmi2Error);
}

/* The eight FMI getters and setters, one line each. */
#define GETTER(Type, TYPE)                                                                         \
    fmi2Status fmi2Get##Type(fmi2Component component, const fmi2ValueReference vr[], size_t nvr,   \
                             fmi2##Type value[])                                                   \
    {                                                                                              \
        BEGIN("fmi2Get" #Type, MASK_Get);                                                          \
        RETURN(get_variables(c, &TYPE, vr, nvr, value));                                           \
    }
#define SETTER(Type, TYPE)                                                                         \
    fmi2Status fmi2Set##Type(fmi2Component component, const fmi2ValueReference vr[], size_t nvr,   \
                             const fmi2##Type value[])                                             \
    {                                                                                              \
        BEGIN("fmi2Set" #Type, MASK_Set);                                                          \
        RETURN(set_variables(c, &TYPE, vr, nvr, value));                                           \
    }

GETTER(Real, REAL)
GETTER(Integer, INTEGER)
GETTER(Boolean, BOOLEAN)
GETTER(String, STRING)
SETTER(Real, REAL)
SETTER(Integer, INTEGER)
SETTER(Boolean, BOOLEAN)
SETTER(String, STRING)

/* -- state ---------------------------------------------------------------------------------- */

/* An FMU state is the tuple (call-sequence state, last successful time, the slave's _get_fmu_state()
 * object): restoring it restores where the instance was in the call sequence too. Serialised as named values
 * by the helper (fmi2_layer.py: dumps, loads), never pickled. NULL with the problem logged if `state` is not
 * such a tuple. */
static PyObject *slave_part(Instance *c, PyObject *state, const char *call, State *where, fmi2Real *time)
{
    if (PyTuple_Check(state) && PyTuple_Size(state) == 3 && PyLong_Check(PyTuple_GetItem(state, 0)) &&
        PyFloat_Check(PyTuple_GetItem(state, 1))) {
        long saved = PyLong_AsLong(PyTuple_GetItem(state, 0));
        if ((saved & MASK_GetFMUstate) != 0 && (saved & (saved - 1)) == 0) { /* one allowed state */
            *where = (State)saved;
            *time = PyFloat_AsDouble(PyTuple_GetItem(state, 1));
            return PyTuple_GetItem(state, 2);
        }
    }
    PyErr_Clear();
    emitf(c, fmi2Error, "%s: %s: not an FMU state of this FMU (saved by another FMU or another version)", c->name,
          call);
    return NULL;
}

fmi2Status fmi2GetFMUstate(fmi2Component component, fmi2FMUstate *state)
{
    BEGIN("fmi2GetFMUstate", MASK_GetFMUstate);
    if (!given(c, state, "fmi2GetFMUstate", "FMUstate") || !has_slave(c, "fmi2GetFMUstate"))
        RETURN(fmi2Error);
    PyObject *got = PyObject_CallMethod(c->slave, "_get_fmu_state", NULL);
    PyObject *whole = got ? Py_BuildValue("(idO)", (int)c->state, c->time, got) : NULL;
    Py_XDECREF(got);
    if (whole == NULL) {
        log_exception(c, "_get_fmu_state");
        RETURN(fmi2Error);
    }
    Py_XDECREF((PyObject *)*state); /* FMI: a state passed in is overwritten */
    *state = whole;
    flush_log(c);
    RETURN(fmi2OK);
}

fmi2Status fmi2SetFMUstate(fmi2Component component, fmi2FMUstate state)
{
    BEGIN("fmi2SetFMUstate", MASK_FMUstate);
    if (!given(c, state, "fmi2SetFMUstate", "FMUstate") || !has_slave(c, "fmi2SetFMUstate"))
        RETURN(fmi2Error);
    State where;
    fmi2Real time;
    PyObject *slave_state = slave_part(c, (PyObject *)state, "fmi2SetFMUstate", &where, &time);
    if (slave_state == NULL)
        RETURN(fmi2Error);
    fmi2Status status =
        settle(c, "_set_fmu_state", PyObject_CallMethod(c->slave, "_set_fmu_state", "(O)", slave_state), fmi2Error);
    if (status <= fmi2Warning) {
        c->state = where;
        c->time = time;
        c->discarded = 0;
    }
    RETURN(status);
}

fmi2Status fmi2FreeFMUstate(fmi2Component component, fmi2FMUstate *state)
{
    BEGIN("fmi2FreeFMUstate", MASK_FMUstate);
    if (state != NULL) {
        Py_XDECREF((PyObject *)*state);
        *state = NULL;
    }
    RETURN(fmi2OK);
}

/* The bytes of `state` (helper.dumps: the slave's identity and its values, a new reference), or NULL with the
 * reason logged: the call's output argument `out` (named `argument`) is NULL, there is no slave or no state, or
 * the state cannot be written. */
static PyObject *serialised(Instance *c, fmi2FMUstate state, const void *out, const char *call, const char *argument)
{
    if (!given(c, out, call, argument) || !has_slave(c, call))
        return NULL;
    PyObject *bytes = state ? PyObject_CallMethod(helper, "dumps", "(OO)", (PyObject *)state, c->slave) : NULL;
    if (bytes == NULL && state == NULL)
        emitf(c, fmi2Error, "%s: no FMU state to serialise", c->name);
    else if (bytes == NULL)
        log_exception(c, "serialising the FMU state");
    return bytes;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component component, fmi2FMUstate state, size_t *size)
{
    BEGIN("fmi2SerializedFMUstateSize", MASK_FMUstate);
    PyObject *bytes = serialised(c, state, size, "fmi2SerializedFMUstateSize", "size");
    if (bytes == NULL)
        RETURN(fmi2Error);
    *size = (size_t)PyBytes_Size(bytes);
    Py_DECREF(bytes);
    RETURN(fmi2OK);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component component, fmi2FMUstate state, fmi2Byte serializedState[],
                                 size_t size)
{
    BEGIN("fmi2SerializeFMUstate", MASK_FMUstate);
    PyObject *bytes = serialised(c, state, serializedState, "fmi2SerializeFMUstate", "serializedState");
    if (bytes == NULL)
        RETURN(fmi2Error);
    size_t n = (size_t)PyBytes_Size(bytes);
    if (n != size) {
        emitf(c, fmi2Error, "%s: the state needs %zu bytes, the host gave %zu (fmi2SerializedFMUstateSize)", c->name,
              n, size);
        Py_DECREF(bytes);
        RETURN(fmi2Error);
    }
    memcpy(serializedState, PyBytes_AsString(bytes), n);
    Py_DECREF(bytes);
    RETURN(fmi2OK);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component component, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *state)
{
    BEGIN("fmi2DeSerializeFMUstate", MASK_FMUstate);
    if (!given(c, serializedState, "fmi2DeSerializeFMUstate", "serializedState") ||
        !given(c, state, "fmi2DeSerializeFMUstate", "FMUstate") || !has_slave(c, "fmi2DeSerializeFMUstate"))
        RETURN(fmi2Error);
    PyObject *bytes = PyBytes_FromStringAndSize(serializedState, (Py_ssize_t)size);
    PyObject *loaded = bytes ? PyObject_CallMethod(helper, "loads", "(OO)", bytes, c->slave) : NULL;
    Py_XDECREF(bytes);
    if (loaded == NULL) {
        log_exception(c, "deserialising the FMU state");
        RETURN(fmi2Error);
    }
    if (PyUnicode_Check(loaded)) { /* refused: the helper says why (another FMU or version, damaged bytes) */
        const char *why = PyUnicode_AsUTF8AndSize(loaded, NULL);
        emitf(c, fmi2Error, "%s: fmi2DeSerializeFMUstate: %s", c->name, why ? why : "refused");
        PyErr_Clear();
        Py_DECREF(loaded);
        RETURN(fmi2Error);
    }
    State where;
    fmi2Real time;
    if (slave_part(c, loaded, "fmi2DeSerializeFMUstate", &where, &time) == NULL) {
        Py_DECREF(loaded);
        RETURN(fmi2Error);
    }
    Py_XDECREF((PyObject *)*state);
    *state = loaded;
    RETURN(fmi2OK);
}

/* -- stepping ------------------------------------------------------------------------------- */

fmi2Status fmi2DoStep(fmi2Component component, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    BEGIN("fmi2DoStep", MASK_DoStep);
    if (!has_slave(c, "fmi2DoStep"))
        RETURN(fmi2Error);
    fmi2Real t = currentCommunicationPoint, h = communicationStepSize;
    c->state = STEP_IN_PROGRESS; /* another thread's call on this instance meanwhile is refused */
    PyObject *t_obj = PyFloat_FromDouble(t), *h_obj = PyFloat_FromDouble(h);
    PyObject *r = t_obj && h_obj ? PyObject_CallMethodObjArgs(c->slave, name_do_step, t_obj, h_obj, NULL) : NULL;
    Py_XDECREF(t_obj);
    Py_XDECREF(h_obj);
    fmi2Status status = settle(c, "do_step", r, fmi2Discard);
    c->state = STEP_COMPLETE; /* also after fmi2Discard: the host may change an input or restore a state */
    if (status == fmi2Discard && c->discarded && c->discard_t == t && c->discard_h == h) {
        /* the host retried the refused step unchanged (fmpy does so forever): stop it here */
        emitf(c, fmi2Error,
              "%s: the step at t = %.17g s, h = %.17g s was refused twice; the reason is logged above", c->name, t, h);
        status = fmi2Error;
    }
    c->discarded = status == fmi2Discard;
    c->discard_t = t;
    c->discard_h = h;
    if (status <= fmi2Warning)
        c->time = t + h;
    RETURN(status);
}

fmi2Status fmi2CancelStep(fmi2Component component)
{
    BEGIN("fmi2CancelStep", MASK_CancelStep);
    emitf(c, fmi2Error, "%s: fmi2CancelStep: steps are synchronous, nothing to cancel", c->name);
    RETURN(fmi2Error);
}

/* The status functions: only fmi2LastSuccessfulTime and fmi2Terminated are available (no asynchronous
 * step); for the other kinds FMI asks for fmi2Discard. */
#define STATUS_BEGIN(call)                                                                         \
    BEGIN(call, MASK_Status);                                                                      \
    if (!given(c, value, call, "value"))                                                           \
    RETURN(fmi2Error)

/* A status kind this FMU never has (no asynchronous step): fmi2Discard once the arguments are checked. */
#define NO_STATUS(name, type)                                                                      \
    fmi2Status name(fmi2Component component, const fmi2StatusKind s, type *value)                  \
    {                                                                                              \
        (void)s;                                                                                   \
        STATUS_BEGIN(#name);                                                                       \
        RETURN(fmi2Discard);                                                                       \
    }

/* The one kind `kind` a status function answers, with `answer`; fmi2Discard for the others. */
#define ONE_STATUS(name, type, kind, answer)                                                       \
    fmi2Status name(fmi2Component component, const fmi2StatusKind s, type *value)                  \
    {                                                                                              \
        STATUS_BEGIN(#name);                                                                       \
        if (s != kind)                                                                             \
            RETURN(fmi2Discard);                                                                   \
        *value = answer;                                                                           \
        RETURN(fmi2OK);                                                                            \
    }

NO_STATUS(fmi2GetStatus, fmi2Status)
ONE_STATUS(fmi2GetRealStatus, fmi2Real, fmi2LastSuccessfulTime, c->time)
NO_STATUS(fmi2GetIntegerStatus, fmi2Integer)
/* a refused step never ends the simulation by itself: the host decides */
ONE_STATUS(fmi2GetBooleanStatus, fmi2Boolean, fmi2Terminated, fmi2False)
NO_STATUS(fmi2GetStringStatus, fmi2String)

/* -- not provided by a Python slave ----------------------------------------------------------- */

static fmi2Status unsupported(fmi2Component component, const char *what)
{
    BEGIN(what, ~0);
    emitf(c, fmi2Error, "%s: %s is not supported by this FMU", c->name, what);
    RETURN(fmi2Error);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz, const fmi2Real du[], fmi2Real dz[])
{
    (void)u, (void)nu, (void)z, (void)nz, (void)du, (void)dz;
    return unsupported(c, "fmi2GetDirectionalDerivative");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return unsupported(c, "fmi2SetRealInputDerivatives");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return unsupported(c, "fmi2GetRealOutputDerivatives");
}
