/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES 5.3 writing: a list of entities, each with its parameter text ready,
 * laid out as S, G, D, P and T sections at the end. Entities refer to each
 * other by directory pointer, which is known when an entity is added
 * (entity k has DE pointer 2k + 1), so no second pass is needed.
 */
#ifndef PC_IO_IGES_WRITE_H
#define PC_IO_IGES_WRITE_H

#include <stddef.h>

#include "io/text_buf.h"
#include "nurbs/nurbs.h"
#include "projcurve.h"

/* Status digits of the directory: visibility, subordinate switch, use
 * flag, hierarchy (IGES 5.3 s2.2.4.4.9). */
#define PC_IGES_STATUS_INDEPENDENT "00000000"
#define PC_IGES_STATUS_PART "00010000"           /* physically dependent geometry */
#define PC_IGES_STATUS_PARAMETRIC_PART "00010500" /* dependent, 2D parametric */

typedef struct pc_iges_out_entity {
    int type, form;
    char status[9];
    char *params; /* "f1,f2,...,fn;" without the leading type number */
} pc_iges_out_entity;

typedef struct pc_iges_out {
    pc_iges_out_entity *entities;
    size_t count, cap;
    int unit_flag; /* global parameters 14 and 15 (pc_iges_unit_flag); 0 = millimetres */
} pc_iges_out;

/* Parameter fields: each followed by the parameter delimiter ','. */
void pc_iges_param_real(pc_text_buf *b, double v);
void pc_iges_param_int(pc_text_buf *b, long long v);
/* Replaces the last ',' by ';' (the record delimiter). */
void pc_iges_param_end(pc_text_buf *b);

/* Appends an entity; takes ownership of params->text on success. *de gets
 * its DE pointer. */
projcurve_status pc_iges_out_add(projcurve_context *ctx, pc_iges_out *out, int type, int form,
                                 const char *status, pc_text_buf *params, size_t *de);
void pc_iges_out_free(pc_iges_out *out);
/* Drops the entities from index count on (those added since out held
 * count), so that a failed addition of several entities leaves none. */
void pc_iges_out_truncate(pc_iges_out *out, size_t count);

/* Parameter text of entity 128 / 126 from the library's NURBS storage; for
 * 126 `planar_z` != 0 marks a curve lying in the plane z = 0 (a pcurve). */
void pc_iges_format_surface(pc_text_buf *b, const pc_nurbs_surface *s);
void pc_iges_format_curve(pc_text_buf *b, const pc_nurbs_curve *c, int planar_z);
/* Entity 126 of c run from its end to its start: parameter s = a + b - t
 * over the same knot interval [a, b], so that member k + 1 of a composite
 * curve (102) starts where member k ends. */
void pc_iges_format_curve_reversed(pc_text_buf *b, const pc_nurbs_curve *c, int planar_z);
/* Entity 102 (composite curve) of the n curves at DE pointers members, in
 * the order the composite runs through them. */
void pc_iges_format_composite(pc_text_buf *b, const size_t *members, size_t n);
/* Entity 126 of degree 1 through n points (x, y, z) with parameters t
 * (strictly increasing); planar_z as above. */
void pc_iges_format_polyline(pc_text_buf *b, const double *xyz, const double *t, size_t n,
                             int planar_z);

/* Writes the file. */
projcurve_status pc_iges_out_write(projcurve_context *ctx, const pc_iges_out *out,
                                   const char *path);
/* The whole file as text (malloc'ed, NUL-terminated); for tests and memory
 * writers. */
projcurve_status pc_iges_out_text(projcurve_context *ctx, const pc_iges_out *out, char **text,
                                  size_t *len);

#endif /* PC_IO_IGES_WRITE_H */
