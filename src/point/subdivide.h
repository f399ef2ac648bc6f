/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Recursive subdivision of one Bezier patch without recursion: a depth-first
 * walk over quarter sub-patches kept on a small stack of control nets, with
 * the caller deciding for each sub-patch whether to discard it, stop at it or
 * split it. Also the tests that decide: distance of the control net's box,
 * and whether a sub-patch can hold a foot point at all.
 */
#ifndef PC_POINT_SUBDIVIDE_H
#define PC_POINT_SUBDIVIDE_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "common/vec.h"

/* Deepest subdivision level, counted in halvings of the parameter box: a
 * split into quarters counts 2, a split of one direction only (a sub-patch
 * much longer in 3D one way than the other, see pc_subdiv_walk) counts 1.
 * A sub-patch is then at least 1/4096 x 1/4096 of its patch, or as small in
 * area when it was split one way only. */
#define PC_SUBDIV_MAX_DEPTH 24

typedef struct pc_subpatch {
    double u0, u1, v0, v1;  /* parameter box in the surface's parameters */
    int depth;
    const double *cw;       /* homogeneous net, (p+1) x (q+1), u fastest */
    const double *xyz;      /* its Cartesian points, 3 each */
    double box[6];          /* box of xyz */
    double flatness;        /* pc_subpatch_flatness, or < 0 until computed */
} pc_subpatch;

typedef enum pc_subdiv_action { PC_SUBDIV_DROP = 0, PC_SUBDIV_STOP = 1, PC_SUBDIV_SPLIT = 2 } pc_subdiv_action;

typedef pc_subdiv_action (*pc_subdiv_fn)(void *user, const pc_subpatch *sp);

/* Doubles of scratch kept inside pc_subdiv_work: enough for degrees up
 * to (4, 4) (32 KiB), so that a query on the usual surfaces allocates
 * nothing; higher degrees allocate. */
#define PC_SUBDIV_LOCAL 4096

/* Ratio of the 3D extents along u and v above which only the longer
 * direction is split. */
#define PC_SUBDIV_ANISOTROPY 4.0

/* Scratch memory for walks over patches of degree (p, q). Holds a pointer
 * into itself: not to be copied once initialised. */
typedef struct pc_subdiv_work {
    int p, q;
    size_t net_len;  /* doubles per homogeneous net */
    double *mem;     /* local or malloc'd */
    size_t n_slots;
    double local[PC_SUBDIV_LOCAL];
} pc_subdiv_work;

projcurve_status pc_subdiv_work_init(projcurve_context *ctx, pc_subdiv_work *w, int p, int q);
void pc_subdiv_work_free(pc_subdiv_work *w);

/* Walks the patch: decide() is called for the patch itself and for every
 * sub-patch that a SPLIT produced; a SPLIT that would pass
 * PC_SUBDIV_MAX_DEPTH counts as STOP. A SPLIT halves only the direction in
 * which the control net is more than PC_SUBDIV_ANISOTROPY times longer in
 * 3D than in the other (a knot span of 1e-8 next to one of 1: quartering
 * it would leave it as thin after every split, while its shape and the
 * culling tests depend on the long direction alone), else both. */
void pc_subdiv_walk(pc_subdiv_work *w, const pc_bezier_patch *patch, pc_subdiv_fn decide,
                    void *user);

/* Squared distance from p to the box. */
double pc_box_distance_sq(const double box[6], pc_vec3 p);

/* 0 when the sub-patch provably holds no point with (S - p).Su = 0, or none
 * with (S - p).Sv = 0; 1 when it may hold a foot point. */
int pc_subpatch_may_hold_foot(const pc_subpatch *sp, int p, int q, int rational, pc_vec3 pt);

/* Largest distance of a control point from the bilinear interpolant of the
 * four corners, relative to the net's box diagonal (pc_bezier_net_flatness;
 * for a whole patch kept by the patch grid). */
double pc_subpatch_flatness(const pc_subpatch *sp, int p, int q);

#endif /* PC_POINT_SUBDIVIDE_H */
