/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP units: the length and plane angle units of the geometric context
 * (GLOBAL_UNIT_ASSIGNED_CONTEXT) and its distance precision
 * (GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT). A unit is an SI_UNIT with an
 * optional prefix, or a CONVERSION_BASED_UNIT ('INCH', 'DEGREE', ...)
 * whose measure refers to another unit, followed to a bounded depth.
 * Coordinates are kept as the file gives them; the model only records the
 * unit, so a caller can scale.
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "io/step.h"

/* Conversion-based units referring to conversion-based units: longer
 * chains than this are taken as a cycle and the unit as unknown. */
#define PC_STEP_UNIT_DEPTH 4

typedef enum unit_kind { UNIT_NONE, UNIT_LENGTH, UNIT_ANGLE } unit_kind;

static const struct {
    const char *name;
    double factor;
} k_prefixes[] = {{"EXA", 1e18},   {"PETA", 1e15},  {"TERA", 1e12},  {"GIGA", 1e9},
                  {"MEGA", 1e6},   {"KILO", 1e3},   {"HECTO", 1e2},  {"DECA", 1e1},
                  {"DECI", 1e-1},  {"CENTI", 1e-2}, {"MILLI", 1e-3}, {"MICRO", 1e-6},
                  {"NANO", 1e-9},  {"PICO", 1e-12}, {"FEMTO", 1e-15}, {"ATTO", 1e-18}};

static int enum_is(const pc_step_node *n, const char *name)
{
    return n != NULL && n->kind == PC_STEP_ENUM && n->len == strlen(name) &&
           memcmp(n->text, name, n->len) == 0;
}

static double prefix_factor(const pc_step_node *n)
{
    for (size_t i = 0; i < sizeof k_prefixes / sizeof *k_prefixes; ++i)
        if (enum_is(n, k_prefixes[i].name))
            return k_prefixes[i].factor;
    return 1.0;
}

static const pc_step_node *parse_ref(const pc_step_file *f, pc_arena *arena,
                                     const pc_step_node *ref)
{
    if (ref == NULL || ref->kind != PC_STEP_REF)
        return NULL;
    const pc_step_instance *inst = pc_step_find(f, ref->ref);
    pc_step_node *node = NULL;
    if (inst == NULL || pc_step_parse(f, inst, arena, &node) != PROJCURVE_OK)
        return NULL;
    return node;
}

/* The size of the unit #ref in metres or radians; UNIT_NONE when it is
 * neither or cannot be followed. */
static unit_kind unit_size(const pc_step_file *f, pc_arena *arena, const pc_step_node *ref,
                           int depth, double *size)
{
    const pc_step_node *u = parse_ref(f, arena, ref);
    if (u == NULL || depth > PC_STEP_UNIT_DEPTH)
        return UNIT_NONE;
    const unit_kind kind = pc_step_part(u, "LENGTH_UNIT") ? UNIT_LENGTH
                           : pc_step_part(u, "PLANE_ANGLE_UNIT") ? UNIT_ANGLE
                                                                 : UNIT_NONE;
    if (kind == UNIT_NONE)
        return UNIT_NONE;
    const pc_step_node *si = pc_step_part(u, "SI_UNIT");
    if (si != NULL && si->n_children >= 2) {
        /* SI_UNIT(prefix, name), or with the dimensions first in the
         * simple form: the last two attributes. */
        const pc_step_node *prefix = pc_step_child(si, si->n_children - 2);
        const pc_step_node *name = pc_step_child(si, si->n_children - 1);
        if (!(enum_is(name, "METRE") || enum_is(name, "RADIAN")))
            return UNIT_NONE;
        *size = prefix_factor(prefix);
        return kind;
    }
    const pc_step_node *conv = pc_step_part(u, "CONVERSION_BASED_UNIT");
    if (conv == NULL)
        return UNIT_NONE;
    /* CONVERSION_BASED_UNIT(name, #m), #m = ..._MEASURE_WITH_UNIT(X(value), #unit) */
    const pc_step_node *m = parse_ref(f, arena, pc_step_child(conv, 1));
    const pc_step_node *value = m ? pc_step_child(m, 0) : NULL;
    if (value && value->kind == PC_STEP_TYPED)
        value = value->first;
    double inner = 0.0;
    if (value == NULL || value->kind != PC_STEP_NUMBER || !(value->number > 0.0) ||
        !isfinite(value->number) ||
        unit_size(f, arena, pc_step_child(m, 1), depth + 1, &inner) != kind)
        return UNIT_NONE;
    *size = value->number * inner;
    return kind;
}

static void read_context_units(pc_step_file *f, pc_arena *arena, const pc_step_node *ctx_node,
                               projcurve_model *model)
{
    const pc_step_node *units = pc_step_child(pc_step_part(ctx_node, "GLOBAL_UNIT_ASSIGNED_CONTEXT"), 0);
    for (const pc_step_node *c = units ? units->first : NULL; c != NULL; c = c->next) {
        double size = 0.0;
        const unit_kind kind = unit_size(f, arena, c, 0, &size);
        if (kind == UNIT_LENGTH && !model->has_length_unit) {
            model->metres_per_unit = size;
            model->has_length_unit = 1;
        } else if (kind == UNIT_ANGLE) {
            f->radians_per_angle_unit = size;
        }
    }
    const pc_step_node *unc = pc_step_child(pc_step_part(ctx_node, "GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT"), 0);
    for (const pc_step_node *c = unc ? unc->first : NULL; c && !model->has_precision; c = c->next) {
        /* UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(x), #unit, name, description) */
        const pc_step_node *m = parse_ref(f, arena, c);
        const pc_step_node *value = m ? pc_step_child(m, 0) : NULL;
        if (value && value->kind == PC_STEP_TYPED)
            value = value->first;
        double size = 0.0;
        if (value == NULL || value->kind != PC_STEP_NUMBER || !(value->number > 0.0) ||
            !isfinite(value->number) ||
            unit_size(f, arena, pc_step_child(m, 1), 0, &size) != UNIT_LENGTH)
            continue;
        const double model_unit = model->has_length_unit ? model->metres_per_unit : size;
        model->precision = value->number * size / model_unit;
        model->has_precision = 1;
    }
}

projcurve_status pc_step_read_units(pc_step_file *f, projcurve_model *model)
{
    f->radians_per_angle_unit = 1.0;
    pc_arena arena;
    pc_arena_init(&arena, 1u << 12);
    for (size_t i = 0; i < f->n_instances && !model->has_length_unit; ++i) {
        const pc_step_instance *inst = &f->instances[i];
        /* Contexts are complex instances: their text starts with '('. */
        size_t pos = inst->begin;
        while (pos < inst->end && (f->text[pos] == ' ' || f->text[pos] == '\n' ||
                                   f->text[pos] == '\r' || f->text[pos] == '\t'))
            ++pos;
        if (pos >= inst->end || f->text[pos] != '(')
            continue;
        pc_step_node *node = NULL;
        if (pc_step_parse(f, inst, &arena, &node) == PROJCURVE_OK &&
            pc_step_part(node, "GLOBAL_UNIT_ASSIGNED_CONTEXT") != NULL)
            read_context_units(f, &arena, node, model);
        pc_arena_release(&arena);
    }
    pc_arena_release(&arena);
    return PROJCURVE_OK;
}
