/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP writing (ISO 10303-21 exchange structure, schema AP214
 * AUTOMOTIVE_DESIGN): geometry instances are formatted into the DATA text
 * as they are added, numbered from PC_STEP_FIRST_GEOMETRY_ID on; the
 * header and the instances that place the geometry in a product (product,
 * shape representation with one GEOMETRIC_SET, geometric context, units,
 * uncertainty) are laid out when the file is written, numbered after the
 * geometry, so the unit and uncertainty may be set at any time. Instance
 * #1 is the 2D parametric context of every pcurve, laid out with them.
 */
#ifndef PC_IO_STEP_WRITE_H
#define PC_IO_STEP_WRITE_H

#include <stddef.h>

#include "io/text_buf.h"
#include "nurbs/nurbs.h"
#include "projcurve.h"

#define PC_STEP_PARAMETRIC_CONTEXT_ID 1L
#define PC_STEP_FIRST_GEOMETRY_ID 2L

/* A B-spline curve to write, borrowed: Cartesian poles (dim 2 for a
 * pcurve in (u, v), or 3) with optional weights, or the homogeneous poles
 * (x w, y w, z w, w) of nurbs/nurbs.h. */
typedef struct pc_step_spline {
    int degree, dim;
    size_t n_poles;
    const double *knots;   /* n_poles + degree + 1, clamped */
    const double *poles;   /* dim per pole, or 4 per pole when homogeneous */
    const double *weights; /* n_poles, or NULL for all 1; unused when homogeneous */
    int homogeneous;
} pc_step_spline;

typedef struct pc_step_surface_key {
    long id;
    char *key; /* the surface's exact data as text, to write it once */
} pc_step_surface_key;

typedef struct pc_step_out {
    pc_text_buf data;  /* the geometry instances so far */
    size_t line_start; /* where data's last line starts (lines are broken near 72 columns) */
    long next_id;
    struct {
        long *items; /* the GEOMETRIC_SET's elements */
        size_t count, capacity;
    } set;
    struct {
        pc_step_surface_key *items;
        size_t count, capacity;
    } surfaces;
    int has_pcurves;        /* #1 is laid out */
    double metres_per_unit; /* the length unit */
    double uncertainty;     /* model units, > 0 */
} pc_step_out;

/* How far an out has come: pc_step_out_rollback returns to it, so that a
 * failed addition of several instances leaves none. */
typedef struct pc_step_mark {
    size_t len, line_start, n_set, n_surfaces;
    long next_id;
    int has_pcurves;
} pc_step_mark;

void pc_step_out_init(pc_step_out *out);
void pc_step_out_free(pc_step_out *out);
pc_step_mark pc_step_out_mark(const pc_step_out *out);
void pc_step_out_rollback(pc_step_out *out, const pc_step_mark *mark);

/* A B_SPLINE_SURFACE_WITH_KNOTS (the complex rational entity where a
 * weight is not 1) and its points, unless an equal surface (same data,
 * bit for bit) is there; *id gets its instance number. A new surface is an
 * element of the GEOMETRIC_SET. Statuses: OK, NOT_FINITE, NO_MEMORY. */
projcurve_status pc_step_out_surface(projcurve_context *ctx, pc_step_out *out,
                                     const pc_nurbs_surface *s, long *id);
/* A B_SPLINE_CURVE_WITH_KNOTS (rational complex entity where a weight is
 * not 1) and its points, in 3D or (a pcurve's) 2D; *id gets its number.
 * Statuses: OK, NOT_FINITE, NO_MEMORY. */
projcurve_status pc_step_out_curve(projcurve_context *ctx, pc_step_out *out,
                                   const pc_step_spline *c, long *id);
/* The PCURVE of the 2D curve #curve2d on the surface #surface (through
 * its DEFINITIONAL_REPRESENTATION in the parametric context #1). */
projcurve_status pc_step_out_pcurve(projcurve_context *ctx, pc_step_out *out, long surface,
                                    long curve2d, long *id);
/* SURFACE_CURVE of the 3D curve #curve3d and the PCURVE #pcurve; the
 * master representation is the pcurve (.PCURVE_S1.: S o q lies exactly on
 * the surface, the 3D curve within the uncertainty of it). */
projcurve_status pc_step_out_surface_curve(projcurve_context *ctx, pc_step_out *out,
                                           long curve3d, long pcurve, long *id);
/* A COMPOSITE_CURVE_SEGMENT of a composite curve: its curve, whether the
 * composite runs along it in its own sense, and whether it continues into
 * the next segment (the first after the last, on a closed composite)
 * without a gap. */
typedef struct pc_step_segment {
    long curve;
    int same_sense;
    int continuous; /* .CONTINUOUS., else .DISCONTINUOUS. */
} pc_step_segment;

/* A COMPOSITE_CURVE of the n segments (self_intersect .U.), each a
 * COMPOSITE_CURVE_SEGMENT; *id gets its number. ISO 10303-42 asks for
 * exactly one discontinuous transition on an open composite (its last
 * segment's) and none on a closed one. Statuses: OK, NO_MEMORY. */
projcurve_status pc_step_out_composite_curve(projcurve_context *ctx, pc_step_out *out,
                                             const pc_step_segment *segments, size_t n,
                                             long *id);
/* Makes #id an element of the GEOMETRIC_SET. */
projcurve_status pc_step_out_add_to_set(projcurve_context *ctx, pc_step_out *out, long id);

/* The whole file as text (malloc'ed, NUL-terminated). */
projcurve_status pc_step_out_text(projcurve_context *ctx, const pc_step_out *out, char **text,
                                  size_t *len);
/* Writes the file. Statuses: OK, IO, NO_MEMORY. */
projcurve_status pc_step_out_write(projcurve_context *ctx, const pc_step_out *out,
                                   const char *path);

/* The instances after the geometry (step_write_context.c): product,
 * representation, GEOMETRIC_SET, 3D context, units and uncertainty, from
 * #first on; and #1 when the file has pcurves. */
void pc_step_format_context(pc_text_buf *b, const pc_step_out *out, long first);

#endif /* PC_IO_STEP_WRITE_H */
