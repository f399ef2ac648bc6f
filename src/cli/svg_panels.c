/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The right-hand side and the foot of the picture: one parameter panel per
 * surface (its own (u, v) domain, axes with numbers, the branches' traced
 * pcurves in their colours) and the legend naming every branch, up to
 * SVG_LEGEND_MAX, then how many more there are.
 */
#include <stdlib.h>

#include "shape_job.h"
#include "svg.h"

#define PANEL_LEFT 50.0  /* room for the v numbers */
#define PANEL_TOP 24.0   /* room for the panel's title */
#define PANEL_EXTRA 70.0 /* margins around the plot, per direction */
#define TICKS 3          /* numbers per axis: start, middle, end */

static const char *const palette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                      "#17becf", "#e377c2", "#8c564b", "#bcbd22", "#7f7f7f"};
#define PALETTE_SIZE (sizeof palette / sizeof *palette)

const char *svg_colour(size_t k)
{
    return palette[k % PALETTE_SIZE];
}

void svg_escaped(FILE *f, const char *s)
{
    for (; *s; ++s) {
        switch (*s) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default:
            if ((unsigned char)*s >= 32 && (unsigned char)*s < 127)
                fputc(*s, f);
        }
    }
}

double *svg_branch_points(projcurve_context *ctx, const projcurve_result *r, size_t b, size_t *n)
{
    double probe[3];
    *n = 0;
    if (projcurve_result_branch_points(ctx, r, b, 0, probe, n) != PROJCURVE_OK || *n == 0)
        return NULL;
    double *tuv = malloc(3 * *n * sizeof *tuv);
    if (tuv && projcurve_result_branch_points(ctx, r, b, *n, tuv, n) != PROJCURVE_OK) {
        free(tuv);
        return NULL;
    }
    return tuv;
}

static size_t surface_branches(const cli_job *job, size_t s)
{
    size_t n = 0;
    for (size_t i = 0; i < job->n_pairs; ++i)
        if (job->pairs[i].surface == s)
            n += projcurve_result_branch_count(job->pairs[i].result);
    return n;
}

void svg_panels_layout(const cli_job *job, svg_panels *p)
{
    p->count = 0;
    const int all = job->n_surfaces <= SVG_MAX_PANELS;
    for (size_t s = 0; s < job->n_surfaces && p->count < SVG_MAX_PANELS; ++s)
        if (all || surface_branches(job, s) > 0)
            p->surface[p->count++] = s;
    p->omitted = job->n_surfaces - p->count;
    p->columns = p->count <= 1 ? 1 : 2;
    p->rows = (p->count + p->columns - 1) / p->columns;
    p->plot = p->columns == 1 ? 320.0 : 140.0;
    p->cell_w = p->plot + PANEL_EXTRA;
    p->cell_h = p->plot + PANEL_EXTRA;
}

double svg_panels_height(const svg_panels *p)
{
    return (double)p->rows * p->cell_h + (p->omitted ? 24.0 : 0.0);
}

/* The axes of a plot at (x, y): frame, grid, numbers of the domain d. */
static void axes(FILE *f, double x, double y, double size, const double d[4])
{
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#f7f7f7\" "
               "stroke=\"#333333\" stroke-width=\"1\"/>\n",
            x, y, size, size);
    for (int i = 1; i < SVG_ISO_LINES - 1; ++i) {
        const double a = size * i / (SVG_ISO_LINES - 1);
        fprintf(f,
                "<path d=\"M%.1f %.1fV%.1fM%.1f %.1fH%.1f\" stroke=\"#dddddd\" "
                "stroke-width=\"0.6\" fill=\"none\"/>\n",
                x + a, y, y + size, x, y + a, x + size);
    }
    for (int i = 0; i < TICKS; ++i) {
        const double a = (double)i / (TICKS - 1);
        const double u = d[0] + (d[1] - d[0]) * a, v = d[2] + (d[3] - d[2]) * a;
        fprintf(f,
                "<path d=\"M%.1f %.1fv5M%.1f %.1fh-5\" stroke=\"#333333\" stroke-width=\"1\" "
                "fill=\"none\"/>\n",
                x + size * a, y + size, x, y + size * (1.0 - a));
        fprintf(f,
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"middle\">%.4g</text>\n"
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"end\">%.4g</text>\n",
                x + size * a, y + size + 16, u, x - 7, y + size * (1.0 - a) + 3, v);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">u</text>\n",
            x + size / 2, y + size + 32);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">v</text>\n", x - PANEL_LEFT + 2,
            y + size / 2 - 10);
}

/* The pcurves of the branches on job surface s, in their legend colours
 * (with --faces their connected curves'). */
static void pcurves(projcurve_context *ctx, FILE *f, const cli_job *job, size_t s, double x,
                    double y, double size, const double d[4])
{
    size_t k = 0; /* the branch's number across the job: its colour */
    for (size_t i = 0; i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        const size_t nb = projcurve_result_branch_count(p->result);
        for (size_t b = 0; b < nb; ++b, ++k) {
            size_t n;
            double *tuv = p->surface == s ? svg_branch_points(ctx, p->result, b, &n) : NULL;
            if (tuv == NULL)
                continue;
            /* --faces: a face piece in its connected curve's colour */
            const size_t colour =
                job->shapes ? cli_shape_connected_of(job->shapes, p->result, b) : k;
            fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" points=\"",
                    svg_colour(colour));
            for (size_t j = 0; j < n; ++j) {
                const double a = (tuv[3 * j + 1] - d[0]) / (d[1] - d[0]);
                const double c = (tuv[3 * j + 2] - d[2]) / (d[3] - d[2]);
                fprintf(f, "%s%.2f,%.2f", j ? " " : "", x + size * a, y + size * (1.0 - c));
            }
            fputs("\"/>\n", f);
            free(tuv);
        }
    }
}

void svg_panels_write(projcurve_context *ctx, FILE *f, const cli_job *job, const svg_panels *p)
{
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"13\">Where the branches lie on each "
               "surface (parameters u, v)</text>\n",
            SVG_PANELS_X0, SVG_PANELS_Y0 - 16);
    for (size_t i = 0; i < p->count; ++i) {
        const size_t s = p->surface[i];
        double d[4];
        if (projcurve_surface_domain(ctx, job->surfaces[s], d) != PROJCURVE_OK ||
            !(d[1] > d[0]) || !(d[3] > d[2]))
            continue;
        const double x = SVG_PANELS_X0 + (double)(i % p->columns) * p->cell_w + PANEL_LEFT;
        const double y = SVG_PANELS_Y0 + (double)(i / p->columns) * p->cell_h + PANEL_TOP;
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">surface %zu</text>\n", x,
                y - 8, cli_surface_number(job, s));
        axes(f, x, y, p->plot, d);
        pcurves(ctx, f, job, s, x, y, p->plot, d);
    }
    if (p->omitted)
        fprintf(f,
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">%zu more surface(s) without a "
                "panel (%s)</text>\n",
                SVG_PANELS_X0, SVG_PANELS_Y0 + (double)p->rows * p->cell_h + 12, p->omitted,
                p->count < SVG_MAX_PANELS ? "no branch lies on them"
                                          : "at most 12 panels; the JSON report has them all");
}

size_t svg_branch_total(const cli_job *job)
{
    size_t n = 0;
    for (size_t i = 0; i < job->n_pairs; ++i)
        n += projcurve_result_branch_count(job->pairs[i].result);
    return n;
}

double svg_legend_height(size_t branches)
{
    const size_t lines = branches == 0 ? 1
                         : branches > SVG_LEGEND_MAX ? SVG_LEGEND_MAX + 1
                                                     : branches;
    return (double)lines * SVG_LEGEND_LINE + 8.0;
}

/* --faces: a line per connected curve. */
static void connected_legend(projcurve_context *ctx, FILE *f, const cli_shape_job *sj, double y0)
{
    const size_t total = cli_shape_connected_total(sj);
    double y = y0 + SVG_LEGEND_LINE;
    for (size_t k = 0; k < total && k < SVG_LEGEND_MAX; ++k, y += SVG_LEGEND_LINE) {
        const cli_shape_run *run = NULL;
        size_t curve = 0, n = 0;
        int closed = 0;
        if (!cli_shape_connected_at(sj, k, &run, &curve))
            break;
        projcurve_shape_result_curve_info(ctx, run->result, curve, &n, NULL, &closed);
        fprintf(f,
                "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"4\" fill=\"%s\"/>"
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">connected curve %zu: curve %zu "
                "onto shape %zu, %zu face piece(s)%s</text>\n",
                SVG_VIEW_X0, y - 4, svg_colour(k), SVG_VIEW_X0 + 24, y, k,
                cli_shape_curve_number(sj, run->curve), run->shape, n, closed ? ", closed" : "");
    }
    if (total > SVG_LEGEND_MAX)
        fprintf(f,
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">and %zu more connected curves "
                "(the JSON report, --json, lists all %zu)</text>\n",
                SVG_VIEW_X0 + 24, y, total - SVG_LEGEND_MAX, total);
    if (total == 0)
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">no connected curve: no curve "
                   "projects onto a face</text>\n",
                SVG_VIEW_X0, y);
}

void svg_legend_write(projcurve_context *ctx, FILE *f, const cli_job *job, double y0)
{
    if (job->shapes != NULL) {
        connected_legend(ctx, f, job->shapes, y0);
        return;
    }
    size_t k = 0;
    double y = y0 + SVG_LEGEND_LINE;
    for (size_t i = 0; i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        const size_t nb = projcurve_result_branch_count(p->result);
        for (size_t b = 0; b < nb && k < SVG_LEGEND_MAX; ++b, ++k, y += SVG_LEGEND_LINE) {
            projcurve_branch_start s = PROJCURVE_START_CURVE_START;
            projcurve_branch_end e = PROJCURVE_END_CURVE_END;
            projcurve_result_branch_info(ctx, p->result, b, NULL, &s, &e, NULL, NULL);
            fprintf(f,
                    "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"4\" fill=\"%s\"/>"
                    "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">branch %zu: curve %zu onto "
                    "surface %zu, from %s to %s</text>\n",
                    SVG_VIEW_X0, y - 4, svg_colour(k), SVG_VIEW_X0 + 24, y, k,
                    cli_curve_number(job, p->curve), cli_surface_number(job, p->surface),
                    cli_start_words(s), cli_end_words(e));
        }
        if (k == SVG_LEGEND_MAX)
            break;
    }
    const size_t total = svg_branch_total(job);
    if (total > SVG_LEGEND_MAX)
        fprintf(f,
                "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">and %zu more branches (the legend "
                "names the first %d; the JSON report, --json, lists all %zu)</text>\n",
                SVG_VIEW_X0 + 24, y, total - SVG_LEGEND_MAX, SVG_LEGEND_MAX, total);
    if (total == 0)
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">no branch: no curve projects "
                   "onto a surface</text>\n",
                SVG_VIEW_X0, y);
}
