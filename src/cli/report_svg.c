/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * SVG picture of a projection: on the left a three-quarter view of the
 * surfaces (iso-parameter lines), the input curves, a few projection rays
 * and every branch in its own colour (with --faces every connected curve
 * as one path, its face pieces in chain order); on the right a parameter panel per
 * surface (svg_panels.c); below, the legend. The height grows with the
 * panels and the legend. The file is self-contained SVG 1.1: no scripts,
 * fonts or links.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "shape_job.h"
#include "svg.h"

#define AZIMUTH_DEG (-30.0)
#define ELEVATION_DEG 25.0
#define ISO_SAMPLES 48
#define CURVE_SAMPLES 240
#define RAYS_PER_PAIR 7
#define MAX_SURFACES_DRAWN 64
#define DEG_TO_RAD (3.14159265358979323846 / 180.0)

typedef struct view {
    double right[3], up[3];
    double box[4]; /* xmin, ymin, xmax, ymax of projected points */
    double scale, ox, oy;
    int emitting;  /* 0: measuring the box, 1: writing */
    FILE *f;
    size_t open_points; /* points written in the current polyline */
} view;

static void project(const view *v, const double p[3], double *x, double *y)
{
    *x = p[0] * v->right[0] + p[1] * v->right[1] + p[2] * v->right[2];
    *y = p[0] * v->up[0] + p[1] * v->up[1] + p[2] * v->up[2];
}

static void begin_line(view *v, const char *colour, double width, const char *extra)
{
    v->open_points = 0;
    if (v->emitting)
        fprintf(v->f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%.2f\"%s points=\"",
                colour, width, extra);
}

static void point(view *v, const double p[3])
{
    double x, y;
    project(v, p, &x, &y);
    if (!isfinite(x) || !isfinite(y))
        return;
    if (!v->emitting) {
        v->box[0] = fmin(v->box[0], x);
        v->box[1] = fmin(v->box[1], y);
        v->box[2] = fmax(v->box[2], x);
        v->box[3] = fmax(v->box[3], y);
        return;
    }
    fprintf(v->f, "%s%.2f,%.2f", v->open_points ? " " : "", v->ox + v->scale * x,
            v->oy - v->scale * y);
    ++v->open_points;
}

static void end_line(view *v)
{
    if (v->emitting)
        fputs("\"/>\n", v->f);
}

static void draw_surface(projcurve_context *ctx, view *v, const projcurve_surface *s)
{
    double d[4];
    if (projcurve_surface_domain(ctx, s, d) != PROJCURVE_OK)
        return;
    for (int dir = 0; dir < 2; ++dir)
        for (int i = 0; i < SVG_ISO_LINES; ++i) {
            const double a = (double)i / (SVG_ISO_LINES - 1);
            begin_line(v, "#9aa5b1", 0.6, "");
            for (int k = 0; k < ISO_SAMPLES; ++k) {
                const double b = (double)k / (ISO_SAMPLES - 1);
                const double u = d[0] + (d[1] - d[0]) * (dir ? b : a);
                const double w = d[2] + (d[3] - d[2]) * (dir ? a : b);
                double p[3];
                if (projcurve_surface_eval(ctx, s, u, w, 0, p) == PROJCURVE_OK)
                    point(v, p);
            }
            end_line(v);
        }
}

static void draw_curve(projcurve_context *ctx, view *v, const projcurve_curve *c,
                       const char *colour, double width)
{
    double t0, t1;
    if (projcurve_curve_domain(ctx, c, &t0, &t1) != PROJCURVE_OK)
        return;
    begin_line(v, colour, width, " stroke-linejoin=\"round\"");
    for (int k = 0; k < CURVE_SAMPLES; ++k) {
        double p[3];
        if (projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * k / (CURVE_SAMPLES - 1), 0, p) ==
            PROJCURVE_OK)
            point(v, p);
    }
    end_line(v);
}

static void draw_branch(projcurve_context *ctx, view *v, const cli_job *job, const cli_pair *p,
                        size_t b, const char *colour)
{
    projcurve_curve *c = NULL;
    if (projcurve_result_branch_curve(ctx, p->result, b, &c) == PROJCURVE_OK) {
        draw_curve(ctx, v, c, colour, 2.4);
        projcurve_curve_destroy(c);
        return;
    }
    size_t n;
    double *tuv = svg_branch_points(ctx, p->result, b, &n);
    if (tuv == NULL)
        return;
    begin_line(v, colour, 2.4, "");
    for (size_t i = 0; i < n; ++i) {
        double q[3];
        if (projcurve_surface_eval(ctx, job->surfaces[p->surface], tuv[3 * i + 1], tuv[3 * i + 2],
                                   0, q) == PROJCURVE_OK)
            point(v, q);
    }
    end_line(v);
    free(tuv);
}

/* The points of a face piece's 3D curve in the order the chain runs
 * along it, appended to the open line (its first point repeats the last
 * piece's end, within the chaining tolerance). */
static void connected_piece(projcurve_context *ctx, view *v, const projcurve_result *r,
                            size_t branch, const double t_range[2])
{
    projcurve_curve *c = NULL;
    if (projcurve_result_branch_curve(ctx, r, branch, &c) != PROJCURVE_OK)
        return;
    double t0, t1;
    if (projcurve_curve_domain(ctx, c, &t0, &t1) == PROJCURVE_OK) {
        const int backwards = t_range[0] > t_range[1];
        for (int k = 0; k < CURVE_SAMPLES; ++k) {
            const double s = (double)(backwards ? CURVE_SAMPLES - 1 - k : k) / (CURVE_SAMPLES - 1);
            double p[3];
            if (projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * s, 0, p) == PROJCURVE_OK)
                point(v, p);
        }
    }
    projcurve_curve_destroy(c);
}

/* Connected curve k of the shape job as one polyline (class "connected"). */
static void draw_connected(projcurve_context *ctx, view *v, const cli_shape_job *sj, size_t k)
{
    const cli_shape_run *run = NULL;
    size_t curve = 0, n = 0;
    if (!cli_shape_connected_at(sj, k, &run, &curve) ||
        projcurve_shape_result_curve_info(ctx, run->result, curve, &n, NULL, NULL) !=
            PROJCURVE_OK)
        return;
    begin_line(v, svg_colour(k), 2.4, " stroke-linejoin=\"round\" class=\"connected\"");
    for (size_t j = 0; j < n; ++j) {
        const projcurve_result *fr = NULL;
        size_t b = 0;
        double t[2];
        if (projcurve_shape_result_piece(ctx, run->result, curve, j, NULL, &fr, &b, t, NULL,
                                         NULL) == PROJCURVE_OK)
            connected_piece(ctx, v, fr, b, t);
    }
    end_line(v);
}

/* A few segments P(t) -> S(u, v), spread over the pair's branches. */
static void draw_rays(projcurve_context *ctx, view *v, const cli_job *job, const cli_pair *p)
{
    const size_t nb = projcurve_result_branch_count(p->result);
    for (size_t b = 0; b < nb; ++b) {
        size_t n;
        double *tuv = svg_branch_points(ctx, p->result, b, &n);
        if (tuv == NULL)
            continue;
        const size_t rays = RAYS_PER_PAIR / nb + 1;
        const double t_first = tuv[0], t_last = tuv[3 * (n - 1)];
        for (size_t r = 0; r < rays; ++r) {
            /* the traced point nearest to evenly spread curve parameters */
            const double t = t_first + (t_last - t_first) * ((double)r + 0.5) / (double)rays;
            size_t i = 0;
            for (size_t j = 1; j < n; ++j)
                if (fabs(tuv[3 * j] - t) < fabs(tuv[3 * i] - t))
                    i = j;
            double a[3], q[3];
            if (projcurve_curve_eval(ctx, job->curves[p->curve], tuv[3 * i], 0, a) !=
                    PROJCURVE_OK ||
                projcurve_surface_eval(ctx, job->surfaces[p->surface], tuv[3 * i + 1],
                                       tuv[3 * i + 2], 0, q) != PROJCURVE_OK)
                continue;
            begin_line(v, "#666666", 0.8, " stroke-dasharray=\"4 3\"");
            point(v, a);
            point(v, q);
            end_line(v);
        }
        free(tuv);
    }
}

static void draw_scene(projcurve_context *ctx, view *v, const cli_job *job)
{
    const size_t ns = job->n_surfaces < MAX_SURFACES_DRAWN ? job->n_surfaces : MAX_SURFACES_DRAWN;
    for (size_t s = 0; s < ns; ++s)
        draw_surface(ctx, v, job->surfaces[s]);
    for (size_t i = 0; i < job->n_pairs; ++i)
        if (job->pairs[i].result)
            draw_rays(ctx, v, job, &job->pairs[i]);
    for (size_t c = 0; c < job->n_curves; ++c)
        draw_curve(ctx, v, job->curves[c], "#222222", 1.6);
    if (job->shapes != NULL) {
        const size_t n = cli_shape_connected_total(job->shapes);
        for (size_t k = 0; k < n; ++k)
            draw_connected(ctx, v, job->shapes, k);
        return;
    }
    size_t k = 0;
    for (size_t i = 0; i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        for (size_t b = 0; b < projcurve_result_branch_count(p->result); ++b, ++k)
            draw_branch(ctx, v, job, p, b, svg_colour(k));
    }
}

int cli_write_svg(projcurve_context *ctx, const cli_job *job, const char *title, const char *path)
{
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "projcurve: cannot create %s\n", path);
        return 0;
    }
    const double az = AZIMUTH_DEG * DEG_TO_RAD, el = ELEVATION_DEG * DEG_TO_RAD;
    view v = {.right = {-sin(az), cos(az), 0.0},
              .up = {-sin(el) * cos(az), -sin(el) * sin(az), cos(el)},
              .box = {INFINITY, INFINITY, -INFINITY, -INFINITY},
              .f = f};
    draw_scene(ctx, &v, job); /* measure */
    const double w = v.box[2] - v.box[0], h = v.box[3] - v.box[1];
    v.scale = (w > 0.0 || h > 0.0) ? fmin((SVG_VIEW_X1 - SVG_VIEW_X0) / fmax(w, 1e-300),
                                          (SVG_VIEW_Y1 - SVG_VIEW_Y0) / fmax(h, 1e-300))
                                   : 1.0;
    if (!isfinite(v.scale))
        v.scale = 1.0;
    v.ox = (SVG_VIEW_X0 + SVG_VIEW_X1) / 2 - v.scale * (v.box[0] + v.box[2]) / 2;
    v.oy = (SVG_VIEW_Y0 + SVG_VIEW_Y1) / 2 + v.scale * (v.box[1] + v.box[3]) / 2;
    if (!isfinite(v.ox) || !isfinite(v.oy))
        v.ox = v.oy = 0.0;
    svg_panels panels;
    svg_panels_layout(job, &panels);
    const double legend_y = fmax(SVG_VIEW_Y1, SVG_PANELS_Y0 + svg_panels_height(&panels)) + 12.0;
    const size_t named = job->shapes ? cli_shape_connected_total(job->shapes)
                                     : svg_branch_total(job);
    const double height = legend_y + svg_legend_height(named) + 12.0;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%.0f\" "
               "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\">\n<title>",
            SVG_WIDTH, height, SVG_WIDTH, height);
    svg_escaped(f, title);
    fprintf(f, "</title>\n<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n"
               "<text x=\"%.1f\" y=\"30\" font-size=\"18\">",
            SVG_VIEW_X0);
    svg_escaped(f, title);
    fprintf(f, "</text>\n<text x=\"%.1f\" y=\"%.1f\" font-size=\"13\">3D view (z up): "
               "surfaces grey, curves black, projection rays dashed</text>\n",
            SVG_VIEW_X0, SVG_VIEW_Y0 - 16);
    v.emitting = 1;
    draw_scene(ctx, &v, job);
    svg_panels_write(ctx, f, job, &panels);
    svg_legend_write(ctx, f, job, legend_y);
    fputs("</svg>\n", f);
    const int ok = fclose(f) == 0;
    if (!ok)
        fprintf(stderr, "projcurve: error writing %s\n", path);
    return ok;
}
