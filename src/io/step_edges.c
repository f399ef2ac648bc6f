/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The 3D curve of a STEP EDGE_CURVE, bounded by its vertices
 * (step_geom.h): a LINE becomes the segment between the vertices' line
 * parameters, a CIRCLE or an ELLIPSE the arc between their angles, counter
 * clockwise about the conic's axis as Part 42 orients it.
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "common/vec.h"
#include "io/step_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Vertices this close (relative to the conic's size) are one: the edge is
 * a whole turn. */
#define PC_STEP_CLOSED_EDGE_REL 1e-9

static projcurve_status vertex_point(pc_step_file *f, pc_arena *arena,
                                     const pc_step_instance *from, const pc_step_node *ref,
                                     double p[3])
{
    pc_step_located v;
    projcurve_status st = pc_step_resolve(f, arena, from, ref, &v);
    if (st != PROJCURVE_OK)
        return st;
    if (!pc_step_is(v.node, "VERTEX_POINT"))
        return pc_step_bad(f, v.inst, "expected a VERTEX_POINT");
    return pc_step_point(f, arena, v.inst, pc_step_child(v.node, 1), p);
}

static projcurve_status line_edge(pc_step_file *f, pc_arena *arena, const pc_step_located *c,
                                  const double from[3], const double to[3], pc_io_curve *out)
{
    double o[3], v[3];
    projcurve_status st = pc_step_line(f, arena, c, o, v);
    if (st != PROJCURVE_OK)
        return st;
    const pc_vec3 d = vec3_load(v), po = vec3_load(o);
    const double dd = vec3_dot(d, d);
    if (!(dd > 0.0))
        return pc_step_bad(f, c->inst, "a LINE of direction zero");
    const double t0 = vec3_dot(vec3_sub(vec3_load(from), po), d) / dd;
    const double t1 = vec3_dot(vec3_sub(vec3_load(to), po), d) / dd;
    if (!(t1 > t0))
        return pc_step_bad(f, c->inst, "an edge whose vertices do not follow its LINE's direction");
    return pc_line_segment(f->ctx, arena, o, v, t0, t1, out);
}

/* The conic's parameter t of a point: o + a cos t x + b sin t y. */
static double conic_parameter(const double o[3], const double x[3], const double y[3], double a,
                              double b, const double p[3])
{
    const pc_vec3 d = vec3_sub(vec3_load(p), vec3_load(o));
    return atan2(vec3_dot(d, vec3_load(y)) / b, vec3_dot(d, vec3_load(x)) / a);
}

static projcurve_status conic_edge(pc_step_file *f, pc_arena *arena, const pc_step_located *c,
                                   const double from[3], const double to[3], pc_io_curve *out,
                                   pc_angle_map *map, const char **skip)
{
    double o[3], x[3], y[3], a = 0.0, b = 0.0;
    projcurve_status st = pc_step_conic(f, arena, c, o, x, y, &a, &b, skip);
    if (st != PROJCURVE_OK || *skip != NULL)
        return st;
    double t0 = conic_parameter(o, x, y, a, b, from), t1 = conic_parameter(o, x, y, a, b, to);
    if (t0 < 0.0)
        t0 += 2.0 * M_PI;
    if (t1 < 0.0)
        t1 += 2.0 * M_PI;
    const double gap = vec3_dist(vec3_load(from), vec3_load(to));
    if (gap <= PC_STEP_CLOSED_EDGE_REL * fmax(a, b))
        t1 = t0 + 2.0 * M_PI;
    else if (t1 <= t0)
        t1 += 2.0 * M_PI;
    if (map != NULL)
        *map = pc_angle_map_make(t0, t1);
    return pc_ellipse_arc(f->ctx, arena, o, x, y, a, b, t0, t1, out);
}

projcurve_status pc_step_edge_curve(pc_step_file *f, pc_arena *arena, const pc_step_located *edge,
                                    pc_io_curve *out, pc_angle_map *map, const char **skip)
{
    *skip = NULL;
    if (map != NULL)
        *map = (pc_angle_map){.is_angle = 0};
    if (!pc_step_is(edge->node, "EDGE_CURVE"))
        return pc_step_bad(f, edge->inst, "expected an EDGE_CURVE");
    double v[2][3];
    projcurve_status st;
    for (size_t k = 0; k < 2; ++k)
        if ((st = vertex_point(f, arena, edge->inst, pc_step_child(edge->node, 1 + k), v[k])) != PROJCURVE_OK)
            return st;
    const pc_step_node *sense = pc_step_child(edge->node, 4);
    const int forward = !(sense && sense->kind == PC_STEP_ENUM && sense->len == 1 && sense->text[0] == 'F');
    const double *from = forward ? v[0] : v[1], *to = forward ? v[1] : v[0];
    pc_step_located c;
    if ((st = pc_step_resolve(f, arena, edge->inst, pc_step_child(edge->node, 3), &c)) != PROJCURVE_OK)
        return st;
    if (pc_step_is(c.node, "SURFACE_CURVE") || pc_step_is(c.node, "SEAM_CURVE"))
        if ((st = pc_step_resolve(f, arena, c.inst, pc_step_child(c.node, 1), &c)) != PROJCURVE_OK)
            return st;
    if (pc_step_is(c.node, "LINE"))
        return line_edge(f, arena, &c, from, to, out);
    if (pc_step_is(c.node, "CIRCLE") || pc_step_is(c.node, "ELLIPSE"))
        return conic_edge(f, arena, &c, from, to, out, map, skip);
    return pc_step_curve(f, arena, &c, out, map, skip);
}
