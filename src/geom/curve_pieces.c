/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Control-point boxes of a curve over stretches of t (geom/curve_pieces.h).
 */
#include "geom/curve_pieces.h"

#include <math.h>
#include <string.h>

static int weights_positive(const pc_nurbs_curve *c)
{
    for (size_t i = 0; i < c->n_ctrl; ++i)
        if (!(c->cw[4 * i + 3] > 0.0))
            return 0;
    return 1;
}

projcurve_status pc_curve_pieces_build(projcurve_context *ctx, const projcurve_curve *c,
                                       pc_curve_pieces *out)
{
    memset(out, 0, sizeof *out);
    if (c->kind != PC_CURVE_NURBS || !weights_positive(&c->nurbs))
        return PROJCURVE_OK;
    return pc_bezier_curves_build(ctx, &out->bz, &c->nurbs);
}

void pc_curve_pieces_free(pc_curve_pieces *p)
{
    pc_bezier_curves_free(&p->bz);
}

/* The segment holding t: the last k with breaks[k] <= t (t in the domain). */
static size_t segment_of(const pc_bezier_curves *bz, double t)
{
    size_t lo = 0, hi = bz->n_segments;
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (bz->breaks[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* De Casteljau at s of the n homogeneous points w (4 doubles each), in
 * place: w becomes the part over [s, 1] when keep_right, else over [0, s]. */
static void cut(double *w, int n, double s, int keep_right)
{
    if (keep_right) {
        for (int r = 1; r < n; ++r)
            for (int i = 0; i + r < n; ++i)
                for (int k = 0; k < 4; ++k)
                    w[4 * i + k] += s * (w[4 * (i + 1) + k] - w[4 * i + k]);
        return;
    }
    for (int r = 1; r < n; ++r)
        for (int i = n - 1; i >= r; --i)
            for (int k = 0; k < 4; ++k)
                w[4 * i + k] = w[4 * (i - 1) + k] + s * (w[4 * i + k] - w[4 * (i - 1) + k]);
}

static pc_vec3 point_of(const double *h)
{
    return vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
}

/* What is done with the cut control points of a segment. */
typedef struct cut_sink {
    double *box;                /* grown by the points, or NULL */
    pc_piece_value_fn value;    /* its range taken, or NULL */
    const void *user;
    double range[2];
} cut_sink;

/* Hands the control points of segment k cut to [a, b] (within its breaks)
 * to the sink; its end points into *first / *last when they are not NULL. */
static void add_segment(const pc_bezier_curves *bz, size_t k, double a, double b, cut_sink *sink,
                        pc_vec3 *first, pc_vec3 *last)
{
    const int n = bz->degree + 1;
    double w[4 * (PROJCURVE_MAX_DEGREE + 1)];
    memcpy(w, bz->cw + 4 * (size_t)n * k, 4 * (size_t)n * sizeof *w);
    const double b0 = bz->breaks[k], b1 = bz->breaks[k + 1];
    const double sa = (a - b0) / (b1 - b0);
    double sb = (b - b0) / (b1 - b0);
    if (sa > 0.0) {
        cut(w, n, sa, 1);
        /* sa = 1: the piece is the segment's last point, w all of it */
        sb = sa < 1.0 ? (sb - sa) / (1.0 - sa) : 1.0;
    }
    if (sb < 1.0)
        cut(w, n, sb > 0.0 ? sb : 0.0, 0);
    for (int i = 0; i < n; ++i) {
        const pc_vec3 p = point_of(w + 4 * i);
        if (sink->box != NULL) {
            const double c[3] = {p.x, p.y, p.z};
            box_add_point(sink->box, c);
        }
        if (sink->value != NULL) {
            const double v = sink->value(sink->user, p);
            sink->range[0] = fmin(sink->range[0], v);
            sink->range[1] = fmax(sink->range[1], v);
        }
    }
    if (first != NULL)
        *first = point_of(w);
    if (last != NULL)
        *last = point_of(w + 4 * (n - 1));
}

/* Every segment over [ta, tb] into the sink; 0 when unbounded. */
static int cut_all(const pc_curve_pieces *p, double ta, double tb, cut_sink *sink,
                   pc_vec3 ends[2])
{
    const pc_bezier_curves *bz = &p->bz;
    if (bz->n_segments == 0)
        return 0;
    const double t0 = bz->breaks[0], t1 = bz->breaks[bz->n_segments];
    ta = ta < t0 ? t0 : (ta > t1 ? t1 : ta);
    tb = tb < ta ? ta : (tb > t1 ? t1 : tb);
    const size_t ka = segment_of(bz, ta), kb = segment_of(bz, tb);
    /* at most n_segments passes */
    for (size_t k = ka; k <= kb; ++k) {
        const double a = k == ka ? ta : bz->breaks[k];
        const double b = k == kb ? tb : bz->breaks[k + 1];
        add_segment(bz, k, a, b, sink, ends != NULL && k == ka ? &ends[0] : NULL,
                    ends != NULL && k == kb ? &ends[1] : NULL);
    }
    return 1;
}

int pc_curve_pieces_box(const pc_curve_pieces *p, double ta, double tb, double box[6],
                        pc_vec3 ends[2])
{
    box_empty(box);
    cut_sink sink = {box, NULL, NULL, {0.0, 0.0}};
    return cut_all(p, ta, tb, &sink, ends);
}

int pc_curve_pieces_range(const pc_curve_pieces *p, double ta, double tb,
                          pc_piece_value_fn value, const void *user, double range[2])
{
    cut_sink sink = {NULL, value, user, {INFINITY, -INFINITY}};
    if (!cut_all(p, ta, tb, &sink, NULL))
        return 0;
    range[0] = sink.range[0];
    range[1] = sink.range[1];
    return 1;
}
