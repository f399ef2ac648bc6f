/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Jump detection, [SY13] s3.4: deciding cheaply, at each check of the
 * sweep, whether the ray L2 through P(t) may meet S where no traced branch
 * is (a branch born in mid-curve) or may have lost a hit (a branch that left
 * S), and matching the points found by a full search to the active
 * branches.
 *
 * For every patch (Inter_Patch) whose control polygon L2 meets, with
 * Active_Patch_i the patch holding the current point cur_Q_i of branch i:
 *   1. Inter_Patch is no Active_Patch_i and neighbours none of them;
 *   2. it neighbours some Active_Patch_i, but S(cur_Q_i) is farther than the
 *      arc-length step ds from their common edge;
 *   3. it is an Active_Patch_i and L2 meets its control polygon more often
 *      than L1 (the previous check's ray) did;
 *   4. it is an Active_Patch_i and a hit of L2 with its control polygon is
 *      farther than ds from every hit of L1 with it.
 * and the boundary criterion: L2 meets fewer control polygons than L1.
 * (The other boundary criterion, a predicted point leaving the domain, is
 * handled by the tracer itself: pc_locate_exit.) Any of them asks for a full
 * line/surface intersection. With no active branch, a ray that meets any
 * patch's box asks for one too: the control polygon need not be hit where
 * the surface is. (Matching the points found to the branches is generic:
 * trace/seed_match.c.)
 */
#include "bezier/bezier.h"
#include "directional/line_seeds.h"

static pc_vec3 surface_point(const projcurve_surface *s, double u, double v)
{
    pc_vec3 out;
    pc_nurbs_surface_eval(&s->nurbs, u, v, 0, NULL, NULL, &out);
    return out;
}

static size_t index_gap(size_t a, size_t b)
{
    return a > b ? a - b : b - a;
}

static int is_neighbour(const pc_bezier_patch *a, const pc_bezier_patch *b)
{
    return index_gap(a->iu, b->iu) + index_gap(a->iv, b->iv) == 1;
}

/* Distance from S(u, v) (in patch a) to the edge a shares with b. */
static double distance_to_common_edge(const projcurve_surface *s, const pc_bezier_patch *a,
                                      const pc_bezier_patch *b, double u, double v)
{
    double eu = u, ev = v;
    if (b->iu != a->iu)
        eu = b->iu > a->iu ? a->u1 : a->u0;
    else
        ev = b->iv > a->iv ? a->v1 : a->v0;
    return vec3_dist(surface_point(s, u, v), surface_point(s, eu, ev));
}

static size_t hits_on_patch(const pc_polygon_hits *l, size_t patch)
{
    size_t n = 0;
    for (size_t k = 0; k < l->count; ++k)
        n += l->items[k].patch == patch;
    return n;
}

/* Criterion 4: some hit of L2 on the patch is farther than ds from every
 * hit of L1 on it. */
static int hits_moved(const pc_polygon_hits *l1, const pc_polygon_hits *l2, size_t patch,
                      double ds)
{
    for (size_t k = 0; k < l2->count; ++k) {
        if (l2->items[k].patch != patch)
            continue;
        int near = 0;
        for (size_t i = 0; i < l1->count && !near; ++i)
            near = l1->items[i].patch == patch &&
                   vec3_dist(l1->items[i].x, l2->items[k].x) <= ds;
        if (!near)
            return 1;
    }
    return 0;
}

/* Criteria 1-4 for one Inter_Patch. */
static int patch_may_jump(const pc_line_finder *f, size_t patch, const pc_seed *active,
                          size_t n_active, double ds)
{
    const projcurve_surface *s = f->proj->surface;
    const pc_patch_grid *grid = &s->grid;
    const pc_bezier_patch *inter = &grid->patches[patch];
    int neighbour = 0, near_edge = 0;
    for (size_t i = 0; i < n_active; ++i) {
        const size_t a = pc_patch_grid_locate(grid, active[i].u, active[i].v);
        if (a == patch) /* criteria 3 and 4 */
            return hits_on_patch(&f->l2, patch) > hits_on_patch(&f->l1, patch) ||
                   hits_moved(&f->l1, &f->l2, patch, ds);
        if (is_neighbour(&grid->patches[a], inter)) {
            neighbour = 1;
            if (distance_to_common_edge(s, &grid->patches[a], inter, active[i].u,
                                        active[i].v) <= ds)
                near_edge = 1;
        }
    }
    return !neighbour || !near_edge; /* criteria 1 and 2 */
}

int pc_line_may_jump(pc_seed_finder *self, double t, const pc_seed *active, size_t n_active,
                     double ds)
{
    pc_line_finder *f = self->state;
    pc_vec3 p;
    if (pc_curve_eval(f->proj->curve, t, 0, &f->curve_hint, &p) != PROJCURVE_OK)
        return 1; /* let the full search report the failure */
    if (!pc_line_polygon_hits(f, p, &f->l2)) {
        f->have_l1 = 0;
        return 1;
    }
    int jump = !f->have_l1 || (n_active == 0 && f->n_patches > 0) ||
               f->l2.count < f->l1.count;
    for (size_t k = 0; k < f->l2.count && !jump; ++k) {
        const size_t patch = f->l2.items[k].patch;
        if (k > 0 && f->l2.items[k - 1].patch == patch)
            continue; /* hits come grouped by patch */
        jump = patch_may_jump(f, patch, active, n_active, ds);
    }
    const pc_polygon_hits tmp = f->l1;
    f->l1 = f->l2;
    f->l2 = tmp;
    f->have_l1 = 1;
    return jump;
}

void pc_line_jump_reset(pc_seed_finder *self)
{
    pc_line_finder *f = self->state;
    f->have_l1 = 0;
}
