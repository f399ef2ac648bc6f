/* SPDX-License-Identifier: BSD-3-Clause */
#include "check.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int pc_test_failures = 0;
int pc_test_checks = 0;

void pc_test_fail_at(const char *file, int line, const char *fmt, ...)
{
    ++pc_test_failures;
    fprintf(stderr, "%s:%d: FAIL: ", file, line);
    va_list args;
    va_start(args, fmt);
    vfprintf(stderr, fmt, args);
    va_end(args);
    fputc('\n', stderr);
}

int pc_test_finish(const char *name)
{
    printf("%s: %d checks, %d failures\n", name, pc_test_checks, pc_test_failures);
    return pc_test_failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

void pc_test_skip(const char *why)
{
    printf("SKIP: %s\n", why);
    exit(77);
}

void pc_test_missing_data(const char *what)
{
    fprintf(stderr, "FAIL: test data %s is missing (tests/data is part of the repository; "
                    "$PROJCURVE_TEST_DATA_DIR, if set, must name a copy of it)\n",
            what);
    exit(EXIT_FAILURE);
}

void pc_test_hang_guard(unsigned seconds)
{
    alarm(seconds * (unsigned)PC_TEST_SLOWDOWN);
}

const char *pc_test_data_path(const char *relative)
{
    static char buffer[4096];
    const char *root = getenv("PROJCURVE_TEST_DATA_DIR");
    if (root == NULL || root[0] == '\0')
        root = PC_TEST_DATA_DIR;
    snprintf(buffer, sizeof buffer, "%s/%s", root, relative);
    return buffer;
}

void pc_test_rng_seed(pc_test_rng *rng, unsigned long long seed)
{
    rng->state = seed ? seed : 0x9E3779B97F4A7C15ull;
}

double pc_test_rng_uniform(pc_test_rng *rng, double lo, double hi)
{
    unsigned long long x = rng->state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    rng->state = x;
    const unsigned long long r = x * 0x2545F4914F6CDD1Dull;
    return lo + (hi - lo) * ((double)(r >> 11) * 0x1.0p-53);
}

char *pc_test_read_file(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (fp == NULL)
        return NULL;
    char *text = NULL;
    long n = -1;
    if (fseek(fp, 0, SEEK_END) == 0)
        n = ftell(fp);
    if (n >= 0 && fseek(fp, 0, SEEK_SET) == 0)
        text = malloc((size_t)n + 1);
    if (text != NULL && fread(text, 1, (size_t)n, fp) != (size_t)n) {
        free(text);
        text = NULL;
    }
    fclose(fp);
    if (text != NULL) {
        text[n] = '\0';
        if (len != NULL)
            *len = (size_t)n;
    }
    return text;
}
