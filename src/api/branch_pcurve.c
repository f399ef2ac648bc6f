/* SPDX-License-Identifier: BSD-3-Clause */
#include "api/branch_pcurve.h"

#include <math.h>

#include "common/arena.h"
#include "common/error.h"
#include "io/io_geom.h"
#include "seam/seam.h"

/* Consecutive pieces share their end (u, v) exactly (the refined vertex);
 * a larger gap, relative to the coordinates, is a broken branch. */
#define PC_PCURVE_GAP_REL 1e-12

/* Piece k as a Bezier curve over its curve-parameter range, t increasing. */
static projcurve_status piece_part(projcurve_context *ctx, pc_arena *arena,
                                   const projcurve_result *r, size_t branch, size_t k,
                                   pc_io_curve *part, double *size)
{
    int degree = 0;
    double uv[2 * PROJCURVE_MAX_PCURVE_POINTS], range[2];
    projcurve_status st = projcurve_result_piece_pcurve(ctx, r, branch, k, &degree, uv);
    if (st == PROJCURVE_OK)
        st = projcurve_result_piece(ctx, r, branch, k, NULL, NULL, NULL, range, NULL);
    if (st != PROJCURVE_OK)
        return st;
    if (degree < 1 || degree >= PROJCURVE_MAX_PCURVE_POINTS || !(range[0] != range[1]))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "branch %zu piece %zu: pcurve of degree %d over [%g, %g]", branch, k,
                       degree, range[0], range[1]);
    const size_t n = (size_t)degree + 1;
    const int reversed = range[0] > range[1];
    /* across the seams of a joined branch the pcurve is unwrapped, as its
     * compact pcurve (projcurve_result_branch_seam_count) */
    double shift[2];
    pc_seam_unwrap_shift(&r->branches[branch], 0.5 * (range[0] + range[1]), shift);
    for (size_t i = 0; i < n; ++i) {
        uv[2 * i] -= shift[0];
        uv[2 * i + 1] -= shift[1];
    }
    part->degree = degree;
    part->n_ctrl = n;
    part->weights = NULL;
    part->ctrl = pc_arena_calloc(arena, 3 * n, sizeof(double));
    part->knots = pc_arena_calloc(arena, 2 * n, sizeof(double));
    if (part->ctrl == NULL || part->knots == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory joining a pcurve");
    for (size_t i = 0; i < n; ++i) {
        const size_t from = reversed ? n - 1 - i : i;
        part->ctrl[3 * i] = uv[2 * from];
        part->ctrl[3 * i + 1] = uv[2 * from + 1];
        *size = fmax(*size, fmax(fabs(uv[2 * from]), fabs(uv[2 * from + 1])));
        part->knots[i] = fmin(range[0], range[1]);
        part->knots[n + i] = fmax(range[0], range[1]);
    }
    return PROJCURVE_OK;
}

projcurve_status pc_branch_pcurve(projcurve_context *ctx, const projcurve_result *r,
                                  size_t branch, projcurve_curve **out)
{
    size_t n_pieces = 0;
    projcurve_status st =
        projcurve_result_branch_info(ctx, r, branch, NULL, NULL, NULL, NULL, &n_pieces);
    if (st != PROJCURVE_OK)
        return st;
    if (n_pieces == 0)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "branch %zu has no composed pieces",
                       branch);
    pc_arena arena;
    pc_arena_init(&arena, 1u << 14);
    pc_io_curve *parts = pc_arena_calloc(&arena, n_pieces, sizeof *parts);
    double range[2], size = 1.0;
    st = parts == NULL ? pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory joining a pcurve")
                       : projcurve_result_piece(ctx, r, branch, 0, NULL, NULL, NULL, range, NULL);
    /* A branch traced with t decreasing has its pieces in that order. */
    const int reversed = st == PROJCURVE_OK && range[0] > range[1];
    for (size_t k = 0; st == PROJCURVE_OK && k < n_pieces; ++k)
        st = piece_part(ctx, &arena, r, branch, reversed ? n_pieces - 1 - k : k, &parts[k], &size);
    pc_io_curve joined;
    if (st == PROJCURVE_OK)
        st = pc_io_curve_join(ctx, &arena, parts, n_pieces, PC_PCURVE_GAP_REL * size, &joined);
    if (st == PROJCURVE_OK)
        st = projcurve_curve_create_nurbs(ctx, joined.degree, joined.n_ctrl, joined.ctrl, NULL,
                                          joined.knots, out);
    pc_arena_release(&arena);
    return st;
}
