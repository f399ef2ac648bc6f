/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The face BVH of a shape (brep/shape_bvh.h) against brute force: random
 * boxes (1 to 300 of them, some degenerate, some repeated) and random query
 * boxes; the faces a query returns are exactly those whose box overlaps
 * the query box, in increasing order.
 */
#include <stdlib.h>

#include "brep/shape_bvh.h"
#include "check.h"

static int overlaps(const void *user, const double box[6])
{
    const double *q = user;
    for (int i = 0; i < 3; ++i)
        if (box[i] > q[i + 3] || box[i + 3] < q[i])
            return 0;
    return 1;
}

static void random_box(pc_test_rng *rng, double size, double box[6])
{
    for (int i = 0; i < 3; ++i) {
        const double c = pc_test_rng_uniform(rng, 0.0, 100.0);
        const double h = pc_test_rng_uniform(rng, 0.0, size);
        box[i] = c - h;
        box[i + 3] = c + h;
    }
}

int main(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 18);
    static const size_t counts[] = {0, 1, 2, 4, 5, 17, 64, 300};
    for (size_t ci = 0; ci < sizeof counts / sizeof counts[0]; ++ci) {
        const size_t n = counts[ci];
        double *boxes = malloc((6 * n + 1) * sizeof *boxes);
        size_t *got = malloc((n + 1) * sizeof *got);
        CHECK(boxes != NULL && got != NULL);
        if (boxes == NULL || got == NULL)
            return pc_test_finish("test_brep_shape_bvh");
        for (size_t i = 0; i < n; ++i) {
            random_box(&rng, i % 7 == 0 ? 0.0 : 10.0, boxes + 6 * i);
            if (i % 11 == 3)
                for (int k = 0; k < 6; ++k)
                    boxes[6 * i + k] = boxes[k]; /* a repeated box */
        }
        pc_face_bvh bvh;
        CHECK_OK(pc_face_bvh_build(NULL, &bvh, boxes, n));
        for (int q = 0; q < 200; ++q) {
            double query[6];
            random_box(&rng, 30.0, query);
            const size_t found = pc_face_bvh_query(&bvh, overlaps, query, got);
            size_t k = 0, wrong = 0;
            for (size_t i = 0; i < n; ++i)
                if (overlaps(query, boxes + 6 * i))
                    wrong += k >= found || got[k++] != i;
            CHECK(k == found);
            CHECK(wrong == 0);
        }
        pc_face_bvh_free(&bvh);
        free(boxes);
        free(got);
    }
    return pc_test_finish("test_brep_shape_bvh");
}
