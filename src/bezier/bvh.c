/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bounding-volume hierarchy over the Bezier patches of a surface.
 *
 * Built top-down without recursion: a node's patches are split at the median
 * of their box centres along the longest axis of those centres, so the tree
 * is balanced and its height is ceil(log2(n / leaf size)) + 1 whatever the
 * geometry. Queries walk it with a fixed-size stack of PC_BVH_MAX_DEPTH
 * entries, which a balanced tree over any size_t number of patches cannot
 * exceed.
 */
#include <stdlib.h>
#include <string.h>

#include "bezier/bvh.h"
#include "common/error.h"

#define PC_BVH_LEAF_SIZE 4   /* patches per leaf */
#define PC_BVH_MAX_DEPTH 64  /* traversal stack; a median split tree is shallower */

typedef struct build_item {
    uint32_t node, begin, end;
    int depth;
} build_item;

static double centre(const double box[6], int axis) { return 0.5 * (box[axis] + box[axis + 3]); }

/* Quickselect rounds before select_median sorts instead: about twice
 * log2 of the patches on any input that is not adversarial. */
#define PC_BVH_SELECT_ROUNDS 64

static double centre_at(const uint32_t *order, size_t k, const pc_patch_grid *grid, int axis)
{
    return centre(grid->patches[order[k]].box, axis);
}

/* Moves order[k] down the heap order[lo, lo + n) (largest centre on top). */
static void sift_down(uint32_t *order, size_t lo, size_t n, size_t k, const pc_patch_grid *grid,
                      int axis)
{
    for (;;) { /* bounded: k at least doubles */
        size_t big = k;
        const size_t l = 2 * k + 1, r = l + 1;
        if (l < n && centre_at(order, lo + l, grid, axis) > centre_at(order, lo + big, grid, axis))
            big = l;
        if (r < n && centre_at(order, lo + r, grid, axis) > centre_at(order, lo + big, grid, axis))
            big = r;
        if (big == k)
            return;
        const uint32_t tmp = order[lo + k];
        order[lo + k] = order[lo + big];
        order[lo + big] = tmp;
        k = big;
    }
}

/* Sorts order[lo, hi] by centre along axis: heapsort, O(n log n) on every
 * input and in place. */
static void sort_by_centre(uint32_t *order, size_t lo, size_t hi, const pc_patch_grid *grid,
                           int axis)
{
    const size_t n = hi - lo + 1;
    for (size_t k = n / 2; k-- > 0;)
        sift_down(order, lo, n, k, grid, axis);
    for (size_t m = n; m-- > 1;) {
        const uint32_t tmp = order[lo];
        order[lo] = order[lo + m];
        order[lo + m] = tmp;
        sift_down(order, lo, m, 0, grid, axis);
    }
}

/* Rearranges order[begin, end) so that order[mid] has the median centre
 * along axis, smaller before, larger after (Hoare quickselect, iterative).
 * Its middle pivot is the smallest centre of a range made of runs already
 * sorted (the patches of a long strip listed row by row), where each round
 * removes one patch: after PC_BVH_SELECT_ROUNDS rounds the range left is
 * sorted instead, so the build stays O(n log^2 n) on any surface. */
static void select_median(uint32_t *order, size_t begin, size_t end, size_t mid,
                          const pc_patch_grid *grid, int axis)
{
    size_t lo = begin, hi = end - 1;
    for (int round = 0; lo < hi; ++round) {
        if (round == PC_BVH_SELECT_ROUNDS) {
            sort_by_centre(order, lo, hi, grid, axis);
            return;
        }
        const double pivot = centre_at(order, lo + (hi - lo) / 2, grid, axis);
        size_t i = lo, j = hi;
        while (i <= j) {
            while (centre_at(order, i, grid, axis) < pivot)
                ++i;
            while (centre_at(order, j, grid, axis) > pivot)
                --j;
            if (i <= j) {
                const uint32_t tmp = order[i];
                order[i] = order[j];
                order[j] = tmp;
                ++i;
                if (j == 0)
                    break;
                --j;
            }
        }
        if (mid <= j)
            hi = j;
        else if (mid >= i)
            lo = i;
        else
            break;
    }
}

static int longest_axis_of_centres(const uint32_t *order, size_t begin, size_t end,
                                   const pc_patch_grid *grid)
{
    double box[6];
    box_empty(box);
    for (size_t k = begin; k < end; ++k) {
        const double *b = grid->patches[order[k]].box;
        const double c[3] = {centre(b, 0), centre(b, 1), centre(b, 2)};
        box_add_point(box, c);
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (box[k + 3] - box[k] > box[axis + 3] - box[axis])
            axis = k;
    return axis;
}

projcurve_status pc_bvh_build(projcurve_context *ctx, pc_bvh *bvh, const pc_patch_grid *grid)
{
    memset(bvh, 0, sizeof *bvh);
    const size_t n = grid->spans_u * grid->spans_v;
    if (n == 0 || n > UINT32_MAX / 2)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "%zu patches exceed the BVH limit", n);
    const size_t capacity = 2 * n; /* a binary tree with n leaves at most has 2n - 1 nodes */
    bvh->nodes = malloc(capacity * sizeof(pc_bvh_node));
    bvh->order = malloc(n * sizeof(uint32_t));
    bvh->boxes = malloc(6 * n * sizeof(double));
    build_item *work = malloc(capacity * sizeof(build_item));
    if (bvh->nodes == NULL || bvh->order == NULL || bvh->boxes == NULL || work == NULL) {
        free(work);
        pc_bvh_free(bvh);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the patch BVH");
    }
    for (size_t k = 0; k < n; ++k)
        bvh->order[k] = (uint32_t)k;
    size_t n_work = 0, n_nodes = 1;
    work[n_work++] = (build_item){0, 0, (uint32_t)n, 1};
    while (n_work > 0) {
        const build_item it = work[--n_work];
        pc_bvh_node *node = &bvh->nodes[it.node];
        box_empty(node->box);
        for (uint32_t k = it.begin; k < it.end; ++k)
            box_add_box(node->box, grid->patches[bvh->order[k]].box);
        if (it.depth > bvh->depth)
            bvh->depth = it.depth;
        if (it.end - it.begin <= PC_BVH_LEAF_SIZE) {
            node->first = it.begin;
            node->count = it.end - it.begin;
            continue;
        }
        const uint32_t mid = it.begin + (it.end - it.begin) / 2;
        select_median(bvh->order, it.begin, it.end, mid,
                      grid, longest_axis_of_centres(bvh->order, it.begin, it.end, grid));
        const uint32_t left = (uint32_t)n_nodes;
        n_nodes += 2;
        node->first = left;
        node->count = 0;
        work[n_work++] = (build_item){left, it.begin, mid, it.depth + 1};
        work[n_work++] = (build_item){left + 1, mid, it.end, it.depth + 1};
    }
    free(work);
    bvh->n_nodes = n_nodes;
    for (size_t k = 0; k < n; ++k)
        memcpy(bvh->boxes + 6 * k, grid->patches[bvh->order[k]].box, 6 * sizeof(double));
    return PROJCURVE_OK;
}

void pc_bvh_free(pc_bvh *bvh)
{
    if (bvh == NULL)
        return;
    free(bvh->nodes);
    free(bvh->order);
    free(bvh->boxes);
    memset(bvh, 0, sizeof *bvh);
}

static double box_distance_sq(const double box[6], pc_vec3 p)
{
    const double pp[3] = {p.x, p.y, p.z};
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double e = pp[k] < box[k] ? box[k] - pp[k] : (pp[k] > box[k + 3] ? pp[k] - box[k + 3] : 0.0);
        d2 += e * e;
    }
    return d2;
}

/* Shared walk: `meets` decides for a box, visit is called for leaf patches. */
typedef int (*box_test_fn)(const void *query, const double box[6]);

static void walk(const pc_bvh *bvh, box_test_fn meets, const void *query, pc_bvh_visit_fn visit,
                 void *user)
{
    if (bvh->n_nodes == 0)
        return;
    uint32_t stack[PC_BVH_MAX_DEPTH + 1];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const pc_bvh_node *node = &bvh->nodes[stack[--top]];
        if (!meets(query, node->box))
            continue;
        if (node->count > 0) {
            for (uint32_t k = node->first; k < node->first + node->count; ++k)
                if (meets(query, bvh->boxes + 6 * (size_t)k) && visit(user, bvh->order[k]))
                    return;
            continue;
        }
        /* Depth-first: at most one pending sibling per level. */
        stack[top++] = node->first + 1;
        stack[top++] = node->first;
    }
}

void pc_bvh_query_nodes(const pc_bvh *bvh, pc_bvh_enter_fn enter, pc_bvh_visit_fn visit,
                        void *user)
{
    if (bvh->n_nodes == 0)
        return;
    uint32_t stack[PC_BVH_MAX_DEPTH + 1];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const uint32_t k = stack[--top];
        if (!enter(user, k))
            continue;
        const pc_bvh_node *node = &bvh->nodes[k];
        if (node->count > 0) {
            for (uint32_t i = node->first; i < node->first + node->count; ++i)
                if (visit(user, bvh->order[i]))
                    return;
            continue;
        }
        stack[top++] = node->first + 1;
        stack[top++] = node->first;
    }
}

/* A line query prepared once: the slab test multiplies by the reciprocal
 * direction instead of dividing (six divisions per box otherwise), and
 * knows from the sign of each component which slab plane is entered
 * first. Components that are exactly 0 keep the containment test. */
typedef struct line_slabs {
    double o[3], inv[3];
    int parallel[3];  /* d[k] == 0 */
    int negative[3];  /* d[k] < 0: the max plane is met first */
    double lo, hi, pad;
} line_slabs;

static line_slabs line_slabs_init(pc_vec3 origin, pc_vec3 dir, double lo, double hi, double pad)
{
    line_slabs q;
    const double o[3] = {origin.x, origin.y, origin.z}, d[3] = {dir.x, dir.y, dir.z};
    for (int k = 0; k < 3; ++k) {
        q.o[k] = o[k];
        q.parallel[k] = d[k] == 0.0;
        q.negative[k] = d[k] < 0.0;
        q.inv[k] = q.parallel[k] ? 0.0 : 1.0 / d[k];
    }
    q.lo = lo;
    q.hi = hi;
    q.pad = pad;
    return q;
}

/* Does the line meet the box grown by pad for some lambda in [lo, hi]? */
static int slabs_meet(const line_slabs *q, const double box[6])
{
    double lo = q->lo, hi = q->hi;
    for (int k = 0; k < 3; ++k) {
        const double bmin = box[k] - q->pad, bmax = box[k + 3] + q->pad;
        if (q->parallel[k]) {
            if (q->o[k] < bmin || q->o[k] > bmax)
                return 0;
            continue;
        }
        const double near = q->negative[k] ? bmax : bmin, far = q->negative[k] ? bmin : bmax;
        const double t0 = (near - q->o[k]) * q->inv[k], t1 = (far - q->o[k]) * q->inv[k];
        if (t0 > lo)
            lo = t0;
        if (t1 < hi)
            hi = t1;
        if (!(lo <= hi))
            return 0;
    }
    return 1;
}

/* walk() with the slab test inlined: the line query is the hot path of
 * intersection (about 2 log2(patches) box tests per ray). */
void pc_bvh_query_line(const pc_bvh *bvh, pc_vec3 origin, pc_vec3 dir, double lambda_min,
                       double lambda_max, double pad, pc_bvh_visit_fn visit, void *user)
{
    if (bvh->n_nodes == 0)
        return;
    const line_slabs q = line_slabs_init(origin, dir, lambda_min, lambda_max, pad);
    uint32_t stack[PC_BVH_MAX_DEPTH + 1];
    size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const pc_bvh_node *node = &bvh->nodes[stack[--top]];
        if (!slabs_meet(&q, node->box))
            continue;
        if (node->count > 0) {
            for (uint32_t k = node->first; k < node->first + node->count; ++k)
                if (slabs_meet(&q, bvh->boxes + 6 * (size_t)k) && visit(user, bvh->order[k]))
                    return;
            continue;
        }
        stack[top++] = node->first + 1;
        stack[top++] = node->first;
    }
}

typedef struct sphere_query {
    pc_vec3 centre;
    double radius_sq;
} sphere_query;

static int sphere_test(const void *query, const double box[6])
{
    const sphere_query *q = query;
    return box_distance_sq(box, q->centre) <= q->radius_sq;
}

void pc_bvh_query_sphere(const pc_bvh *bvh, pc_vec3 p, double radius, pc_bvh_visit_fn visit,
                         void *user)
{
    const sphere_query q = {p, radius * radius};
    walk(bvh, sphere_test, &q, visit, user);
}

void pc_bvh_query_nearest(const pc_bvh *bvh, pc_vec3 p, pc_bvh_nearest_fn visit, void *user)
{
    if (bvh->n_nodes == 0)
        return;
    typedef struct pending {
        uint32_t node;
        double d2;
    } pending;
    pending stack[PC_BVH_MAX_DEPTH + 1];
    size_t top = 0;
    double bound = INFINITY;
    stack[top++] = (pending){0, box_distance_sq(bvh->nodes[0].box, p)};
    while (top > 0) {
        const pending it = stack[--top];
        if (!(it.d2 < bound))
            continue;
        const pc_bvh_node *node = &bvh->nodes[it.node];
        if (node->count > 0) {
            /* At most PC_BVH_LEAF_SIZE patches: visit them nearest first. */
            pending order[PC_BVH_LEAF_SIZE];
            uint32_t n = 0;
            for (uint32_t k = node->first; k < node->first + node->count; ++k) {
                const pending item = {k, box_distance_sq(bvh->boxes + 6 * (size_t)k, p)};
                uint32_t at = n++;
                while (at > 0 && order[at - 1].d2 > item.d2) {
                    order[at] = order[at - 1];
                    --at;
                }
                order[at] = item;
            }
            for (uint32_t k = 0; k < n; ++k)
                if (order[k].d2 < bound)
                    bound = visit(user, bvh->order[order[k].node], order[k].d2);
            continue;
        }
        const pending a = {node->first, box_distance_sq(bvh->nodes[node->first].box, p)};
        const pending b = {node->first + 1, box_distance_sq(bvh->nodes[node->first + 1].box, p)};
        /* Push the farther child first so that the nearer one is walked first. */
        stack[top++] = a.d2 <= b.d2 ? b : a;
        stack[top++] = a.d2 <= b.d2 ? a : b;
    }
}
