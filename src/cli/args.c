/* SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* mkdir */

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "cli.h"

int cli_parse_double(const char *text, double *v)
{
    char *end = NULL;
    errno = 0;
    const double x = strtod(text, &end);
    if (end == text || *end != '\0' || errno != 0 || !isfinite(x))
        return 0;
    *v = x;
    return 1;
}

int cli_parse_index(const char *text, size_t *v)
{
    size_t x = 0;
    if (*text == '\0')
        return 0;
    for (const char *p = text; *p; ++p) {
        if (*p < '0' || *p > '9' || x > ((size_t)1 << 53) / 10)
            return 0;
        x = 10 * x + (size_t)(*p - '0');
    }
    *v = x;
    return 1;
}

int cli_parse_reals(const char *text, size_t n, double *v)
{
    const char *p = text;
    for (size_t k = 0; k < n; ++k) {
        char *end = NULL;
        errno = 0;
        v[k] = strtod(p, &end);
        if (end == p || errno != 0 || !isfinite(v[k]))
            return 0;
        if (k + 1 < n) {
            if (*end != ',')
                return 0;
            p = end + 1;
        } else if (*end != '\0') {
            return 0;
        }
    }
    return n > 0;
}

int cli_parse_vec3(const char *text, double v[3])
{
    return cli_parse_reals(text, 3, v);
}

int cli_is_help(const char *arg)
{
    return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0;
}

int cli_usage_error(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    fputs("projcurve: ", stderr);
    vfprintf(stderr, fmt, args);
    fputc('\n', stderr);
    va_end(args);
    return CLI_EXIT_USAGE;
}

int cli_make_dir(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return S_ISDIR(st.st_mode);
    return mkdir(path, 0777) == 0;
}

int cli_make_dirs(const char *path)
{
    char buf[4096];
    const size_t len = strlen(path);
    if (len == 0 || len >= sizeof buf)
        return 0;
    memcpy(buf, path, len + 1);
    /* each '/' after the first character ends a parent: one pass */
    for (size_t i = 1; i < len; ++i) {
        if (buf[i] != '/')
            continue;
        buf[i] = '\0';
        const int ok = cli_make_dir(buf);
        buf[i] = '/';
        if (!ok)
            return 0;
    }
    return cli_make_dir(buf);
}

double cli_now_ms(void)
{
    struct timespec ts;
    if (timespec_get(&ts, TIME_UTC) == 0)
        return 0.0;
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}
