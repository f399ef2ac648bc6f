/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bounding-volume hierarchy over the Bezier patches of a surface, built once
 * per surface handle. Leaves hold a few patches; boxes are the patches'
 * control-net boxes.
 */
#ifndef PC_BEZIER_BVH_H
#define PC_BEZIER_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "bezier/bezier.h"

typedef struct pc_bvh_node {
    double box[6];
    uint32_t first;  /* leaf: first index into order[]; inner: left child */
    uint32_t count;  /* leaf: number of patches; inner: 0 (right = left + 1) */
} pc_bvh_node;

typedef struct pc_bvh {
    pc_bvh_node *nodes;
    size_t n_nodes;
    uint32_t *order;  /* patch indices, leaves point into ranges of it */
    double *boxes;    /* 6 per entry of order[]: that patch's box, so a leaf
                         tests its patches without touching the grid */
    int depth;        /* height of the tree, bounds the traversal stack */
} pc_bvh;

projcurve_status pc_bvh_build(projcurve_context *ctx, pc_bvh *bvh, const pc_patch_grid *grid);
void pc_bvh_free(pc_bvh *bvh);

/* Calls visit(user, patch_index) for every patch whose box meets the line
 * origin + lambda * dir with lambda in [lambda_min, lambda_max] (use
 * -INFINITY / INFINITY for a full line). The box test is padded by `pad`
 * (model units) so that grazing hits are not lost. A nonzero return from
 * visit stops the walk. */
typedef int (*pc_bvh_visit_fn)(void *user, size_t patch_index);
void pc_bvh_query_line(const pc_bvh *bvh, pc_vec3 origin, pc_vec3 dir, double lambda_min,
                       double lambda_max, double pad, pc_bvh_visit_fn visit, void *user);

/* Depth-first walk for searches with their own node test: enters node k
 * (the root first) when enter(user, k) is nonzero, and calls visit for
 * every patch of the leaves entered; a nonzero return from visit stops the
 * walk. */
typedef int (*pc_bvh_enter_fn)(void *user, size_t node_index);
void pc_bvh_query_nodes(const pc_bvh *bvh, pc_bvh_enter_fn enter, pc_bvh_visit_fn visit,
                        void *user);

/* The same for every patch whose box is within `radius` of point p. */
void pc_bvh_query_sphere(const pc_bvh *bvh, pc_vec3 p, double radius, pc_bvh_visit_fn visit,
                         void *user);

/* Nearest-first walk for closest-point searches: visits patches roughly in
 * order of the distance of their boxes from p (nearer child first), and
 * skips every node and patch whose box is at squared distance >= the bound
 * that the last visit returned (start: INFINITY). visit(user, patch_index,
 * box_distance_sq) returns the new bound. */
typedef double (*pc_bvh_nearest_fn)(void *user, size_t patch_index, double box_distance_sq);
void pc_bvh_query_nearest(const pc_bvh *bvh, pc_vec3 p, pc_bvh_nearest_fn visit, void *user);

#endif /* PC_BEZIER_BVH_H */
