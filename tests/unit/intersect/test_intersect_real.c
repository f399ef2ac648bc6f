/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Line / surface intersection on every surface of every real CAD model in
 * tests/data/real (a file that does not load fails the test; the
 * directory missing altogether skips it), against the brute-force oracle
 * (tests/support/ray_oracle.c: a dense triangulation with a few cells per
 * knot span, Newton polish with the public evaluator): every oracle hit
 * found exactly once, every claimed hit on the line, boundary and tangent
 * flags where the oracle can decide them. At least PC_REAL_RAYS lines in
 * all: 100,000; the sanitizer build, ~20 times slower, sets 20,000
 * (tests/CMakeLists.txt).
 *
 * And the knot cluster of linkrods.step surface 16: spans 2e-8 wide at
 * v ~ -3.6, where the surface retraces one sheet back and forth; a line
 * across it crosses that sheet once.
 */
#define _POSIX_C_SOURCE 200809L /* opendir, stat */

#include "check.h"
#include "intersect/intersect.h"
#include "ray_oracle.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifndef PC_REAL_RAYS
#define PC_REAL_RAYS 100000
#endif

#define PI 3.14159265358979323846

/* Oracle mesh: at least this many cells per knot span, more for high
 * degrees, for spans whose control polygon turns a lot (so that a cell
 * turns by at most PC_CELL_TURN), and at least PC_CELLS_MIN along a side
 * of few spans. A side has at most PC_CELLS_MAX cells. (Lines nearly
 * parallel to the surface, which pass between chords and surface, are
 * seeded by the cells they pass close to: ray_oracle.c.) */
#define PC_CELLS_PER_SPAN 6
#define PC_CELL_TURN (PI / 24.0)
#define PC_CELLS_MIN 128
#define PC_CELLS_MAX 8192

/* The oracle's evaluator: the public evaluation, with parameters inside a
 * span of (near) zero width moved to its end that borders a real span. The
 * point is the same (such a span is a curve of the surface); the
 * derivatives are then those of the surface, not of the span's
 * parametrisation, whose normal means nothing. */
#define PC_SPAN_ZERO 1e-12

/* Whether a side has a span of (near) zero width. */
static int has_zero_span(const double *breaks, size_t spans)
{
    for (size_t k = 0; k < spans; ++k)
        if (breaks[k + 1] - breaks[k] <= PC_SPAN_ZERO * (breaks[spans] - breaks[0]))
            return 1;
    return 0;
}

static double off_zero_span(const double *breaks, size_t spans, double x)
{
    const double zero = PC_SPAN_ZERO * (breaks[spans] - breaks[0]);
    for (size_t k = 0; k < spans; ++k) {
        if (!(breaks[k + 1] - breaks[k] <= zero) || x < breaks[k] || x > breaks[k + 1])
            continue;
        return k + 1 < spans ? breaks[k + 1] : breaks[k];
    }
    return x;
}

typedef struct oracle_surface {
    const projcurve_surface *s;
    int zero_u, zero_v; /* has_zero_span of either side */
} oracle_surface;

static void eval_surface(void *user, double u, double v, int n_deriv, double out[9])
{
    const oracle_surface *os = user;
    const projcurve_surface *s = os->s;
    if (os->zero_u)
        u = off_zero_span(s->grid.breaks_u, s->grid.spans_u, u);
    if (os->zero_v)
        v = off_zero_span(s->grid.breaks_v, s->grid.spans_v, v);
    if (projcurve_surface_eval(NULL, s, u, v, n_deriv, out) != PROJCURVE_OK)
        for (int k = 0; k < 9; ++k)
            out[k] = NAN;
}

/* The largest turning (sum of angles between consecutive legs) of the
 * control polygons of the patches in span `span` along u (along_u) or v. */
static double span_turning(const projcurve_surface *s, size_t span, int along_u)
{
    const pc_patch_grid *g = &s->grid;
    const size_t across = along_u ? g->spans_v : g->spans_u;
    double worst = 0.0;
    for (size_t k = 0; k < across; ++k) {
        const pc_bezier_patch *p =
            pc_patch_grid_at(g, along_u ? span : k, along_u ? k : span);
        const int m = p->deg_u, n = p->deg_v;
        const int len = along_u ? m : n, rows = along_u ? n : m;
        for (int r = 0; r <= rows; ++r) {
            double turn = 0.0, prev[3] = {0, 0, 0};
            int have_prev = 0;
            for (int i = 0; i < len; ++i) {
                const size_t a = along_u ? (size_t)r * (size_t)(m + 1) + (size_t)i
                                         : (size_t)i * (size_t)(m + 1) + (size_t)r;
                const size_t b = along_u ? a + 1 : a + (size_t)(m + 1);
                const double *pa = p->cw + 4 * a, *pb = p->cw + 4 * b;
                double leg[3];
                for (int c = 0; c < 3; ++c)
                    leg[c] = pb[c] / pb[3] - pa[c] / pa[3];
                const double ll = sqrt(leg[0] * leg[0] + leg[1] * leg[1] + leg[2] * leg[2]);
                if (!(ll > 0.0))
                    continue;
                if (have_prev) {
                    const double c = (leg[0] * prev[0] + leg[1] * prev[1] + leg[2] * prev[2]) / ll;
                    turn += acos(fmax(-1.0, fmin(1.0, c)));
                }
                for (int c = 0; c < 3; ++c)
                    prev[c] = leg[c] / ll;
                have_prev = 1;
            }
            worst = fmax(worst, turn);
        }
    }
    return worst;
}

/* Samples along one side: each span cut into its number of cells. Returns
 * the number of cells (samples = cells + 1, malloc'd into *out). */
static int side_samples(const projcurve_surface *s, int along_u, double **out)
{
    const pc_patch_grid *g = &s->grid;
    const size_t spans = along_u ? g->spans_u : g->spans_v;
    const double *breaks = along_u ? g->breaks_u : g->breaks_v;
    const int degree = along_u ? s->nurbs.deg_u : s->nurbs.deg_v;
    int *cells = malloc(sizeof *cells * spans);
    long total = 0;
    for (size_t k = 0; k < spans; ++k) {
        int c = PC_CELLS_PER_SPAN;
        /* A span of (near) zero width is a curve of the surface, the edge
         * of its neighbours' cells: no cells of its own (their triangles
         * would be degenerate, and the cells beside them would not be the
         * domain's edge cells, whose seeds reach past the edge). */
        if (breaks[k + 1] - breaks[k] <= PC_SPAN_ZERO * (breaks[spans] - breaks[0])) {
            cells[k] = 0;
            continue;
        }
        if (c < 2 * degree)
            c = 2 * degree;
        const int by_turn = (int)ceil(span_turning(s, k, along_u) / PC_CELL_TURN);
        if (c < by_turn)
            c = by_turn;
        const int few = (int)((PC_CELLS_MIN + spans - 1) / spans);
        if (c < few)
            c = few;
        cells[k] = c;
        total += c;
    }
    /* Very fine sides: scaled down, never below PC_CELLS_PER_SPAN. */
    if (total > PC_CELLS_MAX) {
        const long before = total;
        total = 0;
        for (size_t k = 0; k < spans; ++k) {
            const long c = (long)cells[k] * PC_CELLS_MAX / before;
            if (cells[k] > 0)
                cells[k] = c > PC_CELLS_PER_SPAN ? (int)c : PC_CELLS_PER_SPAN;
            total += cells[k];
        }
    }
    double *x = malloc(sizeof *x * (size_t)(total + 1));
    long at = 0;
    for (size_t k = 0; k < spans; ++k) {
        const double a = breaks[k], b = breaks[k + 1];
        for (int i = 0; i < cells[k]; ++i)
            x[at++] = a + (b - a) * i / cells[k];
    }
    x[0] = breaks[0]; /* past a leading zero-width span */
    x[at] = breaks[spans];
    free(cells);
    *out = x;
    return (int)total;
}

typedef struct real_stats {
    pc_oracle_stats oracle;
    long surfaces, files;
    long cells;
} real_stats;

/* A random line: half through the surface's box grown by 20%, half through
 * a point of the surface (a random span, then uniform in it, so that narrow
 * spans get their share) in a random direction. */
static void random_line(pc_test_rng *rng, const projcurve_surface *s, int k, double o[3],
                        double d[3])
{
    double n2;
    do {
        for (int c = 0; c < 3; ++c)
            d[c] = pc_test_rng_uniform(rng, -1, 1);
        n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (n2 > 1.0 || n2 < 1e-4);
    if (k % 2 == 0) {
        double box[6];
        CHECK_OK(projcurve_surface_bounds(NULL, s, box));
        const double diag = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                                 (box[4] - box[1]) * (box[4] - box[1]) +
                                 (box[5] - box[2]) * (box[5] - box[2]));
        for (int c = 0; c < 3; ++c) {
            const double mid = 0.5 * (box[c] + box[c + 3]);
            const double h = 0.6 * (box[c + 3] - box[c]) + 1e-3 * diag;
            o[c] = pc_test_rng_uniform(rng, mid - h, mid + h);
        }
        return;
    }
    const pc_patch_grid *g = &s->grid;
    size_t iu = (size_t)pc_test_rng_uniform(rng, 0, (double)g->spans_u);
    size_t iv = (size_t)pc_test_rng_uniform(rng, 0, (double)g->spans_v);
    iu = iu < g->spans_u ? iu : g->spans_u - 1;
    iv = iv < g->spans_v ? iv : g->spans_v - 1;
    const double u = pc_test_rng_uniform(rng, g->breaks_u[iu], g->breaks_u[iu + 1]);
    const double v = pc_test_rng_uniform(rng, g->breaks_v[iv], g->breaks_v[iv + 1]);
    double f[9];
    CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 0, f));
    const double back = pc_test_rng_uniform(rng, 0.1, 2.0);
    for (int c = 0; c < 3; ++c)
        o[c] = f[c] - back * d[c];
}

static void compare_surface(const projcurve_surface *s, const char *name, int n_lines,
                            unsigned long long seed, real_stats *total)
{
    if (getenv("PC_TEST_VERBOSE"))
        printf("-- %s\n", name);
    double *us = NULL, *vs = NULL;
    const int cu = side_samples(s, 1, &us), cv = side_samples(s, 0, &vs);
    oracle_surface os = {s, has_zero_span(s->grid.breaks_u, s->grid.spans_u),
                         has_zero_span(s->grid.breaks_v, s->grid.spans_v)};
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build_samples(&mesh, eval_surface, &os, us, cu, vs, cv));
    free(us);
    free(vs);
    /* The library's merging tolerance is relative to the control net's
     * box, which can be far larger than the surface (linkrods.step surface
     * 16: 46 against 8), and its magnitude measures from that box's
     * centre: "one point" is judged on the same scale. */
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    for (int c = 0; c < 3; ++c)
        mesh.centre[c] = 0.5 * (box[c] + box[c + 3]);
    mesh.model_size = sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                           (box[5] - box[2]) * (box[5] - box[2]));
    total->cells += (long)cu * cv;
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    pc_hit_list hits = {0};
    pc_oracle_stats st = {0};
    double *uvl = NULL;
    unsigned *flags = NULL;
    size_t cap = 0;
    for (int k = 0; k < n_lines; ++k) {
        double o[3], d[3];
        random_line(&rng, s, k, o, d);
        const int ray_only = k % 3 == 0;
        CHECK_OK(pc_intersect_line(NULL, s, vec3_load(o), vec3_load(d), ray_only, &hits));
        const size_t n = hits.count;
        if (n + 1 > cap) {
            cap = 2 * (n + 1);
            uvl = realloc(uvl, sizeof *uvl * 3 * cap);
            flags = realloc(flags, sizeof *flags * cap);
        }
        for (size_t h = 0; h < n; ++h) {
            uvl[3 * h] = hits.items[h].u;
            uvl[3 * h + 1] = hits.items[h].v;
            uvl[3 * h + 2] = hits.items[h].lambda;
            flags[h] = hits.items[h].flags;
        }
        pc_oracle_compare(&mesh, o, d, ray_only, n, uvl, flags, &st);
    }
    if (st.missed + st.duplicated > 0 || st.grazing_extra > 0)
        printf("%s: %ld lines, %ld hits (oracle %ld), %ld missed, %ld duplicated, %ld grazing "
               "hits the mesh missed\n", name, st.lines, st.hits, st.oracle_hits, st.missed,
               st.duplicated, st.grazing_extra);
    /* Half the lines pass through a point of the surface. */
    CHECK(st.hits >= n_lines / 2);
    pc_oracle_stats *t = &total->oracle;
    t->lines += st.lines;
    t->hits += st.hits;
    t->oracle_hits += st.oracle_hits;
    t->grazing_extra += st.grazing_extra;
    t->missed += st.missed;
    t->duplicated += st.duplicated;
    t->in_run += st.in_run;
    t->run_split += st.run_split;
    t->extra_sheets += st.extra_sheets;
    t->cluster_sheets += st.cluster_sheets;
    t->flags_checked += st.flags_checked;
    t->max_residual = fmax(t->max_residual, st.max_residual / mesh.scale);
    t->max_excess = fmax(t->max_excess, st.max_excess);
    free(uvl);
    free(flags);
    pc_hit_list_free(&hits);
    pc_oracle_mesh_free(&mesh);
}

/* ---- the files ------------------------------------------------------------------ */

#define PC_MAX_FILES 64

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The model files of the directory (not directories, not *.md), sorted;
 * returns the count (-1 when the directory cannot be opened). */
static int list_models(const char *dir, char **names, int capacity)
{
    DIR *d = opendir(dir);
    if (d == NULL)
        return -1;
    int n = 0;
    for (struct dirent *e = readdir(d); e != NULL; e = readdir(d)) {
        const char *name = e->d_name;
        const size_t len = strlen(name);
        if (name[0] == '.' || (len > 3 && strcmp(name + len - 3, ".md") == 0))
            continue;
        char path[4608];
        if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path)
            continue; /* no model has such a name */
        struct stat info;
        if (stat(path, &info) != 0 || S_ISDIR(info.st_mode))
            continue;
        CHECK(n < capacity);
        if (n < capacity) {
            names[n] = malloc(len + 1);
            memcpy(names[n], name, len + 1);
            ++n;
        }
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, by_name);
    return n;
}

static void test_all_real(void)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", pc_test_data_path("real"));
    char *names[PC_MAX_FILES];
    const int n_files = list_models(dir, names, PC_MAX_FILES);
    if (n_files < 0)
        pc_test_missing_data("real/");
    projcurve_model *models[PC_MAX_FILES];
    size_t n_surfaces = 0;
    for (int f = 0; f < n_files; ++f) {
        char path[4608];
        models[f] = NULL;
        ++pc_test_checks;
        if (snprintf(path, sizeof path, "%s/%s", dir, names[f]) >= (int)sizeof path) {
            pc_test_fail_at(__FILE__, __LINE__, "path of %s too long", names[f]);
            continue;
        }
        const projcurve_status st = projcurve_model_read_file(NULL, path, &models[f]);
        ++pc_test_checks;
        if (st != PROJCURVE_OK) {
            pc_test_fail_at(__FILE__, __LINE__, "%s does not load: %s", path,
                            projcurve_status_string(st));
            models[f] = NULL;
            continue;
        }
        n_surfaces += projcurve_model_surface_count(models[f]);
    }
    CHECK(n_surfaces > 0);
    const int per_surface = n_surfaces > 0 ? (int)((PC_REAL_RAYS + n_surfaces - 1) / n_surfaces) : 0;
    real_stats total = {{0}, 0, 0, 0};
    for (int f = 0; f < n_files; ++f) {
        if (models[f] == NULL)
            continue;
        ++total.files;
        const size_t count = projcurve_model_surface_count(models[f]);
        for (size_t k = 0; k < count; ++k) {
            const projcurve_surface *s = projcurve_model_surface(models[f], k);
            CHECK(s != NULL);
            if (s == NULL)
                continue;
            char name[512];
            snprintf(name, sizeof name, "%s surface %zu", names[f], k);
            compare_surface(s, name, per_surface, 1000u * (unsigned long long)f + k, &total);
            ++total.surfaces;
        }
        projcurve_model_destroy(models[f]);
    }
    const pc_oracle_stats *t = &total.oracle;
    printf("real surfaces: %ld files, %ld surfaces, %ld lines, %ld hits (oracle %ld), "
           "%ld missed, %ld duplicated, %ld in runs of sheets, %ld runs split, %ld extra sheets, "
           "%ld sheets of knot clusters seen by one side, "
           "%ld grazing hits the mesh missed, "
           "%ld flags checked, "
           "%ld mesh cells; largest residual %.3g of the model, %.3g of the allowance\n",
           total.files, total.surfaces, t->lines, t->hits, t->oracle_hits, t->missed,
           t->duplicated, t->in_run, t->run_split, t->extra_sheets, t->cluster_sheets, t->grazing_extra, t->flags_checked, total.cells, t->max_residual,
           t->max_excess);
    CHECK(t->lines >= PC_REAL_RAYS);
    /* Each claimed hit lies on the line to 1e-12 of the model plus the
     * parameters' resolution; what the oracle checks (1e-11) is looser. */
    CHECK(t->max_excess <= 1.0);
    for (int f = 0; f < n_files; ++f)
        free(names[f]);
}

/* ---- the knot cluster of linkrods.step ----------------------------------------- */

/* Surface 16 has nine knots of multiplicity 9 (degree 10) within 2e-7 at
 * v ~ -3.6127526: spans of 1.8e-8 across which the surface runs back and
 * forth along one sheet (|Sv| up to 1e8), so that a line crossing that
 * sheet crosses it on many spans, at points within ~1e-7 of each other.
 * The sheet is crossed once: one hit, whose (u, v) put S on the line as
 * well as doubles allow there (one ulp of v moves S by |Sv| ulp(v) ~ 4e-8),
 * and the line's ordinary hit elsewhere. */
static void test_knot_cluster(void)
{
    projcurve_model *model = NULL;
    const char *path = pc_test_data_path("real/linkrods.step");
    if (projcurve_model_read_file(NULL, path, &model) != PROJCURVE_OK) {
        FILE *f = fopen(path, "rb");
        CHECK(f == NULL); /* present but unreadable: test_all_real fails too */
        if (f)
            fclose(f);
        return;
    }
    const projcurve_surface *s = projcurve_model_surface(model, 16);
    CHECK(s != NULL);
    if (s == NULL) {
        projcurve_model_destroy(model);
        return;
    }
    const double o[3] = {32.652281713758171, -7.127163406956246, 8.1858399014510397};
    const double d[3] = {-0.86762602194099125, 0.3232405447002562, -0.2068242674024201};
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    double hits[3 * 8];
    unsigned flags[8];
    size_t n = 0;
    CHECK_OK(projcurve_surface_intersect_line(NULL, s, o, d, 0, 8, hits, flags, &n));
    ++pc_test_checks;
    if (n != 2)
        pc_test_fail_at(__FILE__, __LINE__, "linkrods.step surface 16: %zu hits, expected 2", n);
    /* The ordinary hit (where the oracle polishes it, a 512 x 512 mesh
     * finds it) and the cluster's: lambda of the sheet's crossing. */
    const double lambda[2] = {32.457263602650, 33.0585497};
    for (size_t h = 0; h < n && h < 2; ++h) {
        const double u = hits[3 * h], v = hits[3 * h + 1];
        double f[9];
        CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 1, f));
        double r = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double x = o[c] + hits[3 * h + 2] * d[c] - f[c];
            r += x * x;
        }
        r = sqrt(r);
        const double allowed = 1e-12 * size + pc_oracle_resolution(u, v, f);
        CHECK_NEAR(hits[3 * h + 2], lambda[h], h == 0 ? 1e-11 : 2e-7);
        CHECK(flags[h] == 0);
        ++pc_test_checks;
        if (!(r <= allowed))
            pc_test_fail_at(__FILE__, __LINE__,
                            "hit %zu (%.17g, %.17g, lambda %.17g): S is %.3g off the line, "
                            "allowed %.3g", h, u, v, hits[3 * h + 2], r, allowed);
    }
    if (n == 2) {
        CHECK(hits[4] > -3.6127527 && hits[4] < -3.6127525); /* in the cluster */
        /* Of the sheet's ~20 crossings (its copies on the cluster's spans),
         * whose reported parameters put S 4e-10 to 1.7e-8 off the line, the
         * one kept is the nearest. */
        double f[9], r = 0.0;
        CHECK_OK(projcurve_surface_eval(NULL, s, hits[3], hits[4], 0, f));
        for (int c = 0; c < 3; ++c)
            r += (o[c] + hits[5] * d[c] - f[c]) * (o[c] + hits[5] * d[c] - f[c]);
        CHECK(sqrt(r) <= 1e-9);
    }
    projcurve_model_destroy(model);
}

int main(void)
{
    test_knot_cluster();
    test_all_real();
    return pc_test_finish("test_intersect_real");
}
