/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Shared parts of the SVG picture (report_svg.c: the document and the 3D
 * view; svg_panels.c: the parameter panels and the legend).
 */
#ifndef PC_CLI_SVG_H
#define PC_CLI_SVG_H

#include <stdio.h>

#include "cli.h"

#define SVG_WIDTH 1120.0
#define SVG_VIEW_X0 20.0 /* 3D view */
#define SVG_VIEW_X1 660.0
#define SVG_VIEW_Y0 60.0
#define SVG_VIEW_Y1 520.0
#define SVG_PANELS_X0 690.0 /* parameter panels, to SVG_WIDTH - 20 */
#define SVG_PANELS_Y0 60.0
#define SVG_MAX_PANELS 12   /* surfaces with their own parameter panel */
#define SVG_LEGEND_MAX 30   /* branches named in the legend; then "and N more" */
#define SVG_LEGEND_LINE 16.0
#define SVG_ISO_LINES 9     /* per direction and surface */

/* The colour of the k-th branch of the job (in pair order). */
const char *svg_colour(size_t k);
/* s with the XML specials escaped; non-ASCII and control bytes dropped. */
void svg_escaped(FILE *f, const char *s);
/* The traced (t, u, v) points of a branch (malloc'ed), or NULL. */
double *svg_branch_points(projcurve_context *ctx, const projcurve_result *r, size_t b, size_t *n);

/* Which surfaces get a parameter panel: all when there are at most
 * SVG_MAX_PANELS, else the first SVG_MAX_PANELS that have a branch. */
typedef struct svg_panels {
    size_t surface[SVG_MAX_PANELS]; /* job indices */
    size_t count, omitted;          /* omitted: surfaces without a panel */
    size_t columns, rows;
    double cell_w, cell_h, plot;    /* a panel's cell and its square plot */
} svg_panels;

void svg_panels_layout(const cli_job *job, svg_panels *p);
/* The height the panels take below SVG_PANELS_Y0. */
double svg_panels_height(const svg_panels *p);
void svg_panels_write(projcurve_context *ctx, FILE *f, const cli_job *job, const svg_panels *p);

/* Total branches of the job, and the height of the legend for them. */
size_t svg_branch_total(const cli_job *job);
double svg_legend_height(size_t branches);
void svg_legend_write(projcurve_context *ctx, FILE *f, const cli_job *job, double y0);

#endif /* PC_CLI_SVG_H */
