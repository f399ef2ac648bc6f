/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP geometry readers shared by the files of src/io/ that read STEP
 * entities (step_read.c implements them): references, points, directions,
 * placements and curves, each checked, with a PARSE message naming the
 * instance and its line. Nodes and arrays live in the caller's arena.
 */
#ifndef PC_IO_STEP_GEOM_H
#define PC_IO_STEP_GEOM_H

#include "analytic/analytic.h"
#include "io/io_geom.h"
#include "io/step.h"

typedef struct pc_step_located {
    const pc_step_instance *inst;
    const pc_step_node *node;
} pc_step_located;

/* PARSE with "STEP #id (line n): what". */
projcurve_status pc_step_bad(const pc_step_file *f, const pc_step_instance *at, const char *what);

/* The instance a reference (#n) names, parsed. */
projcurve_status pc_step_resolve(pc_step_file *f, pc_arena *arena, const pc_step_instance *from,
                                 const pc_step_node *ref, pc_step_located *out);

/* CARTESIAN_POINT (missing coordinates are 0). */
projcurve_status pc_step_point(pc_step_file *f, pc_arena *arena, const pc_step_instance *from,
                               const pc_step_node *ref, double p[3]);

/* DIRECTION, made unit (ZERO length is a PARSE error). */
projcurve_status pc_step_direction(pc_step_file *f, pc_arena *arena,
                                   const pc_step_instance *from, const pc_step_node *ref,
                                   double d[3]);

/* AXIS2_PLACEMENT_3D as origin and orthonormal x, y (z = x cross y); a 2D
 * placement sets *skip. */
projcurve_status pc_step_placement(pc_step_file *f, pc_arena *arena,
                                   const pc_step_instance *from, const pc_step_node *ref,
                                   double o[3], double x[3], double y[3], const char **skip);

/* A bounded 3D curve entity as an exact NURBS: a B-spline curve (its own
 * parameter), a CIRCLE or an ELLIPSE (a full turn, *map from the angle to
 * the NURBS parameter) or a TRIMMED_CURVE of a LINE, CIRCLE, ELLIPSE or
 * B-spline; *map (may be NULL) is the identity for all but full circles
 * and ellipses. A valid curve that is not converted sets *skip. */
projcurve_status pc_step_curve(pc_step_file *f, pc_arena *arena, const pc_step_located *c,
                               pc_io_curve *out, pc_angle_map *map, const char **skip);

/* CIRCLE (a = b = radius) or ELLIPSE: centre o, axes x, y and semi-axes a
 * (along x), b; a 2D placement sets *skip. */
projcurve_status pc_step_conic(pc_step_file *f, pc_arena *arena, const pc_step_located *c,
                               double o[3], double x[3], double y[3], double *a, double *b,
                               const char **skip);

/* LINE('', point, VECTOR): P(t) = o + t v (v with the vector's magnitude). */
projcurve_status pc_step_line(pc_step_file *f, pc_arena *arena, const pc_step_located *l,
                              double o[3], double v[3]);

/* The 3D curve of an EDGE_CURVE between its vertices, as an exact NURBS
 * (step_edges.c). It runs along the basis curve in the basis curve's own
 * direction and parameter (a LINE's t, a CIRCLE's or ELLIPSE's angle
 * through *map, which may be NULL), over the part the edge covers: from
 * the first vertex to the second when the edge's same_sense is .T., from
 * the second to the first otherwise; equal vertices on a conic give the
 * whole turn. The basis curve of a SURFACE_CURVE / SEAM_CURVE is its 3D
 * curve. B-spline curves and TRIMMED_CURVEs are returned as pc_step_curve
 * reads them (their ends are the vertices in the files seen). Other
 * curves set *skip. */
projcurve_status pc_step_edge_curve(pc_step_file *f, pc_arena *arena, const pc_step_located *edge,
                                    pc_io_curve *out, pc_angle_map *map, const char **skip);

/* The entity name of a simple instance (empty for a complex one) without
 * parsing it; returns its length. */
size_t pc_step_name(const pc_step_file *f, const pc_step_instance *inst, char name[PC_STEP_MAX_NAME]);

#endif /* PC_IO_STEP_GEOM_H */
