/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Line plots as SVG: one or more panels side by side, each with linear or
 * logarithmic axes, several named series, tick labels and a legend.
 * Points that cannot be drawn (non-finite, or <= 0 on a log axis) are
 * skipped.
 */
#ifndef PCB_SVG_H
#define PCB_SVG_H

#include <stddef.h>

typedef struct pcb_series {
    const char *name;
    const double *x, *y;
    size_t n;
} pcb_series;

typedef struct pcb_plot {
    const char *title;
    const char *x_label, *y_label;
    int log_x, log_y;
    const pcb_series *series;
    size_t n_series;
} pcb_plot;

/* Writes the panels to path. Returns 0 or -1 (file error). */
int pcb_svg_write(const char *path, const pcb_plot *plots, size_t n_plots);

#endif /* PCB_SVG_H */
