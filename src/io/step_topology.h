/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * STEP topology, internal: the state of reading the faces of a file
 * (step_topology.c) and the loop pieces made from an edge's PCURVE
 * (step_pcurve.c) or, where it has none, from its 3D curve projected onto
 * the face (step_edge_projection.c).
 *
 * A problem with one face is not an error of the read: it sets the face's
 * reason (pc_step_give_up), the face is listed as not built and the file
 * goes on. Only NO_MEMORY and parse failures of the file stop the read.
 */
#ifndef PC_IO_STEP_TOPOLOGY_H
#define PC_IO_STEP_TOPOLOGY_H

#include <math.h>

#include "brep/face.h"
#include "io/step_geom.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The precision when the file gives no UNCERTAINTY_MEASURE_WITH_UNIT, as
 * a fraction of the surface's size. */
#define PC_STEP_DEFAULT_PRECISION_REL 1e-7
/* A pcurve whose ends, or whose image on the surface, are farther than
 * this many precisions from its edge is reported. */
#define PC_STEP_PCURVE_CHECK_FACTOR 100.0
#define PC_STEP_REASON 200

typedef struct stopo {
    pc_step_file *f;
    projcurve_model *model;
    pc_arena *arena;
    double precision;  /* 0: none in the file */
    long *face_of;     /* per instance: the model's face index, -1 */
    char *reason;      /* why the face being read cannot be built */
    /* The face's surface is analytic: the maps from its (u, v), in which
     * the pcurves are given, to its NURBS's (s, t); NULL for B-splines. */
    const pc_angle_map *maps;
    int analytic; /* the face's surface is analytic (maps may be NULL) */
} stopo;

static inline double pc_step_dist3(const double a[3], const double b[3])
{
    return hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
}

/* step_topology.c. Sets the face's reason (the first one only, fmt with
 * the instance id and a text) and returns OK. */
projcurve_status pc_step_give_up(const stopo *t, const char *fmt, long id, const char *what);
/* The instance ref points at, parsed; out->inst is NULL (and the face's
 * reason set) when ref is no reference or names no instance. */
projcurve_status pc_step_fetch(const stopo *t, const pc_step_node *ref, long from, pc_step_located *out);

/* step_pcurve.c. The precision of a face on s (s may be NULL: the file's
 * only). */
double pc_step_precision(const stopo *t, const projcurve_surface *s);
/* A piece (along its own parameter) at fraction a of its domain; 0 when
 * it is not a valid curve. */
int pc_step_piece_at(const pc_piece_input *p, double a, double uv[2]);
/* S(uv), uv clamped to the domain; 0 on failure. */
int pc_step_surface_point(const projcurve_surface *s, const double uv[2], double p[3]);
/* A 2D LINE pcurve between the (u, v) of the vertices v0 -> v1. */
projcurve_status pc_step_line_piece(const stopo *t, const pc_step_located *curve,
                                    const projcurve_surface *s, const double v0[3],
                                    const double v1[3], pc_piece_input *out);
/* A 2D B-spline pcurve over its whole domain. */
projcurve_status pc_step_bspline_piece(const stopo *t, const pc_step_located *curve,
                                       pc_piece_input *out);
/* The 2D curves of the PCURVEs of a SURFACE_CURVE / SEAM_CURVE on the
 * surface #surface_id, at most two. */
projcurve_status pc_step_pcurves_on(const stopo *t, const pc_step_located *geom, long surface_id,
                                    pc_step_located found[2], size_t *n);
/* Cuts a B-spline pcurve to its edge v0 -> v1 (curve3: the edge's 3D
 * curve, whose parameter the pcurve shares; its inst may be NULL). */
projcurve_status pc_step_restrict_to_edge(const stopo *t, const projcurve_surface *s,
                                          pc_piece_input *piece, const double v0[3],
                                          const double v1[3], const pc_step_located *curve3);
/* Reports a pcurve whose ends are off its vertices (and marks a pole). */
projcurve_status pc_step_check_piece(const stopo *t, const projcurve_surface *s, long surface_id,
                                     long edge_id, pc_piece_input *piece, const double v0[3],
                                     const double v1[3], unsigned *flags);
/* Reports a pcurve whose surface image is off its edge's 3D curve. */
projcurve_status pc_step_check_against_curve(const stopo *t, const projcurve_surface *s,
                                             long surface_id, long edge_id,
                                             const pc_piece_input *piece, const pc_step_located *curve);

/* step_pcurve_map.c. A piece given in the analytic (u, v) of the face's
 * surface (t->maps set) carried into its NURBS's (s, t), along the same
 * parameter; the face gives up when its angles do not fit the NURBS's
 * turn. */
projcurve_status pc_step_piece_to_nurbs(const stopo *t, const projcurve_surface *s, long curve_id,
                                        pc_piece_input *piece);
/* The pieces of one loop on an analytic surface, in (s, t): a piece that
 * meets its neighbours only a turn away (a seam's pcurve on the other
 * side, an arc given past the seam) is moved by that turn. */
projcurve_status pc_step_join_turns(const stopo *t, pc_piece_input *pieces, size_t n);
/* The pieces in[0 .. n) of one loop on an analytic surface with a
 * degenerate piece (PC_PIECE_DEGENERATE, no edge) wherever two that follow
 * each other are apart in (s, t) but meet in 3D within the precision (a
 * pole: a sphere's seam meets itself there a turn away). out holds 2 n. */
projcurve_status pc_step_bridge_poles(const stopo *t, const projcurve_surface *s,
                                      const pc_piece_input *in, size_t n, pc_piece_input *out,
                                      size_t *n_out);
/* The file's (u, v) (angles in its angle unit) of a NURBS (s, t). */
void pc_step_uv_to_analytic(const pc_step_file *f, const pc_angle_map maps[2], const double st[2],
                            double uv[2]);

/* step_edge_projection.c. The pcurve of an edge without one: its 3D curve
 * v0 -> v1 projected onto s. */
projcurve_status pc_step_edge_projection(const stopo *t, const pc_step_located *curve,
                                         const projcurve_surface *s, const double v0[3],
                                         const double v1[3], pc_piece_input *out);

#endif /* PC_IO_STEP_TOPOLOGY_H */
