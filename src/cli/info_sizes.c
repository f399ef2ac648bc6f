/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The sizes part of projcurve info: for each surface and curve its degrees,
 * control points (poles), knot spans, domain and bounding box, and the
 * model's box, as text lines or as JSON members. A box is that of the
 * control points, which holds the geometry (convex hull property; the
 * weights of a NURBS are positive); projcurve_surface_bounds gives it for
 * surfaces, the control points for curves.
 */
#include <math.h>
#include <stdlib.h>

#include "cli.h"

typedef struct info_box {
    double lo[3], hi[3];
    int empty;
} info_box;

static void box_clear(info_box *b)
{
    for (int k = 0; k < 3; ++k)
        b->lo[k] = INFINITY, b->hi[k] = -INFINITY;
    b->empty = 1;
}

static void box_add(info_box *b, const double lo[3], const double hi[3])
{
    for (int k = 0; k < 3; ++k) {
        b->lo[k] = fmin(b->lo[k], lo[k]);
        b->hi[k] = fmax(b->hi[k], hi[k]);
    }
    b->empty = 0;
}

static double box_diagonal(const info_box *b)
{
    return hypot(hypot(b->hi[0] - b->lo[0], b->hi[1] - b->lo[1]), b->hi[2] - b->lo[2]);
}

typedef struct curve_size {
    int degree, rational;
    size_t poles, spans;
    double t0, t1;
    info_box box;
} curve_size;

/* The size of a NURBS curve; 0 when its data cannot be read (memory). */
static int measure_curve(projcurve_context *ctx, const projcurve_curve *c, curve_size *z)
{
    size_t n_knots = 0;
    box_clear(&z->box);
    z->degree = z->rational = 0;
    z->poles = z->spans = 0;
    z->t0 = z->t1 = 0.0;
    if (projcurve_curve_nurbs_info(ctx, c, &z->degree, &z->poles, &n_knots, &z->rational) !=
            PROJCURVE_OK ||
        projcurve_curve_domain(ctx, c, &z->t0, &z->t1) != PROJCURVE_OK || z->poles == 0)
        return 0;
    double *ctrl = malloc(3 * z->poles * sizeof *ctrl);
    double *knots = malloc(n_knots * sizeof *knots);
    int ok = ctrl && knots &&
             projcurve_curve_nurbs_data(ctx, c, ctrl, NULL, knots) == PROJCURVE_OK;
    if (ok) {
        for (size_t i = 0; i < z->poles; ++i)
            box_add(&z->box, ctrl + 3 * i, ctrl + 3 * i);
        for (size_t i = 0; i + 1 < n_knots; ++i)
            if (knots[i + 1] > knots[i] && knots[i] >= z->t0 && knots[i + 1] <= z->t1)
                ++z->spans;
    }
    free(knots);
    free(ctrl);
    return ok;
}

static void surface_box(projcurve_context *ctx, const projcurve_surface *s, info_box *b)
{
    double box[6];
    box_clear(b);
    if (projcurve_surface_bounds(ctx, s, box) == PROJCURVE_OK)
        box_add(b, box, box + 3);
}

static void print_box(FILE *out, const info_box *b)
{
    if (b->empty) {
        fputs("none", out);
        return;
    }
    fprintf(out, "[%g, %g] x [%g, %g] x [%g, %g]", b->lo[0], b->hi[0], b->lo[1], b->hi[1],
            b->lo[2], b->hi[2]);
}

void cli_print_sizes(projcurve_context *ctx, const projcurve_model *m)
{
    info_box model;
    box_clear(&model);
    for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
        int du = 0, dv = 0, rational = 0;
        size_t nu = 0, nv = 0, su = 0, sv = 0;
        double d[4] = {0, 0, 0, 0};
        const projcurve_surface *s = projcurve_model_surface(m, i);
        projcurve_surface_info(ctx, s, &du, &dv, &nu, &nv, &su, &sv, &rational);
        projcurve_surface_domain(ctx, s, d);
        info_box b;
        surface_box(ctx, s, &b);
        if (!b.empty)
            box_add(&model, b.lo, b.hi);
        printf("  surface %zu: degree %dx%d, %zux%zu control points, %zux%zu spans, %s, "
               "domain [%g, %g] x [%g, %g], box ",
               i, du, dv, nu, nv, su, sv, rational ? "rational" : "polynomial", d[0], d[1], d[2],
               d[3]);
        print_box(stdout, &b);
        printf("\n");
    }
    for (size_t i = 0; i < projcurve_model_curve_count(m); ++i) {
        curve_size z;
        measure_curve(ctx, projcurve_model_curve(m, i), &z);
        if (!z.box.empty)
            box_add(&model, z.box.lo, z.box.hi);
        printf("  curve %zu: degree %d, %zu control points, %zu spans, %s, domain [%g, %g], box ",
               i, z.degree, z.poles, z.spans, z.rational ? "rational" : "polynomial", z.t0, z.t1);
        print_box(stdout, &z.box);
        printf("\n");
    }
    printf("  model box: ");
    print_box(stdout, &model);
    if (!model.empty)
        printf(", diagonal %g", box_diagonal(&model));
    printf("\n");
}

static void json_real(FILE *out, double v)
{
    if (isfinite(v))
        fprintf(out, "%.17g", v);
    else
        fputs("null", out);
}

static void json_box(FILE *out, const info_box *b)
{
    if (b->empty) {
        fputs("null", out);
        return;
    }
    fputc('[', out);
    for (int k = 0; k < 6; ++k) {
        fputs(k ? ", " : "", out);
        json_real(out, k < 3 ? b->lo[k] : b->hi[k - 3]);
    }
    fputc(']', out);
}

void cli_print_sizes_json(projcurve_context *ctx, const projcurve_model *m, FILE *out)
{
    info_box model;
    box_clear(&model);
    fputs("  \"surface_list\": [", out);
    for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
        int du = 0, dv = 0, rational = 0;
        size_t nu = 0, nv = 0, su = 0, sv = 0;
        double d[4] = {0, 0, 0, 0};
        const projcurve_surface *s = projcurve_model_surface(m, i);
        projcurve_surface_info(ctx, s, &du, &dv, &nu, &nv, &su, &sv, &rational);
        projcurve_surface_domain(ctx, s, d);
        info_box b;
        surface_box(ctx, s, &b);
        if (!b.empty)
            box_add(&model, b.lo, b.hi);
        fprintf(out,
                "%s\n    {\"degree\": [%d, %d], \"poles\": [%zu, %zu], \"spans\": [%zu, %zu], "
                "\"rational\": %s, \"domain\": [",
                i ? "," : "", du, dv, nu, nv, su, sv, rational ? "true" : "false");
        for (int k = 0; k < 4; ++k) {
            fputs(k ? ", " : "", out);
            json_real(out, d[k]);
        }
        fputs("], \"box\": ", out);
        json_box(out, &b);
        fputc('}', out);
    }
    fputs("],\n  \"curve_list\": [", out);
    for (size_t i = 0; i < projcurve_model_curve_count(m); ++i) {
        curve_size z;
        measure_curve(ctx, projcurve_model_curve(m, i), &z);
        if (!z.box.empty)
            box_add(&model, z.box.lo, z.box.hi);
        fprintf(out,
                "%s\n    {\"degree\": %d, \"poles\": %zu, \"spans\": %zu, \"rational\": %s, "
                "\"domain\": [",
                i ? "," : "", z.degree, z.poles, z.spans, z.rational ? "true" : "false");
        json_real(out, z.t0);
        fputs(", ", out);
        json_real(out, z.t1);
        fputs("], \"box\": ", out);
        json_box(out, &z.box);
        fputc('}', out);
    }
    fputs("],\n  \"box\": ", out);
    json_box(out, &model);
    fputs(",\n", out);
}
