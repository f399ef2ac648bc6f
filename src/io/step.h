/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP (ISO 10303-21) reading, internal pieces.
 *
 * The DATA section is indexed once (instance number -> text span); the
 * parameters of an instance are parsed on demand into a small tree of
 * values: numbers, strings, enumerations, references, lists, typed values
 * (NAME(...)) and, for complex instances (A(...) B(...)), a list of typed
 * values. Nesting deeper than PC_STEP_MAX_DEPTH is refused, so garbage
 * cannot exhaust the stack.
 */
#ifndef PC_IO_STEP_H
#define PC_IO_STEP_H

#include <stddef.h>

#include "common/arena.h"
#include "io/io_model.h"

#define PC_STEP_MAX_DEPTH 32
#define PC_STEP_MAX_NAME 64

typedef enum pc_step_kind {
    PC_STEP_NUMBER,
    PC_STEP_STRING,
    PC_STEP_ENUM,
    PC_STEP_REF,
    PC_STEP_LIST,
    PC_STEP_TYPED,   /* NAME(args): a simple instance, a sub-entity or a typed parameter */
    PC_STEP_COMPLEX, /* (A(...) B(...) ...): children are TYPED */
    PC_STEP_OMITTED, /* $ */
    PC_STEP_DERIVED  /* * */
} pc_step_kind;

typedef struct pc_step_node pc_step_node;
struct pc_step_node {
    pc_step_kind kind;
    double number;
    long ref;
    const char *text; /* string/enum/type name (not NUL-terminated) */
    size_t len;
    pc_step_node *first; /* children of lists, typed values, complex instances */
    pc_step_node *next;  /* next sibling */
    size_t n_children;
};

typedef struct pc_step_instance {
    long id;
    size_t begin, end; /* text after '=' up to (not including) ';' */
    size_t line;
} pc_step_instance;

typedef struct pc_step_file {
    projcurve_context *ctx;
    const char *text;
    size_t len;
    pc_step_instance *instances; /* sorted by id */
    size_t n_instances;
    /* Characters parsed so far and the most allowed: an instance is parsed
     * again for each reference to it, and the budget keeps a file of many
     * references to one large instance from taking quadratic time. */
    size_t *work_done;
    size_t work_limit;
    /* The plane angle unit of the geometric context in radians (1 unless
     * the file says degrees), set by pc_step_read_units. */
    double radians_per_angle_unit;
} pc_step_file;

/* Indexes the DATA section (step_lexer.c). instances is malloc'ed: release
 * with pc_step_index_free. */
projcurve_status pc_step_index(pc_step_file *f);
void pc_step_index_free(pc_step_file *f);
/* The instance #id, or NULL. */
const pc_step_instance *pc_step_find(const pc_step_file *f, long id);
/* Parses an instance's value (TYPED or COMPLEX) into arena nodes. */
projcurve_status pc_step_parse(const pc_step_file *f, const pc_step_instance *inst,
                               pc_arena *arena, pc_step_node **out);

/* Child i of a node (NULL past the end). */
const pc_step_node *pc_step_child(const pc_step_node *n, size_t i);
/* 1 when a TYPED node has this name. */
int pc_step_is(const pc_step_node *n, const char *name);
/* The sub-entity named name of a complex instance, or the instance itself
 * if it is simple and so named; NULL otherwise. */
const pc_step_node *pc_step_part(const pc_step_node *inst, const char *name);

/* Reads the length unit, the plane angle unit and the distance precision
 * of the first geometric context that states them (step_units.c) into the
 * model and f->radians_per_angle_unit. */
projcurve_status pc_step_read_units(pc_step_file *f, projcurve_model *model);

/* Reads the geometry of the file into the model (step_read.c): B-spline
 * surfaces and curves in file order, then the analytic surfaces. */
projcurve_status pc_step_read_geometry(pc_step_file *f, projcurve_model *model);

/* Reads every analytic surface (PLANE, CYLINDRICAL_SURFACE, ...) into the
 * model as an exact NURBS, an unbounded one over the box of the faces that
 * use it (step_analytic.c). */
projcurve_status pc_step_read_analytic(pc_step_file *f, projcurve_model *model);

#endif /* PC_IO_STEP_H */
