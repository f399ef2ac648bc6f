/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP analytic surfaces (PLANE, CYLINDRICAL_SURFACE, CONICAL_SURFACE,
 * SPHERICAL_SURFACE, TOROIDAL_SURFACE, DEGENERATE_TOROIDAL_SURFACE,
 * SURFACE_OF_REVOLUTION, SURFACE_OF_LINEAR_EXTRUSION) as exact NURBS.
 *
 * Angle directions are built over their whole turn (the sphere's latitude
 * over [-pi/2, pi/2]), a swept curve's direction over the curve; the
 * unbounded directions (the plane's two, the heights of cylinders and
 * cones, the length of an extrusion) over the range that the given points
 * need, with the margin of pc_analytic_box_covering (analytic.h: 1 % of
 * the range plus 1e-3 of its largest end or the radius, on each side).
 */
#ifndef PC_IO_STEP_ANALYTIC_H
#define PC_IO_STEP_ANALYTIC_H

#include "analytic/analytic.h"
#include "io/step.h"

/* One surface read. desc.curve points at swept (do not copy the struct
 * while desc is used). map_u, map_v map the file's (u, v) to the NURBS's:
 * a pcurve given in the analytic parametrisation is carried onto nurbs by
 * them, and box is the analytic box that nurbs covers. */
typedef struct pc_step_analytic {
    const char *kind; /* "plane", "cylinder", ... (pc_analytic_kind_name) */
    pc_analytic_surface desc;
    pc_io_curve swept;
    pc_io_surface nurbs;
    pc_angle_map map_u, map_v;
    double box[4];
} pc_step_analytic;

/* The *skip of a surface whose values are refused (the context holds the
 * refusal's message). */
extern const char *const pc_step_refused_reason;

/* 1 when name is one of the entities above. */
int pc_step_is_analytic_surface(const char *name);

/* Reads the surface instance #id and builds its NURBS over the box that
 * covers points[0 .. 3 n_points) (a face's loop points; may be empty for
 * the bounded kinds). Arrays live in the arena. A valid surface that cannot
 * be converted (a spindle DEGENERATE_TOROIDAL_SURFACE, an unbounded
 * surface without points, a swept curve of an unsupported type) sets
 * *skip with the reason and returns OK; so does a surface whose values are
 * refused (a radius <= 0, ...), with the refusal's message in the
 * context. Statuses: OK, PARSE (a malformed instance, naming it),
 * NO_MEMORY. */
projcurve_status pc_step_analytic_surface(pc_step_file *f, pc_arena *arena, long id,
                                          const double *points, size_t n_points,
                                          pc_step_analytic *out, const char **skip);

#endif /* PC_IO_STEP_ANALYTIC_H */
