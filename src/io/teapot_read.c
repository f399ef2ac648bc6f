/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The Newell teapot text layout: a patch count, one line of 16 one-based
 * vertex indices per bicubic Bezier patch (4 x 4, row-major), a vertex
 * count and one "x,y,z" line per vertex. Each patch becomes a bicubic
 * surface with knots {0,0,0,0,1,1,1,1}; the row index is v, the column u.
 */
#include <math.h>
#include <stdio.h>

#include "common/error.h"
#include "io/io_model.h"
#include "io/io_text.h"

#define PC_TEAPOT_NET 4
#define PC_TEAPOT_INDICES (PC_TEAPOT_NET * PC_TEAPOT_NET)

static const char separators[] = " \t\r\n,";

static projcurve_status count(projcurve_context *ctx, pc_text_cursor *c, size_t max,
                              const char *what, size_t *out)
{
    double v;
    if (!pc_text_real(c, separators, &v) || v != floor(v) || v < 1.0 || v > (double)max)
        return pc_fail(ctx, PROJCURVE_ERR_PARSE, "teapot line %zu: expected the number of %s",
                       c->line, what);
    *out = (size_t)v;
    return PROJCURVE_OK;
}

projcurve_status pc_teapot_read(projcurve_context *ctx, const char *data, size_t len,
                                projcurve_model *model)
{
    pc_text_cursor c;
    pc_text_init(&c, data, len);
    pc_arena arena;
    pc_arena_init(&arena, 1u << 14);
    size_t n_patches = 0, n_verts = 0;
    projcurve_status st = count(ctx, &c, len / PC_TEAPOT_INDICES + 1, "patches", &n_patches);
    size_t *idx = NULL;
    double *verts = NULL;
    if (st == PROJCURVE_OK) {
        idx = pc_arena_calloc(&arena, n_patches * PC_TEAPOT_INDICES, sizeof *idx);
        if (idx == NULL)
            st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading the teapot");
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < n_patches * PC_TEAPOT_INDICES; ++i) {
        double v;
        if (!pc_text_real(&c, separators, &v) || v != floor(v) || v < 1.0 || v > (double)len)
            st = pc_fail(ctx, PROJCURVE_ERR_PARSE,
                         "teapot line %zu: patch %zu needs 16 vertex indices", c.line,
                         i / PC_TEAPOT_INDICES + 1);
        else
            idx[i] = (size_t)v;
    }
    if (st == PROJCURVE_OK)
        st = count(ctx, &c, len / 3 + 1, "vertices", &n_verts);
    if (st == PROJCURVE_OK) {
        verts = pc_arena_calloc(&arena, 3 * n_verts, sizeof *verts);
        if (verts == NULL)
            st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading the teapot");
    }
    for (size_t i = 0; st == PROJCURVE_OK && i < 3 * n_verts; ++i)
        if (!pc_text_real(&c, separators, &verts[i]))
            st = pc_fail(ctx, PROJCURVE_ERR_PARSE, "teapot line %zu: vertex %zu needs x,y,z",
                         c.line, i / 3 + 1);
    double knots[2 * PC_TEAPOT_NET] = {0, 0, 0, 0, 1, 1, 1, 1};
    for (size_t p = 0; st == PROJCURVE_OK && p < n_patches; ++p) {
        double ctrl[3 * PC_TEAPOT_INDICES];
        for (size_t k = 0; k < PC_TEAPOT_INDICES && st == PROJCURVE_OK; ++k) {
            const size_t v = idx[p * PC_TEAPOT_INDICES + k];
            if (v > n_verts)
                st = pc_fail(ctx, PROJCURVE_ERR_PARSE,
                             "teapot patch %zu: vertex index %zu, but only %zu vertices", p + 1, v,
                             n_verts);
            else
                for (size_t d = 0; d < 3; ++d)
                    ctrl[3 * k + d] = verts[3 * (v - 1) + d];
        }
        if (st != PROJCURVE_OK)
            break;
        const pc_io_surface s = {.deg_u = 3, .deg_v = 3, .n_u = 4, .n_v = 4, .ctrl = ctrl,
                                 .weights = NULL, .knots_u = knots,
                                 .knots_v = knots};
        char origin[48];
        snprintf(origin, sizeof origin, "teapot patch %zu", p + 1);
        st = pc_model_add_surface(ctx, model, &s, origin);
    }
    pc_arena_release(&arena);
    return st;
}
