/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * c_reference — the oracle of the Python package's bit-for-bit test: reads
 * a model, projects its curve 0 onto its surface 0 through the C API only
 * and prints every number of the result as a C99 hexadecimal float (%a),
 * which the test (tests/python/test_against_c.py) compares with what the
 * package returns for the same call, bit for bit.
 *
 * Usage: c_reference FILE dir DX DY DZ TOL
 *        c_reference FILE eye EX EY EZ TOL (conical)
 *        c_reference FILE ortho TOL
 * Output lines: "branch I T0 T1 START END N_POINTS N_PIECES", "tuv I ...",
 * "piece I K DEGREE ctrl... weights... t0 t1 uv...", "compact_curve I
 * ctrl... knots..." and "compact_pcurve I ..." (the curve data), "stat K V".
 * Exit status 0, or 1 with a message on stderr.
 */
#include <projcurve.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(projcurve_context *ctx, const char *what, projcurve_status st)
{
    fprintf(stderr, "c_reference: %s: %s (%s)\n", what, projcurve_context_message(ctx),
            projcurve_status_string(st));
    return 1;
}

static void print_doubles(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        printf(" %a", v[i]);
}

/* The NURBS data of a result's curve: "NAME I ctrl... knots...". */
static int print_curve(projcurve_context *ctx, const char *name, size_t branch,
                       const projcurve_curve *c)
{
    int degree = 0, rational = 0;
    size_t n = 0, nk = 0;
    projcurve_status st = projcurve_curve_nurbs_info(ctx, c, &degree, &n, &nk, &rational);
    if (st != PROJCURVE_OK)
        return fail(ctx, name, st);
    double *ctrl = malloc(sizeof(double) * 3 * n);
    double *knots = malloc(sizeof(double) * nk);
    int rc = 0;
    if (!ctrl || !knots) {
        fprintf(stderr, "c_reference: out of memory\n");
        rc = 1;
    } else if ((st = projcurve_curve_nurbs_data(ctx, c, ctrl, NULL, knots)) != PROJCURVE_OK) {
        rc = fail(ctx, name, st);
    } else {
        printf("%s %zu", name, branch);
        print_doubles(ctrl, 3 * n);
        print_doubles(knots, nk);
        printf("\n");
    }
    free(ctrl);
    free(knots);
    return rc;
}

static int print_branch(projcurve_context *ctx, const projcurve_result *r, size_t b)
{
    double t[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n_points = 0, n_pieces = 0;
    projcurve_status st = projcurve_result_branch_info(ctx, r, b, t, &start, &end, &n_points,
                                                       &n_pieces);
    if (st != PROJCURVE_OK)
        return fail(ctx, "branch info", st);
    printf("branch %zu %a %a %d %d %zu %zu\n", b, t[0], t[1], (int)start, (int)end, n_points,
           n_pieces);
    double *tuv = malloc(sizeof(double) * 3 * (n_points ? n_points : 1));
    size_t count = 0;
    if (!tuv)
        return 1;
    st = projcurve_result_branch_points(ctx, r, b, n_points, tuv, &count);
    if (st != PROJCURVE_OK) {
        free(tuv);
        return fail(ctx, "branch points", st);
    }
    printf("tuv %zu", b);
    print_doubles(tuv, 3 * count);
    printf("\n");
    free(tuv);
    for (size_t k = 0; k < n_pieces; k++) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
        double range[2], uv[4];
        st = projcurve_result_piece(ctx, r, b, k, &degree, ctrl, w, range, uv);
        if (st != PROJCURVE_OK)
            return fail(ctx, "piece", st);
        printf("piece %zu %zu %d", b, k, degree);
        print_doubles(ctrl, 3 * (size_t)(degree + 1));
        print_doubles(w, (size_t)(degree + 1));
        print_doubles(range, 2);
        print_doubles(uv, 4);
        printf("\n");
    }
    projcurve_curve *c = NULL;
    if (projcurve_result_branch_compact_curve(ctx, r, b, &c) == PROJCURVE_OK) {
        int rc = print_curve(ctx, "compact_curve", b, c);
        projcurve_curve_destroy(c);
        if (rc)
            return rc;
    }
    c = NULL;
    if (projcurve_result_branch_compact_pcurve(ctx, r, b, &c) == PROJCURVE_OK) {
        int rc = print_curve(ctx, "compact_pcurve", b, c);
        projcurve_curve_destroy(c);
        if (rc)
            return rc;
    }
    return 0;
}

int main(int argc, char **argv)
{
    int directional = argc == 7 && strcmp(argv[2], "dir") == 0;
    int conical = argc == 7 && strcmp(argv[2], "eye") == 0;
    if (!directional && !conical && !(argc == 4 && strcmp(argv[2], "ortho") == 0)) {
        fprintf(stderr, "usage: c_reference FILE dir DX DY DZ TOL | FILE eye EX EY EZ TOL"
                        " | FILE ortho TOL\n");
        return 2;
    }
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return 1;
    projcurve_model *m = NULL;
    projcurve_options *o = NULL;
    projcurve_result *r = NULL;
    int rc = 1;
    projcurve_status st = projcurve_model_read_file(ctx, argv[1], &m);
    if (st != PROJCURVE_OK) {
        rc = fail(ctx, argv[1], st);
        goto done;
    }
    if ((st = projcurve_options_create(ctx, &o)) != PROJCURVE_OK ||
        (st = projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE,
                                           strtod(argv[directional || conical ? 6 : 3], NULL))) !=
            PROJCURVE_OK) {
        rc = fail(ctx, "options", st);
        goto done;
    }
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    const projcurve_curve *c = projcurve_model_curve(m, 0);
    if (directional || conical) {
        const double v[3] = {strtod(argv[3], NULL), strtod(argv[4], NULL),
                             strtod(argv[5], NULL)};
        st = directional ? projcurve_project_directional(ctx, s, c, v, o, &r)
                         : projcurve_project_conical(ctx, s, c, v, o, &r);
    } else {
        st = projcurve_project_orthogonal(ctx, s, c, o, &r);
    }
    if (st != PROJCURVE_OK) {
        rc = fail(ctx, "projection", st);
        goto done;
    }
    rc = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r) && rc == 0; b++)
        rc = print_branch(ctx, r, b);
    for (int k = PROJCURVE_STAT_POINTS; k <= PROJCURVE_STAT_MAX_ERROR && rc == 0; k++) {
        double v = 0;
        if ((st = projcurve_result_stat(ctx, r, (projcurve_stat)k, &v)) != PROJCURVE_OK)
            rc = fail(ctx, "stat", st);
        else
            printf("stat %d %a\n", k, v);
    }
done:
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_model_destroy(m);
    projcurve_context_destroy(ctx);
    return rc;
}
