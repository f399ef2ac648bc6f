/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Shared state of the tolerance control of one branch (refine/). The stages,
 * each in its own file:
 *   vertices.c   growable vertex lists
 *   exact.c      exact points of the projection (corrector seeded from the
 *                traced polyline) and images on S
 *   cells.c      which Bezier patch holds a segment; exact knot-line crossings
 *   deviation.c  Hausdorff distance of a composed segment to the exact curve
 *   split.c      the subdivision loop: knot lines, then Hausdorff (eps_D)
 *   march.c      the vertices: a step-controlled march along the exact curve
 *   march_step.c what both marches share: a step's candidate end, the
 *                fallback past a failure, a piece's end directions
 *   angle.c      joint angle control (eps_T)
 *   march_cubic.c, cubic.c   the same march with cubic Hermite pcurves
 *   corners.c    corners of the curve P: fixed vertices, one-sided tangents
 *   refine.c     the driver: options, branches, composition, statistics
 */
#ifndef PC_REFINE_INTERNAL_H
#define PC_REFINE_INTERNAL_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "common/budget.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

/* Largest degree of a composed piece and its homogeneous storage. */
#define PC_PIECE_MAX_DEGREE (2 * PROJCURVE_MAX_DEGREE)
#define PC_PIECE_MAX_CW (4 * (PC_PIECE_MAX_DEGREE + 1))

/* A vertex of the parameter-space polyline: curve parameter t and (u, v).
 * `fixed` marks the vertices every output keeps: branch ends and the
 * knot-line crossings of the traced polyline (the march runs between them).
 * `gap` marks a vertex after which the exact projection could not be
 * followed (the corrector fails all the way down to the parameter floor,
 * e.g. where the traced polyline jumped across a fold): the segment to the
 * next vertex is not composed and the branch is split there (refine.c). */
typedef struct pc_rvertex {
    double t, u, v;
    int fixed;
    int gap; /* 0, or a pc_gap_kind */
    /* Cubic pcurves (march_cubic.c): when in_cubic is 1, the segment ending
     * here is the cubic Hermite from the previous vertex with the (u, v)
     * derivatives in_d0 there and in_d1 here (q' per unit t, one-sided at
     * knot lines). Meaningful only in cubic mode, where every vertex after
     * a branch's first sets it. */
    int in_cubic;
    double in_d0[2], in_d1[2];
    /* q'(t) at this vertex when has_d (from the projector's derivatives,
     * not at knot lines): the corrector's guesses between two such
     * vertices are then cubic Hermite, O(h^4) off the curve instead of the
     * chord's O(h^2), and Newton converges in one step (exact.c). */
    int has_d;
    double d[2];
} pc_rvertex;

/* Why a segment is a gap: the corrector failed, or the vertex before it is
 * on a silhouette (|det J| below the tracer's fold threshold: the exact
 * tangent is undefined there and the branch ends, as the tracer ends it). */
typedef enum pc_gap_kind { PC_GAP_FAILED = 1, PC_GAP_SILHOUETTE = 2 } pc_gap_kind;

typedef struct pc_vertex_list {
    pc_rvertex *items;
    size_t count, capacity;
} pc_vertex_list;

typedef struct pc_refiner {
    projcurve_context *ctx;
    const pc_projector *proj;
    const pc_nurbs_surface *nurbs;
    const pc_patch_grid *grid;
    double eps_d;        /* distance to reach, model units (safety factor applied) */
    double cos_eps_t;    /* cosine of the joint angle tolerance */
    double half_angle;   /* eps_T / 2 in radians (safety applied): the bound on
                            each piece end's tangent error */
    double step;         /* the march's current parameter step (0 = none yet) */
    size_t forced;       /* segments the march accepted without meeting the bounds */
    double min_dt;       /* parameter intervals below this are not split */
    double t_range;      /* the branch's parameter range */
    double min_move;     /* uv step below which a knot crossing is converged */
    double snap;         /* a crossing this close (u, v) to a patch corner is put on it */
    double snap_far;     /* a crossing bracketed to min_dt this close to its knot line is
                            put on it; farther, the curve jumps across the line */
    /* The traced polyline (ascending t, knot crossings included): bracketing
     * exact points give the corrector its initial guesses. */
    const pc_rvertex *guide;
    size_t n_guide;
    size_t max_vertices; /* output vertices allowed for this branch (pieces + 1) */
    int limit_hit;       /* set when max_vertices stopped the refinement */
    size_t gaps;         /* gap vertices made (see pc_rvertex) */
    int last_singular;   /* the last pc_refine_exact_tangent was at a vertex
                            with |det J| below the fold threshold */
    int last_has_d;      /* and it gave q' (last_d) from the projector */
    double last_d[2];
    size_t hint_u, hint_v;
    int pcurve_degree;   /* 1 (straight segments) or 3 (cubic Hermite) */
    /* The call's budget (NULL: none), polled once per output vertex: the
     * work between two is bounded (the march's rejections, a split's
     * depth). The branch being refined covers the stage's progress
     * [progress_lo, progress_lo + progress_width] over its t from t_lo. */
    pc_budget *budget;
    double progress_lo, progress_width, t_lo;
} pc_refiner;

/* vertices.c */
projcurve_status pc_vertex_list_push(projcurve_context *ctx, pc_vertex_list *list,
                                     const pc_rvertex *v);
void pc_vertex_list_free(pc_vertex_list *list);

/* Appends v to the output list unless the vertex budget or the call's
 * budget is spent (then sets r->limit_hit and returns LIMIT_REACHED). */
projcurve_status pc_refine_output(pc_refiner *r, pc_vertex_list *out, const pc_rvertex *v);
/* Marks the last output vertex as a gap of the given kind, then appends v. */
projcurve_status pc_refine_output_gap(pc_refiner *r, pc_vertex_list *out, const pc_rvertex *v,
                                      pc_gap_kind kind);

/* exact.c: the exact projection point at t between the exact vertices a and b
 * (t between a.t and b.t): the corrector started from the interpolation of
 * the closest known exact points. Returns 1 on success. */
int pc_refine_exact_point(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b, double t,
                          pc_rvertex *out);
/* Index of the last guide vertex with t_k <= t (0 if none). */
size_t pc_refine_guide_index(const pc_refiner *r, double t);
/* S(u, v). */
pc_vec3 pc_refine_surface_point(pc_refiner *r, double u, double v);

/* v moved onto the knot lines it lies within r->snap of (rounding of the
 * tracer's corrector: a traced vertex 1e-14 beside a knot line would
 * otherwise count as crossing it, and the crossing, found a rounding error
 * later in t, would leave a run too short for the corrector). */
void pc_refine_snap_to_knot_lines(const pc_refiner *r, pc_rvertex *v);

/* corners.c: 1 when the exact projection may turn at v: v lies on an inner
 * knot line of S (pc_refine_on_knot_line) or at a corner of P (a knot
 * where P is only C0); the tangents there are one-sided. */
int pc_refine_at_crease(const pc_refiner *r, const pc_rvertex *v);
/* corners.c: marks the vertices of list at a corner of P fixed: every
 * output keeps them, so no piece straddles a corner. */
void pc_refine_fix_corners(const pc_refiner *r, pc_vertex_list *list);
/* corners.c: the curve parameter at which to evaluate the derivatives of
 * the projection at t for the side before t (the neighbouring double when
 * t is a corner of P, t elsewhere). */
double pc_refine_corner_left(const pc_refiner *r, double t);

/* cells.c: the patch whose closed parameter box holds both a and b (then the
 * whole segment lies in it), or NULL. */
const pc_bezier_patch *pc_refine_common_patch(const pc_refiner *r, const pc_rvertex *a,
                                              const pc_rvertex *b);
/* 1 when v lies on an inner knot line (then S may have a crease there). */
int pc_refine_on_knot_line(const pc_refiner *r, const pc_rvertex *v);
/* For a segment with no common patch: the vertex where the projection meets
 * the first knot line crossed by the chord a-b, lying exactly on that line
 * and strictly between a and b in t. Returns 0 (out untouched) when the
 * corrector cannot give it or the segment is below min_dt: then there is no
 * vertex on the projection to offer, and the caller makes a gap. */
int pc_refine_knot_crossing(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                            pc_rvertex *out);

/* deviation.c: Rational Bezier curve of degree n (homogeneous cw): point and
 * first two derivatives at s (n >= 2). */
void pc_piece_eval(int n, const double *cw, double s, pc_vec3 out[3]);
/* Distance from x to the composed curve, by Newton on the foot parameter from
 * s0 (an upper bound of the true distance; *s_foot may be NULL). */
double pc_piece_distance(int n, const double *cw, pc_vec3 x, double s0, double *s_foot);
/* Estimated Hausdorff distance between the segment a-b, composed as the
 * degree-n curve cw, and the exact projection over [a.t, b.t]; *t_far gets
 * where it is largest. Stops early with the first value found above limit.
 * INFINITY when the exact curve could not be evaluated. */
double pc_refine_deviation(pc_refiner *r, int n, const double *cw, const pc_rvertex *a,
                           const pc_rvertex *b, double limit, double *t_far);

/* split.c: appends the vertices after a up to and including b (out's last
 * vertex is a), subdividing until every segment lies in one patch and, when
 * `hausdorff` is set, is within eps_D. Statuses: OK, LIMIT_REACHED, NO_MEMORY. */
projcurve_status pc_refine_split(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                 int hausdorff, pc_vertex_list *out);

/* march.c: tangent of the exact projection at v along increasing t, on the
 * side of v towards `other` (an exact point on the same run): at a knot line
 * of S, where the surface may have a crease, the one-sided tangent by a
 * short difference; elsewhere q' from the projector. Zero if unavailable,
 * and at a near-singular vertex (then r->last_singular is set): there the
 * direction of q' = J^-1 (...) is not resolved and no angle is bound. */
pc_vec3 pc_refine_exact_tangent(pc_refiner *r, const pc_rvertex *v, const pc_rvertex *other);

/* march_step.c: the step a march run (or its restart after a gap) first
 * tries, from h, the step last taken: never below the length at which a
 * piece's end directions are resolved. */
double pc_refine_march_start_step(const pc_refiner *r, double h);
/* march_step.c: the candidate end for a step h from cur towards the run
 * end b: b itself when h reaches it, else the exact point at cur.t + h
 * (at most half of what remains: two balanced pieces rather than a long
 * one and a sliver). Returns 1 when the corrector reached it. */
int pc_refine_march_candidate(pc_refiner *r, const pc_rvertex *cur, const pc_rvertex *b,
                              double h, pc_rvertex *cand);
/* march_step.c: the first traced vertex after cur (or b): what is known of
 * the exact curve when the corrector cannot reach it from cur. */
pc_rvertex pc_refine_next_known(const pc_refiner *r, const pc_rvertex *cur, const pc_rvertex *b);
/* march_step.c: the direction of the start (at_end = 0) or end tangent of
 * the rational Bezier curve cw of degree n, both along increasing s: the
 * derivative of A / w at an end is (A' - w' C) / w with A' = n (cw_1 -
 * cw_0); only its direction is needed, so the positive factors are dropped. */
pc_vec3 pc_refine_end_direction(int n, const double *cw, int at_end);

/* march.c: appends the vertices after a up to and including b (ascending t,
 * out's last vertex is a): every segment in one patch, within eps_D, and with
 * end tangents within eps_T / 2 of the exact ones. Statuses: OK,
 * LIMIT_REACHED, NO_MEMORY. */
projcurve_status pc_refine_march(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                 pc_vertex_list *out);

/* march_cubic.c: pc_refine_march for cubic pcurves: the same contract, and
 * every vertex appended says through in_cubic how its segment is made
 * (cubic Hermite, or a straight segment where the cubic would leave its
 * patch or q' is not available). */
projcurve_status pc_refine_march_cubic(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                       pc_vertex_list *out);

/* cubic.c: the (u, v) derivative q' of the exact projection at v, with S's
 * derivatives taken inside `patch` (one-sided on its boundary, where S may
 * have a crease). Returns 1 on success. */
int pc_refine_uv_tangent(pc_refiner *r, const pc_rvertex *v, const pc_bezier_patch *patch,
                         double d[2]);
/* cubic.c: the Hermite pcurve of the segment a-b (a.t < b.t) with the
 * derivatives d0 at a and d1 at b, as Bezier control points uv[8]; 0 when
 * they leave patch's box (beyond rounding, which is clamped away). */
int pc_refine_hermite(const pc_refiner *r, const pc_bezier_patch *patch, const pc_rvertex *a,
                      const pc_rvertex *b, const double d0[2], const double d1[2], double uv[8]);
/* refine.c: appends to b the composed piece cw (homogeneous, degree n) of
 * the segment a-e, in Cartesian form with its weights when S is rational,
 * without weights (exactly polynomial) when not. Statuses: OK, NO_MEMORY,
 * BAD_DEGREE. */
projcurve_status pc_refine_store_piece(pc_refiner *r, pc_branch *b, int n, const double *cw,
                                       int rational, const pc_rvertex *a, const pc_rvertex *e);
/* cubic.c: composes the segment from-to whose pcurve `seg` holds (seg is the
 * later of the two in t; from may be either end) and appends it to branch
 * b. *done is 0 (nothing appended) when seg holds no cubic or it cannot be
 * composed: the caller then makes the straight piece. */
projcurve_status pc_refine_add_cubic_piece(pc_refiner *r, pc_branch *b, const pc_rvertex *from,
                                           const pc_rvertex *to, const pc_rvertex *seg,
                                           int rational, int *done);

/* angle.c: inserts vertices until every joint angle is within eps_T (needed
 * only where the march had to force a segment);
 * `list` is replaced by the result (scratch is working storage). */
projcurve_status pc_refine_angles(pc_refiner *r, pc_vertex_list *list, pc_vertex_list *scratch);

/* deviation.c: the composed segment a-b (both in patch): its degree is
 * returned, its homogeneous control points written to cw. */
int pc_refine_compose(const pc_bezier_patch *patch, const pc_rvertex *a, const pc_rvertex *b,
                      double *cw);

#endif /* PC_REFINE_INTERNAL_H */
