/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The list of open cases of a sweep test: cases known to fail today, each
 * with the failure classes it is allowed (tests/realdata/realdata_open.tsv). A listed
 * case failing only in its listed classes is reported as open, not as a
 * failure; any other failure fails the test, so the list can only shrink.
 * Lines: the case's key, a tab, its classes separated by spaces; '#' starts
 * a comment line.
 */
#ifndef PC_TEST_OPEN_CASES_H
#define PC_TEST_OPEN_CASES_H

#include <stddef.h>

typedef struct pc_open_case {
    char *key;
    char *classes; /* " a b c " : each name between spaces */
    int seen;      /* the case ran */
    int passed;    /* ... and did not fail */
} pc_open_case;

typedef struct pc_open_cases {
    pc_open_case *items;
    size_t count;
} pc_open_cases;

/* Reads the list at path; a missing file is an empty list. Returns 0 on
 * success, -1 on a malformed line or no memory (after printing why). */
int pc_open_cases_read(const char *path, pc_open_cases *out);

/* The listed case of this key, or NULL. */
pc_open_case *pc_open_cases_find(const pc_open_cases *list, const char *key);

/* 1 when the class name is allowed for the case. */
int pc_open_case_allows(const pc_open_case *c, const char *class_name);

void pc_open_cases_free(pc_open_cases *list);

#endif /* PC_TEST_OPEN_CASES_H */
