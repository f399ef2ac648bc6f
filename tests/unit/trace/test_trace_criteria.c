/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The jump criteria of [SY13] s3.4 (src/directional/jump_detect.c), called
 * directly: pc_line_may_jump with hand-placed rays L1 (the previous check)
 * and L2 (this check) and hand-placed current points of the active branches.
 * Each case is built so that exactly one criterion can hold, and is paired
 * with the same rays where a single change (ds, or where the active point
 * lies: the Active_Patch bookkeeping) makes it fail, so that the answer is
 * shown to come from that criterion.
 *
 * The surfaces are planar-faceted with control points chosen by hand, so
 * the control-polygon hits of each ray are known exactly:
 *   flat: z = 0 over [0, 90]^2, bilinear, 3 x 3 patches of 30 x 30 (patch
 *         (iu, iv) covers x in [30 iu, 30 iu + 30], y likewise; u = x / 90);
 *   fold: one patch across u whose control polygon folds back over itself
 *         (columns at x = 0, 60, 30 with z = 0, 0, 10), 2 patches along v
 *         (y in [0, 50] and [50, 100]): a ray from above at x in (30, 60)
 *         meets that polygon twice, at x < 30 once.
 *
 * Then the sweep itself, with its periodic full search switched off (the
 * white-box parameter sweep_criteria_only): the births on the C- and Z-folded
 * sheets of test_trace_jumps must still be found, now by the criteria alone,
 * with the same start and end reasons and nothing missed by brute force.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "directional/directional.h"
#include "directional/directional_project.h"
#include "directional/line_seeds.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9
/* Height of the rays' origins above the sheets. */
#define RAY_HEIGHT 50.0

static projcurve_surface *flat_sheet(void)
{
    double ctrl[3 * 16];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            ctrl[3 * (4 * j + i) + 0] = 30.0 * i;
            ctrl[3 * (4 * j + i) + 1] = 30.0 * j;
            ctrl[3 * (4 * j + i) + 2] = 0.0;
        }
    const double k[6] = {0, 0, 1.0 / 3.0, 2.0 / 3.0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 1, 1, 4, 4, ctrl, NULL, k, k, &s);
    return s;
}

static projcurve_surface *folded_patch_sheet(void)
{
    const double px[3] = {0, 60, 30}, pz[3] = {0, 0, 10};
    double ctrl[3 * 9];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            ctrl[3 * (3 * j + i) + 0] = px[i];
            ctrl[3 * (3 * j + i) + 1] = 50.0 * j;
            ctrl[3 * (3 * j + i) + 2] = pz[i];
        }
    const double ku[6] = {0, 0, 0, 1, 1, 1};
    const double kv[5] = {0, 0, 0.5, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 2, 1, 3, 3, ctrl, NULL, ku, kv, &s);
    return s;
}

/* One call of the criteria: the finder's previous ray L1 through (x1, y1),
 * the current ray L2 through (x2, y2) (both straight down from
 * RAY_HEIGHT), the active points (u, v) and ds. Returns what
 * pc_line_may_jump says at L2, or -1 when the setup fails. */
static int criteria(const projcurve_surface *s, double x1, double y1, double x2, double y2,
                    const pc_seed *active, size_t n_active, double ds)
{
    const double pts[6] = {x1, y1, RAY_HEIGHT, x2, y2, RAY_HEIGHT};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    if (c == NULL || s == NULL) {
        projcurve_curve_destroy(c);
        return -1;
    }
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    const pc_vec3 down = vec3(0, 0, -1);
    pc_directional_init(&proj, &data, &cache, s, c, down, 1e-12, 50);
    pc_line_finder f;
    pc_line_finder_init(&f, &proj, down);
    /* the first call has no L1: it always asks for a search */
    const int first = pc_line_may_jump(&f.base, 0.0, active, n_active, ds);
    const int answer = first == 1 ? pc_line_may_jump(&f.base, 1.0, active, n_active, ds) : -1;
    pc_line_finder_free(&f);
    projcurve_curve_destroy(c);
    return answer;
}

/* An active point at (x, y) of the flat sheet (u = x / 90, v = y / 90). */
static pc_seed flat_point(double x, double y)
{
    const pc_seed p = {0.0, x / 90.0, y / 90.0};
    return p;
}

#define CHECK_CRITERIA(name, got, expected)                                                \
    do {                                                                                   \
        const int got_ = (got);                                                            \
        ++pc_test_checks;                                                                  \
        if (got_ != (expected))                                                            \
            pc_test_fail_at(__FILE__, __LINE__, "%s: pc_line_may_jump = %d, expected %d", \
                            name, got_, expected);                                         \
    } while (0)

static void test_flat_criteria(void)
{
    projcurve_surface *s = flat_sheet();
    CHECK(s != NULL);
    const double ds = 5.0;

    /* Nothing changed: L1 (10, 5) and L2 (12, 5) each meet patch (0, 0)
     * once, 2 apart (< ds), and the active branch is on that patch. (No ray
     * here passes through the diagonal of a patch, where it would meet
     * both triangles of its quad.) */
    const pc_seed a00 = flat_point(12, 5);
    CHECK_CRITERIA("quiet", criteria(s, 10, 5, 12, 5, &a00, 1, ds), 0);

    /* Criterion 4 alone: the same patch, the same count, the hit moved 10
     * (> ds = 5); with ds = 15 the same rays ask nothing. */
    const pc_seed a00b = flat_point(20, 5);
    CHECK_CRITERIA("criterion 4", criteria(s, 10, 5, 20, 5, &a00b, 1, ds), 1);
    CHECK_CRITERIA("criterion 4, ds 15", criteria(s, 10, 5, 20, 5, &a00b, 1, 15.0), 0);

    /* Criterion 1 alone: L2 (75, 70) meets patch (2, 2) only, the branch is on
     * (0, 0), neither it nor a neighbour of it; counts equal (1, 1). */
    CHECK_CRITERIA("criterion 1", criteria(s, 10, 5, 75, 70, &a00, 1, ds), 1);
    /* ... and not when the active point is on (1, 2), a neighbour of
     * (2, 2), 2 from their common edge x = 60 (<= ds): the same rays. */
    const pc_seed a12_near = flat_point(58, 70);
    CHECK_CRITERIA("criterion 1, neighbour", criteria(s, 10, 5, 75, 70, &a12_near, 1, ds), 0);

    /* Criterion 2 alone: the active point on the neighbour (1, 2), but 20
     * from the common edge (> ds); with ds = 25 it is near, and nothing is
     * asked. */
    const pc_seed a12_far = flat_point(40, 70);
    CHECK_CRITERIA("criterion 2", criteria(s, 10, 5, 75, 70, &a12_far, 1, ds), 1);
    CHECK_CRITERIA("criterion 2, ds 25", criteria(s, 10, 5, 75, 70, &a12_far, 1, 25.0), 0);
    /* Two neighbours of (2, 2): (1, 2) far from its edge, (2, 1) at 3 from
     * the edge y = 60: one branch near the common edge is enough. */
    const pc_seed two[2] = {a12_far, flat_point(75, 57)};
    CHECK_CRITERIA("criterion 2, one near", criteria(s, 10, 5, 75, 70, two, 2, ds), 0);
    const pc_seed two_far[2] = {a12_far, flat_point(75, 45)};
    CHECK_CRITERIA("criterion 2, both far", criteria(s, 10, 5, 75, 70, two_far, 2, ds), 1);

    /* The boundary criterion alone: L1 (85, 45) meets patch (2, 1), L2
     * (95, 45) is off the sheet and meets nothing (no patch can ask). When
     * L2 stays on (88, 45), 3 from L1 (< ds), nothing is asked. */
    const pc_seed a21 = flat_point(85, 45);
    CHECK_CRITERIA("boundary", criteria(s, 85, 45, 95, 45, &a21, 1, ds), 1);
    CHECK_CRITERIA("boundary, inside", criteria(s, 85, 45, 88, 45, &a21, 1, ds), 0);

    /* No branch alive: a ray that meets a patch box asks; one that meets
     * nothing (as L1 did not) does not. */
    CHECK_CRITERIA("none alive, hit", criteria(s, 10, 5, 12, 5, NULL, 0, ds), 1);
    CHECK_CRITERIA("none alive, miss", criteria(s, -20, 10, -10, 10, NULL, 0, ds), 0);
    projcurve_surface_destroy(s);
}

static void test_fold_criterion(void)
{
    projcurve_surface *s = folded_patch_sheet();
    CHECK(s != NULL);
    /* ds = 100 exceeds every distance between the hits: criterion 4 cannot
     * hold, so the only criterion left on the active patch is 3. */
    const double ds = 100.0;
    /* patch (0, 0): y in [0, 50]; the point's (u, v) only selects the patch */
    const pc_seed a00 = {0.0, 0.1, 0.25};
    /* L1 at x = 10 meets the polygon of (0, 0) once, L2 at x = 40 twice
     * (off the diagonals of its triangles: a ray through one would meet
     * both triangles of the quad) */
    CHECK_CRITERIA("criterion 3", criteria(s, 10, 25, 40, 25, &a00, 1, ds), 1);
    /* both rays twice: the count does not grow */
    CHECK_CRITERIA("criterion 3, same count", criteria(s, 40, 20, 40, 25, &a00, 1, ds), 0);
    /* the same rays as the first, but the branch is on (0, 1), 1 from the
     * common edge y = 50: (0, 0) is not its Active_Patch, so criteria 3 and
     * 4 are not asked, and criterion 2 is not met */
    const pc_seed a01_near = {0.0, 0.1, 0.51};
    CHECK_CRITERIA("criterion 3, not active", criteria(s, 10, 25, 40, 25, &a01_near, 1, ds), 0);
    projcurve_surface_destroy(s);
}

/* The jump sweep with only the criteria to start full searches. */
static void check_criteria_only(const char *name, const projcurve_surface *s,
                                const projcurve_curve *c, const projcurve_branch_start *starts,
                                size_t n_expected, double expected_jumps)
{
    pc_params p;
    pc_params_defaults(&p);
    p.compose = 0;
    p.sweep_criteria_only = 1;
    CHECK_OK(pc_params_distance_tolerance(NULL, &p, s->size, &p.tol_distance));
    pc_budget budget;
    pc_budget_init(&budget, 0.0, 0, NULL, NULL);
    p.budget = &budget;
    projcurve_result *r = NULL;
    CHECK_OK(pc_directional_project(NULL, s, c, vec3(0, 0, -1), &p, &r));
    const size_t nb = projcurve_result_branch_count(r);
    printf("%s (criteria only): %zu branches, expected %zu\n", name, nb, n_expected);
    CHECK(nb == n_expected);
    int used[4] = {0};
    for (size_t i = 0; i < nb; ++i) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        double range[2];
        CHECK_OK(projcurve_result_branch_info(NULL, r, i, range, &start, &end, NULL, NULL));
        printf("  branch %zu: t [%.6f, %.6f] start %d end %d\n", i, range[0], range[1],
               (int)start, (int)end);
        CHECK(end == PROJCURVE_END_CURVE_END);
        int found = 0;
        for (size_t k = 0; k < n_expected && k < 4 && !found; ++k)
            if (!used[k] && starts[k] == start)
                found = used[k] = 1;
        CHECK(found);
    }
    double jumps = -1.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_JUMPS, &jumps));
    CHECK_NEAR(jumps, expected_jumps, 0.0);
    trace_oracle_report rep;
    const double down[3] = {0, 0, -1};
    trace_oracle_check(s, c, down, r, N_SAMPLES, &rep);
    trace_oracle_print(name, &rep);
    CHECK(rep.uncovered_far == 0);
    CHECK(!trace_oracle_missed_branch(&rep));
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    projcurve_result_destroy(r);
}

static void test_births_by_criteria(void)
{
    /* C-fold, the curve over the flat parts: both branches are born on
     * their sheets' edges (x = 0 bottom, x = 20 top) in mid-curve */
    projcurve_surface *s = shape_c_fold();
    const double flat[6] = {-10, 50, 40, 70, 50, 40};
    projcurve_curve *c = shape_bspline_curve(1, 2, flat);
    const projcurve_branch_start c_starts[2] = {PROJCURVE_START_BOUNDARY,
                                                PROJCURVE_START_BOUNDARY};
    check_criteria_only("c-fold flat", s, c, c_starts, 2, 2.0);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);

    /* Z-fold: bottom and middle from the start, the top born at its edge */
    s = shape_z_fold();
    const double pts[6] = {90, 50, 60, 45, 50, 60};
    c = shape_bspline_curve(1, 2, pts);
    const projcurve_branch_start z_starts[3] = {
        PROJCURVE_START_CURVE_START, PROJCURVE_START_CURVE_START, PROJCURVE_START_BOUNDARY};
    check_criteria_only("z-fold", s, c, z_starts, 3, 1.0);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_flat_criteria();
    test_fold_criterion();
    test_births_by_criteria();
    return pc_test_finish("test_trace_criteria");
}
