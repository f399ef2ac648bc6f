/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Minimal test harness: checks print the inputs, expected and actual values
 * and count failures; a test program returns pc_test_finish().
 * A test that needs something missing (a data file, a tool) calls
 * pc_test_skip(), which exits with the CTest skip code 77.
 */
#ifndef PC_TEST_CHECK_H
#define PC_TEST_CHECK_H

#include <stddef.h>

#include "projcurve.h"

extern int pc_test_failures;
extern int pc_test_checks;

void pc_test_fail_at(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#define CHECK(cond)                                                   \
    do {                                                              \
        ++pc_test_checks;                                             \
        if (!(cond))                                                  \
            pc_test_fail_at(__FILE__, __LINE__, "CHECK(%s)", #cond);  \
    } while (0)

/* |actual - expected| <= tol, printing both. */
#define CHECK_NEAR(actual, expected, tol)                                          \
    do {                                                                           \
        ++pc_test_checks;                                                          \
        const double pc_a_ = (actual), pc_e_ = (expected), pc_t_ = (tol);          \
        if (!(fabs(pc_a_ - pc_e_) <= pc_t_))                                       \
            pc_test_fail_at(__FILE__, __LINE__, "%s = %.17g, expected %.17g +- %.3g", \
                            #actual, pc_a_, pc_e_, pc_t_);                         \
    } while (0)

/* A call that must return the given status. */
#define CHECK_STATUS(call, expected)                                                 \
    do {                                                                             \
        ++pc_test_checks;                                                            \
        const projcurve_status pc_s_ = (call);                                       \
        if (pc_s_ != (expected))                                                     \
            pc_test_fail_at(__FILE__, __LINE__, "%s returned %s, expected %s", #call, \
                            projcurve_status_string(pc_s_),                          \
                            projcurve_status_string(expected));                      \
    } while (0)

#define CHECK_OK(call) CHECK_STATUS(call, PROJCURVE_OK)

/* Prints a summary and returns the process exit code. */
int pc_test_finish(const char *name);

/* Exits with code 77 (CTest SKIP_RETURN_CODE) after printing why. */
void pc_test_skip(const char *why);

/* Exits with failure (not a skip) after printing which test data is
 * missing: the data is part of the repository, so its absence is an error. */
void pc_test_missing_data(const char *what);

/* Ends the program (SIGALRM, a test failure) if it runs longer than
 * seconds times PC_TEST_SLOWDOWN: a guard against hangs, not a timing.
 * PC_TEST_SLOWDOWN is 1 in plain builds and larger in the sanitizer and
 * coverage builds, which run the same work several times slower. */
void pc_test_hang_guard(unsigned seconds);

/* Path of a file under tests/data (e.g. "cases/MANIFEST.tsv",
 * "real/horn.xml"), in a static buffer. The root is
 * $PROJCURVE_TEST_DATA_DIR if set, else the source tree's tests/data. */
const char *pc_test_data_path(const char *relative);

/* The whole file at path, NUL-terminated, malloc'd (release with free);
 * its length in *len (may be NULL). NULL when it cannot be opened or read
 * whole. */
char *pc_test_read_file(const char *path, size_t *len);

/* Deterministic pseudo-random numbers for tests (xorshift64*). */
typedef struct pc_test_rng {
    unsigned long long state;
} pc_test_rng;
void pc_test_rng_seed(pc_test_rng *rng, unsigned long long seed);
double pc_test_rng_uniform(pc_test_rng *rng, double lo, double hi);

#endif /* PC_TEST_CHECK_H */
