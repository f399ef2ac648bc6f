/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The curve parameter ranges that can reach a face (shapeproj/t_ranges.h).
 */
#include "shapeproj/t_ranges.h"

#include <stdlib.h>
#include <string.h>

#include "bezier/bezier.h"
#include "common/array.h"
#include "common/error.h"
#include "shapeproj/face_select.h"

/* Nodes of one segment's tree. */
static size_t tree_nodes(void)
{
    return ((size_t)2 << PC_T_RANGE_DEPTH) - 1;
}

/* The box of n homogeneous points (4 doubles each, weights > 0). */
static void hull_box(const double *cw, int n, double box[6])
{
    box_empty(box);
    for (int i = 0; i < n; ++i) {
        const double *h = cw + 4 * i;
        const double p[3] = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
        box_add_point(box, p);
    }
}

/* The halves at s = 1/2 of the Bezier curve cw (n points, homogeneous) by
 * de Casteljau: left[0..n-1], right[0..n-1]. */
static void halve(const double *cw, int n, double *left, double *right)
{
    double w[4 * (PROJCURVE_MAX_DEGREE + 1)];
    memcpy(w, cw, 4 * (size_t)n * sizeof *w);
    for (int r = 0; r < n; ++r) {
        memcpy(left + 4 * r, w, 4 * sizeof *w);
        memcpy(right + 4 * (n - 1 - r), w + 4 * (n - 1 - r), 4 * sizeof *w);
        for (int i = 0; i + 1 < n - r; ++i)
            for (int k = 0; k < 4; ++k)
                w[4 * i + k] = 0.5 * (w[4 * i + k] + w[4 * (i + 1) + k]);
    }
}

/* The boxes of node k (at depth d) of a segment and below it; recursion
 * bounded by PC_T_RANGE_DEPTH. */
static void fill_tree(const double *cw, int n, size_t k, int d, double *boxes)
{
    hull_box(cw, n, boxes + 6 * k);
    if (d == PC_T_RANGE_DEPTH)
        return;
    double left[4 * (PROJCURVE_MAX_DEGREE + 1)], right[4 * (PROJCURVE_MAX_DEGREE + 1)];
    halve(cw, n, left, right);
    fill_tree(left, n, 2 * k + 1, d + 1, boxes);
    fill_tree(right, n, 2 * k + 2, d + 1, boxes);
}

static int weights_positive(const pc_nurbs_curve *c)
{
    for (size_t i = 0; i < c->n_ctrl; ++i)
        if (!(c->cw[4 * i + 3] > 0.0))
            return 0;
    return 1;
}

projcurve_status pc_curve_boxes_build(projcurve_context *ctx, const projcurve_curve *curve,
                                      const pc_projection_spec *spec, pc_curve_boxes *out)
{
    memset(out, 0, sizeof *out);
    out->t0 = curve->t0;
    out->t1 = curve->t1;
    if (curve->kind != PC_CURVE_NURBS || spec->kind == PROJCURVE_PROJECT_ORTHOGONAL ||
        !weights_positive(&curve->nurbs))
        return PROJCURVE_OK;
    pc_bezier_curves bz;
    projcurve_status st = pc_bezier_curves_build(ctx, &bz, &curve->nurbs);
    if (st != PROJCURVE_OK)
        return st;
    const size_t nodes = tree_nodes();
    const size_t bytes = pc_size_mul(pc_size_mul(bz.n_segments, nodes), 6 * sizeof(double));
    if (bytes == 0) {
        pc_bezier_curves_free(&bz);
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "the curve's boxes overflow");
    }
    out->boxes = malloc(bytes);
    out->breaks = malloc((bz.n_segments + 1) * sizeof *out->breaks);
    if (out->boxes == NULL || out->breaks == NULL) {
        pc_bezier_curves_free(&bz);
        pc_curve_boxes_free(out);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the curve's boxes");
    }
    const int n = bz.degree + 1;
    for (size_t s = 0; s < bz.n_segments; ++s)
        fill_tree(bz.cw + 4 * (size_t)n * s, n, 0, 0, out->boxes + 6 * nodes * s);
    memcpy(out->breaks, bz.breaks, (bz.n_segments + 1) * sizeof *out->breaks);
    out->n_segments = bz.n_segments;
    pc_bezier_curves_free(&bz);
    return PROJCURVE_OK;
}

void pc_curve_boxes_free(pc_curve_boxes *cb)
{
    free(cb->breaks);
    free(cb->boxes);
    memset(cb, 0, sizeof *cb);
}

double pc_t_range_pad(const pc_params *p, double size)
{
    return 1000.0 * pc_params_precision(p) * size;
}

/* The range [a, b] added to out, merged with the last one when the gap is
 * below merge_gap. */
static projcurve_status add_range(projcurve_context *ctx, pc_t_ranges *out, double a, double b,
                                  double merge_gap)
{
    if (out->count > 0 && a - out->items[out->count - 1].b <= merge_gap) {
        out->items[out->count - 1].b = b;
        return PROJCURVE_OK;
    }
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, out, out->count + 1, 4, "curve ranges");
    if (st == PROJCURVE_OK)
        out->items[out->count++] = (pc_t_range){a, b};
    return st;
}

typedef struct range_search {
    const pc_projection_spec *spec;
    const double *face_box;
    const double *boxes; /* one segment's tree */
    double merge_gap;
    pc_t_ranges *out;
} range_search;

static int piece_meets(const range_search *rs, const double piece_box[6])
{
    if (rs->spec->kind == PROJCURVE_PROJECT_CONICAL)
        return pc_cone_box_meets(piece_box, rs->spec->vec, rs->face_box);
    return pc_swept_box_meets(piece_box, rs->spec->vec, rs->face_box);
}

/* The ranges of node k (depth d, over [ta, tb]) and below it; recursion
 * bounded by PC_T_RANGE_DEPTH. */
static projcurve_status search(projcurve_context *ctx, const range_search *rs, size_t k, int d,
                               double ta, double tb)
{
    if (!piece_meets(rs, rs->boxes + 6 * k))
        return PROJCURVE_OK;
    if (d == PC_T_RANGE_DEPTH)
        return add_range(ctx, rs->out, ta, tb, rs->merge_gap);
    const double tm = 0.5 * (ta + tb);
    const projcurve_status st = search(ctx, rs, 2 * k + 1, d + 1, ta, tm);
    return st == PROJCURVE_OK ? search(ctx, rs, 2 * k + 2, d + 1, tm, tb) : st;
}

projcurve_status pc_t_ranges_find(projcurve_context *ctx, const pc_curve_boxes *cb,
                                  const pc_projection_spec *spec, const double face_box[6],
                                  double pad, pc_t_ranges *out)
{
    out->count = 0;
    const double merge_gap = PC_T_RANGE_MERGE_GAP * (cb->t1 - cb->t0);
    if (cb->n_segments == 0)
        return add_range(ctx, out, cb->t0, cb->t1, merge_gap);
    double box[6];
    for (int i = 0; i < 3; ++i) {
        box[i] = face_box[i] - pad;
        box[i + 3] = face_box[i + 3] + pad;
    }
    range_search rs = {spec, box, NULL, merge_gap, out};
    projcurve_status st = PROJCURVE_OK;
    for (size_t s = 0; st == PROJCURVE_OK && s < cb->n_segments; ++s) {
        rs.boxes = cb->boxes + 6 * tree_nodes() * s;
        st = search(ctx, &rs, 0, 0, cb->breaks[s], cb->breaks[s + 1]);
    }
    /* the ends of the domain exactly (the halving rounds) */
    if (st == PROJCURVE_OK && out->count > 0) {
        if (out->items[0].a <= cb->t0)
            out->items[0].a = cb->t0;
        if (out->items[out->count - 1].b >= cb->t1)
            out->items[out->count - 1].b = cb->t1;
    }
    return st;
}
