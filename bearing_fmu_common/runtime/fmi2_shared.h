/* What the FMU's entry library (fmi2_loader.c) and its Python layer (fmi2_python.c) both need: which messages
 * the host's logger takes and in which format, the resources/ hint files and the resource URI. Each includes it once; every function is
 * static, so each library keeps its own copy and exports nothing of it.
 *
 * SPDX-License-Identifier: MIT.
 */
#ifndef BEARING_FMU_FMI2_SHARED_H
#define BEARING_FMU_FMI2_SHARED_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define PYTHON_ENV "BEARING_FMU_PYTHON" /* a Python executable (e.g. venv/bin/python) for a native host */
#define PYTHON_HINT "python.txt"        /* resources/ file: the interpreter that built the FMU */
#define GUID_FILE "guid.txt"            /* resources/ file: the GUID of the FMU's modelDescription.xml */

/* The FMI logger takes a printf format: the text with every '%' doubled (malloc'ed; NULL without memory), so
 * that a host that formats prints it unchanged and a message can never be read as a conversion. */
static char *printf_safe(const char *text)
{
    size_t n = strlen(text), extra = 0;
    for (size_t i = 0; i < n; i++)
        extra += text[i] == '%';
    char *format = malloc(n + extra + 1);
    if (format == NULL)
        return NULL;
    char *out = format;
    for (size_t i = 0; i < n; i++) {
        *out++ = text[i];
        if (text[i] == '%')
            *out++ = '%';
    }
    *out = '\0';
    return format;
}

/* Whether the host's logger takes a message of this status: warnings and errors always, the others (debug
 * messages) only with logging on. */
static int wanted(fmi2CallbackLogger logger, int logging_on, fmi2Status status)
{
    return logger != NULL && (status != fmi2OK || logging_on);
}

/* The message of the printf format `fmt` with `args` if the host's logger takes it (wanted), malloc'ed; NULL if
 * not wanted or without memory. Sized to the message, on the heap: a host thread's stack may be small. */
static char *wanted_message(fmi2CallbackLogger logger, int logging_on, fmi2Status status, const char *fmt,
                            va_list args)
{
    if (!wanted(logger, logging_on, status))
        return NULL;
    va_list again;
    va_copy(again, args);
    int n = vsnprintf(NULL, 0, fmt, args);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (text != NULL)
        vsnprintf(text, (size_t)n + 1, fmt, again);
    va_end(again);
    return text;
}

/* Read the first line of resources/<name> into buf; 0 if absent. */
static int read_hint(const char *resources, const char *name, char *buf, size_t size)
{
    size_t n = strlen(resources) + strlen(name) + 2;
    char *path = malloc(n); /* on the heap, as every buffer sized for a path: a host thread's stack may be small */
    if (path == NULL)
        return 0;
    snprintf(path, n, "%s/%s", resources, name);
    FILE *fh = fopen(path, "r");
    free(path);
    if (fh == NULL)
        return 0;
    int ok = fgets(buf, (int)size, fh) != NULL;
    fclose(fh);
    buf[strcspn(buf, "\r\n")] = '\0';
    return ok && buf[0] != '\0';
}

/* fmuResourceLocation is a file URI (file:///path or file:/path, percent-encoded); malloc'ed path or NULL. */
static char *uri_to_path(const char *uri)
{
    if (uri == NULL)
        return NULL;
    const char *p = uri;
    if (strncmp(p, "file://", 7) == 0) {
        p += 7;
        if (strncmp(p, "localhost", 9) == 0)
            p += 9;
    } else if (strncmp(p, "file:", 5) == 0) {
        p += 5;
    }
    char *path = malloc(strlen(p) + 1), *out = path;
    if (path == NULL)
        return NULL;
    for (; *p; p++) {
        unsigned int byte;
        if (p[0] == '%' && p[1] && p[2] && sscanf(p + 1, "%2x", &byte) == 1) {
            *out++ = (char)byte;
            p += 2;
        } else {
            *out++ = *p;
        }
    }
    *out = '\0';
    size_t n = strlen(path);
    while (n > 1 && path[n - 1] == '/')
        path[--n] = '\0';
    return path;
}

#endif
