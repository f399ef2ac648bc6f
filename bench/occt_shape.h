/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Open CASCADE's projection of a curve onto a whole model, for the shape
 * bench: the file read by its STEP / IGES reader (occt_read.h), the curve
 * rebuilt from our NURBS data as a Geom_BSplineCurve edge, then
 * BRepProj_Projection with the cylindrical (direction) or the conical (eye
 * point) constructor. Built only where the data exchange toolkits are
 * installed (PCB_HAVE_OCCT_READ).
 */
#ifndef PCB_OCCT_SHAPE_H
#define PCB_OCCT_SHAPE_H

#include <stddef.h>

#include "occt_geometry.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pcb_occt_shape_out {
    double ms;        /* median CPU ms of one BRepProj_Projection */
    int wires;        /* connected curves: the wires of the result */
    int edges;
    long poles;       /* poles of the edges' 3D curves (B-spline, else 0) */
    double *samples;  /* 3 per point, `samples_per_edge` per edge (malloc'd) */
    size_t n_samples;
    char note[160];   /* why it failed, "" on success */
} pcb_occt_shape_out;

typedef struct pcb_occt_model pcb_occt_model;

/* Reads the model; NULL when the reader fails. */
pcb_occt_model *pcb_occt_model_read(const char *path);
void pcb_occt_model_free(pcb_occt_model *m);

/* Projects the curve onto the model, reps timed runs (one untimed first):
 * conical 0 projects along vec (a direction), 1 from the eye point vec.
 * Returns 0, or -1 with out->note set. out->samples is released with
 * pcb_occt_shape_out_free. */
int pcb_occt_shape_project(const pcb_occt_model *m, const pcb_nurbs_data *curve, int conical,
                           const double vec[3], int reps, size_t samples_per_edge,
                           pcb_occt_shape_out *out);
void pcb_occt_shape_out_free(pcb_occt_shape_out *out);

#ifdef __cplusplus
}
#endif

#endif /* PCB_OCCT_SHAPE_H */
