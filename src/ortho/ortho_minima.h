/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Which foot points the orthogonal projection returns
 * (PROJCURVE_OPT_FOOT_POINTS). By default only the local minima of the
 * distance |S - P(t)| (Morse index 0, ortho/morse_index.h): what pulling a
 * curve onto a face gives. A branch of minima ends where P(t) reaches a
 * centre of curvature (the index changes there), and the engine's seeds
 * are filtered the same way (ortho_seeds.c), so that the saddles and maxima
 * (the far side of a torus tube, the far wall of a cylinder) are neither
 * traced nor returned.
 */
#ifndef PC_ORTHO_MINIMA_H
#define PC_ORTHO_MINIMA_H

#include "trace/projector.h"
#include "trace/result.h"

/* 1 when the foot point (u, v) of P(t) is a local minimum of the distance
 * (or when its index cannot be evaluated: the caller's corrector then
 * decides). */
int pc_ortho_is_minimum(const pc_projector *proj, double t, double u, double v);

/* Removes the branches of r (points (t, u, v), split at centres of
 * curvature by ortho_centres.c, so that each has one Morse index) whose
 * vertices are, by majority, no local minima of the distance. */
void pc_ortho_keep_minima(const pc_projector *proj, projcurve_result *r);

#endif /* PC_ORTHO_MINIMA_H */
