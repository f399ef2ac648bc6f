/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The CPU time of one case's projection per stage of the engine (seeding,
 * tracing, jump sweep, refinement, composition, verification, fitting),
 * read by the engine's stage clock (common/stage_clock.h) through its
 * internal entry points: the same call as the public one, with the clock
 * set in its parameters.
 */
#ifndef PCB_PROFILE_H
#define PCB_PROFILE_H

#include <stddef.h>

#include "cases.h"
#include "common/stage_clock.h"

typedef struct pcb_profile {
    double tol;                        /* eps_D used (model units) */
    double total_ms;                   /* CPU ms per call, whole call */
    double stage_ms[PC_STAGE_COUNT];   /* per call; "other" = total - the rest */
    double pieces, points;             /* of the last call */
    double poles, pcurve_poles;        /* compact 3D curves and pcurves, summed */
    double calls;                      /* calls averaged */
} pcb_profile;

/* Profiles case c at eps_D = tol with the case's options otherwise (the
 * library's defaults but for its tolerances): calls repeated until they
 * take min_s of CPU (at least 3; one when quick). Returns 0, or -1 with a
 * message in status. */
int pcb_profile_case(const pcb_case *c, double tol, int quick, double min_s, pcb_profile *out,
                     char *status, size_t status_size);

/* Prints the header and one row of the profile table. */
void pcb_profile_print_header(void);
void pcb_profile_print(const char *name, const char *label, const pcb_profile *p);

#endif /* PCB_PROFILE_H */
