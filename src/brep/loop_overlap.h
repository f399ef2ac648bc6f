/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Whether the loops of a face lie apart as a face needs them: no loop
 * crossing another or itself, every hole inside the outer loop and in no
 * other hole. The classifier counts winding numbers, so loops that overlap
 * would give points in two holes, or outside the outer loop, or in the
 * second lobe of a figure eight, the answer IN.
 */
#ifndef PC_BREP_LOOP_OVERLAP_H
#define PC_BREP_LOOP_OVERLAP_H

#include "brep/face.h"

/* Checks the flattened loops of a built face f (outer loop counter-
 * clockwise, holes clockwise, its classifier built). Two segments that
 * cross properly (the ends of each strictly on both sides of the other's
 * line), of two loops or of one, are a crossing; a loop touching another
 * or itself is not. A hole whose first point has winding number 0 about the other loops
 * is outside the outer loop or inside another hole. Statuses: OK,
 * INVALID_ARGUMENT (naming the loops and the point), NO_MEMORY. `what`
 * names the face in the message. */
projcurve_status pc_face_check_loops_apart(projcurve_context *ctx, const projcurve_face *f,
                                           const char *what);

#endif /* PC_BREP_LOOP_OVERLAP_H */
