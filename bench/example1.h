/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The paper's Example 1 for the benchmarks: read from
 * cases/song_yong_example1.igs, or built from the numbers of [SY13] s5
 * when the file cannot be read.
 */
#ifndef PCB_EXAMPLE1_H
#define PCB_EXAMPLE1_H

#include "projcurve.h"

typedef struct pcb_example1 {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    double dir[3];
    const char *source;  /* "IGES" or "built-in" */
    projcurve_model *model;
    projcurve_surface *own_surface;
    projcurve_curve *own_curve;
} pcb_example1;

/* Returns 1 on success, 0 on failure (printed). */
int pcb_example1_load(const char *data_dir, pcb_example1 *ex);
void pcb_example1_free(pcb_example1 *ex);

#endif /* PCB_EXAMPLE1_H */
