/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An independent check of a directional projection result: dense brute
 * force (the ray P(t) + lambda Dir, lambda > 0, intersected with S at n
 * evenly spaced t) against the traced branches, and every traced vertex
 * against the projection equation. The ray's hits are those of the
 * independent mesh intersection of ray_oracle.h (which shares nothing with
 * the seed finder of the tracer), joined by those of the public
 * line/surface intersection that it does not find (grazing pairs a mesh
 * can miss): a hit missed by the library's intersection, and so by the
 * tracer's seeds, is still a hit the branches must cover.
 */
#ifndef PC_TEST_TRACE_ORACLE_H
#define PC_TEST_TRACE_ORACLE_H

#include <stddef.h>

#include "projcurve.h"

typedef struct trace_oracle_report {
    size_t samples;        /* t values sampled */
    size_t hits;           /* ray hits found by brute force (both intersections) */
    size_t oracle_hits;    /* of them, found by the mesh intersection */
    size_t library_only;   /* found by the public intersection alone */
    size_t oracle_only;    /* found by the mesh, not by the public intersection */
    int mesh_failed;       /* the mesh could not be built (out of memory) */
    size_t covered;        /* hits within half a step of a branch at that t */
    size_t uncovered_near; /* hits not covered, within two steps of a branch end */
    size_t uncovered_far;  /* hits not covered elsewhere: a missed branch */
    double worst_far_t;    /* t of one such hit */
    double missed_arc;     /* longest run of such hits over consecutive
                              samples, as an arc length on S */
    double step;           /* largest chord of the traced polylines: the
                              arc-length step ds */
    double max_residual;   /* max over vertices of |Dir x (S - P)| (model units) */
    size_t behind;         /* vertices with (S - P).Dir <= 0 */
    size_t vertices;
} trace_oracle_report;

/* The criterion: no branch missed that spans more than two steps. */
int trace_oracle_missed_branch(const trace_oracle_report *rep);

void trace_oracle_check(const projcurve_surface *s, const projcurve_curve *c, const double dir[3],
                        const projcurve_result *r, size_t n_samples, trace_oracle_report *rep);

/* Prints the report (for failing tests). */
void trace_oracle_print(const char *name, const trace_oracle_report *rep);

#endif /* PC_TEST_TRACE_ORACLE_H */
