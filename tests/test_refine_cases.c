/*
 * End to end on the shared cases (../shared/cases/MANIFEST.tsv): every
 * directional case is projected through the public API at eps_D = 1e-2,
 * 1e-4 and 1e-6 of the model size with eps_T = 1 degree, and at 1e-3 with
 * 10 degrees; every composed branch is measured against the exact projection
 * by the test oracles (tests/support/piece_oracle): the Hausdorff distance
 * both ways on dense samples, the joint angles, the joins, and that each
 * piece stays in one Bezier patch. The exact projection at t is the oracle
 * projector's own Newton solution, started from the branch's pcurve.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "piece_oracle.h"

#define MAX_CASES 32
#define NAME_LEN 96

typedef struct manifest_case {
    char name[NAME_LEN];
    int orthogonal;
    double dir[3];
    long expected_branches;
} manifest_case;

/* Rows of MANIFEST.tsv (name, mode, dir_x, dir_y, dir_z, tol_dist,
 * tol_angle_deg, expected_branches, notes). */
static size_t read_manifest(manifest_case *cases, size_t capacity)
{
    FILE *f = fopen(pc_test_shared_path("cases/MANIFEST.tsv"), "r");
    if (f == NULL)
        return 0;
    char line[2048];
    size_t n = 0;
    while (n < capacity && fgets(line, sizeof line, f) != NULL) {
        if (line[0] == '#')
            continue;
        char mode[32];
        double tol_d, tol_a;
        manifest_case c;
        if (sscanf(line, "%95s %31s %lf %lf %lf %lf %lf %ld", c.name, mode, &c.dir[0], &c.dir[1],
                   &c.dir[2], &tol_d, &tol_a, &c.expected_branches) == 8 &&
            strcmp(mode, "directional") == 0) {
            c.orthogonal = strcmp(mode, "orthogonal") == 0;
            cases[n++] = c;
        }
    }
    fclose(f);
    return n;
}

/* The exact projection along a branch: Q(t) from the oracle's corrector
 * seeded by the branch's pcurve, Q'(t) = Su u' + Sv v'. */
typedef struct branch_exact {
    const pc_projector *proj;
    const pc_branch *branch;
    int *failures; /* corrector failures, counted */
} branch_exact;

static void pcurve_guess(const pc_branch *b, double t, double uv[2])
{
    const double *p = b->points;
    const size_t n = b->n_points;
    const double dir = p[3 * (n - 1)] >= p[0] ? 1.0 : -1.0;
    size_t lo = 0, hi = n - 1; /* bisection for the segment holding t */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (dir * (p[3 * mid] - t) <= 0.0)
            lo = mid;
        else
            hi = mid;
    }
    const double *a = p + 3 * lo, *c = p + 3 * hi;
    const double w = c[0] != a[0] ? (t - a[0]) / (c[0] - a[0]) : 0.0;
    uv[0] = a[1] + w * (c[1] - a[1]);
    uv[1] = a[2] + w * (c[2] - a[2]);
}

static void exact_on_branch(const void *user, double t, pc_vec3 q[3])
{
    const branch_exact *e = user;
    double uv[2];
    pcurve_guess(e->branch, t, uv);
    pc_proj_point pt;
    if (!e->proj->correct(e->proj, t, uv, NULL) ||
        !e->proj->derivatives(e->proj, t, uv[0], uv[1], &pt)) {
        ++*e->failures;
        q[0] = vec3(NAN, NAN, NAN);
        return;
    }
    double s[18];
    projcurve_surface_eval(NULL, e->proj->surface, uv[0], uv[1], 1, s);
    q[0] = vec3_load(s);
    q[1] = vec3_add(vec3_scale(vec3_load(s + 3), pt.du), vec3_scale(vec3_load(s + 6), pt.dv));
    q[2] = vec3(0.0, 0.0, 0.0);
}

static void check_case(const manifest_case *c, const projcurve_surface *s,
                       const projcurve_curve *curve, double rel_eps, double angle)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, rel_eps * s->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, angle));
    projcurve_result *r = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const projcurve_status st = projcurve_project_directional(ctx, s, curve, c->dir, o, &r);
    CHECK_OK(st);
    if (st != PROJCURVE_OK) {
        fprintf(stderr, "%s: %s\n", c->name, projcurve_context_message(ctx));
        projcurve_context_destroy(ctx);
        projcurve_options_destroy(o);
        return;
    }
    CHECK((long)r->n_branches == c->expected_branches);
    pc_oracle_dir d;
    pc_projector proj;
    if (c->orthogonal)
        pc_oracle_projector_orthogonal(s, curve, &proj);
    else
        pc_oracle_projector(s, curve, c->dir, &d, &proj);
    size_t pieces = 0;
    double worst = 0.0, worst_angle = 0.0;
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        CHECK(b->n_pieces > 0);
        if (b->n_pieces == 0)
            continue;
        int failures = 0;
        const branch_exact e = {&proj, b, &failures};
        const pc_oracle_measure m = pc_oracle_measure_branch(b, exact_on_branch, &e, &s->grid);
        CHECK(failures == 0);
        CHECK(m.hausdorff <= rel_eps * s->size);
        CHECK(m.max_angle <= angle * (1.0 + 1e-9));
        CHECK(m.max_gap <= 1e-12 * s->size);
        CHECK(m.max_end_err <= 1e-9 * s->size);
        CHECK(m.off_patch == 0);
        pieces += b->n_pieces;
        worst = fmax(worst, m.hausdorff / (rel_eps * s->size));
        worst_angle = fmax(worst_angle, m.max_angle);
    }
    printf("%-28s eps_D %.0e eps_T %4.1f: %zu branches, %5zu pieces, Hausdorff %.2f eps_D, "
           "joints <= %.3f deg\n",
           c->name, rel_eps, angle, r->n_branches, pieces, worst, worst_angle);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
}

int main(void)
{
    manifest_case cases[MAX_CASES];
    const size_t n = read_manifest(cases, MAX_CASES);
    if (n == 0)
        pc_test_skip("no cases in ../shared/cases/MANIFEST.tsv");
    static const double rel_eps[] = {1e-2, 1e-4, 1e-6};
    for (size_t k = 0; k < n; ++k) {
        char rel[NAME_LEN + 16];
        snprintf(rel, sizeof rel, "cases/%.*s.igs", NAME_LEN - 1, cases[k].name);
        projcurve_model *model = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, pc_test_shared_path(rel), &model));
        const projcurve_surface *s = projcurve_model_surface(model, 0);
        const projcurve_curve *curve = projcurve_model_curve(model, 0);
        CHECK(s != NULL && curve != NULL);
        if (s != NULL && curve != NULL) {
            for (size_t e = 0; e < sizeof rel_eps / sizeof rel_eps[0]; ++e)
                check_case(&cases[k], s, curve, rel_eps[e], 1.0);
            check_case(&cases[k], s, curve, 1e-3, 10.0);
        }
        projcurve_model_destroy(model);
    }
    return pc_test_finish("test_refine_cases");
}
