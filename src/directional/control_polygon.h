/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Rays against the control polygon of a Bezier patch (its control net split
 * into triangles), used by [SY13] s3.3 (estimating the projection's length)
 * and s3.4 (the jump criteria count these hits).
 */
#ifndef PC_DIRECTIONAL_CONTROL_POLYGON_H
#define PC_DIRECTIONAL_CONTROL_POLYGON_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "common/vec.h"

/* Hits of the ray origin + lambda * dir (lambda > 0) with the triangulated
 * control net of the patch, in net order. Up to max points are written to
 * out (may be NULL when max is 0); returns the number of hits (which may
 * exceed max). Degenerate triangles (collapsed edges) are skipped. */
size_t pc_control_polygon_ray_hits(const pc_bezier_patch *patch, pc_vec3 origin, pc_vec3 dir,
                                   pc_vec3 *out, size_t max);

#endif /* PC_DIRECTIONAL_CONTROL_POLYGON_H */
