/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Creases of the parametric orthogonal projection: interior knot lines
 * where S is only C0 (a knot of multiplicity >= the degree; every interior
 * knot of a degree-1, faceted surface). There the normal jumps, and a foot
 * point reaching the crease on one patch need not continue on the other:
 * past a convex crease the nearest point stays on the crease line, which is
 * a foot point of neither patch (S has no normal there). The tracer, whose
 * domain is the whole surface, then fails on the crease. The projection
 * onto a C0 surface is that onto its smooth pieces, and a crease is a
 * boundary of those: this pass names a branch end lying on a crease
 * PROJCURVE_END_BOUNDARY (instead of FAILED) and a branch start there
 * (found by the jump sweep) PROJCURVE_START_BOUNDARY.
 */
#ifndef PC_ORTHO_CREASES_H
#define PC_ORTHO_CREASES_H

#include "trace/projector.h"
#include "trace/result.h"

/* Renames the FAILED ends and JUMP starts of r's branches (points (t, u,
 * v)) whose end vertex lies on a crease of proj's surface. */
void pc_ortho_name_crease_ends(const pc_projector *proj, projcurve_result *r);

#endif /* PC_ORTHO_CREASES_H */
