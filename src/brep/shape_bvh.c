/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The face BVH of a shape (brep/shape_bvh.h).
 */
#include "brep/shape_bvh.h"

#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "common/vec.h"

/* Deepest tree: median splits halve the faces, so depth <= log2(n) + 1. */
#define PC_FACE_BVH_STACK 128

typedef struct build_state {
    const double *boxes;
    size_t *order;
    pc_face_bvh_node *nodes;
    size_t n_nodes;
    int axis; /* of the current sort */
} build_state;

static double centre(const double *box, int axis) { return box[axis] + box[axis + 3]; }

/* Sorts order[first .. first + count) by box centre on axis (insertion
 * sort for small ranges, qsort's comparator cannot see the boxes). */
static void sort_range(const build_state *b, size_t first, size_t count, int axis)
{
    size_t *o = b->order + first;
    for (size_t i = 1; i < count; ++i) {
        const size_t f = o[i];
        const double c = centre(b->boxes + 6 * f, axis);
        size_t j = i;
        while (j > 0 && (centre(b->boxes + 6 * o[j - 1], axis) > c ||
                         (centre(b->boxes + 6 * o[j - 1], axis) == c && o[j - 1] > f))) {
            o[j] = o[j - 1];
            --j;
        }
        o[j] = f;
    }
}

/* Builds the node of order[first .. first + count) and returns its index;
 * recursion depth <= log2(count) + 1. */
static size_t build_node(build_state *b, size_t first, size_t count)
{
    const size_t k = b->n_nodes++;
    pc_face_bvh_node *nd = &b->nodes[k];
    box_empty(nd->box);
    for (size_t i = 0; i < count; ++i)
        box_add_box(nd->box, b->boxes + 6 * b->order[first + i]);
    nd->first = first;
    nd->count = count;
    if (count <= PC_FACE_BVH_LEAF)
        return k;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (nd->box[a + 3] - nd->box[a] > nd->box[axis + 3] - nd->box[axis])
            axis = a;
    sort_range(b, first, count, axis);
    const size_t half = count / 2;
    const size_t left = build_node(b, first, half);
    const size_t right = build_node(b, first + half, count - half);
    nd = &b->nodes[k];
    nd->count = 0;
    nd->left = left;
    nd->right = right;
    return k;
}

projcurve_status pc_face_bvh_build(projcurve_context *ctx, pc_face_bvh *bvh, const double *boxes,
                                   size_t n)
{
    memset(bvh, 0, sizeof *bvh);
    bvh->order = malloc((n + 1) * sizeof *bvh->order);
    bvh->nodes = malloc((2 * n + 1) * sizeof *bvh->nodes);
    if (bvh->order == NULL || bvh->nodes == NULL) {
        pc_face_bvh_free(bvh);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a shape's face BVH");
    }
    for (size_t i = 0; i < n; ++i)
        bvh->order[i] = i;
    bvh->n_faces = n;
    bvh->boxes = boxes;
    if (n == 0)
        return PROJCURVE_OK;
    build_state b = {.boxes = boxes, .order = bvh->order, .nodes = bvh->nodes};
    build_node(&b, 0, n);
    bvh->n_nodes = b.n_nodes;
    return PROJCURVE_OK;
}

void pc_face_bvh_free(pc_face_bvh *bvh)
{
    free(bvh->order);
    free(bvh->nodes);
    bvh->order = NULL;
    bvh->nodes = NULL;
    bvh->n_nodes = bvh->n_faces = 0;
}

static int by_index(const void *a, const void *b)
{
    const size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

size_t pc_face_bvh_query(const pc_face_bvh *bvh, pc_box_test test, const void *user,
                         size_t *out)
{
    if (bvh->n_nodes == 0)
        return 0;
    size_t stack[PC_FACE_BVH_STACK], top = 0, found = 0;
    stack[top++] = 0;
    /* bounded: every node is pushed at most once */
    while (top > 0) {
        const pc_face_bvh_node *nd = &bvh->nodes[stack[--top]];
        if (!test(user, nd->box))
            continue;
        if (nd->count > 0) {
            for (size_t i = 0; i < nd->count; ++i) {
                const size_t f = bvh->order[nd->first + i];
                if (test(user, bvh->boxes + 6 * f))
                    out[found++] = f;
            }
        } else if (top + 2 <= PC_FACE_BVH_STACK) { /* always: depth <= log2(n) + 1 */
            stack[top++] = nd->right;
            stack[top++] = nd->left;
        }
    }
    qsort(out, found, sizeof *out, by_index);
    return found;
}
