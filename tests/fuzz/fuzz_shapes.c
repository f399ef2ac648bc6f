/* SPDX-License-Identifier: BSD-3-Clause */
#include "fuzz_shapes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define FUZZ_MAX_DEGREE 3
#define FUZZ_MAX_EXTRA 4 /* control points beyond degree + 1, per direction */

uint8_t fuzz_byte(fuzz_bytes *b)
{
    return b->at < b->size ? b->data[b->at++] : 0;
}

/* A signed value in [-1, 1) from one byte. */
static double signed_unit(fuzz_bytes *b)
{
    return ((double)fuzz_byte(b) - 128.0) / 128.0;
}

/* n + degree + 1 knots: clamped with interior knots from the bytes (a zero
 * increment repeats a knot, so multiplicities up to and past the degree
 * occur) or, with the flag, unclamped; scaled by a power of two. */
static void make_knots(fuzz_bytes *b, int degree, size_t n, double *k)
{
    const uint8_t mode = fuzz_byte(b);
    const double scale = ldexp(1.0, (int)(mode >> 4) - 8);
    const size_t m = n + (size_t)degree + 1;
    double t = 0.0;
    for (size_t i = 0; i < m; ++i) {
        const int clamped_end = (mode & 1) == 0 && (i <= (size_t)degree || i >= n);
        if (i > 0 && !(clamped_end && i <= (size_t)degree))
            t += clamped_end && i > n ? 0.0 : (double)(fuzz_byte(b) % 4);
        k[i] = t * scale;
    }
    /* a last increment of 0 would leave an empty domain: make the domain
     * end one step beyond the last interior knot (not always: an empty
     * domain is an input to refuse, too) */
    if ((mode & 2) == 0 && k[n] == k[degree])
        for (size_t i = n; i < m; ++i)
            k[i] += scale;
}

static void make_weights(fuzz_bytes *b, size_t n, double *w)
{
    for (size_t i = 0; i < n; ++i)
        w[i] = 0.25 + 4.0 * (double)fuzz_byte(b) / 255.0;
}

projcurve_status fuzz_make_surface(projcurve_context *ctx, fuzz_bytes *b,
                                   projcurve_surface **out)
{
    const uint8_t shape = fuzz_byte(b);
    const int du = 1 + shape % FUZZ_MAX_DEGREE, dv = 1 + (shape / 3) % FUZZ_MAX_DEGREE;
    const uint8_t counts = fuzz_byte(b);
    const size_t nu = (size_t)du + 1 + counts % (FUZZ_MAX_EXTRA + 1);
    const size_t nv = (size_t)dv + 1 + (counts / 5) % (FUZZ_MAX_EXTRA + 1);
    double net[3 * 64], w[64], ku[16], kv[16];
    const int free_form = (shape & 0x40) != 0, rational = (shape & 0x80) != 0;
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            double *p = net + 3 * (j * nu + i);
            /* a height field over the unit grid (folds when the offsets
             * are large), or a free net */
            const double reach = free_form ? 4.0 : 0.45;
            p[0] = (free_form ? 0.0 : (double)i) + reach * signed_unit(b);
            p[1] = (free_form ? 0.0 : (double)j) + reach * signed_unit(b);
            p[2] = 2.0 * signed_unit(b);
        }
    make_knots(b, du, nu, ku);
    make_knots(b, dv, nv, kv);
    if (rational)
        make_weights(b, nu * nv, w);
    return projcurve_surface_create_nurbs(ctx, du, dv, nu, nv, net, rational ? w : NULL, ku, kv,
                                          out);
}

projcurve_status fuzz_make_curve(projcurve_context *ctx, fuzz_bytes *b, projcurve_curve **out)
{
    const uint8_t shape = fuzz_byte(b);
    const int degree = 1 + shape % FUZZ_MAX_DEGREE;
    const size_t n = (size_t)degree + 1 + (shape / 3) % (FUZZ_MAX_EXTRA + 1);
    double pts[3 * 8], w[8], k[12];
    const int rational = (shape & 0x80) != 0;
    for (size_t i = 0; i < n; ++i) {
        /* above the unit grid of the surfaces, a little beyond it */
        pts[3 * i] = 3.0 * (signed_unit(b) + 1.0) - 0.5;
        pts[3 * i + 1] = 3.0 * (signed_unit(b) + 1.0) - 0.5;
        pts[3 * i + 2] = 3.0 * signed_unit(b) + ((shape & 0x40) ? 0.0 : 3.0);
    }
    make_knots(b, degree, n, k);
    if (rational)
        make_weights(b, n, w);
    return projcurve_curve_create_nurbs(ctx, degree, n, pts, rational ? w : NULL, k, out);
}

void fuzz_make_direction(fuzz_bytes *b, double dir[3])
{
    const uint8_t mode = fuzz_byte(b);
    const double spread = (mode & 1) ? 4.0 : 0.25;
    dir[0] = spread * signed_unit(b);
    dir[1] = spread * signed_unit(b);
    dir[2] = (mode & 1) ? spread * signed_unit(b) : -1.0;
}

projcurve_status fuzz_make_options(projcurve_context *ctx, fuzz_bytes *b,
                                   projcurve_options **out)
{
    projcurve_options *o = NULL;
    projcurve_status st = projcurve_options_create(ctx, &o);
    if (st != PROJCURVE_OK)
        return st;
    const uint8_t f = fuzz_byte(b), tol = fuzz_byte(b), angle = fuzz_byte(b);
    st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_MAX_WORK, FUZZ_MAX_WORK);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TIME_LIMIT, FUZZ_TIME_LIMIT);
    /* eps_D from 1e-1 to 1e-7 (below the 1e-12-of-the-size floor only for
     * tiny models, which is then refused with a status), or automatic */
    if (st == PROJCURVE_OK && (tol & 0x80))
        st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE,
                                          pow(10.0, -1.0 - (double)(tol % 7)));
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_ANGLE_DEG,
                                          1.0 + (double)(angle % 45));
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, (f & 1) ? 3 : 1);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_FOOT_POINTS, (f >> 1) & 1);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_JUMP_DETECTION, !((f >> 2) & 1));
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_COMPOSE, !((f >> 3) & 1));
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_METHOD,
                                       ((f >> 4) & 3) == 3 ? PROJCURVE_METHOD_RK4
                                                           : PROJCURVE_METHOD_SECOND_ORDER);
    if (st == PROJCURVE_OK && (f & 0x40))
        st = projcurve_options_set_int(ctx, o, PROJCURVE_OPT_MAX_PIECES, 1 + tol % 64);
    if (st != PROJCURVE_OK) {
        projcurve_options_destroy(o);
        return st;
    }
    *out = o;
    return PROJCURVE_OK;
}

static void finding(const char *what, projcurve_context *ctx)
{
    fprintf(stderr, "fuzz finding: %s (%s)\n", what, projcurve_context_message(ctx));
    abort();
}

void fuzz_require_message(projcurve_context *ctx, projcurve_status st)
{
    if (st != PROJCURVE_OK && projcurve_context_message(ctx)[0] == '\0')
        finding("a failed call left no message", ctx);
}

void fuzz_walk_result(projcurve_context *ctx, const projcurve_result *r)
{
    const size_t n = projcurve_result_branch_count(r);
    double value = 0.0;
    for (int key = PROJCURVE_STAT_POINTS; key <= PROJCURVE_STAT_MAX_ERROR; ++key)
        if (r != NULL && projcurve_result_stat(ctx, r, (projcurve_stat)key, &value) != PROJCURVE_OK)
            finding("a statistic of a result could not be read", ctx);
    (void)projcurve_result_failure_count(r);
    const size_t dim = (size_t)projcurve_result_point_dim(r);
    for (size_t i = 0; i < n; ++i) {
        double t[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n_points = 0, n_pieces = 0, got = 0;
        if (projcurve_result_branch_info(ctx, r, i, t, &start, &end, &n_points, &n_pieces) !=
            PROJCURVE_OK)
            finding("branch_info failed on an existing branch", ctx);
        double *pts = malloc((n_points ? n_points : 1) * (dim ? dim : 1) * sizeof *pts);
        if (pts != NULL &&
            projcurve_result_branch_points(ctx, r, i, n_points, pts, &got) != PROJCURVE_OK)
            finding("branch_points failed on an existing branch", ctx);
        if (pts != NULL && got != n_points)
            finding("branch_points gave another count than branch_info", ctx);
        free(pts);
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], range[2],
                uv_range[4], uv[2 * PROJCURVE_MAX_PCURVE_POINTS];
            if (projcurve_result_piece(ctx, r, i, k, &degree, ctrl, w, range, uv_range) !=
                PROJCURVE_OK)
                finding("piece failed on an existing piece", ctx);
            if (projcurve_result_piece_pcurve(ctx, r, i, k, &degree, uv) != PROJCURVE_OK)
                finding("piece_pcurve failed on an existing piece", ctx);
        }
        projcurve_curve *c = NULL;
        const projcurve_status st = projcurve_result_branch_curve(ctx, r, i, &c);
        if (st == PROJCURVE_OK) {
            double d0 = 0.0, d1 = 0.0, p[9];
            if (projcurve_curve_domain(ctx, c, &d0, &d1) != PROJCURVE_OK ||
                projcurve_curve_eval(ctx, c, 0.5 * (d0 + d1), 2, p) != PROJCURVE_OK)
                finding("a branch curve cannot be evaluated", ctx);
        } else if (st != PROJCURVE_ERR_INVALID_ARGUMENT && st != PROJCURVE_ERR_NO_MEMORY &&
                   st != PROJCURVE_ERR_OUT_OF_RANGE) {
            finding("branch_curve failed", ctx);
        }
        projcurve_curve_destroy(c);
    }
}
