/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The accuracy of a projection onto a whole model, measured the same way
 * for ours and for Open CASCADE's: at dense 3D samples of the output, the
 * distance to the model's faces (the closest point on the surfaces of the
 * faces whose boxes hold the sample, untrimmed) and the distance to the
 * projection's rays (the nearest line P(t) + lambda Dir, or the nearest
 * line from the eye through P(t), over t sampled and refined by golden
 * section). Neither uses the parameter the projection reports.
 */
#ifndef PCB_SHAPE_ACCURACY_H
#define PCB_SHAPE_ACCURACY_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pcb_shape_accuracy {
    double face;   /* largest distance of a sample to the faces */
    double ray;    /* largest distance of a sample to the rays */
} pcb_shape_accuracy;

/* Measures n samples (3 doubles each); conical 0: vec is Dir, 1: the eye.
 * Returns 0, or -1 when a library call fails. */
int pcb_shape_accuracy_of(const projcurve_shape *shape, const projcurve_curve *curve, int conical,
                          const double vec[3], const double *samples, size_t n,
                          pcb_shape_accuracy *out);

#endif /* PCB_SHAPE_ACCURACY_H */
