/* SPDX-License-Identifier: BSD-3-Clause */
#include "trace_oracle.h"

#include "ray_oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Most hits of one ray considered. */
#define ORACLE_MAX_HITS 16
/* A hit grazes S when |cos| of the angle between Dir and the normal is
 * below this (the library's PROJCURVE_HIT_TANGENT rule, ray_patch.c). */
#define ORACLE_TANGENT_COS 1e-6
/* Hits of the two intersections closer than this fraction of the model
 * size are one point (both polish to ~1e-11 of it). */
#define ORACLE_SAME_HIT 1e-7
/* Mesh of the independent intersection: cells per knot span and side,
 * within bounds (the chord error of a bicubic span of these tests at 24
 * cells is ~1e-4 of its size, far below the folds' curvature radii). */
#define ORACLE_CELLS_PER_SPAN 24
#define ORACLE_MIN_CELLS 96
#define ORACLE_MAX_CELLS 384

/* The independent oracle's evaluator: S, Su, Sv by the public evaluation. */
static void eval_surface(void *user, double u, double v, int n_deriv, double out[9])
{
    projcurve_surface_eval(NULL, (const projcurve_surface *)user, u, v, n_deriv, out);
}

static int mesh_cells(size_t spans)
{
    const size_t c = ORACLE_CELLS_PER_SPAN * spans;
    return c < ORACLE_MIN_CELLS ? ORACLE_MIN_CELLS : (c > ORACLE_MAX_CELLS ? ORACLE_MAX_CELLS : (int)c);
}

/* One brute-force hit: the point and whether it grazes S. */
typedef struct sample_hit {
    double x[3];
    int tangent;
} sample_hit;

typedef struct branch_view {
    double *pts; /* (t, u, v) */
    size_t n;
    double max_dt;    /* largest t-gap between vertices */
    double max_chord; /* largest 3D distance between vertices */
} branch_view;

static void surface_point(const projcurve_surface *s, double u, double v, double out[3])
{
    projcurve_surface_eval(NULL, s, u, v, 0, out);
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Residual of the projection equation at a vertex. */
static void check_vertex(const projcurve_surface *s, const projcurve_curve *c, const double d[3],
                         const double *p, trace_oracle_report *rep)
{
    double sp[3], cp[3];
    surface_point(s, p[1], p[2], sp);
    projcurve_curve_eval(NULL, c, p[0], 0, cp);
    const double w[3] = {sp[0] - cp[0], sp[1] - cp[1], sp[2] - cp[2]};
    const double x[3] = {d[1] * w[2] - d[2] * w[1], d[2] * w[0] - d[0] * w[2],
                         d[0] * w[1] - d[1] * w[0]};
    const double res = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (res > rep->max_residual)
        rep->max_residual = res;
    if (d[0] * w[0] + d[1] * w[1] + d[2] * w[2] <= 0.0 && res > 0.0)
        rep->behind++;
    rep->vertices++;
}

/* Point of branch b at t (interpolated in (u, v)), or 0 when t is outside. */
static int branch_at(const branch_view *b, double t, double uv[2])
{
    if (b->n < 2 || t < b->pts[0] || t > b->pts[3 * (b->n - 1)])
        return 0;
    size_t lo = 0, hi = b->n - 1;
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        if (b->pts[3 * mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    const double *p = b->pts + 3 * lo;
    const double w = p[3] > p[0] ? (t - p[0]) / (p[3] - p[0]) : 0.0;
    uv[0] = p[1] + w * (p[4] - p[1]);
    uv[1] = p[2] + w * (p[5] - p[2]);
    return 1;
}

void trace_oracle_check(const projcurve_surface *s, const projcurve_curve *c, const double dir[3],
                        const projcurve_result *r, size_t n_samples, trace_oracle_report *rep)
{
    memset(rep, 0, sizeof *rep);
    const double dn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const double d[3] = {dir[0] / dn, dir[1] / dn, dir[2] / dn};
    const size_t nb = projcurve_result_branch_count(r);
    branch_view *views = calloc(nb ? nb : 1, sizeof *views);
    double max_chord = 0.0;
    for (size_t i = 0; i < nb; ++i) {
        size_t n = 0;
        projcurve_result_branch_points(NULL, r, i, 0, NULL, &n);
        views[i].pts = malloc(3 * (n ? n : 1) * sizeof(double));
        projcurve_result_branch_points(NULL, r, i, n, views[i].pts, &views[i].n);
        for (size_t k = 0; k < n; ++k) {
            check_vertex(s, c, d, views[i].pts + 3 * k, rep);
            if (k > 0) {
                const double *p = views[i].pts + 3 * k;
                double a[3], b[3];
                surface_point(s, p[-2], p[-1], a);
                surface_point(s, p[1], p[2], b);
                views[i].max_chord = fmax(views[i].max_chord, dist3(a, b));
                views[i].max_dt = fmax(views[i].max_dt, p[0] - p[-3]);
            }
        }
        max_chord = fmax(max_chord, views[i].max_chord);
    }
    rep->step = max_chord;
    /* uncovered hits of the previous sample, to measure runs of them */
    double prev_far[3 * 2 * ORACLE_MAX_HITS];
    size_t n_prev_far = 0;
    double run = 0.0;
    double t0, t1;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    double dom[4], box[6];
    size_t spans_u = 1, spans_v = 1;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &spans_u, &spans_v, NULL);
    const double lo[3] = {box[0], box[1], box[2]}, hi[3] = {box[3], box[4], box[5]};
    const double same = ORACLE_SAME_HIT * dist3(lo, hi);
    pc_oracle_mesh mesh;
    const int have_mesh = pc_oracle_mesh_build(&mesh, eval_surface, (void *)s, dom,
                                               mesh_cells(spans_u), mesh_cells(spans_v));
    rep->mesh_failed = !have_mesh;
    for (size_t k = 0; k < n_samples; ++k) {
        const double t = t0 + (t1 - t0) * (double)k / (double)(n_samples - 1);
        double p[3], hits[3 * ORACLE_MAX_HITS];
        unsigned flags[ORACLE_MAX_HITS];
        size_t n_lib = 0;
        projcurve_curve_eval(NULL, c, t, 0, p);
        projcurve_surface_intersect_line(NULL, s, p, d, 1, ORACLE_MAX_HITS, hits, flags, &n_lib);
        rep->samples++;
        if (n_lib > ORACLE_MAX_HITS)
            n_lib = ORACLE_MAX_HITS;
        /* the independent intersection's hits, then the library's that it
         * did not find (grazing pairs the mesh can miss): each must be
         * covered */
        sample_hit all[2 * ORACLE_MAX_HITS];
        size_t count = 0;
        pc_oracle_hit oh[ORACLE_MAX_HITS];
        size_t n_or = have_mesh ? pc_oracle_line_hits(&mesh, p, d, 1, oh, ORACLE_MAX_HITS) : 0;
        if (n_or > ORACLE_MAX_HITS)
            n_or = ORACLE_MAX_HITS;
        for (size_t h = 0; h < n_or; ++h) {
            surface_point(s, oh[h].u, oh[h].v, all[count].x);
            all[count++].tangent = oh[h].cos_dir < ORACLE_TANGENT_COS;
        }
        rep->oracle_hits += n_or;
        for (size_t h = 0; h < n_lib; ++h) {
            const double x[3] = {p[0] + hits[3 * h + 2] * d[0], p[1] + hits[3 * h + 2] * d[1],
                                 p[2] + hits[3 * h + 2] * d[2]};
            int known = 0;
            for (size_t i = 0; i < n_or && !known; ++i)
                known = dist3(all[i].x, x) <= same;
            if (known)
                continue;
            memcpy(all[count].x, x, sizeof x);
            all[count++].tangent = (flags[h] & PROJCURVE_HIT_TANGENT) != 0;
            rep->library_only++;
        }
        for (size_t i = 0; i < n_or; ++i) {
            int known = 0;
            for (size_t h = 0; h < n_lib && !known; ++h) {
                const double x[3] = {p[0] + hits[3 * h + 2] * d[0],
                                     p[1] + hits[3 * h + 2] * d[1],
                                     p[2] + hits[3 * h + 2] * d[2]};
                known = dist3(all[i].x, x) <= same;
            }
            rep->oracle_only += !known;
        }
        double far[3 * 2 * ORACLE_MAX_HITS];
        size_t n_far = 0;
        for (size_t h = 0; h < count; ++h) {
            const double *x = all[h].x;
            rep->hits++;
            int covered = 0, near_end = 0;
            for (size_t i = 0; i < nb && !covered; ++i) {
                double uv[2], q[3];
                if (branch_at(&views[i], t, uv)) {
                    surface_point(s, uv[0], uv[1], q);
                    covered = dist3(q, x) <= 0.5 * views[i].max_chord + 1e-9;
                }
                if (views[i].n >= 2) {
                    const double a = views[i].pts[0], b = views[i].pts[3 * (views[i].n - 1)];
                    const double reach = 2.0 * views[i].max_dt;
                    near_end |= fabs(t - a) <= reach || fabs(t - b) <= reach;
                }
            }
            if (covered) {
                rep->covered++;
            } else if (near_end || all[h].tangent) {
                rep->uncovered_near++;
            } else {
                rep->uncovered_far++;
                rep->worst_far_t = t;
                memcpy(far + 3 * n_far++, x, 3 * sizeof *x);
            }
        }
        /* extend the run by the closest step between uncovered hits of
         * consecutive samples, or restart it */
        double link = INFINITY;
        for (size_t a = 0; a < n_far; ++a)
            for (size_t b = 0; b < n_prev_far; ++b)
                link = fmin(link, dist3(far + 3 * a, prev_far + 3 * b));
        run = n_far == 0 ? 0.0 : (isfinite(link) ? run + link : 0.0);
        if (run > rep->missed_arc)
            rep->missed_arc = run;
        memcpy(prev_far, far, 3 * n_far * sizeof(double));
        n_prev_far = n_far;
    }
    if (have_mesh)
        pc_oracle_mesh_free(&mesh);
    for (size_t i = 0; i < nb; ++i)
        free(views[i].pts);
    free(views);
}

int trace_oracle_missed_branch(const trace_oracle_report *rep)
{
    return rep->missed_arc > 2.0 * rep->step;
}

void trace_oracle_print(const char *name, const trace_oracle_report *rep)
{
    printf("%s: %zu samples, %zu hits (%zu by the mesh, %zu only by the library, %zu missed by "
           "the library), %zu covered, %zu near ends, %zu missed (t=%.6g, longest run %.3g on "
           "S, step %.3g); %zu vertices, max residual %.3g, %zu behind%s\n",
           name, rep->samples, rep->hits, rep->oracle_hits, rep->library_only, rep->oracle_only,
           rep->covered, rep->uncovered_near, rep->uncovered_far, rep->worst_far_t,
           rep->missed_arc, rep->step, rep->vertices, rep->max_residual, rep->behind,
           rep->mesh_failed ? " (NO MESH)" : "");
}
