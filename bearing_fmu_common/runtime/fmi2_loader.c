/* The FMU's binary (binaries/linux64/<modelIdentifier>.so): finds the Python interpreter, then loads the
 * FMI layer (fmi2_python.abi3.so beside it, fmi2_python.c) and passes every call on.
 *
 * SPDX-License-Identifier: MIT. docs/fmu_runtime.md, "Which Python", is the user's side of this file.
 *
 * This library needs no libpython, so every host loads it: the layer, built for CPython's stable ABI, takes
 * the interpreter's symbols from the process. At the first fmi2Instantiate of this copy:
 * - a Python host (fmpy, libcosimpy, the project's master) already runs Python 3.10 or later: its symbols
 *   are in the global scope and the layer uses them;
 * - a native host has no interpreter: one is searched for (BEARING_FMU_PYTHON if set, and then nothing
 *   else; otherwise python3 and python in each PATH directory, then the interpreter that built the FMU,
 *   resources/python.txt), each candidate asked in a child process for its version, shared libpython and
 *   whether numpy and numba are there; the first with all of them has its libpython loaded into the
 *   global scope (RTLD_GLOBAL: numpy's and numba's extension modules resolve against it) and started as
 *   that executable (a virtual environment's python brings its site-packages). If none qualifies, the
 *   host's logger gets every candidate tried and what it lacks, and fmi2Instantiate returns NULL.
 * Starting Python is serialised process-wide (process_lock): every FMU brings its own copy of this file.
 */
#define _GNU_SOURCE /* dladdr, RTLD_DEFAULT, RTLD_NODELETE, pipe2 */
#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fmi2_function_list.h"
#include "fmi2_shared.h"

extern char **environ;

#define LAYER_FILE "fmi2_python.abi3.so" /* beside this library */
#define OLDEST_MINOR 10                  /* Python 3.10: the stable ABI the layer is built for */
#define LAST_PYCONFIG_MINOR 13           /* Python 3.13: the last started through PyConfig (later: PEP 741) */
#define PROBE_SECONDS 60                 /* a candidate that has not answered by then is given up */

/* -- the layer's functions ------------------------------------------------------------------- */

static struct {
    FMI2_FUNCTIONS(FMI2_POINTER)
} layer; /* all NULL until the layer is loaded: no instance exists before that */

static pthread_mutex_t load_lock = PTHREAD_MUTEX_INITIALIZER; /* this copy's: one loading at a time */

/* A message kept until the loader has released its locks. */
typedef struct Message {
    struct Message *next;
    fmi2Status status;
    char *text;
} Message;

/* The host's logger and the instance it is about. Messages are kept (`kept`, in order) while the loader holds
 * its locks and passed to the logger after: a host's logger may wait for a lock of the host that another host
 * thread holds while it calls fmi2Instantiate, which waits for the loader's locks. */
typedef struct {
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
    const char *name;
    int logging_on;
    Message *kept, **last;
} Host;

static void log_text(fmi2CallbackLogger logger, fmi2ComponentEnvironment env, const char *name, fmi2Status status,
                     const char *category, const char *text)
{
    if (logger == NULL)
        return;
    char *format = printf_safe(text);
    if (format == NULL)
        return;
    logger(env, name, status, category, format);
    free(format);
}

/* Keep a message for the host's logger (passed on by pass_on). */
static void say(Host *host, fmi2Status status, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    char *text = wanted_message(host->logger, host->logging_on, status, fmt, args);
    va_end(args);
    Message *message = text != NULL ? malloc(sizeof *message) : NULL;
    if (message == NULL) {
        free(text);
        return;
    }
    message->text = text;
    message->status = status;
    message->next = NULL;
    *host->last = message;
    host->last = &message->next;
}

/* Pass the kept messages to the host's logger, in order; the loader holds none of its locks. */
static void pass_on(Host *host)
{
    for (Message *message = host->kept, *next; message != NULL; message = next) {
        next = message->next;
        log_text(host->logger, host->env, host->name, message->status,
                 message->status >= fmi2Error ? "logStatusError" : "logAll", message->text);
        free(message->text);
        free(message);
    }
    host->kept = NULL;
    host->last = &host->kept;
}

/* What was tried, for the host's logger: "candidate: what it lacks; ..." */
typedef struct {
    char text[6144];
} Report;

static void note(Report *report, const char *fmt, ...)
{
    size_t n = strlen(report->text);
    if (n > 0 && n + 2 < sizeof report->text) {
        strcpy(report->text + n, "; ");
        n += 2;
    }
    va_list args;
    va_start(args, fmt);
    vsnprintf(report->text + n, sizeof report->text - n, fmt, args);
    va_end(args);
}

/* -- the process-wide lock of the interpreter's start -------------------------------------------- */

/* Each FMU brings its own copy of this library, with its own statics: a mutex of the library would let
 * two copies start Python at once from two host threads (which crashes it), and before Python runs
 * there is no shared Python object to lock. The lock is the name of an abstract Unix socket that carries
 * the process id: binding a name is atomic and exclusive, so the copy that binds it holds the lock; Linux
 * drops the name when the socket is closed or the process ends, so a crash leaves nothing behind (a named
 * semaphore would stay in /dev/shm, held, for a later process of the same id), and other processes never
 * wait for it. Returns the socket to close to release the lock, or -1 if no socket can be made. */
static int process_lock(void)
{
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0)
        return -1;
    struct sockaddr_un address = {.sun_family = AF_UNIX}; /* sun_path[0] = '\0': the abstract namespace */
    int n = snprintf(address.sun_path + 1, sizeof address.sun_path - 1, "bearing_fmu_runtime.%ld", (long)getpid());
    socklen_t length = (socklen_t)(offsetof(struct sockaddr_un, sun_path) + 1 + (size_t)n);
    useconds_t wait = 100; /* us; the holder starts Python: tens to hundreds of milliseconds */
    while (bind(fd, (struct sockaddr *)&address, length) != 0) {
        if (errno != EADDRINUSE) {
            int cause = errno;
            close(fd);
            errno = cause;
            return -1;
        }
        usleep(wait);
        wait = wait < 10000 ? 2 * wait : wait;
    }
    return fd;
}

/* -- finding an interpreter (native hosts) ------------------------------------------------------ */

/* Asked of each candidate in a child process (valid Python 2 too, so that an old `python` can say
 * which version it is): version, executable, shared libpython, which of numpy and numba it lacks.
 * find_spec locates a package without importing it. */
static const char *PROBE_SOURCE =
    "import os, sys\n"
    "lib = ''\n"
    "try:\n"
    "    import sysconfig\n"
    "    d = sysconfig.get_config_var('LIBDIR') or ''\n"
    "    n = sysconfig.get_config_var('INSTSONAME') or sysconfig.get_config_var('LDLIBRARY') or ''\n"
    "    if d and '.so' in n:\n"
    "        lib = os.path.join(d, n)\n"
    "except Exception:\n"
    "    pass\n"
    "try:\n"
    "    from importlib.util import find_spec\n"
    "    missing = [m for m in ('numpy', 'numba') if find_spec(m) is None]\n"
    "except ImportError:\n"
    "    missing = ['numpy', 'numba']\n"
    "sys.stdout.write('BEARING_FMU_PROBE %d.%d.%d\\n%s\\n%s\\n%s\\n' % (tuple(sys.version_info[:3]) + "
    "(sys.executable, lib, ', '.join(missing))))\n";

typedef struct {
    char label[4200];      /* how it was found, for messages: "python3 on PATH (/usr/bin/python3)" */
    char executable[4096]; /* its sys.executable: the program name Python is started with */
    char libpython[4096];
    int major, minor, micro;
} Interpreter;

/* The search's working memory, on the heap (about 60 kB): a host may call fmi2Instantiate on a thread with a
 * small stack, and the search's buffers are sized for paths. */
typedef struct {
    Interpreter found;     /* the interpreter chosen */
    Interpreter candidate; /* the one being probed */
    Report report;         /* every candidate tried and what it lacks */
    char out[8192];        /* a probe's output */
    char label[4200];      /* how the candidate was found */
    char dir[4096], real[PATH_MAX], path[4096 + 16], key[PATH_MAX + 16], hint[4096];
} Search;

/* Run `program -c PROBE_SOURCE`; its output (stdout and stderr) into out. Returns the exit status, or
 * -1 with out saying why it did not run or did not answer in time. */
static int run_probe(const char *program, char *out, size_t size)
{
    int pipe_fds[2];
    out[0] = '\0';
    if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
        snprintf(out, size, "cannot make a pipe (%s)", strerror(errno));
        return -1;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
    char *argv[] = {(char *)program, "-c", (char *)PROBE_SOURCE, NULL};
    pid_t pid;
    int failed = strchr(program, '/') ? posix_spawn(&pid, program, &actions, NULL, argv, environ)
                                      : posix_spawnp(&pid, program, &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_fds[1]);
    if (failed) {
        close(pipe_fds[0]);
        snprintf(out, size, "cannot be run (%s)", strerror(failed));
        return -1;
    }
    size_t n = 0;
    int timed_out = 0;
    time_t deadline = time(NULL) + PROBE_SECONDS;
    for (;;) {
        struct pollfd ready = {.fd = pipe_fds[0], .events = POLLIN};
        int left = (int)(deadline - time(NULL));
        if (left <= 0 || poll(&ready, 1, left * 1000) == 0) {
            timed_out = 1;
            break;
        }
        char chunk[1024];
        ssize_t got = read(pipe_fds[0], chunk, sizeof chunk);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            break;
        size_t keep = (size_t)got < size - 1 - n ? (size_t)got : size - 1 - n;
        memcpy(out + n, chunk, keep);
        n += keep;
    }
    out[n] = '\0';
    close(pipe_fds[0]);
    if (timed_out)
        kill(pid, SIGKILL); /* only the child started here */
    int status = 0;
    pid_t waited;
    do
        waited = waitpid(pid, &status, 0);
    while (waited < 0 && errno == EINTR);
    if (timed_out) {
        snprintf(out, size, "did not answer within %d s", PROBE_SECONDS);
        return -1;
    }
    if (waited < 0) /* the host ignores SIGCHLD: the child was reaped already; judge by its output */
        return strstr(out, "BEARING_FMU_PROBE ") ? 0 : -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* The last non-empty line of text (a traceback's or a shell's error), in place. */
static const char *last_line(char *text)
{
    size_t n = strlen(text);
    while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r'))
        text[--n] = '\0';
    char *line = strrchr(text, '\n');
    return line ? line + 1 : text;
}

/* Is `program` (found as `label`) an interpreter this FMU can start? Fills `found` if so; otherwise notes
 * what it lacks. `required_minor` >= 0: a libpython 3.<required_minor> is already in the process. */
static int probe(Search *search, const char *program, const char *label, int required_minor)
{
    Report *report = &search->report;
    if (strchr(program, '/') != NULL) {
        if (access(program, F_OK) != 0) {
            note(report, "%s: no such file", label);
            return 0;
        }
        if (access(program, X_OK) != 0) {
            note(report, "%s: not executable", label);
            return 0;
        }
    }
    char *out = search->out;
    int status = run_probe(program, out, sizeof search->out);
    char *marker = strstr(out, "BEARING_FMU_PROBE ");
    if (status != 0 || marker == NULL) {
        if (status < 0 && marker == NULL)
            note(report, "%s: %s", label, out[0] ? last_line(out) : "does not run");
        else
            note(report, "%s: does not run as Python (exit status %d: %s)", label, status,
                 out[0] ? last_line(out) : "no output");
        return 0;
    }
    Interpreter *it = &search->candidate;
    memset(it, 0, sizeof *it);
    char *lines[4] = {NULL};
    char *cursor = marker + strlen("BEARING_FMU_PROBE ");
    for (int k = 0; k < 4 && cursor != NULL; k++) {
        lines[k] = cursor;
        cursor = strchr(cursor, '\n');
        if (cursor != NULL)
            *cursor++ = '\0';
    }
    if (lines[3] == NULL || sscanf(lines[0], "%d.%d.%d", &it->major, &it->minor, &it->micro) != 3) {
        note(report, "%s: unexpected answer to the probe", label);
        return 0;
    }
    snprintf(it->label, sizeof it->label, "%s", label);
    snprintf(it->executable, sizeof it->executable, "%s", lines[1]);
    snprintf(it->libpython, sizeof it->libpython, "%s", lines[2]);
    const char *missing = lines[3];
    char version[32];
    snprintf(version, sizeof version, "Python %d.%d.%d", it->major, it->minor, it->micro);
    if (it->major != 3 || it->minor < OLDEST_MINOR) {
        note(report, "%s, %s: this FMU starts Python 3.%d or later", label, version, OLDEST_MINOR);
        return 0;
    }
    if (required_minor >= 0 && it->minor != required_minor) {
        note(report, "%s, %s: the process has libpython 3.%d loaded already", label, version, required_minor);
        return 0;
    }
    if (it->libpython[0] == '\0' || access(it->libpython, R_OK) != 0) {
        note(report, "%s, %s: no shared libpython%s%s (a Python built with --enable-shared, or the distribution's "
             "libpython3.%d package)", label, version, it->libpython[0] ? " " : "", it->libpython, it->minor);
        return 0;
    }
    if (missing[0] != '\0') {
        note(report, "%s, %s: no module%s %s", label, version, strchr(missing, ',') ? "s" : "", missing);
        return 0;
    }
    search->found = *it;
    return 1;
}

/* The search (docs/fmu_runtime.md, "Which Python"): BEARING_FMU_PYTHON alone if it is set; else python3
 * and python in each PATH directory, then the interpreter that built the FMU. */
static int find_python(Search *search, const char *resources, int required_minor)
{
    Report *report = &search->report;
    char *label = search->label;
    const char *env = getenv(PYTHON_ENV);
    if (env != NULL && env[0] != '\0') {
        snprintf(label, sizeof search->label, "%s=%s", PYTHON_ENV, env);
        if (probe(search, env, label, required_minor))
            return 1;
        note(report, "nothing else was tried: %s names the interpreter to use", PYTHON_ENV);
        return 0;
    }
    note(report, "%s: not set", PYTHON_ENV);
    const char *path = getenv("PATH");
    if (path == NULL || path[0] == '\0')
        note(report, "PATH: not set");
    static const char *NAMES[] = {"python3", "python"};
    enum { MAX_TRIED = 64 };
    char (*tried)[PATH_MAX + 16] = malloc(MAX_TRIED * sizeof *tried);
    int n_tried = 0;
    for (const char *dir = path; dir != NULL && *dir != '\0';) {
        const char *end = strchr(dir, ':');
        size_t length = end ? (size_t)(end - dir) : strlen(dir);
        snprintf(search->dir, sizeof search->dir, "%.*s", (int)length, dir);
        const char *resolved = realpath(search->dir, search->real); /* /bin and /usr/bin are often one directory */
        for (int k = 0; k < 2 && length > 0 && resolved != NULL; k++) {
            snprintf(search->path, sizeof search->path, "%s/%s", search->dir, NAMES[k]);
            snprintf(search->key, sizeof search->key, "%s/%s", resolved, NAMES[k]);
            int seen = 0;
            for (int i = 0; i < n_tried; i++)
                seen |= strcmp(tried[i], search->key) == 0;
            if (seen || access(search->path, X_OK) != 0)
                continue; /* a directory without that name is no candidate */
            if (tried != NULL && n_tried < MAX_TRIED)
                snprintf(tried[n_tried++], sizeof tried[0], "%s", search->key);
            snprintf(label, sizeof search->label, "%s on PATH (%s)", NAMES[k], search->path);
            if (probe(search, search->path, label, required_minor)) {
                free(tried);
                return 1;
            }
        }
        dir = end ? end + 1 : NULL;
    }
    free(tried);
    if (resources != NULL && read_hint(resources, PYTHON_HINT, search->hint, sizeof search->hint)) {
        snprintf(label, sizeof search->label, "the interpreter that built the FMU (%s, resources/%s)", search->hint,
                 PYTHON_HINT);
        if (probe(search, search->hint, label, required_minor))
            return 1;
    }
    return 0;
}

/* -- starting it ------------------------------------------------------------------------------ */

/* Python is started with the executable found as its program name (argv[0]: Python finds its prefix, and a
 * virtual environment's pyvenv.cfg, from it), honouring the environment (PYTHONHOME, PYTHONPATH) and the
 * user's site-packages as `python` does, and without Python's start-up signal handlers (SIGPIPE, SIGXFSZ
 * and a SIGINT handler of the host's stay the host's). The layer is built for the stable ABI, which has no
 * start-up API; these are CPython's public, documented start-up functions, looked up in the libpython:
 * - Python 3.14 on: the opaque configuration of PEP 741 (PyInitConfig_Create, options set by name,
 *   Py_InitializeFromInitConfig), which depends on no structure layout, after Py_PreInitialize with
 *   PyPreConfig_InitPythonConfig's pre-configuration (allocated, never written to);
 * - Python 3.10 to 3.13: PyConfig_InitPythonConfig, PyConfig_SetBytesArgv and Py_InitializeFromConfig. The
 *   PyConfig structure is caller-allocated (a buffer larger than any of those versions' PyConfig) and one
 *   field is written, install_signal_handlers, at its place in the head the structure has kept in every
 *   version from 3.8 to 3.14 (Include/cpython/initconfig.h); those versions are released, so their layout
 *   no longer changes. Before writing, the head is checked against what PyConfig_InitPythonConfig and
 *   PyConfig_InitIsolatedConfig wrote into it. */

/* PyStatus (Python 3.8 on), returned by value by the PyConfig functions */
typedef struct {
    int type; /* 0: ok, 1: error, 2: exit */
    const char *func;
    const char *err_msg;
    int exitcode;
} Status;
/* the head of PyConfig (Python 3.8 to 3.14) */
typedef struct {
    int config_init, isolated, use_environment, dev_mode, install_signal_handlers;
} ConfigHead;
#define CONFIG_BYTES 16384   /* more than sizeof(PyConfig) of any of those versions */
#define PRECONFIG_BYTES 1024 /* more than sizeof(PyPreConfig) of any version (40 bytes in 3.8 to 3.14) */

#define LOOK_UP(lib, type, name) ((type)dlsym((lib), (name)))

/* Python 3.10 to 3.13: PyConfig. 1 once Python runs; otherwise 0 with the reason logged. */
static int start_with_pyconfig(Host *host, const Interpreter *it, void *lib)
{
    void (*init_python)(void *) = LOOK_UP(lib, void (*)(void *), "PyConfig_InitPythonConfig");
    void (*init_isolated)(void *) = LOOK_UP(lib, void (*)(void *), "PyConfig_InitIsolatedConfig");
    Status (*set_argv)(void *, ptrdiff_t, char *const *) =
        LOOK_UP(lib, Status(*)(void *, ptrdiff_t, char *const *), "PyConfig_SetBytesArgv");
    Status (*initialize)(const void *) = LOOK_UP(lib, Status(*)(const void *), "Py_InitializeFromConfig");
    void (*clear)(void *) = LOOK_UP(lib, void (*)(void *), "PyConfig_Clear");
    void *config = calloc(1, CONFIG_BYTES), *isolated = calloc(1, CONFIG_BYTES);
    if (!init_python || !init_isolated || !set_argv || !initialize || !clear || !config || !isolated) {
        say(host, fmi2Error, "%s (of %s) lacks Python's start-up functions", it->libpython, it->label);
        free(config);
        free(isolated);
        return 0;
    }
    init_python(config);
    init_isolated(isolated);
    const ConfigHead *python = config, *alone = isolated;
    int laid_out = python->isolated == 0 && python->use_environment == 1 && python->install_signal_handlers == 1 &&
                   alone->isolated == 1 && alone->use_environment == 0 && alone->install_signal_handlers == 0;
    clear(isolated);
    free(isolated);
    if (!laid_out) {
        say(host, fmi2Error, "cannot start Python %d.%d.%d (%s): its PyConfig does not begin as in Python 3.8 to "
            "3.14", it->major, it->minor, it->micro, it->label);
        clear(config);
        free(config);
        return 0;
    }
    ((ConfigHead *)config)->install_signal_handlers = 0;
    char *argv[] = {(char *)it->executable, NULL};
    Status status = set_argv(config, 1, argv);
    if (status.type == 0)
        status = initialize(config);
    clear(config);
    free(config);
    if (status.type != 0) {
        say(host, fmi2Error, "cannot start Python %d.%d.%d (%s): %s%s%s", it->major, it->minor, it->micro, it->label,
            status.func ? status.func : "", status.func ? ": " : "", status.err_msg ? status.err_msg : "unknown error");
        return 0;
    }
    return 1;
}

/* Python 3.14 on: PEP 741's PyInitConfig. Python is pre-initialised first as `python` is (PyPreConfig_InitPythonConfig
 * and Py_PreInitialize, caller-allocated but not written to: the locale, UTF-8 mode in the C locale, PYTHONUTF8),
 * which PyInitConfig cannot express (its pre-configuration is an isolated one, without "decided at start-up"
 * values); the configuration's defaults are those of an isolated interpreter (no signal handlers), and the
 * options that make it start as `python` does are set by name. */
static int start_with_init_config(Host *host, const Interpreter *it, void *lib)
{
    void (*init_preconfig)(void *) = LOOK_UP(lib, void (*)(void *), "PyPreConfig_InitPythonConfig");
    Status (*preinitialize)(const void *) = LOOK_UP(lib, Status(*)(const void *), "Py_PreInitialize");
    void *(*create)(void) = LOOK_UP(lib, void *(*)(void), "PyInitConfig_Create");
    void (*release)(void *) = LOOK_UP(lib, void (*)(void *), "PyInitConfig_Free");
    int (*get_error)(void *, const char **) = LOOK_UP(lib, int (*)(void *, const char **), "PyInitConfig_GetError");
    int (*set_int)(void *, const char *, int64_t) =
        LOOK_UP(lib, int (*)(void *, const char *, int64_t), "PyInitConfig_SetInt");
    int (*set_list)(void *, const char *, size_t, char *const *) =
        LOOK_UP(lib, int (*)(void *, const char *, size_t, char *const *), "PyInitConfig_SetStrList");
    int (*initialize)(void *) = LOOK_UP(lib, int (*)(void *), "Py_InitializeFromInitConfig");
    if (!init_preconfig || !preinitialize || !create || !release || !get_error || !set_int || !set_list ||
        !initialize) {
        say(host, fmi2Error, "%s (of %s) lacks Python's start-up functions", it->libpython, it->label);
        return 0;
    }
    void *preconfig = calloc(1, PRECONFIG_BYTES);
    if (preconfig == NULL) {
        say(host, fmi2Error, "out of memory while starting Python");
        return 0;
    }
    init_preconfig(preconfig);
    Status status = preinitialize(preconfig);
    free(preconfig);
    if (status.type != 0) {
        say(host, fmi2Error, "cannot start Python %d.%d.%d (%s): %s%s%s", it->major, it->minor, it->micro, it->label,
            status.func ? status.func : "", status.func ? ": " : "", status.err_msg ? status.err_msg : "unknown error");
        return 0;
    }
    void *config = create();
    if (config == NULL) {
        say(host, fmi2Error, "out of memory while starting Python");
        return 0;
    }
    static const struct {
        const char *name;
        int64_t value;
    } OPTIONS[] = {/* as PyConfig_InitPythonConfig, without signal handlers */
                   {"isolated", 0},          {"use_environment", 1},     {"user_site_directory", 1},
                   {"safe_path", 0},         {"pathconfig_warnings", 1}, {"parse_argv", 1},
                   {"configure_c_stdio", 1}, {"install_signal_handlers", 0}};
    int ok = 1;
    for (size_t k = 0; ok && k < sizeof OPTIONS / sizeof OPTIONS[0]; k++)
        ok = set_int(config, OPTIONS[k].name, OPTIONS[k].value) == 0;
    char *argv[] = {(char *)it->executable, NULL};
    ok = ok && set_list(config, "argv", 1, argv) == 0 && initialize(config) == 0;
    if (!ok) {
        const char *error = NULL;
        get_error(config, &error);
        say(host, fmi2Error, "cannot start Python %d.%d.%d (%s): %s", it->major, it->minor, it->micro, it->label,
            error ? error : "unknown error");
    }
    release(config);
    return ok;
}

/* Load `it`'s libpython into the global scope (unless one of its version is there already) and start the
 * interpreter (above). */
static int start_python(Host *host, const Interpreter *it, int loaded)
{
    void *lib = RTLD_DEFAULT;
    if (!loaded) {
        lib = dlopen(it->libpython, RTLD_NOW | RTLD_GLOBAL);
        if (lib == NULL) {
            say(host, fmi2Error, "cannot load %s (of %s): %s", it->libpython, it->label, dlerror());
            return 0;
        }
        const char *(*version)(void) = LOOK_UP(lib, const char *(*)(void), "Py_GetVersion");
        char expected[16];
        snprintf(expected, sizeof expected, "%d.%d.", it->major, it->minor);
        if (version == NULL || strncmp(version(), expected, strlen(expected)) != 0) {
            say(host, fmi2Error, "%s (of %s) is not the libpython of Python %d.%d", it->libpython, it->label,
                it->major, it->minor);
            dlclose(lib);
            return 0;
        }
        /* kept for good: extension modules resolve against it, and a Python is never unloaded */
        dlopen(it->libpython, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD | RTLD_NODELETE);
    }
    void *(*save_thread)(void) = LOOK_UP(lib, void *(*)(void), "PyEval_SaveThread");
    if (save_thread == NULL) {
        say(host, fmi2Error, "%s (of %s) lacks Python's start-up functions", it->libpython, it->label);
        return 0;
    }
    int started = 0;
    if (dlsym(lib, "PyInitConfig_Create") != NULL)
        started = start_with_init_config(host, it, lib);
    else if (it->minor <= LAST_PYCONFIG_MINOR)
        started = start_with_pyconfig(host, it, lib);
    else
        say(host, fmi2Error, "cannot start Python %d.%d.%d (%s): its libpython has no PyInitConfig_Create (PEP 741)",
            it->major, it->minor, it->micro, it->label);
    if (!started)
        return 0;
    save_thread(); /* release the GIL: every call of the layer takes it with PyGILState_Ensure */
    return 1;
}

/* Make sure an interpreter runs: the host's, one another FMU started, or one found and started here. */
static int ensure_python(Host *host, const char *resources)
{
    int (*is_initialized)(void) = (int (*)(void))dlsym(RTLD_DEFAULT, "Py_IsInitialized");
    const char *(*version)(void) = (const char *(*)(void))dlsym(RTLD_DEFAULT, "Py_GetVersion");
    int major = 0, minor = 0;
    if (is_initialized != NULL && version != NULL) {
        sscanf(version(), "%d.%d", &major, &minor);
        if (major != 3 || minor < OLDEST_MINOR) {
            say(host, fmi2Error, "the process runs Python %.*s; this FMU needs Python 3.%d or later",
                (int)strcspn(version(), " "), version(), OLDEST_MINOR);
            return 0;
        }
        if (is_initialized())
            return 1; /* the host's interpreter (or one another FMU started) */
    }
    /* no interpreter runs; if a libpython is loaded (a host linked it without starting it), start that one */
    int loaded = is_initialized != NULL && version != NULL;
    Search *search = calloc(1, sizeof *search);
    if (search == NULL) {
        say(host, fmi2Error, "out of memory while looking for a Python interpreter");
        return 0;
    }
    int ok = find_python(search, resources, loaded ? minor : -1);
    if (!ok)
        say(host, fmi2Error,
            "no Python interpreter for this FMU: it needs Python 3.%d or later built with a shared libpython, with "
            "numpy and numba installed. Tried: %s. Set %s to such a python executable (a virtual environment's "
            "bin/python works).", OLDEST_MINOR, search->report.text, PYTHON_ENV, PYTHON_ENV);
    else
        ok = start_python(host, &search->found, loaded);
    const Interpreter *it = &search->found;
    if (ok)
        say(host, fmi2OK, "started Python %d.%d.%d: %s (sys.executable %s, %s)%s%s", it->major, it->minor, it->micro,
            it->label, it->executable, it->libpython, search->report.text[0] ? "; before it: " : "",
            search->report.text);
    free(search);
    return ok;
}

/* -- loading the layer ------------------------------------------------------------------------ */

static int load_layer(Host *host)
{
    Dl_info self; /* a static function's address: this copy, whatever another library exports */
    if (!dladdr((void *)&load_layer, &self) || self.dli_fname == NULL) {
        say(host, fmi2Error, "cannot locate the FMU's binary directory");
        return 0;
    }
    const char *slash = strrchr(self.dli_fname, '/');
    char *path = NULL; /* on the heap: a host thread's stack may be small */
    if (asprintf(&path, "%.*s%s", slash ? (int)(slash - self.dli_fname + 1) : 0, self.dli_fname, LAYER_FILE) < 0) {
        say(host, fmi2Error, "out of memory while loading the FMU's Python layer");
        return 0;
    }
    /* RTLD_LOCAL: its fmi2* functions stay out of the global scope; kept for good (its Python objects live
     * as long as the interpreter) */
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle == NULL) {
        say(host, fmi2Error, "cannot load the FMU's Python layer: %s", dlerror());
        free(path);
        return 0;
    }
    typeof(layer) loaded;
#define LOOKUP(name)                                                                               \
    if ((loaded.name = (name##TYPE *)dlsym(handle, #name)) == NULL) {                              \
        say(host, fmi2Error, "%s lacks %s (an incomplete or altered FMU)", path, #name);           \
        free(path);                                                                                \
        return 0;                                                                                  \
    }
    FMI2_FUNCTIONS(LOOKUP)
    free(path);
    layer = loaded;
    /* keep this library (and so `layer`) loaded when a host unloads it after fmi2FreeInstance (fmpy does) */
    dlopen(self.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 1;
}

/* -- the FMI functions ------------------------------------------------------------------------ */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean loggingOn)
{
    Host host = {functions ? functions->logger : NULL, functions ? functions->componentEnvironment : NULL,
                 instanceName ? instanceName : "", loggingOn, NULL, NULL};
    host.last = &host.kept;
    pthread_mutex_lock(&load_lock);
    int ready = layer.fmi2Instantiate != NULL;
    if (!ready) {
        int lock = process_lock();
        if (lock < 0) /* load_lock still keeps this copy's threads apart */
            say(&host, fmi2Warning, "no process-wide lock (socket: %s): two FMUs started at once from two threads "
                "may fail", strerror(errno));
        char *resources = uri_to_path(fmuResourceLocation);
        ready = ensure_python(&host, resources) && load_layer(&host);
        free(resources);
        if (lock >= 0)
            close(lock);
    }
    pthread_mutex_unlock(&load_lock);
    pass_on(&host);
    return ready ? layer.fmi2Instantiate(instanceName, fmuType, fmuGUID, fmuResourceLocation, functions, visible,
                                         loggingOn)
                 : NULL;
}

void fmi2FreeInstance(fmi2Component c)
{
    if (layer.fmi2FreeInstance != NULL)
        layer.fmi2FreeInstance(c);
}

/* Every other call is the layer's (an instance exists only once the layer is loaded: before, any call has
 * a NULL or foreign instance and gets fmi2Error). */
#define FORWARD(name, params, args)                                                                \
    fmi2Status name params { return layer.name != NULL ? layer.name args : fmi2Error; }

FORWARD(fmi2SetDebugLogging, (fmi2Component c, fmi2Boolean on, size_t n, const fmi2String categories[]),
        (c, on, n, categories))
FORWARD(fmi2SetupExperiment,
        (fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance, fmi2Real start, fmi2Boolean stop_defined,
         fmi2Real stop),
        (c, tolerance_defined, tolerance, start, stop_defined, stop))
FORWARD(fmi2EnterInitializationMode, (fmi2Component c), (c))
FORWARD(fmi2ExitInitializationMode, (fmi2Component c), (c))
FORWARD(fmi2Terminate, (fmi2Component c), (c))
FORWARD(fmi2Reset, (fmi2Component c), (c))
FORWARD(fmi2GetReal, (fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]), (c, vr, n, v))
FORWARD(fmi2GetInteger, (fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]), (c, vr, n, v))
FORWARD(fmi2GetBoolean, (fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]), (c, vr, n, v))
FORWARD(fmi2GetString, (fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]), (c, vr, n, v))
FORWARD(fmi2SetReal, (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]), (c, vr, n, v))
FORWARD(fmi2SetInteger, (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]),
        (c, vr, n, v))
FORWARD(fmi2SetBoolean, (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]),
        (c, vr, n, v))
FORWARD(fmi2SetString, (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]),
        (c, vr, n, v))
FORWARD(fmi2GetFMUstate, (fmi2Component c, fmi2FMUstate *state), (c, state))
FORWARD(fmi2SetFMUstate, (fmi2Component c, fmi2FMUstate state), (c, state))
FORWARD(fmi2FreeFMUstate, (fmi2Component c, fmi2FMUstate *state), (c, state))
FORWARD(fmi2SerializedFMUstateSize, (fmi2Component c, fmi2FMUstate state, size_t *size), (c, state, size))
FORWARD(fmi2SerializeFMUstate, (fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size),
        (c, state, bytes, size))
FORWARD(fmi2DeSerializeFMUstate, (fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state),
        (c, bytes, size, state))
FORWARD(fmi2GetDirectionalDerivative,
        (fmi2Component c, const fmi2ValueReference u[], size_t nu, const fmi2ValueReference z[], size_t nz,
         const fmi2Real du[], fmi2Real dz[]),
        (c, u, nu, z, nz, du, dz))
FORWARD(fmi2SetRealInputDerivatives,
        (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer order[], const fmi2Real v[]),
        (c, vr, n, order, v))
FORWARD(fmi2GetRealOutputDerivatives,
        (fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer order[], fmi2Real v[]),
        (c, vr, n, order, v))
FORWARD(fmi2DoStep, (fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean no_set_prior), (c, t, h, no_set_prior))
FORWARD(fmi2CancelStep, (fmi2Component c), (c))
FORWARD(fmi2GetStatus, (fmi2Component c, const fmi2StatusKind s, fmi2Status *v), (c, s, v))
FORWARD(fmi2GetRealStatus, (fmi2Component c, const fmi2StatusKind s, fmi2Real *v), (c, s, v))
FORWARD(fmi2GetIntegerStatus, (fmi2Component c, const fmi2StatusKind s, fmi2Integer *v), (c, s, v))
FORWARD(fmi2GetBooleanStatus, (fmi2Component c, const fmi2StatusKind s, fmi2Boolean *v), (c, s, v))
FORWARD(fmi2GetStringStatus, (fmi2Component c, const fmi2StatusKind s, fmi2String *v), (c, s, v))
