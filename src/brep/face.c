/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/face.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"

/* Samples per direction of the periodicity test and of the speed used for
 * the (u, v) tolerance. */
#define PC_FACE_PERIODIC_SAMPLES 9
#define PC_FACE_SPEED_SAMPLES 17

void pc_piece_ends(const pc_face_piece *p, double start[2], double end[2])
{
    double t0, t1;
    pc_curve2_domain(&p->curve, &t0, &t1);
    pc_curve2_eval(&p->curve, p->sense >= 0 ? t0 : t1, start);
    pc_curve2_eval(&p->curve, p->sense >= 0 ? t1 : t0, end);
}

void pc_face_free(projcurve_face *face)
{
    if (face == NULL)
        return;
    for (size_t l = 0; l < face->n_loops; ++l) {
        for (size_t k = 0; k < face->loops[l].n_pieces; ++k)
            pc_curve2_free(&face->loops[l].pieces[k].curve);
        free(face->loops[l].pieces);
        free(face->loops[l].poly);
    }
    free(face->loops);
    pc_classifier_free(&face->cls);
    free(face);
}

double pc_face_uv_tolerance(const projcurve_surface *surface, double tol_model)
{
    double d[4], speed = 0.0;
    if (projcurve_surface_domain(NULL, surface, d) != PROJCURVE_OK)
        return tol_model;
    for (int i = 0; i < PC_FACE_SPEED_SAMPLES; ++i)
        for (int j = 0; j < PC_FACE_SPEED_SAMPLES; ++j) {
            const double u = d[0] + (d[1] - d[0]) * i / (PC_FACE_SPEED_SAMPLES - 1);
            const double v = d[2] + (d[3] - d[2]) * j / (PC_FACE_SPEED_SAMPLES - 1);
            double e[9];
            if (projcurve_surface_eval(NULL, surface, u, v, 1, e) != PROJCURVE_OK)
                continue;
            /* squared speeds: the root once, at the end */
            speed = fmax(speed, fmax(e[3] * e[3] + e[4] * e[4] + e[5] * e[5],
                                     e[6] * e[6] + e[7] * e[7] + e[8] * e[8]));
        }
    return speed > 0.0 ? tol_model / sqrt(speed) : tol_model;
}

/* 1 when S(lo, t) = S(hi, t) (dir 0: across u) at every sample t. */
static int closes(const projcurve_surface *s, const double d[4], int dir, double tol)
{
    for (int k = 0; k < PC_FACE_PERIODIC_SAMPLES; ++k) {
        const double t = dir == 0 ? d[2] + (d[3] - d[2]) * k / (PC_FACE_PERIODIC_SAMPLES - 1)
                                  : d[0] + (d[1] - d[0]) * k / (PC_FACE_PERIODIC_SAMPLES - 1);
        double a[3], b[3];
        if (projcurve_surface_eval(NULL, s, dir == 0 ? d[0] : t, dir == 0 ? t : d[2], 0, a) ||
            projcurve_surface_eval(NULL, s, dir == 0 ? d[1] : t, dir == 0 ? t : d[3], 0, b))
            return 0;
        if (hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]) > tol)
            return 0;
    }
    return 1;
}

static projcurve_status natural_loop(projcurve_context *ctx, const double d[4], pc_face_loop *loop)
{
    loop->pieces = calloc(4, sizeof *loop->pieces);
    if (loop->pieces == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
    const double corner[5][2] = {{d[0], d[2]}, {d[1], d[2]}, {d[1], d[3]}, {d[0], d[3]}, {d[0], d[2]}};
    static const double knots[4] = {0.0, 0.0, 1.0, 1.0};
    loop->outer = 1;
    for (int k = 0; k < 4; ++k) {
        const double ctrl[4] = {corner[k][0], corner[k][1], corner[k + 1][0], corner[k + 1][1]};
        pc_face_piece *p = &loop->pieces[loop->n_pieces];
        projcurve_status st = pc_curve2_init(ctx, &p->curve, 1, 2, ctrl, NULL, knots, "natural boundary");
        if (st != PROJCURVE_OK)
            return st;
        ++loop->n_pieces;
        p->edge = -1;
        p->sense = p->edge_sense = 1;
        p->flags = PC_PIECE_NATURAL;
    }
    return PROJCURVE_OK;
}

static projcurve_status copy_loop(projcurve_context *ctx, const pc_loop_input *in, size_t index,
                                  const pc_face_params *fp, pc_face_loop *loop)
{
    if (in->n_pieces == 0 || in->pieces == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "%s: loop %zu has no pieces",
                       fp->what, index);
    loop->pieces = calloc(in->n_pieces, sizeof *loop->pieces);
    if (loop->pieces == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
    loop->outer = in->outer;
    for (size_t k = 0; k < in->n_pieces; ++k) {
        const pc_piece_input *pi = &in->pieces[k];
        char what[160];
        snprintf(what, sizeof what, "%s loop %zu piece %zu", fp->what, index, k);
        projcurve_status st = pc_curve2_init(ctx, &loop->pieces[k].curve, pi->degree, pi->n_ctrl,
                                             pi->ctrl, pi->weights, pi->knots, what);
        if (st != PROJCURVE_OK)
            return st;
        ++loop->n_pieces;
        loop->pieces[k].edge = pi->edge;
        loop->pieces[k].sense = pi->sense < 0 ? -1 : 1;
        loop->pieces[k].edge_sense = pi->edge_sense < 0 ? -1 : 1;
        loop->pieces[k].flags = pi->flags;
    }
    return PROJCURVE_OK;
}

static projcurve_status check_closed(projcurve_context *ctx, const pc_face_loop *loop,
                                     size_t index, const pc_face_params *fp)
{
    for (size_t k = 0; k < loop->n_pieces; ++k) {
        const size_t next = (k + 1) % loop->n_pieces;
        double s0[2], e0[2], s1[2], e1[2];
        pc_piece_ends(&loop->pieces[k], s0, e0);
        pc_piece_ends(&loop->pieces[next], s1, e1);
        const double gap = hypot(e0[0] - s1[0], e0[1] - s1[1]);
        if (!(gap <= fp->close_tol))
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "%s: loop %zu is open: piece %zu ends at (%.9g, %.9g), piece %zu "
                           "starts at (%.9g, %.9g), %.3g apart (more than %.3g)",
                           fp->what, index, k, e0[0], e0[1], next, s1[0], s1[1], gap,
                           fp->close_tol);
    }
    return PROJCURVE_OK;
}

static double signed_area(const double *p, size_t n)
{
    double a = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        a += (p[2 * i] - p[0]) * (p[2 * j + 1] - p[1]) - (p[2 * j] - p[0]) * (p[2 * i + 1] - p[1]);
    }
    return 0.5 * a;
}

static void reverse_points(double *p, size_t n)
{
    for (size_t i = 0, j = n - 1; i < j; ++i, --j)
        for (int d = 0; d < 2; ++d) {
            const double t = p[2 * i + d];
            p[2 * i + d] = p[2 * j + d];
            p[2 * j + d] = t;
        }
}

/* Flattens a loop into its polygon, pieces in the loop's direction. */
static projcurve_status flatten_loop(projcurve_context *ctx, pc_face_loop *loop, double err,
                                     size_t index, const pc_face_params *fp)
{
    pc_polyline2 line = {0};
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < loop->n_pieces; ++k) {
        const pc_face_piece *p = &loop->pieces[k];
        char what[160];
        snprintf(what, sizeof what, "%s loop %zu piece %zu", fp->what, index, k);
        const size_t first = line.count;
        st = pc_curve2_flatten(ctx, &p->curve, err, &line, what);
        if (st != PROJCURVE_OK || p->sense > 0)
            continue;
        /* against the curve: its end first, then back to (not including) its start */
        double end[2], t0, t1;
        pc_curve2_domain(&p->curve, &t0, &t1);
        pc_curve2_eval(&p->curve, t1, end);
        st = pc_polyline2_push(ctx, &line, end[0], end[1]);
        if (st == PROJCURVE_OK) {
            reverse_points(line.xy + 2 * first, line.count - first);
            /* the start vertex is now last: it belongs to the next piece */
            --line.count;
        }
    }
    if (st == PROJCURVE_OK && line.count < 3)
        st = pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                     "%s: loop %zu flattens to %zu points, encloses no area", fp->what, index,
                     line.count);
    if (st != PROJCURVE_OK) {
        pc_polyline2_free(&line);
        return st;
    }
    loop->poly = line.xy;
    loop->n_poly = line.count;
    return PROJCURVE_OK;
}

static projcurve_status orient_loops(projcurve_context *ctx, projcurve_face *f,
                                     const pc_face_params *fp)
{
    for (size_t l = 0; l < f->n_loops; ++l) {
        pc_face_loop *loop = &f->loops[l];
        const double a = signed_area(loop->poly, loop->n_poly);
        if (a == 0.0)
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "%s: loop %zu encloses no area",
                           fp->what, l);
        if ((a < 0.0) == (l == 0))
            reverse_points(loop->poly, loop->n_poly);
    }
    /* every hole inside the outer loop (tested at its first vertex) */
    const pc_face_loop *outer = &f->loops[0];
    double *seg = malloc(4 * outer->n_poly * sizeof *seg);
    if (seg == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
    for (size_t i = 0; i < outer->n_poly; ++i) {
        const size_t j = (i + 1) % outer->n_poly;
        seg[4 * i] = outer->poly[2 * i], seg[4 * i + 1] = outer->poly[2 * i + 1];
        seg[4 * i + 2] = outer->poly[2 * j], seg[4 * i + 3] = outer->poly[2 * j + 1];
    }
    projcurve_status st = PROJCURVE_OK;
    for (size_t l = 1; l < f->n_loops && st == PROJCURVE_OK; ++l) {
        const double *p = f->loops[l].poly;
        if (pc_winding_brute(seg, outer->n_poly, p[0], p[1]) == 0)
            st = pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                         "%s: loop %zu (a hole) is outside the outer loop: its point (%.9g, "
                         "%.9g) is not inside",
                         fp->what, l, p[0], p[1]);
    }
    free(seg);
    return st;
}

static projcurve_status take_loops(projcurve_context *ctx, projcurve_face *f,
                                   const pc_loop_input *loops, size_t n_loops,
                                   const pc_face_params *fp)
{
    size_t n_outer = 0, outer_at = 0;
    for (size_t l = 0; l < n_loops; ++l)
        if (loops[l].outer)
            ++n_outer, outer_at = l;
    if (n_outer > 1)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "%s: %zu outer loops (at most one)",
                       fp->what, n_outer);
    f->loops = calloc(n_loops + 1, sizeof *f->loops);
    if (f->loops == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
    projcurve_status st = PROJCURVE_OK;
    const int natural = n_outer == 0 && !(fp->pick_outer && n_loops > 0);
    if (natural) {
        f->n_loops = 1;
        st = natural_loop(ctx, f->domain, &f->loops[0]);
    }
    /* the outer loop first, then the holes in their order */
    for (size_t k = 0; k < n_loops && st == PROJCURVE_OK; ++k) {
        const size_t l = n_outer == 0 ? k : (k == 0 ? outer_at : (k <= outer_at ? k - 1 : k));
        st = copy_loop(ctx, &loops[l], l, fp, &f->loops[f->n_loops]);
        ++f->n_loops;
    }
    for (size_t l = 0; l < f->n_loops && st == PROJCURVE_OK; ++l)
        st = check_closed(ctx, &f->loops[l], l, fp);
    for (size_t l = 0; l < f->n_loops && st == PROJCURVE_OK; ++l)
        st = flatten_loop(ctx, &f->loops[l], f->flat_err, l, fp);
    if (st == PROJCURVE_OK && n_outer == 0 && !natural) {
        size_t best = 0;
        for (size_t l = 1; l < f->n_loops; ++l)
            if (fabs(signed_area(f->loops[l].poly, f->loops[l].n_poly)) >
                fabs(signed_area(f->loops[best].poly, f->loops[best].n_poly)))
                best = l;
        const pc_face_loop tmp = f->loops[0];
        f->loops[0] = f->loops[best];
        f->loops[best] = tmp;
        f->loops[0].outer = 1;
    }
    return st;
}

static void face_boxes(projcurve_face *f)
{
    const pc_face_loop *outer = &f->loops[0];
    f->box_uv[0] = f->box_uv[2] = INFINITY;
    f->box_uv[1] = f->box_uv[3] = -INFINITY;
    for (size_t i = 0; i < outer->n_poly; ++i) {
        f->box_uv[0] = fmin(f->box_uv[0], outer->poly[2 * i]);
        f->box_uv[1] = fmax(f->box_uv[1], outer->poly[2 * i]);
        f->box_uv[2] = fmin(f->box_uv[2], outer->poly[2 * i + 1]);
        f->box_uv[3] = fmax(f->box_uv[3], outer->poly[2 * i + 1]);
    }
    projcurve_surface_bounds(NULL, f->surface, f->box);
}

projcurve_status pc_face_build(projcurve_context *ctx, const projcurve_surface *surface,
                               const pc_loop_input *loops, size_t n_loops,
                               const pc_face_params *fp, projcurve_face **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, out, "out");
    if (n_loops > 0 && loops == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "%s: loops is NULL", fp->what);
    if (!(fp->tol_uv > 0.0) || !isfinite(fp->tol_uv) || !(fp->close_tol >= 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "%s: tolerance %g is not positive",
                       fp->what, fp->tol_uv);
    projcurve_face *f = calloc(1, sizeof *f);
    if (f == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
    f->surface = surface;
    projcurve_surface_domain(NULL, surface, f->domain);
    f->same_sense = fp->same_sense < 0 ? -1 : 1;
    f->tol_uv = fp->tol_uv;
    f->tol_model = fp->tol_model;
    f->flat_err = PC_FACE_FLATTEN_FRACTION * fp->tol_uv;
    f->id = fp->id;
    snprintf(f->kind, sizeof f->kind, "%s", fp->kind ? fp->kind : "bspline");
    for (int dir = 0; dir < 2; ++dir)
        f->periodic[dir] = fp->tol_model > 0.0 && closes(surface, f->domain, dir, fp->tol_model);
    projcurve_status st = take_loops(ctx, f, loops, n_loops, fp);
    if (st == PROJCURVE_OK)
        st = orient_loops(ctx, f, fp);
    if (st == PROJCURVE_OK) {
        const double **polys = malloc(f->n_loops * sizeof *polys);
        size_t *counts = malloc(f->n_loops * sizeof *counts);
        if (polys == NULL || counts == NULL)
            st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building a face");
        for (size_t l = 0; st == PROJCURVE_OK && l < f->n_loops; ++l)
            polys[l] = f->loops[l].poly, counts[l] = f->loops[l].n_poly;
        if (st == PROJCURVE_OK)
            st = pc_classifier_build(ctx, &f->cls, f->n_loops, polys, counts, f->tol_uv);
        free(polys);
        free(counts);
    }
    if (st != PROJCURVE_OK) {
        pc_face_free(f);
        return st;
    }
    face_boxes(f);
    *out = f;
    return PROJCURVE_OK;
}
