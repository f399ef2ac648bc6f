/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The benchmark cases: every row of tests/data/cases/MANIFEST.tsv (IGES
 * surface + curve + mode + tolerances + expected branch count), and, on
 * request, freeform surfaces from tests/data/real/ with curves defined
 * here from the surface itself (so that the projection is known to exist).
 */
#ifndef PCB_CASES_H
#define PCB_CASES_H

#include <stddef.h>

#include "projcurve.h"

#define PCB_CASE_NAME_MAX 64
#define PCB_CASE_ERROR_MAX 200

typedef struct pcb_case {
    char name[PCB_CASE_NAME_MAX];
    int orthogonal;              /* 0 directional, 1 orthogonal */
    double dir[3];               /* directional only */
    double tol_dist;             /* eps_D in model units; 0 = left unset (automatic) */
    double tol_angle_deg;        /* eps_T */
    int expected_branches;       /* -1 when not known */
    int pcurve_degree;           /* PROJCURVE_OPT_PCURVE_DEGREE; 0 = the default (3) */
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    char error[PCB_CASE_ERROR_MAX]; /* non-empty: the case could not be loaded */
    /* Ownership (any may be NULL). */
    projcurve_model *model;
    projcurve_surface *own_surface;
    projcurve_curve *own_curve;
} pcb_case;

typedef struct pcb_case_list {
    pcb_case *items;
    size_t n;
} pcb_case_list;

/* Which real-surface cases pcb_cases_load adds. */
typedef enum pcb_real_cases {
    PCB_REAL_NONE = 0,
    PCB_REAL_SMALL = 1, /* the small lens file only (quick runs) */
    PCB_REAL_ALL = 2
} pcb_real_cases;

/* Loads every manifest case and the chosen real-surface cases.
 * A case that cannot be read is kept with its error set. Returns 0, or -1
 * when the manifest cannot be read (a message is printed). */
int pcb_cases_load(const char *data_dir, pcb_real_cases real, pcb_case_list *list);
void pcb_cases_free(pcb_case_list *list);

/* Options for a case: its tolerances, defaults otherwise. */
projcurve_status pcb_case_options(projcurve_context *ctx, const pcb_case *c,
                                  projcurve_options **out);

/* Runs the case's projection with the given options. */
projcurve_status pcb_case_project(projcurve_context *ctx, const pcb_case *c,
                                  const projcurve_options *opts, projcurve_result **out);

#endif /* PCB_CASES_H */
