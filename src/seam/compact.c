/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The compact forms of two branches joined at a seam made one (seam.h):
 * each pair of B-splines concatenated with a knot of multiplicity p at the
 * joint, the second one's poles shifted into the first one's unwrapped
 * (u, v). When the degrees differ the pcurve is the joined pieces'
 * pcurves instead and the 3D curve is dropped (docs/seams.md).
 */
#include "seam/seam.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"

/* Concatenates a (over [.., t*]) and b (over [t*, ..]) into *out: a's
 * poles but the last, the joint (mean of a's last and b's first + shift),
 * b's poles but the first (+ shift); knots of a but its last, b's from its
 * (p + 1)-th. b's weights are scaled so that the joint's two weights agree
 * (a rational B-spline is unchanged by one common factor). *gap gets the
 * distance of the two ends. Returns 0 (and *out untouched) where the
 * degrees differ or b's first inner knot lies before a's end (spans of
 * ~1e-12), 1 on success, -1 when out of memory. */
static int concat(const pc_bspline *a, const pc_bspline *b, const double *shift,
                  pc_bspline *out, double *gap)
{
    const size_t p = (size_t)a->degree, dim = (size_t)a->dim;
    if (a->degree != b->degree || a->dim != b->dim || a->n_poles < 2 || b->n_poles < 2)
        return 0;
    const size_t na = a->n_poles, nb = b->n_poles, n = na + nb - 1;
    const double t_join = a->knots[na + p];
    if (b->knots[p + 1] < t_join)
        return 0;
    const int rational = a->weights != NULL || b->weights != NULL;
    double *knots = malloc((n + p + 1) * sizeof *knots);
    double *poles = malloc(n * dim * sizeof *poles);
    double *weights = rational ? malloc(n * sizeof *weights) : NULL;
    if (knots == NULL || poles == NULL || (rational && weights == NULL)) {
        free(knots);
        free(poles);
        free(weights);
        return -1;
    }
    memcpy(knots, a->knots, (na + p) * sizeof *knots);
    memcpy(knots + na + p, b->knots + p + 1, nb * sizeof *knots);
    memcpy(poles, a->poles, (na - 1) * dim * sizeof *poles);
    double g2 = 0.0;
    for (size_t d = 0; d < dim; ++d) {
        const double ea = a->poles[(na - 1) * dim + d];
        const double eb = b->poles[d] - (shift != NULL ? shift[d] : 0.0);
        poles[(na - 1) * dim + d] = 0.5 * (ea + eb);
        g2 += (ea - eb) * (ea - eb);
        for (size_t k = 1; k < nb; ++k)
            poles[(na - 1 + k) * dim + d] =
                b->poles[k * dim + d] - (shift != NULL ? shift[d] : 0.0);
    }
    if (rational) {
        const double wa = a->weights ? a->weights[na - 1] : 1.0;
        const double scale = wa / (b->weights ? b->weights[0] : 1.0);
        for (size_t k = 0; k < na; ++k)
            weights[k] = a->weights ? a->weights[k] : 1.0;
        for (size_t k = 1; k < nb; ++k)
            weights[na - 1 + k] = scale * (b->weights ? b->weights[k] : 1.0);
    }
    *out = (pc_bspline){a->degree, a->dim, n, knots, poles, weights};
    *gap = sqrt(g2);
    return 1;
}

/* The cubic Bezier points (u, v) of piece p's pcurve, shifted by -shift. */
static void cubic_pcurve(const pc_piece *p, const double shift[2], double out[8])
{
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 2; ++k) {
            const double c =
                p->uv_degree == 3
                    ? p->uv_ctrl[2 * i + k]
                    : p->uv_ctrl[k] + (p->uv_ctrl[2 + k] - p->uv_ctrl[k]) * i / 3.0;
            out[2 * i + k] = c - shift[k];
        }
}

/* The pcurve of b then next (pieces in increasing t) as their pieces'
 * cubic pcurves joined, knots of multiplicity 3 at the joins, next's
 * shifted by -shift: exact on the composed pieces, as fit/joined.c. */
static int joined_pieces(const pc_branch *b, const pc_branch *next, const double shift[2],
                         pc_bspline *out)
{
    const size_t np = b->n_pieces + next->n_pieces, n = 3 * np + 1;
    double *knots = malloc((n + 4) * sizeof *knots);
    double *poles = malloc(2 * n * sizeof *poles);
    if (knots == NULL || poles == NULL || np == 0) {
        free(knots);
        free(poles);
        return np == 0 ? 0 : -1;
    }
    static const double zero[2] = {0.0, 0.0};
    for (size_t k = 0; k < np; ++k) {
        const int second = k >= b->n_pieces;
        const pc_piece *p = second ? &next->pieces[k - b->n_pieces] : &b->pieces[k];
        double c[8];
        cubic_pcurve(p, second ? shift : zero, c);
        for (size_t i = k == 0 ? 0 : 1; i < 4; ++i)
            for (size_t d = 0; d < 2; ++d)
                poles[2 * (3 * k + i) + d] = c[2 * i + d];
        for (size_t i = 0; i < 3; ++i)
            knots[1 + 3 * k + i] = p->t0;
        if (k == 0)
            knots[0] = p->t0;
        if (k + 1 == np)
            for (size_t i = 0; i < 4; ++i)
                knots[n + i] = p->t1;
    }
    *out = (pc_bspline){3, 2, n, knots, poles, NULL};
    return 1;
}

projcurve_status pc_seam_join_compact(projcurve_context *ctx, pc_branch *b,
                                      const pc_branch *next, const double shift[2])
{
    pc_bspline pcurve = {0}, curve = {0};
    double gap_uv = 0.0, gap_xyz = 0.0;
    int ok = concat(&b->compact_pcurve, &next->compact_pcurve, shift, &pcurve, &gap_uv);
    pc_compact_kind kind = b->compact == PC_COMPACT_FITTED && next->compact == PC_COMPACT_FITTED
                               ? PC_COMPACT_FITTED
                               : PC_COMPACT_JOINED;
    if (ok == 0) {
        ok = joined_pieces(b, next, shift, &pcurve);
        kind = PC_COMPACT_JOINED;
    }
    int ok3 = 0;
    if (ok == 1 && b->compact_curve.n_poles > 0 && next->compact_curve.n_poles > 0)
        ok3 = concat(&b->compact_curve, &next->compact_curve, NULL, &curve, &gap_xyz);
    if (ok < 0 || ok3 < 0) {
        pc_bspline_free(&pcurve);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory joining compact forms");
    }
    if (ok == 0) { /* no pieces to join: no compact forms */
        pc_bspline_free(&b->compact_pcurve);
        pc_bspline_free(&b->compact_curve);
        b->compact = PC_COMPACT_NONE;
        return PROJCURVE_OK;
    }
    /* Moving the joint pole by half the gap moves a B-spline by at most
     * that much (its basis is a partition of unity): the 3D curve's error
     * grows by half its gap. The pcurve's gap is in (u, v); in space its
     * two ends lie within their errors ea, eb of the same exact point, so
     * the halfway joint moves S o q by about (ea + eb) / 2 (to first
     * order). */
    const double ea = b->compact_pcurve_error, eb = next->compact_pcurve_error;
    b->compact_pcurve_error = ea < 0.0 || eb < 0.0 ? -1.0
                              : fmax(ea, eb) + (gap_uv > 0.0 ? 0.5 * (ea + eb) : 0.0);
    pc_bspline_free(&b->compact_pcurve);
    b->compact_pcurve = pcurve;
    b->compact = kind;
    pc_bspline_free(&b->compact_curve);
    if (ok3 == 1) {
        b->compact_curve = curve;
        b->compact_curve_error =
            fmax(b->compact_curve_error, next->compact_curve_error) + 0.5 * gap_xyz;
    } else {
        b->compact_curve_error = -1.0;
    }
    return PROJCURVE_OK;
}
