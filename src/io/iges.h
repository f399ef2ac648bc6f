/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES 5.3 reading, internal pieces.
 *
 * An IGES file is a sequence of 80-column records: columns 1-72 data,
 * column 73 the section letter (S, G, D, P, T in this order), columns 74-80
 * the sequence number. The directory (D) has two records per entity; the
 * parameter data (P) of an entity is free-format text in columns 1-64 of its
 * records, fields separated by the parameter delimiter and ended by the
 * record delimiter, both declared at the start of the global (G) section.
 */
#ifndef PC_IO_IGES_H
#define PC_IO_IGES_H

#include <stddef.h>

#include "common/arena.h"
#include "io/io_geom.h"
#include "io/io_model.h"

#define PC_IGES_RECORD 80
#define PC_IGES_DATA_COLUMNS 72
#define PC_IGES_PARAM_COLUMNS 64

typedef struct pc_iges_section {
    const char **records; /* each PC_IGES_RECORD characters, space padded */
    size_t *lines;        /* line number of each record in the file (1-based) */
    size_t count;
} pc_iges_section;

/* One directory entry (two D records). */
typedef struct pc_iges_entry {
    int type;
    long param_start;   /* P sequence number of the first parameter record */
    long param_lines;   /* number of parameter records */
    long transform;     /* DE pointer of a 124 entity, 0 if none */
    int form;
    int subordinate;    /* status digits 3-4: 0 independent, 1 physically dependent, ... */
    int use;            /* status digits 5-6: 5 = 2D parametric */
} pc_iges_entry;

/* A parameter field: raw text (trimmed) or the string of a Hollerith field. */
typedef struct pc_iges_field {
    const char *text;
    size_t len;
} pc_iges_field;

typedef struct pc_iges_file {
    projcurve_context *ctx;
    pc_arena *arena;
    pc_iges_section sec[5]; /* S, G, D, P, T */
    char param_delim, record_delim;
    pc_iges_entry *entries;
    size_t n_entries;
    /* Parameter characters tokenised so far and the most allowed: entities
     * referenced many times (members, matrices) are parsed each time, and
     * the budget keeps a file of many references to one large entity from
     * taking quadratic time. */
    size_t *work_done;
    size_t work_limit;
    /* The model's surface index of each entry read as a surface, -1 for
     * the others (the faces of iges_topology.c look their surfaces up). */
    long *surface_of;
} pc_iges_file;

/* The parameters of one entity. */
typedef struct pc_iges_params {
    const pc_iges_file *file;
    size_t de;            /* DE pointer (odd sequence number) for messages */
    int type;
    pc_iges_field *fields; /* fields[0] is the entity type */
    size_t count;
} pc_iges_params;

/* Splits the text into sections (iges_records.c). */
projcurve_status pc_iges_split(pc_iges_file *f, const char *data, size_t len);
/* Reads the delimiters from the global section (iges_params.c). */
projcurve_status pc_iges_read_global(pc_iges_file *f);
/* Reads the directory (iges_directory.c). */
projcurve_status pc_iges_read_directory(pc_iges_file *f);
/* Tokenises the parameter data of the entity at DE pointer de (iges_params.c). */
projcurve_status pc_iges_params_of(const pc_iges_file *f, size_t de, pc_iges_params *out);
/* Field i as a real / an integer; a missing or empty field gives the default
 * (0) as IGES prescribes. Non-numeric text gives PARSE naming the entity. */
projcurve_status pc_iges_real(const pc_iges_params *p, size_t i, double *out);
projcurve_status pc_iges_int(const pc_iges_params *p, size_t i, long *out);
/* Fields first .. first + n - 1 into out[0 .. n - 1], as pc_iges_real /
 * pc_iges_int; stops at the first field that fails. */
projcurve_status pc_iges_reals(const pc_iges_params *p, size_t first, size_t n, double *out);
projcurve_status pc_iges_ints(const pc_iges_params *p, size_t first, size_t n, long *out);
/* The entry at DE pointer de, or NULL (with PARSE recorded) when de does not
 * point at the start of a directory entry. */
const pc_iges_entry *pc_iges_entry_at(const pc_iges_file *f, long de, size_t from_de);

/* Geometry of curve and surface entities (iges_geometry.c): the result has
 * the entity's own transformation (DE field 7) applied. A *skip_reason is
 * set (and OK returned) for valid entities that are not converted. */
projcurve_status pc_iges_curve(const pc_iges_file *f, size_t de, pc_io_curve *out,
                               const char **skip_reason);
projcurve_status pc_iges_surface(const pc_iges_file *f, size_t de, pc_io_surface *out);

/* The transformation of the entity at de (field 7, chained 124s composed;
 * identity without one). */
projcurve_status pc_iges_transform(const pc_iges_file *f, size_t de, pc_io_affine *out);

/* The analytic surfaces (iges_analytic.c): 108 plane, 118 ruled surface,
 * 120 surface of revolution, 122 tabulated cylinder, 190 plane surface,
 * 192 right circular cylindrical, 194 right circular conical, 196
 * spherical and 198 toroidal surface, as exact NURBS with the entity's
 * transformation applied; *kind gets the model's kind name. The unbounded
 * 190, 192 and 194 are built over the box that points[0 .. 3 n_points)
 * need (in the entity's own coordinates; none: skipped). Entities the
 * surface is made of (curves, points, directions) are listed in uses[0 ..
 * *n_uses) (at most PC_IGES_MAX_USES) so that the reader does not list
 * them as skipped. A valid entity that is not converted sets *skip_reason
 * (OK returned). */
#define PC_IGES_MAX_USES 4
int pc_iges_is_analytic_surface(int type);
projcurve_status pc_iges_analytic_surface(const pc_iges_file *f, size_t de, const double *points,
                                          size_t n_points, pc_io_surface *out, const char **kind,
                                          long uses[PC_IGES_MAX_USES], size_t *n_uses,
                                          const char **skip_reason);

/* The units flag or name and the minimum resolution of the global section
 * into the model (iges_units.c); fields that are missing or not understood
 * leave the model's unit or precision unset. */
projcurve_status pc_iges_read_units(const pc_iges_file *f, projcurve_model *model);
/* The units flag (1 .. 11, not 3) of a length unit given in metres, 0 when
 * no flag names it (iges_units.c). */
int pc_iges_unit_flag(double metres_per_unit);
/* The unit name (field 15) of a units flag; NULL for 3 and non-flags. */
const char *pc_iges_unit_name(int flag);

/* Faces and the shape of the file (iges_topology.c), after the entities:
 * marks what it reads in consumed. */
projcurve_status pc_iges_read_topology(pc_iges_file *f, projcurve_model *model,
                                       unsigned char *consumed);

/* The model-space curve c bounding a face on the analytic surface s (whose
 * NURBS is not in the entity's own parameters) as a degree-1 pcurve on s
 * by point inversion (iges_face_map.c): every chord's middle within a
 * quarter of tol_uv of the inverted curve, every point within 10 tol_model
 * of s; anchor (or NULL) is the (u, v) the loop reached before c, which
 * picks the side of a seam for a curve along it. *reason is set (and OK
 * returned) when c does not map (off s, across a closed direction's seam,
 * not within tol_uv at the most samples). out lives in f's arena.
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_iges_boundary_by_inversion(const pc_iges_file *f, const projcurve_surface *s,
                                               const pc_io_curve *c, double tol_model,
                                               double tol_uv, const double *anchor,
                                               pc_io_curve *out, const char **reason);

#endif /* PC_IO_IGES_H */
