/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Small STEP files written by a test: instances appended one by one with
 * the next free instance number, then read as a model.
 */
#ifndef PC_TEST_STEP_TEXT_H
#define PC_TEST_STEP_TEXT_H

#include <stddef.h>

#include "projcurve.h"

typedef struct step_text {
    char buf[65536];
    size_t len;
    int next; /* next free instance number; start at 1 */
} step_text;

/* Appends "#n=<fmt>;" and returns n. */
int step_add(step_text *t, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The text wrapped in a header and read; a failed read is a test failure
 * and gives NULL. */
projcurve_model *step_read(projcurve_context *ctx, const step_text *t);

#endif /* PC_TEST_STEP_TEXT_H */
