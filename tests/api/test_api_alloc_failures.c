/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Every allocation of every public entry point fails in turn (the library
 * built with PROJCURVE_ALLOC_HOOK: its allocations go through
 * src/common/alloc_hook.h, and pc_alloc_hook_fail below decides). For each
 * entry point exercised here (surface and curve creation, model reading,
 * directional, conical and orthogonal projection, result access (the
 * branches joined, the exact composition of the compact pcurve), IGES and
 * STEP writing) the
 * call is run once to count its allocations and note the first allocation
 * of each call site, then once per allocation with that one failing (every
 * call site at least once, and every k-th allocation when there are more
 * than PC_MAX_RUNS). Each run must
 *   - return PROJCURVE_ERR_NO_MEMORY with a message and the output pointer
 *     untouched, or OK with the reference output bit for bit (a fallback
 *     that costs only speed);
 *   - leave the caller's objects unchanged (their evaluations, a writer's
 *     file, a result's points);
 *   - not crash or leak: the AddressSanitizer job of .ci/run runs this
 *     test in a build with the hook, and LeakSanitizer checks at exit.
 * `test_api_alloc_failures K/N` makes only the failing runs of part K of N
 * (every N-th run of each entry point, from the K-th), so that CTest can
 * run the parts side by side; without an argument every run is made.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "projcurve.h"

/* Ends the program if a run does not return. */
#define HANG_GUARD_SECONDS 600
/* Runs per entry point beyond the first allocation of each call site. */
#define PC_MAX_RUNS 300
#define PC_MAX_SITES 512

/* ---- the hook ---- */

typedef struct site {
    const char *file;
    int line;
    long first; /* 1-based index of its first allocation in the counting run */
} site;

static int armed, counting;
static long n_allocs, fail_at;
static site sites[PC_MAX_SITES];
static size_t n_sites;

static void note_site(const char *file, int line)
{
    for (size_t i = 0; i < n_sites; ++i)
        if (sites[i].line == line && strcmp(sites[i].file, file) == 0)
            return;
    if (n_sites < PC_MAX_SITES)
        sites[n_sites++] = (site){file, line, n_allocs};
}

int pc_alloc_hook_fail(const char *file, int line);
int pc_alloc_hook_fail(const char *file, int line)
{
    if (!armed)
        return 0;
    ++n_allocs;
    if (counting)
        note_site(file, line);
    return n_allocs == fail_at;
}

/* ---- fingerprints of outputs and of the caller's objects ---- */

typedef unsigned long long hash;

static hash mix(hash h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ p[i]) * 1099511628211ull; /* FNV-1a */
    return h;
}

static hash surface_hash(projcurve_context *ctx, const projcurve_surface *s)
{
    double d[4], p[18];
    hash h = 1469598103934665603ull;
    if (s == NULL || projcurve_surface_domain(ctx, s, d) != PROJCURVE_OK)
        return 0;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j)
            if (projcurve_surface_eval(ctx, s, d[0] + (d[1] - d[0]) * i / 3.0,
                                       d[2] + (d[3] - d[2]) * j / 3.0, 2, p) == PROJCURVE_OK)
                h = mix(h, p, sizeof p);
    return h;
}

static hash curve_hash(projcurve_context *ctx, const projcurve_curve *c)
{
    double t0, t1, p[12];
    hash h = 1469598103934665603ull;
    if (c == NULL || projcurve_curve_domain(ctx, c, &t0, &t1) != PROJCURVE_OK)
        return 0;
    for (int i = 0; i <= 6; ++i)
        if (projcurve_curve_eval(ctx, c, t0 + (t1 - t0) * i / 6.0, 3, p) == PROJCURVE_OK)
            h = mix(h, p, sizeof p);
    return h;
}

/* Branch ends, points and pieces of a result (read with the hook off). */
static hash result_hash(projcurve_context *ctx, const projcurve_result *r)
{
    hash h = 1469598103934665603ull;
    const size_t n = projcurve_result_branch_count(r);
    h = mix(h, &n, sizeof n);
    for (size_t b = 0; b < n; ++b) {
        double t[2], pts[3 * 64];
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n_points = 0, n_pieces = 0, got = 0;
        projcurve_result_branch_info(ctx, r, b, t, &start, &end, &n_points, &n_pieces);
        h = mix(h, t, sizeof t);
        h = mix(h, &n_points, sizeof n_points);
        h = mix(h, &n_pieces, sizeof n_pieces);
        projcurve_result_branch_points(ctx, r, b, 64, pts, &got);
        h = mix(h, pts, 3 * (got < 64 ? got : 64) * sizeof(double));
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS];
            projcurve_result_piece(ctx, r, b, k, &degree, ctrl, NULL, NULL, NULL);
            h = mix(h, ctrl, 3 * (size_t)(degree + 1) * sizeof(double));
        }
    }
    return h;
}

static hash model_hash(projcurve_context *ctx, const projcurve_model *m)
{
    hash h = 1469598103934665603ull;
    const size_t ns = projcurve_model_surface_count(m), nc = projcurve_model_curve_count(m),
                 nk = projcurve_model_skipped_count(m);
    h = mix(h, &ns, sizeof ns);
    h = mix(h, &nc, sizeof nc);
    h = mix(h, &nk, sizeof nk);
    for (size_t i = 0; i < ns; ++i) {
        const hash s = surface_hash(ctx, projcurve_model_surface(m, i));
        h = mix(h, &s, sizeof s);
    }
    for (size_t i = 0; i < nc; ++i) {
        const hash c = curve_hash(ctx, projcurve_model_curve(m, i));
        h = mix(h, &c, sizeof c);
    }
    return h;
}

/* ---- the inputs ---- */

static projcurve_context *ctx;
static double net[3 * 64];
static const double net_knots[12] = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};
static const double curve_pts[] = {5, 10, 30, 30, 40, 30, 60, 60, 30, 95, 90, 30};
static const double curve_knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
static const double down[3] = {0.0, 0.0, -1.0};
/* above the middle of the net, the curve (z = 30) between it and the net */
static const double eye[3] = {50.0, 50.0, 200.0};
static projcurve_surface *surface;
/* the same net with weights: the exact composition's homogeneous poles */
static double net_weights[64];
static projcurve_surface *surface_rational;
static projcurve_result *result_rational;
static projcurve_curve *curve;
static projcurve_options *ortho_opts;
static projcurve_result *result;
static char *iges_text, *xml_text, *step_text;
static size_t iges_len, xml_len, step_len;
static char write_path[256];

static void make_net(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 21);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            net[3 * (j * 8 + i) + 0] = 100.0 * i / 7.0;
            net[3 * (j * 8 + i) + 1] = 100.0 * j / 7.0;
            net[3 * (j * 8 + i) + 2] = pc_test_rng_uniform(&rng, -8.0, 8.0);
            net_weights[j * 8 + i] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        }
}

static char *read_all(const char *relative, size_t *len)
{
    const char *path = pc_test_data_path(relative);
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        pc_test_missing_data(path);
    fseek(f, 0, SEEK_END);
    const long n = ftell(f);
    rewind(f);
    char *text = malloc((size_t)n + 1);
    if (text == NULL || fread(text, 1, (size_t)n, f) != (size_t)n)
        pc_test_missing_data(path);
    fclose(f);
    *len = (size_t)n;
    return text;
}

static hash file_hash(const char *path)
{
    FILE *f = fopen(path, "rb");
    hash h = 1469598103934665603ull;
    if (f == NULL)
        return 0;
    unsigned char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        h = mix(h, buf, n);
    fclose(f);
    return h;
}

/* ---- the entry points: each runs one call armed, returns its status and
 * the fingerprint of its output (0 when none) ---- */

typedef struct outcome {
    projcurve_status st;
    hash out;
    int out_untouched; /* on failure: the output pointer kept its value */
} outcome;

#define SENTINEL ((void *)&ctx)

static outcome call_surface_create(void)
{
    projcurve_surface *s = SENTINEL;
    armed = 1;
    const projcurve_status st =
        projcurve_surface_create_nurbs(ctx, 3, 3, 8, 8, net, NULL, net_knots, net_knots, &s);
    armed = 0;
    outcome o = {st, st == PROJCURVE_OK ? surface_hash(ctx, s) : 0, s == SENTINEL};
    if (st == PROJCURVE_OK)
        projcurve_surface_destroy(s);
    return o;
}

static outcome call_curve_create(void)
{
    projcurve_curve *c = SENTINEL;
    armed = 1;
    const projcurve_status st =
        projcurve_curve_create_nurbs(ctx, 3, 4, curve_pts, NULL, curve_knots, &c);
    armed = 0;
    outcome o = {st, st == PROJCURVE_OK ? curve_hash(ctx, c) : 0, c == SENTINEL};
    if (st == PROJCURVE_OK)
        projcurve_curve_destroy(c);
    return o;
}

static outcome read_model(const char *text, size_t len)
{
    projcurve_model *m = SENTINEL;
    armed = 1;
    const projcurve_status st = projcurve_model_read_memory(ctx, text, len, &m);
    armed = 0;
    outcome o = {st, st == PROJCURVE_OK ? model_hash(ctx, m) : 0, m == SENTINEL};
    if (st == PROJCURVE_OK)
        projcurve_model_destroy(m);
    return o;
}

static outcome call_read_iges(void) { return read_model(iges_text, iges_len); }
static outcome call_read_xml(void) { return read_model(xml_text, xml_len); }
static outcome call_read_step(void) { return read_model(step_text, step_len); }

/* Point queries: the closest points and the foot points of a point above
 * the sheet, and the hits of a line through it. */
static outcome call_point_queries(void)
{
    static const double p[3] = {40.0, 55.0, 20.0};
    double uv[2 * 64], q[3], dist = 0.0, t = 0.0, hits[3 * 64];
    unsigned flags[64];
    size_t n_feet = 0, n_hits = 0;
    outcome o = {PROJCURVE_OK, 0, 1};
    armed = 1;
    o.st = projcurve_surface_closest_point(ctx, surface, p, uv, q, &dist);
    if (o.st == PROJCURVE_OK)
        o.st = projcurve_curve_closest_point(ctx, curve, p, &t, q, &dist);
    if (o.st == PROJCURVE_OK)
        o.st = projcurve_surface_foot_points(ctx, surface, p, 64, uv, &n_feet);
    if (o.st == PROJCURVE_OK)
        o.st = projcurve_surface_intersect_line(ctx, surface, p, down, 0, 64, hits, flags,
                                                &n_hits);
    armed = 0;
    if (o.st == PROJCURVE_OK) {
        o.out = mix(1469598103934665603ull, uv, 2 * (n_feet < 64 ? n_feet : 64) * sizeof(double));
        o.out = mix(o.out, hits, 3 * (n_hits < 64 ? n_hits : 64) * sizeof(double));
        o.out = mix(o.out, &dist, sizeof dist);
    }
    return o;
}

typedef enum { PROJECT_DIRECTIONAL, PROJECT_ORTHOGONAL, PROJECT_CONICAL } project_kind;

static outcome project(project_kind kind)
{
    projcurve_result *r = SENTINEL;
    armed = 1;
    projcurve_status st;
    if (kind == PROJECT_ORTHOGONAL)
        st = projcurve_project_orthogonal(ctx, surface, curve, ortho_opts, &r);
    else if (kind == PROJECT_CONICAL)
        st = projcurve_project_conical(ctx, surface, curve, eye, NULL, &r);
    else
        st = projcurve_project_directional(ctx, surface, curve, down, NULL, &r);
    armed = 0;
    outcome o = {st, st == PROJCURVE_OK ? result_hash(ctx, r) : 0, r == SENTINEL};
    if (st == PROJCURVE_OK)
        projcurve_result_destroy(r);
    return o;
}

static outcome call_directional(void) { return project(PROJECT_DIRECTIONAL); }
static outcome call_conical(void) { return project(PROJECT_CONICAL); }

/* onto a face: the whole domain with a square hole in its middle */
static projcurve_face *face;
/* the curve projected onto it, for the writers' add_shape_result */
static projcurve_shape_result *face_result;

static projcurve_options *nearest_opts;

/* kind DIRECTIONAL along down, or (conical) from an eye high above the
 * face with the nearest hits chosen across its branches */
static outcome project_face(int conical)
{
    static const double high_eye[3] = {50.0, 50.0, 400.0};
    projcurve_shape_result *r = SENTINEL;
    armed = 1;
    const projcurve_status st =
        conical ? projcurve_project_face(ctx, face, curve, PROJCURVE_PROJECT_CONICAL, high_eye,
                                         nearest_opts, &r)
                : projcurve_project_face(ctx, face, curve, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                         NULL, &r);
    armed = 0;
    outcome o = {st, 0, r == SENTINEL};
    if (st == PROJCURVE_OK) {
        o.out = 1469598103934665603ull;
        for (size_t i = 0; i < projcurve_shape_result_face_count(r); ++i) {
            const projcurve_result *fr = NULL;
            projcurve_shape_result_face(ctx, r, i, NULL, &fr, NULL, NULL);
            const hash h = fr ? result_hash(ctx, fr) : 0;
            o.out = mix(o.out, &h, sizeof h);
        }
        const size_t n = projcurve_shape_result_curve_count(r);
        o.out = mix(o.out, &n, sizeof n);
        projcurve_shape_result_destroy(r);
    }
    return o;
}

static outcome call_project_face(void) { return project_face(0); }
static outcome call_project_face_nearest(void) { return project_face(1); }
static outcome call_orthogonal(void) { return project(PROJECT_ORTHOGONAL); }

/* Result access that allocates: every branch as one curve. */
static outcome call_branch_curves(void)
{
    outcome o = {PROJCURVE_OK, 1469598103934665603ull, 1};
    for (size_t b = 0; b < projcurve_result_branch_count(result) && o.st == PROJCURVE_OK; ++b) {
        projcurve_curve *c = SENTINEL;
        armed = 1;
        o.st = projcurve_result_branch_curve(ctx, result, b, &c);
        armed = 0;
        if (o.st == PROJCURVE_OK) {
            const hash h = curve_hash(ctx, c);
            o.out = mix(o.out, &h, sizeof h);
            projcurve_curve_destroy(c);
        } else {
            o.out = 0;
            o.out_untouched = c == SENTINEL;
        }
    }
    return o;
}

/* The exact composition of every branch's compact pcurve with S (its
 * cuts at the knot lines of the 5 x 5 patches, its parts, its poles, the
 * reduction of its joins; for a rational S its homogeneous poles). */
static outcome compact_exact_of(const projcurve_result *r, const projcurve_surface *s)
{
    outcome o = {PROJCURVE_OK, 1469598103934665603ull, 1};
    for (size_t b = 0; b < projcurve_result_branch_count(r) && o.st == PROJCURVE_OK; ++b) {
        projcurve_curve *c = SENTINEL;
        armed = 1;
        o.st = projcurve_result_branch_compact_exact(ctx, r, s, b, &c);
        armed = 0;
        if (o.st == PROJCURVE_OK) {
            const hash h = curve_hash(ctx, c);
            o.out = mix(o.out, &h, sizeof h);
            projcurve_curve_destroy(c);
        } else {
            o.out = 0;
            o.out_untouched = c == SENTINEL;
        }
    }
    return o;
}

static outcome call_compact_exact(void) { return compact_exact_of(result, surface); }

static outcome call_compact_exact_rational(void)
{
    return compact_exact_of(result_rational, surface_rational);
}

/* A writer filled step by step; a failed step must leave the writer as it
 * was (what it writes afterwards, with the hook off, is unchanged). */
static outcome call_iges_write(void)
{
    projcurve_iges_writer *w = SENTINEL;
    outcome o = {PROJCURVE_OK, 0, 1};
    armed = 1;
    o.st = projcurve_iges_writer_create(ctx, &w);
    armed = 0;
    if (o.st != PROJCURVE_OK) {
        o.out_untouched = w == SENTINEL;
        return o;
    }
    for (int step = 0; step < 5 && o.st == PROJCURVE_OK; ++step) {
        const int saved = projcurve_iges_writer_write(ctx, w, write_path) == PROJCURVE_OK;
        const hash before = saved ? file_hash(write_path) : 0;
        armed = 1;
        o.st = step == 0   ? projcurve_iges_writer_add_surface(ctx, w, surface)
               : step == 1 ? projcurve_iges_writer_add_curve(ctx, w, curve)
               : step == 2 ? projcurve_iges_writer_add_result(ctx, w, surface, result)
               : step == 3 ? projcurve_iges_writer_add_shape_result(ctx, w, face_result)
                           : projcurve_iges_writer_write(ctx, w, write_path);
        armed = 0;
        if (o.st != PROJCURVE_OK && step < 4) {
            CHECK(projcurve_iges_writer_write(ctx, w, write_path) == PROJCURVE_OK);
            if (file_hash(write_path) != before)
                pc_test_fail_at(__FILE__, __LINE__, "a failed step %d changed the writer", step);
        }
    }
    if (o.st == PROJCURVE_OK)
        o.out = file_hash(write_path);
    projcurve_iges_writer_destroy(w);
    return o;
}

/* The same for the STEP writer. */
static outcome call_step_write(void)
{
    projcurve_step_writer *w = SENTINEL;
    outcome o = {PROJCURVE_OK, 0, 1};
    armed = 1;
    o.st = projcurve_step_writer_create(ctx, &w);
    armed = 0;
    if (o.st != PROJCURVE_OK) {
        o.out_untouched = w == SENTINEL;
        return o;
    }
    for (int step = 0; step < 5 && o.st == PROJCURVE_OK; ++step) {
        const int saved = projcurve_step_writer_write(ctx, w, write_path) == PROJCURVE_OK;
        const hash before = saved ? file_hash(write_path) : 0;
        armed = 1;
        o.st = step == 0   ? projcurve_step_writer_add_surface(ctx, w, surface)
               : step == 1 ? projcurve_step_writer_add_curve(ctx, w, curve)
               : step == 2 ? projcurve_step_writer_add_result(ctx, w, surface, result)
               : step == 3 ? projcurve_step_writer_add_shape_result(ctx, w, face_result)
                           : projcurve_step_writer_write(ctx, w, write_path);
        armed = 0;
        if (o.st != PROJCURVE_OK && step < 4) {
            CHECK(projcurve_step_writer_write(ctx, w, write_path) == PROJCURVE_OK);
            if (file_hash(write_path) != before)
                pc_test_fail_at(__FILE__, __LINE__, "a failed step %d changed the writer", step);
        }
    }
    if (o.st == PROJCURVE_OK)
        o.out = file_hash(write_path);
    projcurve_step_writer_destroy(w);
    return o;
}

/* ---- the driver ---- */

typedef struct entry {
    const char *name;
    outcome (*call)(void);
} entry;

/* The parts the failing runs are dealt into (tests/CMakeLists.txt
 * registers one test per part); part < 0 makes them all. */
#define PARTS 3
static int part = -1;

/* The caller's objects, which no call may change. */
static hash inputs_hash(void)
{
    hash h[3] = {surface_hash(ctx, surface), curve_hash(ctx, curve), result_hash(ctx, result)};
    return mix(1469598103934665603ull, h, sizeof h);
}

static void check_entry(const entry *e)
{
    const hash inputs = inputs_hash();
    n_allocs = 0;
    n_sites = 0;
    fail_at = 0;
    counting = 1;
    const outcome ref = e->call();
    counting = 0;
    const long total = n_allocs;
    const size_t n_entry_sites = n_sites;
    CHECK_OK(ref.st);
    if (ref.st != PROJCURVE_OK)
        return;
    const long stride = total > PC_MAX_RUNS ? (total + PC_MAX_RUNS - 1) / PC_MAX_RUNS : 1;
    long runs = 0, no_memory = 0, same = 0, n_chosen = 0;
    for (long k = 1; k <= total; ++k) {
        int chosen = (k - 1) % stride == 0;
        for (size_t i = 0; i < n_entry_sites && !chosen; ++i)
            chosen = sites[i].first == k;
        if (!chosen)
            continue;
        if (part >= 0 && n_chosen++ % PARTS != part)
            continue;
        ++runs;
        projcurve_context_clear(ctx);
        n_allocs = 0;
        fail_at = k;
        const outcome got = e->call();
        fail_at = 0;
        if (got.st == PROJCURVE_OK) {
            if (got.out != ref.out)
                pc_test_fail_at(__FILE__, __LINE__,
                                "%s: allocation %ld of %ld failed, the call returned OK with "
                                "another output",
                                e->name, k, total);
            ++same;
        } else {
            ++no_memory;
            if (got.st != PROJCURVE_ERR_NO_MEMORY || !got.out_untouched ||
                projcurve_context_message(ctx)[0] == '\0')
                pc_test_fail_at(__FILE__, __LINE__,
                                "%s: allocation %ld of %ld failed: %s (\"%s\"), output %s",
                                e->name, k, total, projcurve_status_string(got.st),
                                projcurve_context_message(ctx),
                                got.out_untouched ? "untouched" : "changed");
        }
        if (inputs_hash() != inputs)
            pc_test_fail_at(__FILE__, __LINE__, "%s: allocation %ld changed the inputs", e->name,
                            k);
    }
    printf("%-22s %5ld allocations at %3zu sites: %4ld runs, %4ld NO_MEMORY, %4ld OK and "
           "identical\n",
           e->name, total, n_entry_sites, runs, no_memory, same);
}

/* Reads "K/N" into *k_out; N must be PARTS. Returns 0 when it cannot. */
static int parse_part(const char *arg, int *k_out)
{
    int k = -1, n = 0;
    char tail = 0;
    if (sscanf(arg, "%d/%d%c", &k, &n, &tail) != 2 || n != PARTS || k < 0 || k >= n)
        return 0;
    *k_out = k;
    return 1;
}

int main(int argc, char **argv)
{
    if (argc > 2 || (argc == 2 && !parse_part(argv[1], &part))) {
        fprintf(stderr, "usage: test_api_alloc_failures [K/%d]\n", PARTS);
        return 2;
    }
    pc_test_hang_guard(HANG_GUARD_SECONDS);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    make_net();
    snprintf(write_path, sizeof write_path, "test_api_alloc_failures.%ld.igs", (long)getpid());
    iges_text = read_all("cases/bumpy_bicubic_8x8_down.igs", &iges_len);
    xml_text = read_all("real/horn.xml", &xml_len);
    step_text = read_all("real/test-joinsurf_01.stp", &step_len);
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 3, 3, 8, 8, net, NULL, net_knots, net_knots,
                                            &surface));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 3, 4, curve_pts, NULL, curve_knots, &curve));
    CHECK_OK(projcurve_options_create(ctx, &ortho_opts));
    CHECK_OK(projcurve_options_create(ctx, &nearest_opts));
    CHECK_OK(projcurve_options_set_int(ctx, nearest_opts, PROJCURVE_OPT_HITS,
                                       PROJCURVE_HITS_NEAREST));
    CHECK_OK(projcurve_project_directional(ctx, surface, curve, down, NULL, &result));
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 3, 3, 8, 8, net, net_weights, net_knots,
                                            net_knots, &surface_rational));
    CHECK_OK(projcurve_project_directional(ctx, surface_rational, curve, down, NULL,
                                           &result_rational));
    if (surface == NULL || curve == NULL || result == NULL || ortho_opts == NULL ||
        nearest_opts == NULL || result_rational == NULL)
        return pc_test_finish("test_api_alloc_failures");
    CHECK(projcurve_result_branch_count(result) > 0);
    {
        static const double outer[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
        static const double hole[] = {0.4, 0.4, 0.4, 0.6, 0.6, 0.6, 0.6, 0.4, 0.4, 0.4};
        static const double knots[] = {0, 0, 1, 2, 3, 4, 4};
        const size_t loop_pieces[] = {1, 1}, n_ctrl[] = {5, 5};
        const int degrees[] = {1, 1};
        const double *ctrl[] = {outer, hole}, *weights[] = {NULL, NULL};
        const double *kn[] = {knots, knots};
        CHECK_OK(projcurve_face_create(ctx, surface, 2, loop_pieces, degrees, n_ctrl, ctrl,
                                       weights, kn, 0.0, &face));
    }
    CHECK_OK(projcurve_project_face(ctx, face, curve, PROJCURVE_PROJECT_DIRECTIONAL, down, NULL,
                                    &face_result));
    CHECK(projcurve_shape_result_curve_count(face_result) > 0);
    static const entry entries[] = {
        {"project_face", call_project_face},
        {"project_face (conical, nearest)", call_project_face_nearest},
        {"surface_create_nurbs", call_surface_create},
        {"curve_create_nurbs", call_curve_create},
        {"model_read (IGES)", call_read_iges},
        {"model_read (XML)", call_read_xml},
        {"model_read (STEP)", call_read_step},
        {"closest/foot/line", call_point_queries},
        {"project_directional", call_directional},
        {"project_orthogonal", call_orthogonal},
        {"project_conical", call_conical},
        {"result_branch_curve", call_branch_curves},
        {"result_branch_compact_exact", call_compact_exact},
        {"result_branch_compact_exact (rational)", call_compact_exact_rational},
        {"iges_writer", call_iges_write},
        {"step_writer", call_step_write},
    };
    for (size_t i = 0; i < sizeof entries / sizeof entries[0]; ++i)
        check_entry(&entries[i]);
    remove(write_path);
    projcurve_result_destroy(result);
    projcurve_result_destroy(result_rational);
    projcurve_surface_destroy(surface_rational);
    projcurve_shape_result_destroy(face_result);
    projcurve_face_destroy(face);
    projcurve_options_destroy(ortho_opts);
    projcurve_options_destroy(nearest_opts);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surface);
    projcurve_context_destroy(ctx);
    free(iges_text);
    free(xml_text);
    free(step_text);
    return pc_test_finish("test_api_alloc_failures");
}
