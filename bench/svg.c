/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * SVG line plots (see svg.h).
 */
#include "svg.h"

#include <math.h>
#include <stdio.h>

/* Panel geometry in SVG user units. */
#define PANEL_W 460.0
#define PANEL_H 340.0
#define MARGIN_L 70.0
#define MARGIN_R 20.0
#define MARGIN_T 36.0
#define MARGIN_B 52.0
#define LINEAR_TICKS 5
#define MAX_LOG_TICKS 12

static const char *const palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                      "#9467bd", "#8c564b"};
#define PALETTE_SIZE (sizeof palette / sizeof palette[0])

typedef struct axis {
    int log;
    double lo, hi;  /* in axis units (log10 when log) */
} axis;

static int drawable(double value, int log) { return isfinite(value) && (!log || value > 0.0); }

static double to_axis(double value, int log) { return log ? log10(value) : value; }

/* Data range of one coordinate over every series, padded to whole decades
 * on log axes and by 5 % on linear ones. */
static axis axis_range(const pcb_plot *plot, int use_y)
{
    axis a = {use_y ? plot->log_y : plot->log_x, INFINITY, -INFINITY};
    for (size_t s = 0; s < plot->n_series; ++s) {
        const pcb_series *ser = &plot->series[s];
        for (size_t i = 0; i < ser->n; ++i) {
            const double x = ser->x[i], y = ser->y[i];
            if (!drawable(x, plot->log_x) || !drawable(y, plot->log_y))
                continue;
            const double v = to_axis(use_y ? y : x, a.log);
            if (v < a.lo) a.lo = v;
            if (v > a.hi) a.hi = v;
        }
    }
    if (!(a.lo <= a.hi)) {
        a.lo = 0.0;
        a.hi = 1.0;
    }
    if (a.log) {
        a.lo = floor(a.lo);
        a.hi = ceil(a.hi);
        if (a.hi <= a.lo) a.hi = a.lo + 1.0;
    } else {
        const double pad = a.hi > a.lo ? 0.05 * (a.hi - a.lo) : fabs(a.hi) * 0.1 + 1.0;
        a.lo -= pad;
        a.hi += pad;
    }
    return a;
}

static double map(const axis *a, double value, double from, double to)
{
    return from + (to_axis(value, a->log) - a->lo) / (a->hi - a->lo) * (to - from);
}

static void tick_label(char *buf, size_t size, const axis *a, double axis_value)
{
    if (a->log)
        snprintf(buf, size, "1e%d", (int)lround(axis_value));
    else
        snprintf(buf, size, "%.4g", axis_value);
}

/* A round step (1, 2 or 5 times a power of ten) giving about `target`
 * intervals over span. */
static double nice_step(double span, int target)
{
    const double raw = span / (double)target;
    const double mag = pow(10.0, floor(log10(raw)));
    const double f = raw / mag;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * mag;
}

static void draw_ticks(FILE *f, const axis *a, int vertical, double x0, double y0, double x1,
                       double y1)
{
    double step = a->log ? ceil((a->hi - a->lo) / (double)(MAX_LOG_TICKS - 1))
                         : nice_step(a->hi - a->lo, LINEAR_TICKS - 1);
    const double first = a->log ? a->lo : ceil(a->lo / step) * step;
    for (int i = 0; i < MAX_LOG_TICKS + LINEAR_TICKS; ++i) {
        const double v = first + step * (double)i;
        if (v > a->hi + 1e-9 * step)
            break;
        const double frac = (v - a->lo) / (a->hi - a->lo);
        char label[32];
        tick_label(label, sizeof label, a, fabs(v) < 1e-12 * step ? 0.0 : v);
        if (vertical) {
            const double y = y1 - frac * (y1 - y0);
            fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#ddd'/>\n", x0, y,
                    x1, y);
            fprintf(f, "<text x='%.1f' y='%.1f' text-anchor='end' font-size='11'>%s</text>\n",
                    x0 - 4.0, y + 4.0, label);
        } else {
            const double x = x0 + frac * (x1 - x0);
            fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#ddd'/>\n", x, y0,
                    x, y1);
            fprintf(f, "<text x='%.1f' y='%.1f' text-anchor='middle' font-size='11'>%s</text>\n",
                    x, y1 + 15.0, label);
        }
    }
}

static void draw_series(FILE *f, const pcb_plot *plot, const axis *ax, const axis *ay,
                        size_t s, double x0, double y0, double x1, double y1)
{
    const pcb_series *ser = &plot->series[s];
    const char *color = palette[s % PALETTE_SIZE];
    fprintf(f, "<polyline fill='none' stroke='%s' stroke-width='1.8' points='", color);
    for (size_t i = 0; i < ser->n; ++i) {
        if (!drawable(ser->x[i], plot->log_x) || !drawable(ser->y[i], plot->log_y))
            continue;
        fprintf(f, "%.1f,%.1f ", map(ax, ser->x[i], x0, x1), map(ay, ser->y[i], y1, y0));
    }
    fputs("'/>\n", f);
    for (size_t i = 0; i < ser->n; ++i) {
        if (!drawable(ser->x[i], plot->log_x) || !drawable(ser->y[i], plot->log_y))
            continue;
        fprintf(f, "<circle cx='%.1f' cy='%.1f' r='3' fill='%s'/>\n",
                map(ax, ser->x[i], x0, x1), map(ay, ser->y[i], y1, y0), color);
    }
    const double ly = y0 + 14.0 + 16.0 * (double)s;
    fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='%s' stroke-width='2'/>\n",
            x0 + 10.0, ly - 4.0, x0 + 30.0, ly - 4.0, color);
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='11'>%s</text>\n", x0 + 36.0, ly,
            ser->name ? ser->name : "");
}

static void draw_panel(FILE *f, const pcb_plot *plot, double left)
{
    const axis ax = axis_range(plot, 0), ay = axis_range(plot, 1);
    const double x0 = left + MARGIN_L, x1 = left + PANEL_W - MARGIN_R;
    const double y0 = MARGIN_T, y1 = PANEL_H - MARGIN_B;
    draw_ticks(f, &ax, 0, x0, y0, x1, y1);
    draw_ticks(f, &ay, 1, x0, y0, x1, y1);
    fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' fill='none' stroke='#333'/>\n",
            x0, y0, x1 - x0, y1 - y0);
    fprintf(f, "<text x='%.1f' y='20' text-anchor='middle' font-size='13'>%s</text>\n",
            0.5 * (x0 + x1), plot->title ? plot->title : "");
    fprintf(f, "<text x='%.1f' y='%.1f' text-anchor='middle' font-size='12'>%s</text>\n",
            0.5 * (x0 + x1), PANEL_H - 12.0, plot->x_label ? plot->x_label : "");
    fprintf(f,
            "<text transform='translate(%.1f,%.1f) rotate(-90)' text-anchor='middle' "
            "font-size='12'>%s</text>\n",
            left + 16.0, 0.5 * (y0 + y1), plot->y_label ? plot->y_label : "");
    for (size_t s = 0; s < plot->n_series; ++s)
        draw_series(f, plot, &ax, &ay, s, x0, y0, x1, y1);
}

int pcb_svg_write(const char *path, const pcb_plot *plots, size_t n_plots)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    const double width = PANEL_W * (double)(n_plots ? n_plots : 1);
    fprintf(f,
            "<?xml version='1.0' encoding='UTF-8'?>\n"
            "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
            "viewBox='0 0 %.0f %.0f' font-family='sans-serif'>\n"
            "<rect width='100%%' height='100%%' fill='white'/>\n",
            width, PANEL_H, width, PANEL_H);
    for (size_t p = 0; p < n_plots; ++p)
        draw_panel(f, &plots[p], PANEL_W * (double)p);
    fputs("</svg>\n", f);
    const int failed = ferror(f) != 0;
    return (fclose(f) != 0 || failed) ? -1 : 0;
}
