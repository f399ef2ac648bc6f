/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Pcurves on analytic surfaces: a STEP pcurve is given in the surface's
 * analytic (u, v) (a cylinder's u is its angle, in the file's plane angle
 * unit), the face is built on the surface's exact NURBS, whose (s, t) the
 * angle maps of analytic.h relate to (u, v). A piece whose angle
 * coordinates are constant is carried exactly (its control points mapped);
 * any other is resampled as a polyline in (s, t) at the piece's own
 * parameters, doubling the samples until every chord's middle is within
 * PC_STEP_MAP_TOL_FRACTION of the face's (u, v) tolerance of the mapped
 * curve's point there, and then refitted as a cubic B-spline within that
 * tolerance of the samples and of the mapped curve half way between them
 * (fit/resampled.h; the polyline stays when no cubic of up to 128 spans
 * is).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "brep/curve2.h"
#include "common/error.h"
#include "fit/resampled.h"
#include "io/step_topology.h"

#define PC_STEP_MAP_SAMPLES 16
#define PC_STEP_MAP_MAX_SAMPLES 4096
#define PC_STEP_MAP_TOL_FRACTION 0.25
/* An angle this close to its range's end (relative to a turn) is in it. */
#define PC_STEP_MAP_SLACK 1e-9

static double radians_per_unit(const pc_step_file *f)
{
    return f->radians_per_angle_unit > 0.0 ? f->radians_per_angle_unit : 1.0;
}

static int full_turn(const pc_angle_map *m)
{
    return m->is_angle && m->a1 - m->a0 >= 2.0 * M_PI * (1.0 - PC_STEP_MAP_SLACK);
}

void pc_step_uv_to_analytic(const pc_step_file *f, const pc_angle_map maps[2], const double st[2],
                            double uv[2])
{
    for (int k = 0; k < 2; ++k)
        uv[k] = maps[k].is_angle ? pc_nurbs_to_angle(&maps[k], st[k]) / radians_per_unit(f) : st[k];
}

/* (s, t) of a file (u, v) moved by shift (radians) in the angle
 * directions, clamped into the maps' ranges. */
static void to_nurbs(const pc_step_file *f, const pc_angle_map maps[2], const double shift[2],
                     const double uv[2], double st[2])
{
    for (int k = 0; k < 2; ++k) {
        if (!maps[k].is_angle) {
            st[k] = uv[k];
            continue;
        }
        const double a = fmin(fmax(uv[k] * radians_per_unit(f) + shift[k], maps[k].a0), maps[k].a1);
        st[k] = pc_angle_to_nurbs(&maps[k], a);
    }
}

/* The whole turns (in radians) that move the piece's angle range (its
 * control points' hull) into the map's; 0 when none does (a piece across
 * the seam of the NURBS, or wider than its range). */
static int turns_into_range(const pc_step_file *f, const pc_angle_map maps[2],
                            const pc_piece_input *p, double shift[2])
{
    for (int k = 0; k < 2; ++k) {
        shift[k] = 0.0;
        if (!maps[k].is_angle)
            continue;
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < p->n_ctrl; ++i) {
            lo = fmin(lo, p->ctrl[2 * i + k] * radians_per_unit(f));
            hi = fmax(hi, p->ctrl[2 * i + k] * radians_per_unit(f));
        }
        const double turn = 2.0 * M_PI, slack = PC_STEP_MAP_SLACK * turn;
        const int tries = full_turn(&maps[k]) ? 9 : 1;
        int found = 0;
        for (int j = 0; j < tries && !found; ++j) {
            const double m = (j % 2 ? 1.0 : -1.0) * (double)((j + 1) / 2);
            if (lo + m * turn >= maps[k].a0 - slack && hi + m * turn <= maps[k].a1 + slack)
                shift[k] = m * turn, found = 1;
        }
        if (!found)
            return 0;
    }
    return 1;
}

static int angles_constant(const pc_angle_map maps[2], const pc_piece_input *p)
{
    for (int k = 0; k < 2; ++k)
        for (size_t i = 1; maps[k].is_angle && i < p->n_ctrl; ++i)
            if (p->ctrl[2 * i + k] != p->ctrl[k])
                return 0;
    return 1;
}

/* n + 1 samples of c mapped into out; returns the largest distance of a
 * chord's middle from the mapped curve's point half way. */
static double sample(const pc_step_file *f, const pc_angle_map maps[2], const double shift[2],
                     const pc_curve2 *c, size_t n, double *out)
{
    double t0, t1, uv[2], mid[2], err = 0.0;
    pc_curve2_domain(c, &t0, &t1);
    for (size_t i = 0; i <= n; ++i) {
        pc_curve2_eval(c, t0 + (t1 - t0) * (double)i / (double)n, uv);
        to_nurbs(f, maps, shift, uv, out + 2 * i);
        if (i == 0)
            continue;
        pc_curve2_eval(c, t0 + (t1 - t0) * ((double)i - 0.5) / (double)n, uv);
        to_nurbs(f, maps, shift, uv, mid);
        err = fmax(err, hypot(mid[0] - 0.5 * (out[2 * i - 2] + out[2 * i]),
                              mid[1] - 0.5 * (out[2 * i - 1] + out[2 * i + 1])));
    }
    return err;
}

/* The mapped piece at t: the exact curve the resampled one is fitted to. */
typedef struct mapped_piece {
    const pc_step_file *f;
    const pc_angle_map *maps;
    const double *shift;
    const pc_curve2 *c;
} mapped_piece;

static void mapped_at(const void *user, double t, double *st)
{
    const mapped_piece *m = user;
    double uv[2];
    pc_curve2_eval(m->c, t, uv);
    to_nurbs(m->f, m->maps, m->shift, uv, st);
}

/* The t in [lo, hi] where coordinate k of the mapped piece crosses s
 * (bisection, 60 halvings: below the double spacing of any range). */
static double crossing(const mapped_piece *m, int k, double s, double lo, double hi)
{
    double st[2];
    mapped_at(m, lo, st);
    const int below = st[k] < s;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        mapped_at(m, mid, st);
        if ((st[k] < s) == below)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The breaks of the mapped piece: where it crosses a segment end of an
 * angle map, at which the NURBS's rational quadratic segments meet with a
 * jump in the map's second derivative. Sorted, distinct, inside (t0, t1);
 * PC_FIT_RESAMPLED_MAX_BREAKS + 1 when there are more (no fit then). */
static size_t map_breaks(const mapped_piece *m, const double *st, size_t n, double t0, double t1,
                         double *breaks)
{
    size_t nb = 0;
    for (int k = 0; k < 2; ++k) {
        const pc_angle_map *a = &m->maps[k];
        for (size_t j = 1; a->is_angle && j < a->n_seg; ++j) {
            const double s = pc_angle_to_nurbs(a, a->a0 + (a->a1 - a->a0) * (double)j / (double)a->n_seg);
            for (size_t i = 0; i < n; ++i) {
                if ((st[2 * i + k] < s) == (st[2 * i + 2 + k] < s))
                    continue;
                if (nb == PC_FIT_RESAMPLED_MAX_BREAKS)
                    return nb + 1;
                breaks[nb++] = crossing(m, k, s, t0 + (t1 - t0) * (double)i / (double)n,
                                        t0 + (t1 - t0) * (double)(i + 1) / (double)n);
            }
        }
    }
    qsort(breaks, nb, sizeof *breaks, by_value);
    const double eps = 1e-12 * (t1 - t0);
    size_t kept = 0;
    for (size_t i = 0; i < nb; ++i)
        if (breaks[i] > t0 + eps && breaks[i] < t1 - eps &&
            (kept == 0 || breaks[i] > breaks[kept - 1] + eps))
            breaks[kept++] = breaks[i];
    return kept;
}

/* The polyline st (n + 1 samples) as a cubic when one is within tol of the
 * mapped piece (fit/resampled.h), into p; else p keeps the polyline. */
static projcurve_status compact(const stopo *t, const mapped_piece *m, const double *st,
                                size_t n, double tol, pc_piece_input *p)
{
    double t0, t1;
    pc_curve2_domain(m->c, &t0, &t1);
    double *poles = pc_arena_calloc(t->arena, 2 * PC_FIT_RESAMPLED_POLES, sizeof *poles);
    double *knots = pc_arena_calloc(t->arena, PC_FIT_RESAMPLED_POLES + 4, sizeof *knots);
    if (poles == NULL || knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    double breaks[PC_FIT_RESAMPLED_MAX_BREAKS];
    const size_t n_breaks = map_breaks(m, st, n, t0, t1, breaks);
    const pc_fit_resampled_input in = {.dim = 2, .samples = st, .n = n, .t0 = t0, .t1 = t1,
                                       .breaks = breaks, .n_breaks = n_breaks,
                                       .exact = mapped_at, .user = m, .tol = tol};
    size_t n_poles = 0;
    const projcurve_status status = pc_fit_resampled_cubic(t->f->ctx, &in, poles, knots, &n_poles);
    if (status == PROJCURVE_OK && n_poles > 0 && n_poles < n + 1)
        p->degree = 3, p->n_ctrl = n_poles, p->ctrl = poles, p->weights = NULL, p->knots = knots;
    return status;
}

static projcurve_status resample(const stopo *t, const projcurve_surface *s, const double shift[2],
                                 pc_piece_input *p)
{
    pc_curve2 c;
    if (pc_curve2_init(NULL, &c, p->degree, p->n_ctrl, p->ctrl, p->weights, p->knots, "") != PROJCURVE_OK)
        return PROJCURVE_OK; /* pc_step_check_piece names it */
    const double tol = PC_STEP_MAP_TOL_FRACTION * pc_face_uv_tolerance(s, pc_step_precision(t, s));
    double t0, t1, *st = NULL, err = INFINITY;
    pc_curve2_domain(&c, &t0, &t1);
    size_t n = PC_STEP_MAP_SAMPLES;
    for (;; n *= 2) {
        if ((st = pc_arena_calloc(t->arena, 2 * (n + 1), sizeof *st)) == NULL)
            break;
        err = sample(t->f, t->maps, shift, &c, n, st);
        if (err <= tol || n >= PC_STEP_MAP_MAX_SAMPLES)
            break;
    }
    double *knots = st ? pc_arena_calloc(t->arena, n + 3, sizeof *knots) : NULL;
    if (knots == NULL) {
        pc_curve2_free(&c);
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    }
    knots[0] = t0;
    for (size_t i = 0; i < n; ++i)
        knots[i + 1] = t0 + (t1 - t0) * (double)i / (double)n;
    knots[n + 1] = knots[n + 2] = t1; /* not t0 + (t1 - t0), which may round past t1 */
    p->degree = 1, p->n_ctrl = n + 1, p->ctrl = st, p->weights = NULL, p->knots = knots;
    /* the cubic is checked against the mapped piece itself: it may meet
     * the tolerance where 4097 chords do not */
    const mapped_piece m = {t->f, t->maps, shift, &c};
    const projcurve_status status = compact(t, &m, st, n, tol, p);
    pc_curve2_free(&c);
    if (status != PROJCURVE_OK || p->degree == 3 || err <= tol)
        return status;
    return pc_model_add_skipped(t->f->ctx, t->model,
                                "STEP: a pcurve mapped onto its surface's NURBS at %zu "
                                "samples is within %.3g in (s, t) (wanted %.3g)", n + 1, err, tol);
}

projcurve_status pc_step_piece_to_nurbs(const stopo *t, const projcurve_surface *s, long curve_id,
                                        pc_piece_input *piece)
{
    double shift[2];
    if (!turns_into_range(t->f, t->maps, piece, shift))
        return pc_step_give_up(t, "pcurve #%ld: %s", curve_id,
                               "its angles do not fit the turn of its surface's NURBS");
    if (!angles_constant(t->maps, piece))
        return resample(t, s, shift, piece);
    double *st = pc_arena_calloc(t->arena, 2 * piece->n_ctrl, sizeof *st);
    if (st == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    for (size_t i = 0; i < piece->n_ctrl; ++i)
        to_nurbs(t->f, t->maps, shift, piece->ctrl + 2 * i, st + 2 * i);
    piece->ctrl = st;
    return PROJCURVE_OK;
}

/* Start (end = 0) or end (end = 1) of a piece in its loop's direction. */
static int piece_end(const pc_piece_input *p, int end, double uv[2])
{
    return pc_step_piece_at(p, (p->sense > 0) == (end != 0) ? 1.0 : 0.0, uv);
}

static double gap(const pc_piece_input *a, const pc_piece_input *b, double shift_a, double shift_b,
                  int k)
{
    double e[2], s[2];
    if (!piece_end(a, 1, e) || !piece_end(b, 0, s))
        return INFINITY;
    e[k] += shift_a;
    s[k] += shift_b;
    return hypot(e[0] - s[0], e[1] - s[1]);
}

static int fits(const pc_piece_input *p, int k, double shift, const pc_angle_map *m)
{
    const double slack = PC_STEP_MAP_SLACK * (m->a1 - m->a0);
    for (size_t i = 0; i < p->n_ctrl; ++i)
        if (p->ctrl[2 * i + k] + shift < m->a0 - slack || p->ctrl[2 * i + k] + shift > m->a1 + slack)
            return 0;
    return 1;
}

/* 1 when piece i moved by shift would lie on the other use of its edge in
 * the loop (a seam's two sides are a turn apart: their gaps at a pole are
 * not closed by moving one onto the other). */
static int onto_partner(const pc_piece_input *pieces, size_t n, size_t i, int k, double shift,
                        const pc_angle_map *m)
{
    const double slack = PC_STEP_MAP_SLACK * (m->a1 - m->a0);
    for (size_t j = 0; j < n; ++j)
        if (j != i && pieces[j].edge == pieces[i].edge &&
            fabs(pieces[i].ctrl[k] + shift - pieces[j].ctrl[k]) <= slack)
            return 1;
    return 0;
}

projcurve_status pc_step_join_turns(const stopo *t, pc_piece_input *pieces, size_t n)
{
    for (int k = 0; k < 2 && n > 1; ++k) {
        const pc_angle_map *m = &t->maps[k];
        if (!full_turn(m))
            continue;
        const double period = m->a1 - m->a0; /* s = u at the ends of the range */
        for (size_t i = 0; i < n; ++i) {
            pc_piece_input *p = &pieces[i];
            const pc_piece_input *prev = &pieces[(i + n - 1) % n], *next = &pieces[(i + 1) % n];
            const double now = gap(prev, p, 0.0, 0.0, k) + gap(p, next, 0.0, 0.0, k);
            for (int sign = -1; sign <= 1; sign += 2) {
                const double shift = sign * period;
                const double moved = gap(prev, p, 0.0, shift, k) + gap(p, next, shift, 0.0, k);
                if (!(moved < 0.5 * now) || !fits(p, k, shift, m) || onto_partner(pieces, n, i, k, shift, m))
                    continue;
                double *ctrl = pc_arena_calloc(t->arena, 2 * p->n_ctrl, sizeof *ctrl);
                if (ctrl == NULL)
                    return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
                memcpy(ctrl, p->ctrl, 2 * p->n_ctrl * sizeof *ctrl);
                for (size_t j = 0; j < p->n_ctrl; ++j)
                    ctrl[2 * j + k] += shift;
                p->ctrl = ctrl;
                break;
            }
        }
    }
    return PROJCURVE_OK;
}

/* A degenerate piece a -> b in (s, t): the pole between two pieces. */
static projcurve_status pole_piece(const stopo *t, const double a[2], const double b[2],
                                   pc_piece_input *out)
{
    double *ctrl = pc_arena_calloc(t->arena, 4, sizeof *ctrl);
    double *knots = pc_arena_calloc(t->arena, 4, sizeof *knots);
    if (ctrl == NULL || knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    ctrl[0] = a[0], ctrl[1] = a[1], ctrl[2] = b[0], ctrl[3] = b[1];
    knots[0] = knots[1] = 0.0;
    knots[2] = knots[3] = 1.0;
    *out = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl, .knots = knots, .edge = -1,
                            .sense = 1, .edge_sense = 1, .flags = PC_PIECE_DEGENERATE};
    return PROJCURVE_OK;
}

projcurve_status pc_step_bridge_poles(const stopo *t, const projcurve_surface *s,
                                      const pc_piece_input *in, size_t n, pc_piece_input *out,
                                      size_t *n_out)
{
    const double prec = PC_STEP_PCURVE_CHECK_FACTOR * pc_step_precision(t, s);
    const double tol_uv = pc_face_uv_tolerance(s, pc_step_precision(t, s));
    *n_out = 0;
    for (size_t i = 0; i < n; ++i) {
        out[(*n_out)++] = in[i];
        double e[2], b[2], pe[3], pb[3];
        if (!piece_end(&in[i], 1, e) || !piece_end(&in[(i + 1) % n], 0, b) ||
            hypot(e[0] - b[0], e[1] - b[1]) <= tol_uv || !pc_step_surface_point(s, e, pe) ||
            !pc_step_surface_point(s, b, pb) || pc_step_dist3(pe, pb) > prec)
            continue;
        projcurve_status st = pole_piece(t, e, b, &out[(*n_out)++]);
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}
