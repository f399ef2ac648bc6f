/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Analytic surfaces and curves (plane, cylinder, cone, sphere, torus,
 * surfaces of revolution and of linear extrusion; line, circle, ellipse)
 * described as ISO 10303-42 (STEP Part 42) describes them, with
 *
 *   - eval:     the exact point of an analytic parameter pair (u, v);
 *   - invert:   the analytic (u, v) of a point on (or near) the surface;
 *   - to_nurbs: the exact rational NURBS over an analytic parameter box;
 *   - the exact maps between analytic parameters and the NURBS's.
 *
 * Parametrisations (frame: origin C, axis z, reference x, y = z x x):
 *   plane       C + u x + v y
 *   cylinder    C + R (cos u x + sin u y) + v z
 *   cone        C + (R + v tan a) (cos u x + sin u y) + v z   (a: semi-angle)
 *   sphere      C + R cos v (cos u x + sin u y) + R sin v z   (v: latitude)
 *   torus       C + (R + r cos v) (cos u x + sin u y) + r sin v z
 *   revolution  the swept curve K(v) turned by u about the axis (C, z)
 *   extrusion   K(u) + v V
 * Angles are in radians.
 *
 * The NURBS built over a box has the same parameter names: its first
 * direction is u, its second v. A linear direction keeps its parameter
 * (s = u); an angle direction is split into rational quadratic arcs of at
 * most a quarter turn, each a Bezier segment whose knots are the angles of
 * its ends, so that s = u at every segment end and in between
 * tan((u - m) / 2) = (2 tau - 1) tan(h / 2), with m the segment's middle
 * angle, h its half width and tau = (s - s_start) / (s_end - s_start)
 * (pc_angle_map, below). A swept curve's direction is that of its NURBS,
 * mapped from the curve's own parameter by the surface's curve_map.
 *
 * Nothing here allocates except into the caller's arena, and nothing is
 * global: every function is thread-safe.
 */
#ifndef PC_ANALYTIC_H
#define PC_ANALYTIC_H

#include <stddef.h>

#include "common/arena.h"
#include "projcurve.h"

/* A B-spline/NURBS curve as plain arrays: n_ctrl points (3 doubles),
 * weights (n_ctrl, or NULL when polynomial), n_ctrl + degree + 1 knots. */
typedef struct pc_rational_curve {
    int degree;
    size_t n_ctrl;
    double *ctrl;
    double *weights;
    double *knots;
} pc_rational_curve;

/* A tensor-product NURBS surface, control net with the u index fastest. */
typedef struct pc_rational_surface {
    int deg_u, deg_v;
    size_t n_u, n_v;
    double *ctrl;
    double *weights;
    double *knots_u;
    double *knots_v;
} pc_rational_surface;

/* A right-handed orthonormal frame. */
typedef struct pc_frame {
    double origin[3];
    double x[3], y[3], z[3];
} pc_frame;

/* A frame from an origin, an axis (any length but zero) and a reference
 * direction: x is the reference made perpendicular to the axis. ref may be
 * NULL: then x is chosen from the axis alone (the first of the coordinate
 * axes e1, e2 least parallel to it, made perpendicular), as a placement
 * without a reference direction. Statuses: OK, NOT_FINITE, ZERO_DIRECTION
 * (axis or reference of length zero), INVALID_ARGUMENT (reference parallel
 * to the axis). */
projcurve_status pc_frame_make(projcurve_context *ctx, const double origin[3],
                               const double axis[3], const double ref[3], pc_frame *out);

/* ---- the angle <-> NURBS parameter map ------------------------------------ */

/* How one direction of a built NURBS relates to the analytic parameter. */
typedef struct pc_angle_map {
    int is_angle;    /* 0: s = u */
    double a0, a1;   /* the angle range */
    size_t n_seg;    /* rational quadratic segments of equal width */
} pc_angle_map;

/* Segments of at most a quarter turn covering [a0, a1]. */
pc_angle_map pc_angle_map_make(double a0, double a1);

/* NURBS parameter of angle a, and back (closed form per segment, see the
 * top of this file). An angle outside [a0, a1] is first moved by whole
 * turns to the nearest representative inside; one that has none is
 * clamped to the range end. */
double pc_angle_to_nurbs(const pc_angle_map *m, double a);
double pc_nurbs_to_angle(const pc_angle_map *m, double s);

typedef enum pc_analytic_kind {
    PC_ANALYTIC_PLANE = 0,
    PC_ANALYTIC_CYLINDER,
    PC_ANALYTIC_CONE,
    PC_ANALYTIC_SPHERE,
    PC_ANALYTIC_TORUS,
    PC_ANALYTIC_REVOLUTION,
    PC_ANALYTIC_EXTRUSION
} pc_analytic_kind;

/* The name of a kind as the model reports it ("plane", "cylinder", "cone",
 * "sphere", "torus", "revolution", "extrusion"). */
const char *pc_analytic_kind_name(pc_analytic_kind kind);

/* One analytic surface. The swept curve of a revolution or extrusion is
 * borrowed (it must outlive the description). */
typedef struct pc_analytic_surface {
    pc_analytic_kind kind;
    pc_frame frame;         /* revolution: origin and z are the axis */
    double radius;          /* cylinder, cone (at v = 0), sphere; torus: major */
    double minor_radius;    /* torus */
    double semi_angle;      /* cone, radians in (-pi/2, pi/2), not 0 */
    double extrusion[3];    /* extrusion: V, with its length */
    const pc_rational_curve *curve; /* revolution, extrusion */
    /* The swept curve's own parameter (a circle's or an ellipse's angle, as
     * the file gives it) to the parameter of `curve`; is_angle = 0 when
     * they are the same. */
    pc_angle_map curve_map;
} pc_analytic_surface;

/* Checks a description: finite values, radii > 0 (cone: R >= 0), torus
 * minor radius <= major (a spindle torus self-intersects and is refused),
 * cone semi-angle in (-pi/2, pi/2) and not 0, extrusion vector not zero,
 * swept curve present with degree >= 1 and enough knots. Statuses: OK,
 * NULL_ARGUMENT, NOT_FINITE, INVALID_ARGUMENT, ZERO_DIRECTION. */
projcurve_status pc_analytic_check(projcurve_context *ctx, const pc_analytic_surface *s);

/* The natural parameter box of a kind: [0, 2 pi] for every angle,
 * [-pi/2, pi/2] for the sphere's latitude, the swept curve's domain; an
 * unbounded direction (plane, heights, extrusion length) gives 0 in
 * *bounded for it and leaves its range as it is. box = {u0, u1, v0, v1}. */
void pc_analytic_natural_box(const pc_analytic_surface *s, double box[4], int bounded[2]);

/* The box a surface's NURBS needs to cover points[0 .. 3 n) (a face's
 * loop points): the natural box in bounded directions; in an unbounded one
 * the range of the points' invert, widened on each side by
 * PC_ANALYTIC_BOX_MARGIN_REL of the range plus PC_ANALYTIC_BOX_MARGIN_ABS_REL
 * of the largest of the range's ends and the radius (so that points that
 * share one height still give a strip of non-zero width; 1 when all of
 * these are 0). Returns 0 (box partly unset) when a direction is unbounded
 * and n is 0. */
#define PC_ANALYTIC_BOX_MARGIN_REL 0.01
#define PC_ANALYTIC_BOX_MARGIN_ABS_REL 1e-3
int pc_analytic_box_covering(const pc_analytic_surface *s, const double *points, size_t n,
                             double box[4]);

/* The point of (u, v), exactly as the parametrisation above. */
void pc_analytic_eval(const pc_analytic_surface *s, double u, double v, double out[3]);

/* The (u, v) of the point of the surface nearest to p, in closed form for
 * the elementary kinds (angles in [0, 2 pi), sphere latitude in
 * [-pi/2, pi/2]). Where an angle is not defined (a point on the axis, the
 * sphere's poles, the cone's apex, the torus's centre circle) it is 0. For
 * a revolution or extrusion the swept curve's parameter is found by a
 * bounded search (dense samples, then bisection on the derivative of the
 * distance; PC_ANALYTIC_INVERT_ITERATIONS steps at most, whose result is
 * kept when the bound is hit). */
#define PC_ANALYTIC_INVERT_ITERATIONS 200
void pc_analytic_invert(const pc_analytic_surface *s, const double p[3], double *u, double *v);

/* ---- NURBS ------------------------------------------------------------------ */

/* The exact NURBS of s over the analytic box [u0, u1] x [v0, v1] (angle
 * ranges at most one turn; for the sphere's latitude within [-pi/2, pi/2];
 * the swept curve's direction always spans the curve's whole domain, its
 * range in box is not used: a caller cuts it with pc_io_surface_restrict),
 * arrays in the arena; map_u, map_v (may be NULL) receive the parameter
 * maps. Statuses: OK, those of pc_analytic_check, OUT_OF_RANGE (an empty
 * range, an angle span above one turn, a latitude outside the sphere),
 * NO_MEMORY. */
projcurve_status pc_analytic_to_nurbs(projcurve_context *ctx, pc_arena *arena,
                                      const pc_analytic_surface *s, const double box[4],
                                      pc_rational_surface *out, pc_angle_map *map_u,
                                      pc_angle_map *map_v);

/* ---- curves --------------------------------------------------------------- */

/* The arc centre + a cos t x + b sin t y, t in [t0, t1] (t1 > t0, at most
 * one turn), x and y orthonormal: a circle when a = b, an ellipse with
 * semi-axes a, b otherwise (STEP's ELLIPSE parametrisation: t is not the
 * polar angle). Exact rational quadratic, one segment per quarter turn at
 * most, knots as pc_angle_map_make(t0, t1). Statuses: OK, NOT_FINITE,
 * INVALID_ARGUMENT (a radius <= 0, an empty or more than one turn range),
 * NO_MEMORY. */
projcurve_status pc_ellipse_arc(projcurve_context *ctx, pc_arena *arena, const double centre[3],
                                const double x[3], const double y[3], double a, double b,
                                double t0, double t1, pc_rational_curve *out);

/* The line o + t d, t in [t0, t1] (t1 > t0), as a degree-1 curve over
 * [t0, t1]: the NURBS parameter is the line's. Statuses: OK, NOT_FINITE,
 * INVALID_ARGUMENT (empty range), ZERO_DIRECTION, NO_MEMORY. */
projcurve_status pc_line_segment(projcurve_context *ctx, pc_arena *arena, const double o[3],
                                 const double d[3], double t0, double t1,
                                 pc_rational_curve *out);

/* The point of a raw curve at t (clamped to its domain), by de Boor's
 * algorithm on homogeneous points. The curve's degree must be at most
 * PROJCURVE_MAX_DEGREE. */
void pc_rational_curve_eval(const pc_rational_curve *c, double t, double out[3]);

#endif /* PC_ANALYTIC_H */
