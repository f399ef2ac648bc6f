/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP analytic surfaces: the description of each entity (ISO 10303-42
 * attributes) and its NURBS over the box its points need
 * (step_analytic.h). Radii and lengths are in the file's length unit,
 * angles in its plane angle unit.
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "common/vec.h"
#include "io/step_analytic.h"
#include "io/step_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static const struct {
    const char *entity;
    pc_analytic_kind kind;
} k_entities[] = {{"PLANE", PC_ANALYTIC_PLANE},
                  {"CYLINDRICAL_SURFACE", PC_ANALYTIC_CYLINDER},
                  {"CONICAL_SURFACE", PC_ANALYTIC_CONE},
                  {"SPHERICAL_SURFACE", PC_ANALYTIC_SPHERE},
                  {"TOROIDAL_SURFACE", PC_ANALYTIC_TORUS},
                  {"DEGENERATE_TOROIDAL_SURFACE", PC_ANALYTIC_TORUS},
                  {"SURFACE_OF_REVOLUTION", PC_ANALYTIC_REVOLUTION},
                  {"SURFACE_OF_LINEAR_EXTRUSION", PC_ANALYTIC_EXTRUSION}};

/* The reason given for a surface whose values are refused; the context
 * holds the refusal. */
const char *const pc_step_refused_reason = "its values are refused";

int pc_step_is_analytic_surface(const char *name)
{
    for (size_t i = 0; i < sizeof k_entities / sizeof *k_entities; ++i)
        if (strcmp(name, k_entities[i].entity) == 0)
            return 1;
    return 0;
}

static projcurve_status number(pc_step_file *f, const pc_step_located *at, size_t i,
                               double *out)
{
    const pc_step_node *n = pc_step_child(at->node, i);
    if (n == NULL || n->kind != PC_STEP_NUMBER)
        return pc_step_bad(f, at->inst, "a surface attribute that should be a number is not");
    *out = n->number;
    return PROJCURVE_OK;
}

/* AXIS2_PLACEMENT_3D of attribute 1 as a frame. */
static projcurve_status frame_of(pc_step_file *f, pc_arena *arena, const pc_step_located *at,
                                 pc_frame *out, const char **skip)
{
    double o[3], x[3], y[3];
    projcurve_status st = pc_step_placement(f, arena, at->inst, pc_step_child(at->node, 1), o, x,
                                            y, skip);
    if (st != PROJCURVE_OK || *skip != NULL)
        return st;
    double z[3];
    vec3_store(vec3_cross(vec3_load(x), vec3_load(y)), z);
    if (pc_frame_make(f->ctx, o, z, x, out) != PROJCURVE_OK)
        *skip = pc_step_refused_reason;
    return PROJCURVE_OK;
}

static projcurve_status swept_curve(pc_step_file *f, pc_arena *arena, const pc_step_located *at,
                                    pc_step_analytic *out, const char **skip)
{
    pc_step_located c;
    projcurve_status st = pc_step_resolve(f, arena, at->inst, pc_step_child(at->node, 1), &c);
    if (st != PROJCURVE_OK)
        return st;
    st = pc_step_curve(f, arena, &c, &out->swept, &out->desc.curve_map, skip);
    if (st == PROJCURVE_OK && *skip != NULL)
        *skip = "its swept curve is of an unsupported type";
    out->desc.curve = &out->swept;
    return st;
}

/* SURFACE_OF_REVOLUTION('', curve, AXIS1_PLACEMENT('', point, direction)) */
static projcurve_status revolution(pc_step_file *f, pc_arena *arena, const pc_step_located *at,
                                   pc_step_analytic *out, const char **skip)
{
    pc_step_located ax;
    projcurve_status st = pc_step_resolve(f, arena, at->inst, pc_step_child(at->node, 2), &ax);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(ax.node, "AXIS1_PLACEMENT"))
        return pc_step_bad(f, ax.inst, "expected an AXIS1_PLACEMENT");
    double o[3], z[3] = {0.0, 0.0, 1.0};
    const pc_step_node *dir = pc_step_child(ax.node, 2);
    if ((st = pc_step_point(f, arena, ax.inst, pc_step_child(ax.node, 1), o)) != PROJCURVE_OK ||
        (dir && dir->kind == PC_STEP_REF &&
         (st = pc_step_direction(f, arena, ax.inst, dir, z)) != PROJCURVE_OK))
        return st;
    if (pc_frame_make(f->ctx, o, z, NULL, &out->desc.frame) != PROJCURVE_OK) {
        *skip = pc_step_refused_reason;
        return PROJCURVE_OK;
    }
    return swept_curve(f, arena, at, out, skip);
}

/* SURFACE_OF_LINEAR_EXTRUSION('', curve, VECTOR('', direction, magnitude)) */
static projcurve_status extrusion(pc_step_file *f, pc_arena *arena, const pc_step_located *at,
                                  pc_step_analytic *out, const char **skip)
{
    pc_step_located vec;
    projcurve_status st = pc_step_resolve(f, arena, at->inst, pc_step_child(at->node, 2), &vec);
    if (st != PROJCURVE_OK)
        return st;
    const pc_step_node *mag = pc_step_child(vec.node, 2);
    if (!pc_step_is(vec.node, "VECTOR") || mag == NULL || mag->kind != PC_STEP_NUMBER)
        return pc_step_bad(f, vec.inst, "expected VECTOR('', direction, magnitude)");
    double d[3];
    if ((st = pc_step_direction(f, arena, vec.inst, pc_step_child(vec.node, 1), d)) != PROJCURVE_OK)
        return st;
    for (int k = 0; k < 3; ++k)
        out->desc.extrusion[k] = mag->number * d[k];
    return swept_curve(f, arena, at, out, skip);
}

static projcurve_status describe(pc_step_file *f, pc_arena *arena, const pc_step_located *at,
                                 pc_step_analytic *out, const char **skip)
{
    size_t e = 0;
    while (e < sizeof k_entities / sizeof *k_entities && !pc_step_is(at->node, k_entities[e].entity))
        ++e;
    if (e == sizeof k_entities / sizeof *k_entities) {
        *skip = "not an analytic surface";
        return PROJCURVE_OK;
    }
    pc_analytic_surface *d = &out->desc;
    d->kind = k_entities[e].kind;
    out->kind = pc_analytic_kind_name(d->kind);
    if (d->kind == PC_ANALYTIC_REVOLUTION)
        return revolution(f, arena, at, out, skip);
    if (d->kind == PC_ANALYTIC_EXTRUSION) {
        const double o[3] = {0, 0, 0}, z[3] = {0, 0, 1};
        pc_frame_make(f->ctx, o, z, NULL, &d->frame); /* unused by the extrusion */
        return extrusion(f, arena, at, out, skip);
    }
    projcurve_status st = frame_of(f, arena, at, &d->frame, skip);
    if (st != PROJCURVE_OK || *skip != NULL || d->kind == PC_ANALYTIC_PLANE)
        return st;
    if ((st = number(f, at, 2, &d->radius)) != PROJCURVE_OK)
        return st;
    if (d->kind == PC_ANALYTIC_CONE) {
        if ((st = number(f, at, 3, &d->semi_angle)) != PROJCURVE_OK)
            return st;
        d->semi_angle *= f->radians_per_angle_unit > 0.0 ? f->radians_per_angle_unit : 1.0;
    } else if (d->kind == PC_ANALYTIC_TORUS) {
        if ((st = number(f, at, 3, &d->minor_radius)) != PROJCURVE_OK)
            return st;
        if (d->minor_radius > d->radius && pc_step_is(at->node, "DEGENERATE_TOROIDAL_SURFACE"))
            *skip = "a spindle torus (minor radius above the major): not converted";
    }
    return PROJCURVE_OK;
}

projcurve_status pc_step_analytic_surface(pc_step_file *f, pc_arena *arena, long id,
                                          const double *points, size_t n_points,
                                          pc_step_analytic *out, const char **skip)
{
    memset(out, 0, sizeof *out);
    *skip = NULL;
    const pc_step_instance *inst = pc_step_find(f, id);
    if (inst == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_PARSE, "STEP: surface #%ld is not defined", id);
    pc_step_node *node = NULL;
    projcurve_status st = pc_step_parse(f, inst, arena, &node);
    if (st != PROJCURVE_OK)
        return st;
    const pc_step_located at = {inst, node};
    if ((st = describe(f, arena, &at, out, skip)) != PROJCURVE_OK || *skip != NULL)
        return st;
    if (pc_analytic_check(f->ctx, &out->desc) != PROJCURVE_OK) {
        *skip = pc_step_refused_reason;
        return PROJCURVE_OK;
    }
    if (!pc_analytic_box_covering(&out->desc, points, n_points, out->box)) {
        *skip = "unbounded, and used by no face that would bound it";
        return PROJCURVE_OK;
    }
    st = pc_analytic_to_nurbs(f->ctx, arena, &out->desc, out->box, &out->nurbs, &out->map_u,
                              &out->map_v);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return st;
    if (st != PROJCURVE_OK)
        *skip = pc_step_refused_reason;
    return PROJCURVE_OK;
}
