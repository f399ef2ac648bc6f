/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The real-data acceptance sweep: every (curve, surface) pair of the 13
 * real models in tests/data/real that lie near each other (and, to
 * calibrate the verifier, of the synthetic cases of tests/data/cases), and curves
 * synthesised over every surface, projected directionally and
 * orthogonally through the public API with default options, each call in
 * a forked child bounded in CPU time and memory (support/bounded_call.h),
 * each result judged by an independent verifier (support/sweep_verify.h).
 *
 * Cases
 *  - real pairs: curve c and surface s of the same file whose boxes (the
 *    curve's control polygon's, the surface's control net's) are within
 *    NEAR_REL of the model size of each other: a curve there is an edge of
 *    s or of a face next to it, or crosses a small gap, which is what a
 *    user pulls onto a face; farther pairs run the same code from farther
 *    seeds, and the lifted curves below exercise every surface anyway.
 *    Directional along the file's "down" (0, 0, -1), and orthogonal.
 *  - per surface, with N its average unit normal (the centre's normal
 *    where the average cancels, on closed surfaces) and h = LIFT_REL of its
 *    size: a lifted diagonal (a cubic B-spline whose control points are the
 *    image of the domain's diagonal moved by h N), projected along -N and
 *    orthogonally; a curve lying on S (a callback: S composed with the
 *    domain's anti-diagonal, exactly), along -N and orthogonally; and the
 *    lifted diagonal along a grazing direction (GRAZE_DEG below the tangent
 *    plane at the centre), directional only.
 *
 * A call fails when it is killed (hang: over HANG_CPU of CPU or WALL_KILL
 * of wall time), takes over TIME_LIMIT CPU seconds, grows the process by
 * over MEMORY_LIMIT_MIB (or returns NO_MEMORY), returns anything but OK,
 * crashes, or its result fails the verifier: a wrong point, a missed hit or
 * foot, a branch with no pieces, a FAILED branch end the result does not
 * report. Times are CPU times of the child (the machine may be shared);
 * the hang guard is CPU time too, with a wall-clock backstop. Under ASan
 * no address-space limit is set and the memory limit is four times higher
 * (shadow memory and the quarantine of freed blocks count as resident).
 *
 * Open cases: tests/realdata/realdata_open.tsv lists the cases that still fail, each
 * with the classes it may fail in (support/open_cases.h); they are printed
 * and counted but do not fail the test, and one that passes is named so the
 * list can shrink. Every other failure fails the test.
 *
 * Environment: PC_REALDATA_STRIDE=k runs every k-th case only (a
 * stratified subset: cases are enumerated file by file, kind by kind);
 * PC_REALDATA_SLOW=f multiplies the time limits (the sanitizer build sets
 * both, tests/CMakeLists.txt); PC_REALDATA_JOBS=n runs n children at once
 * (default 2); PC_REALDATA_FILE=name runs one file only (its name without
 * the folder, e.g. horn.xml); PC_REALDATA_CASE=k only case #k of the list
 * (as the failure lines number them; with the same FILE and STRIDE);
 * PC_REALDATA_LIST=1 prints the cases without running them;
 * PC_REALDATA_OPEN_LIST=path reads the open cases from path instead of
 * tests/realdata/realdata_open.tsv (/dev/null prints every failure in full);
 * PC_REALDATA_MODEL=path sweeps that model instead of the real files (to
 * check the verifier on the synthetic cases, or a fix on a new model).
 */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bounded_call.h"
#include "check.h"
#include "open_cases.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define PI 3.14159265358979323846

#define NEAR_REL 0.10
#define LIFT_REL 0.03
#define GRAZE_DEG 3.0
#define TIME_LIMIT 1.0
#define HANG_CPU 2.0
/* The wall-clock backstop covers the call and its verification (the
 * verifier takes up to ~9 s of CPU on the folded linkrods surfaces): wide
 * enough that a loaded machine does not turn a slow verification into a
 * failure; the CPU guards above and below are what judge. */
#define WALL_KILL 90.0
#define VERIFY_CPU 40.0
#define MEMORY_LIMIT_MIB 256
/* The child may grow past the limit by this much before the address-space
 * limit stops it, so a call just over the limit is measured, not crashed. */
#define MEMORY_HEADROOM_MIB 128
#define MAX_JOBS 4
#define DIAGONAL_POLES 12
#define COMPLETENESS_T 32
#define MAX_PIECE_SAMPLES 40000
#define MAX_PRINTED 20000

/* The synthetic cases first: there the library is known to be exact (its
 * own tests check them to ~1e-10), so they calibrate the verifier (a
 * failure there is a verifier bug or a regression); then the real models. */
static const char *const k_files[] = {
    "cases/song_yong_example1.igs", "cases/song_yong_example1_paperdir.igs",
    "cases/bumpy_bicubic_8x8_down.igs", "cases/bumpy_boundary_exit_reenter.igs",
    "cases/deg5_quintic_9x8_down.igs", "cases/fold_c_sheet_jump.igs",
    "cases/nurbs_half_cylinder_down.igs", "cases/ortho_bumpy_bicubic_hover.igs",
    "cases/ortho_nurbs_half_cylinder.igs",
    "real/sunglasses_lens.igs", "real/bladex_upper.iges", "real/hammer.iges",
    "real/bearing.iges", "real/linkrods.step", "real/test-joinsurf_01.stp",
    "real/test-joinsurf_04.stp", "real/test_pipe_out_true.step", "real/car_shell1.xml",
    "real/horn.xml", "real/shroud_kaplan.xml", "real/egg.xml", "real/teapot_newell_spd.txt",
};
#define N_FILES (sizeof k_files / sizeof k_files[0])

typedef enum curve_kind { REAL, LIFTED, ON_SURFACE, GRAZING } curve_kind;
static const char *const k_kind_names[] = {"curve", "lifted", "on-surface", "grazing"};

typedef enum fail_class {
    F_HANG, F_TIME, F_MEMORY, F_CRASH, F_STATUS, F_WRONG, F_MISSED, F_ZERO, F_FAILED_END,
    F_VERIFY, N_CLASSES
} fail_class;
static const char *const k_class_names[] = {
    "hang", "time", "memory", "crash", "status", "wrong-point", "missed-hit",
    "zero-piece-branch", "unreported-failed-end", "verifier-timeout"};

/* A curve on S: S(a + t b) for t in [0, 1] (callback). */
typedef struct on_surface_curve {
    const projcurve_surface *s;
    double a[2], b[2];
} on_surface_curve;

typedef struct job {
    size_t index;                /* in the enumeration (PC_REALDATA_CASE) */
    size_t file, surface, curve; /* curve: index in the model (REAL) */
    curve_kind kind;
    int orthogonal;
    double dir[3];
} job;

/* What the child sends: the call, then the verdict. */
typedef struct call_record {
    int status;
    double cpu;
    long rss_growth_kib;
    size_t branches, pieces;
    double eps_d;
} call_record;

typedef struct verdict {
    pc_sweep_report rep;
    long reported_failures; /* FAILED ends the result itself reports */
} verdict;

typedef struct reply {
    call_record call;
    verdict verify;
} reply;

typedef struct surface_data {
    pc_oracle_mesh mesh;
    int have_mesh;
    double size, normal[3], graze[3];
    projcurve_curve *lifted, *on_surface;
    on_surface_curve on_surface_user;
} surface_data;

/* The file being swept, as the children see it (a snapshot at the fork). */
typedef struct sweep_file {
    projcurve_model *model;
    surface_data *surfaces;
    size_t n_surfaces;
} sweep_file;

typedef struct outcome_row {
    job j;
    double cpu;
    long rss_kib;
    unsigned classes;
} outcome_row;

typedef struct sweep {
    double slow;
    long stride, jobs;
    const char *only_file;
    const char *model_path; /* PC_REALDATA_MODEL, or NULL */
    long only_case;         /* PC_REALDATA_CASE, or -1 */
    int list_only;          /* PC_REALDATA_LIST: print the cases, run none */
    sweep_file file;
    const job *current;
    size_t cases, run, failed;
    pc_open_cases open;    /* tests/realdata/realdata_open.tsv */
    size_t open_failing;   /* listed cases that failed as listed */
    size_t per_class[N_CLASSES];
    outcome_row slowest[10];
    size_t n_slowest;
    long max_rss_kib;  /* largest growth of a call */
    long max_peak_kib; /* largest peak resident set of a child (wait4) */
    size_t printed;
    size_t file_run[N_FILES], file_failed[N_FILES];
} sweep;

static int on_surface_fn(void *user, double t, double out[9])
{
    const on_surface_curve *c = user;
    const double u = c->a[0] + t * c->b[0], v = c->a[1] + t * c->b[1];
    double f[18];
    if (projcurve_surface_eval(NULL, c->s, u, v, 2, f) != PROJCURVE_OK)
        return 1;
    const double du = c->b[0], dv = c->b[1];
    for (int k = 0; k < 3; ++k) {
        out[k] = f[k];
        out[3 + k] = f[3 + k] * du + f[6 + k] * dv;
        out[6 + k] = f[9 + k] * du * du + 2.0 * f[12 + k] * du * dv + f[15 + k] * dv * dv;
    }
    return 0;
}

static double norm3(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static int unit_normal(const projcurve_surface *s, double u, double v, double n[3])
{
    double f[9];
    if (projcurve_surface_eval(NULL, s, u, v, 1, f) != PROJCURVE_OK)
        return 0;
    n[0] = f[4] * f[8] - f[5] * f[7];
    n[1] = f[5] * f[6] - f[3] * f[8];
    n[2] = f[3] * f[7] - f[4] * f[6];
    const double l = norm3(n);
    if (!(l > 0.0))
        return 0;
    for (int c = 0; c < 3; ++c)
        n[c] /= l;
    return 1;
}

/* The average unit normal over a 5 x 5 grid of the domain, or the centre's
 * where the normals cancel (closed surfaces), or +z at a collapsed centre. */
static void average_normal(const projcurve_surface *s, const double dom[4], double out[3])
{
    const double du = dom[1] - dom[0], dv = dom[3] - dom[2];
    double sum[3] = {0, 0, 0}, n[3];
    int count = 0;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            if (unit_normal(s, dom[0] + du * (0.1 + 0.2 * i), dom[2] + dv * (0.1 + 0.2 * j), n)) {
                for (int c = 0; c < 3; ++c)
                    sum[c] += n[c];
                ++count;
            }
    if (norm3(sum) > 0.2 * count) {
        for (int c = 0; c < 3; ++c)
            out[c] = sum[c] / norm3(sum);
    } else if (!unit_normal(s, dom[0] + 0.5 * du, dom[2] + 0.5 * dv, out)) {
        out[0] = out[1] = 0.0, out[2] = 1.0;
    }
}

/* A cubic B-spline whose control points are the image of the domain's
 * diagonal (2 % to 98 %) moved by h along n. */
static projcurve_curve *lifted_diagonal(const projcurve_surface *s, const double dom[4],
                                        const double n[3], double h)
{
    double poles[3 * DIAGONAL_POLES], knots[DIAGONAL_POLES + 4];
    for (int k = 0; k < DIAGONAL_POLES; ++k) {
        const double a = 0.02 + 0.96 * k / (DIAGONAL_POLES - 1);
        double p[3] = {0, 0, 0};
        projcurve_surface_eval(NULL, s, dom[0] + a * (dom[1] - dom[0]),
                               dom[2] + a * (dom[3] - dom[2]), 0, p);
        for (int c = 0; c < 3; ++c)
            poles[3 * k + c] = p[c] + h * n[c];
    }
    for (int k = 0; k < DIAGONAL_POLES + 4; ++k) {
        const int inner = k - 3;
        knots[k] = inner <= 0 ? 0.0
                   : inner >= DIAGONAL_POLES - 3 ? 1.0
                                                  : (double)inner / (DIAGONAL_POLES - 3);
    }
    projcurve_curve *c = NULL;
    projcurve_curve_create_nurbs(NULL, 3, DIAGONAL_POLES, poles, NULL, knots, &c);
    return c;
}

/* A tangent direction at the domain's centre (along Sv, else Su, made
 * normal to n), tipped GRAZE_DEG towards the surface. */
static void grazing_direction(const projcurve_surface *s, const double dom[4], const double n[3],
                              double out[3])
{
    double f[9] = {0};
    projcurve_surface_eval(NULL, s, 0.5 * (dom[0] + dom[1]), 0.5 * (dom[2] + dom[3]), 1, f);
    const double *axis = norm3(f + 6) > 0.0 ? f + 6 : f + 3;
    const double along = axis[0] * n[0] + axis[1] * n[1] + axis[2] * n[2];
    double t[3];
    for (int c = 0; c < 3; ++c)
        t[c] = axis[c] - along * n[c];
    const double tl = norm3(t);
    if (tl > 0.0)
        t[0] /= tl, t[1] /= tl, t[2] /= tl;
    else
        t[0] = 1.0, t[1] = t[2] = 0.0;
    const double g = GRAZE_DEG * PI / 180.0;
    for (int c = 0; c < 3; ++c)
        out[c] = cos(g) * t[c] - sin(g) * n[c];
}

/* The frame, the synthesised curves and the oracle mesh of surface s. */
static void prepare_surface(const projcurve_surface *s, surface_data *sd)
{
    memset(sd, 0, sizeof *sd);
    double dom[4], box[6];
    size_t spans_u = 1, spans_v = 1;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &spans_u, &spans_v, NULL);
    const double ext[3] = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
    sd->size = norm3(ext);
    sd->have_mesh = pc_oracle_mesh_build(&sd->mesh, pc_sweep_surface_eval, (void *)s, dom,
                                         pc_sweep_mesh_cells(spans_u), pc_sweep_mesh_cells(spans_v));
    average_normal(s, dom, sd->normal);
    sd->lifted = lifted_diagonal(s, dom, sd->normal, LIFT_REL * sd->size);
    /* The curve on S: the anti-diagonal (5% to 95% in u, 90% to 15% in v). */
    on_surface_curve *oc = &sd->on_surface_user;
    const double du = dom[1] - dom[0], dv = dom[3] - dom[2];
    oc->s = s;
    oc->a[0] = dom[0] + 0.05 * du, oc->a[1] = dom[2] + 0.9 * dv;
    oc->b[0] = 0.9 * du, oc->b[1] = -0.75 * dv;
    projcurve_curve_create_callback(NULL, on_surface_fn, oc, 0.0, 1.0, &sd->on_surface);
    grazing_direction(s, dom, sd->normal, sd->graze);
}

static void release_surface(surface_data *sd)
{
    if (sd->have_mesh)
        pc_oracle_mesh_free(&sd->mesh);
    projcurve_curve_destroy(sd->lifted);
    projcurve_curve_destroy(sd->on_surface);
}

/* A box of curve c: its control polygon's (which holds it), else samples. */
static void curve_box(const projcurve_curve *c, double box[6])
{
    size_t n = 0;
    for (int k = 0; k < 3; ++k)
        box[k] = HUGE_VAL, box[k + 3] = -HUGE_VAL;
    if (projcurve_curve_nurbs_info(NULL, c, NULL, &n, NULL, NULL) == PROJCURVE_OK && n > 0) {
        double *ctrl = malloc(sizeof *ctrl * 3 * n);
        if (ctrl && projcurve_curve_nurbs_data(NULL, c, ctrl, NULL, NULL) == PROJCURVE_OK) {
            for (size_t i = 0; i < n; ++i)
                for (int k = 0; k < 3; ++k) {
                    box[k] = fmin(box[k], ctrl[3 * i + k]);
                    box[k + 3] = fmax(box[k + 3], ctrl[3 * i + k]);
                }
            free(ctrl);
            return;
        }
        free(ctrl);
    }
    double t0 = 0, t1 = 1;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    for (int i = 0; i <= 64; ++i) {
        double p[3];
        if (projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * i / 64, 0, p) != PROJCURVE_OK)
            continue;
        for (int k = 0; k < 3; ++k)
            box[k] = fmin(box[k], p[k]), box[k + 3] = fmax(box[k + 3], p[k]);
    }
}

static double box_gap(const double a[6], const double b[6])
{
    double g[3];
    for (int k = 0; k < 3; ++k)
        g[k] = fmax(0.0, fmax(a[k] - b[k + 3], b[k] - a[k + 3]));
    return norm3(g);
}

/* The call and its verification, in the child. */
static void child_run(void *user, int fd)
{
    const sweep *sw = user;
    const job *j = sw->current;
    const surface_data *sd = &sw->file.surfaces[j->surface];
    const projcurve_surface *s = projcurve_model_surface(sw->file.model, j->surface);
    const projcurve_curve *c = j->kind == REAL ? projcurve_model_curve(sw->file.model, j->curve)
                               : j->kind == ON_SURFACE ? sd->on_surface
                                                       : sd->lifted;
    reply rp;
    memset(&rp, 0, sizeof rp);
    pc_bounded_cpu_guard(HANG_CPU * sw->slow);
    const long rss0 = pc_bounded_rss_kib();
    const double cpu0 = pc_bounded_cpu_now();
    projcurve_result *r = NULL;
    rp.call.status = j->orthogonal ? projcurve_project_orthogonal(NULL, s, c, NULL, &r)
                                   : projcurve_project_directional(NULL, s, c, j->dir, NULL, &r);
    rp.call.cpu = pc_bounded_cpu_now() - cpu0;
    pc_bounded_cpu_guard(0.0);
    rp.call.rss_growth_kib = pc_bounded_peak_rss_kib() - rss0;
    rp.call.branches = projcurve_result_branch_count(r);
    double pieces = 0.0;
    if (r && projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &pieces) == PROJCURVE_OK)
        rp.call.pieces = (size_t)pieces;
    rp.call.eps_d = NAN;
    if (r)
        projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &rp.call.eps_d);
    pc_bounded_send(fd, &rp.call, sizeof rp.call);
    if (rp.call.status != PROJCURVE_OK || r == NULL || !sd->have_mesh) {
        projcurve_result_destroy(r);
        return;
    }
    pc_bounded_cpu_guard(VERIFY_CPU * sw->slow);
    const pc_sweep_input in = {s, c, j->orthogonal, {j->dir[0], j->dir[1], j->dir[2]},
                                &sd->mesh, rp.call.eps_d, sd->size, 2.0 * rp.call.eps_d,
                                COMPLETENESS_T, MAX_PIECE_SAMPLES};
    pc_sweep_verify(&in, r, &rp.verify.rep);
    rp.verify.reported_failures = (long)projcurve_result_failure_count(r);
    projcurve_result_destroy(r);
    pc_bounded_send(fd, &rp.verify, sizeof rp.verify);
}

static const char *file_name(const sweep *sw, size_t f)
{
    return sw->model_path ? sw->model_path : k_files[f];
}

static void describe(const sweep *sw, const job *j, char *out, size_t size)
{
    char curve[64];
    const int at = snprintf(curve, sizeof curve, "#%zu ", j->index);
    if (j->kind == REAL)
        snprintf(curve + at, sizeof curve - (size_t)at, "curve %zu", j->curve);
    else
        snprintf(curve + at, sizeof curve - (size_t)at, "%s", k_kind_names[j->kind]);
    if (j->orthogonal)
        snprintf(out, size, "%s surface %zu %s orthogonal", file_name(sw, j->file), j->surface, curve);
    else
        snprintf(out, size, "%s surface %zu %s dir (%.4g, %.4g, %.4g)", file_name(sw, j->file),
                 j->surface, curve, j->dir[0], j->dir[1], j->dir[2]);
}

/* The case's key in the open list: its description without the "#index "
 * (indices move when cases are added; file, surface, curve and direction
 * do not). */
static void case_key(const sweep *sw, const job *j, char *out, size_t size)
{
    describe(sw, j, out, size);
    char *hash = strchr(out, '#');
    if (hash == NULL)
        return;
    const char *rest = strchr(hash, ' ');
    memmove(hash, rest ? rest + 1 : hash + strlen(hash), strlen(rest ? rest + 1 : "") + 1);
}

/* 1 when the failure is an open case failing only as listed. */
static int is_open(sweep *sw, const job *j, unsigned classes)
{
    char key[160];
    case_key(sw, j, key, sizeof key);
    pc_open_case *c = pc_open_cases_find(&sw->open, key);
    if (c == NULL)
        return 0;
    c->seen = 1;
    c->passed = classes == 0;
    for (int k = 0; k < N_CLASSES; ++k)
        if ((classes & (1u << k)) && !pc_open_case_allows(c, k_class_names[k]))
            return 0;
    return 1;
}

static void keep_slowest(sweep *sw, const outcome_row *row)
{
    size_t at = sw->n_slowest;
    if (at == 10) {
        if (sw->slowest[9].cpu >= row->cpu)
            return;
        at = 9;
    } else {
        ++sw->n_slowest;
    }
    sw->slowest[at] = *row;
    while (at > 0 && sw->slowest[at - 1].cpu < sw->slowest[at].cpu) {
        const outcome_row t = sw->slowest[at - 1];
        sw->slowest[at - 1] = sw->slowest[at];
        sw->slowest[at] = t;
        --at;
    }
}

/* The memory limit of a call. Under ASan, whose shadow memory and 256 MiB
 * quarantine of freed blocks count in the resident set, four times it. */
static long memory_limit_kib(void)
{
    return MEMORY_LIMIT_MIB * 1024L * (pc_bounded_limits_memory() ? 1 : 4);
}

/* Classifies one ended child. */
static void collect(sweep *sw, const job *j, const reply *rp, const pc_bounded_outcome *o)
{
    outcome_row row = {*j, NAN, 0, 0};
    const int have_call = o->received >= sizeof rp->call;
    const int have_verify = o->received >= sizeof rp->call + sizeof rp->verify;
    const long growth = have_call ? rp->call.rss_growth_kib : o->max_rss_kib;
    row.rss_kib = growth;
    char detail[512] = "";
    if (!have_call) {
        const int hang = o->signal == SIGPROF || o->signal == SIGALRM;
        row.classes |= 1u << (hang ? F_HANG : F_CRASH);
        snprintf(detail, sizeof detail, "killed by signal %d after %.1f s wall", o->signal,
                 o->wall_seconds);
    } else {
        row.cpu = rp->call.cpu;
        if (rp->call.cpu > TIME_LIMIT * sw->slow)
            row.classes |= 1u << F_TIME;
        if (growth > memory_limit_kib() || rp->call.status == PROJCURVE_ERR_NO_MEMORY)
            row.classes |= 1u << F_MEMORY;
        else if (rp->call.status != PROJCURVE_OK)
            row.classes |= 1u << F_STATUS;
        if (rp->call.status == PROJCURVE_OK && !have_verify)
            row.classes |= 1u << (o->signal ? F_VERIFY : F_CRASH);
        snprintf(detail, sizeof detail, "%s, %.3f s, %ld MiB, %zu branches",
                 projcurve_status_string(rp->call.status), rp->call.cpu, growth / 1024,
                 rp->call.branches);
    }
    if (have_verify) {
        const pc_sweep_report *v = &rp->verify.rep;
        const size_t wrong = v->off_surface + v->off_projection + v->behind + v->far_from_exact;
        if (wrong > 0 || v->accessor_failures > 0)
            row.classes |= 1u << F_WRONG;
        /* a point image (the curve running along Dir) is no branch, and
         * the result must say so by a failure (projcurve.h) */
        if (v->missed > 0 || (v->point_image_points > 0 && rp->verify.reported_failures <= 0))
            row.classes |= 1u << F_MISSED;
        if (v->zero_piece_branches > 0)
            row.classes |= 1u << F_ZERO;
        if ((long)v->failed_ends > rp->verify.reported_failures)
            row.classes |= 1u << F_FAILED_END;
        const size_t len = strlen(detail);
        snprintf(detail + len, sizeof detail - len,
                 ", %zu pieces; wrong %zu/%zu (off S %zu, off ray %zu, behind %zu, far %zu; "
                 "worst %.3g eps_D; first at t %.6g: gap %.3g eps_D, lambda %.3g); "
                 "missed %zu/%zu (t %.6g, %.3g eps_D; point image %zu); "
                 "zero-piece %zu, failed %zu",
                 v->pieces, wrong, v->samples, v->off_surface, v->off_projection, v->behind,
                 v->far_from_exact, fmax(v->worst_residual, v->worst_exact), v->wrong_t,
                 v->wrong_gap / rp->call.eps_d, v->wrong_lambda,
                 v->missed, v->oracle_points, v->missed_t, v->worst_missed,
                 v->point_image_points,
                 v->zero_piece_branches, v->failed_ends);
    }
    ++sw->run;
    ++sw->file_run[j->file];
    sw->max_rss_kib = growth > sw->max_rss_kib ? growth : sw->max_rss_kib;
    sw->max_peak_kib = o->max_rss_kib > sw->max_peak_kib ? o->max_rss_kib : sw->max_peak_kib;
    if (!isnan(row.cpu))
        keep_slowest(sw, &row);
    if (is_open(sw, j, row.classes)) {
        if (row.classes != 0)
            ++sw->open_failing;
        return;
    }
    if (row.classes == 0)
        return;
    ++sw->failed;
    ++sw->file_failed[j->file];
    char what[160], classes[160] = "";
    describe(sw, j, what, sizeof what);
    for (int k = 0; k < N_CLASSES; ++k)
        if (row.classes & (1u << k)) {
            ++sw->per_class[k];
            strncat(classes, k_class_names[k], sizeof classes - strlen(classes) - 2);
            strncat(classes, " ", sizeof classes - strlen(classes) - 1);
        }
    if (sw->printed++ < MAX_PRINTED)
        printf("FAIL %s: %s: %s\n", what, classes, detail);
}

typedef struct pool {
    pc_bounded_slot slots[MAX_JOBS];
    job jobs[MAX_JOBS];
    reply replies[MAX_JOBS];
    int n;
} pool;

static void wait_one(sweep *sw, pool *p)
{
    pc_bounded_outcome o;
    const int k = pc_bounded_wait(p->slots, p->n, &o);
    if (k >= 0)
        collect(sw, &p->jobs[k], &p->replies[k], &o);
}

static void submit(sweep *sw, pool *p, const job *j)
{
    const size_t index = sw->cases++;
    if (index % (size_t)sw->stride != 0 || (sw->only_case >= 0 && (long)index != sw->only_case))
        return;
    int free_slot = -1;
    for (;;) {
        for (int k = 0; k < p->n && free_slot < 0; ++k)
            if (p->slots[k].pid <= 0)
                free_slot = k;
        if (free_slot >= 0)
            break;
        wait_one(sw, p);
    }
    p->jobs[free_slot] = *j;
    p->jobs[free_slot].index = index;
    if (sw->list_only) {
        char what[160];
        describe(sw, &p->jobs[free_slot], what, sizeof what);
        printf("%s\n", what);
        return;
    }
    memset(&p->replies[free_slot], 0, sizeof p->replies[free_slot]);
    sw->current = &p->jobs[free_slot];
    const pc_bounded_limits lim = {WALL_KILL * sw->slow, MEMORY_LIMIT_MIB + MEMORY_HEADROOM_MIB};
    if (pc_bounded_start(&p->slots[free_slot], &lim, child_run, sw, &p->replies[free_slot],
                         sizeof p->replies[free_slot], 0) < 0) {
        pc_test_fail_at(__FILE__, __LINE__, "fork failed");
        p->slots[free_slot].pid = 0;
    }
}

static void sweep_file_run(sweep *sw, pool *p, size_t f)
{
    const char *path = sw->model_path ? sw->model_path : pc_test_data_path(k_files[f]);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, path, &m) != PROJCURVE_OK) {
        pc_test_missing_data(path);
        return;
    }
    /* The B-spline surfaces, which come first: the sweep's cases (and
     * realdata_open.tsv's indices) are those of the files' splines; the
     * analytic surfaces that STEP files add after them are checked
     * against their exact geometry by test_io_step_analytic. */
    size_t ns = 0;
    while (ns < projcurve_model_surface_count(m) &&
           strcmp(projcurve_model_surface_kind(m, ns), "bspline") == 0)
        ++ns;
    const size_t nc = projcurve_model_curve_count(m);
    sweep_file *sf = &sw->file;
    sf->model = m;
    sf->n_surfaces = ns;
    sf->surfaces = calloc(ns ? ns : 1, sizeof *sf->surfaces);
    double *sbox = malloc(sizeof *sbox * 6 * (ns ? ns : 1));
    double *cbox = malloc(sizeof *cbox * 6 * (nc ? nc : 1));
    double model[6] = {HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < ns; ++i) {
        projcurve_surface_bounds(NULL, projcurve_model_surface(m, i), sbox + 6 * i);
        prepare_surface(projcurve_model_surface(m, i), &sf->surfaces[i]);
        for (int k = 0; k < 3; ++k)
            model[k] = fmin(model[k], sbox[6 * i + k]),
            model[k + 3] = fmax(model[k + 3], sbox[6 * i + k + 3]);
    }
    for (size_t i = 0; i < nc; ++i) {
        curve_box(projcurve_model_curve(m, i), cbox + 6 * i);
        for (int k = 0; k < 3; ++k)
            model[k] = fmin(model[k], cbox[6 * i + k]),
            model[k + 3] = fmax(model[k + 3], cbox[6 * i + k + 3]);
    }
    const double ext[3] = {model[3] - model[0], model[4] - model[1], model[5] - model[2]};
    const double near = NEAR_REL * norm3(ext);
    const size_t before = sw->cases, failed_before = sw->failed;
    size_t pairs = 0;
    for (size_t i = 0; i < nc; ++i)
        for (size_t k = 0; k < ns; ++k) {
            if (!(box_gap(cbox + 6 * i, sbox + 6 * k) <= near))
                continue;
            ++pairs;
            for (int ortho = 0; ortho <= 1; ++ortho) {
                const job j = {0, f, k, i, REAL, ortho, {0.0, 0.0, -1.0}};
                submit(sw, p, &j);
            }
        }
    for (size_t k = 0; k < ns; ++k) {
        const surface_data *sd = &sf->surfaces[k];
        const double down[3] = {-sd->normal[0], -sd->normal[1], -sd->normal[2]};
        const curve_kind kinds[2] = {LIFTED, ON_SURFACE};
        for (int q = 0; q < 2; ++q)
            for (int ortho = 0; ortho <= 1; ++ortho) {
                const job j = {0, f, k, 0, kinds[q], ortho, {down[0], down[1], down[2]}};
                submit(sw, p, &j);
            }
        const job g = {0, f, k, 0, GRAZING, 0, {sd->graze[0], sd->graze[1], sd->graze[2]}};
        submit(sw, p, &g);
    }
    /* The children hold their own copies: the parent may release now. */
    printf("%s: %zu surfaces, %zu curves, %zu near pairs, %zu cases queued\n", file_name(sw, f), ns,
           nc, pairs, sw->cases - before);
    (void)failed_before;
    for (size_t i = 0; i < ns; ++i)
        release_surface(&sf->surfaces[i]);
    free(sf->surfaces);
    free(sbox);
    free(cbox);
    projcurve_model_destroy(m);
    memset(sf, 0, sizeof *sf);
}

static double env_double(const char *name, double fallback)
{
    const char *v = getenv(name);
    return v && v[0] ? atof(v) : fallback;
}

int main(void)
{
    sweep sw;
    memset(&sw, 0, sizeof sw);
    sw.slow = fmax(1.0, env_double("PC_REALDATA_SLOW", 1.0));
    sw.stride = (long)fmax(1.0, env_double("PC_REALDATA_STRIDE", 1.0));
    sw.jobs = (long)fmin(MAX_JOBS, fmax(1.0, env_double("PC_REALDATA_JOBS", 2.0)));
    sw.only_file = getenv("PC_REALDATA_FILE");
    sw.model_path = getenv("PC_REALDATA_MODEL");
    sw.only_case = (long)env_double("PC_REALDATA_CASE", -1.0);
    sw.list_only = env_double("PC_REALDATA_LIST", 0.0) != 0.0;
    if (sw.model_path && !sw.model_path[0])
        sw.model_path = NULL;
    printf("real-data sweep: stride %ld, %ld jobs, limits %.1f s CPU (hang %.1f s), %ld MiB%s\n",
           sw.stride, sw.jobs, TIME_LIMIT * sw.slow, HANG_CPU * sw.slow, memory_limit_kib() / 1024,
           pc_bounded_limits_memory() ? "" : " (measured only: no address-space limit here)");
    if (projcurve_option_info(NULL, (projcurve_option)13, NULL, NULL, NULL, NULL) ==
        PROJCURVE_OK)
        printf("option 13 (FOOT_POINTS) is known; the sweep keeps the defaults: local minima\n");
    const char *open_list = getenv("PC_REALDATA_OPEN_LIST");
    open_list = open_list && open_list[0] ? open_list : PC_REALDATA_OPEN;
    if (pc_open_cases_read(open_list, &sw.open) != 0)
        return EXIT_FAILURE;
    pool p;
    memset(&p, 0, sizeof p);
    p.n = (int)sw.jobs;
    for (size_t f = 0; f < (sw.model_path ? 1 : N_FILES); ++f) {
        if (!sw.model_path && sw.only_file && sw.only_file[0] &&
            strcmp(sw.only_file, strchr(k_files[f], '/') + 1) != 0)
            continue;
        sweep_file_run(&sw, &p, f);
    }
    for (int k = 0; k < p.n; ++k)
        if (p.slots[k].pid > 0)
            wait_one(&sw, &p), k = -1; /* until no child runs */
    printf("\n%zu cases, %zu run, %zu failed", sw.cases, sw.run, sw.failed);
    if (sw.printed > MAX_PRINTED)
        printf(" (first %d printed)", MAX_PRINTED);
    printf("\nfailures by class:");
    for (int k = 0; k < N_CLASSES; ++k)
        printf(" %s %zu%s", k_class_names[k], sw.per_class[k], k + 1 < N_CLASSES ? "," : "\n");
    printf("failed / run by file:");
    for (size_t f = 0; f < N_FILES; ++f)
        if (sw.file_run[f] > 0)
            printf(" %s %zu/%zu", file_name(&sw, f), sw.file_failed[f], sw.file_run[f]);
    printf("\n");
    printf("largest growth of a call: %ld MiB (largest child peak RSS, model and oracle "
           "included: %ld MiB)\nslowest calls (CPU s):\n",
           sw.max_rss_kib / 1024, sw.max_peak_kib / 1024);
    for (size_t k = 0; k < sw.n_slowest; ++k) {
        char what[160];
        describe(&sw, &sw.slowest[k].j, what, sizeof what);
        printf("  %8.3f  %s\n", sw.slowest[k].cpu, what);
    }
    size_t listed_passed = 0;
    for (size_t k = 0; k < sw.open.count; ++k)
        if (sw.open.items[k].seen && sw.open.items[k].passed) {
            printf("open case now passes (remove it from the list): %s\n", sw.open.items[k].key);
            ++listed_passed;
        }
    printf("open cases (%s): %zu listed, %zu failed as listed, %zu now pass\n",
           open_list, sw.open.count, sw.open_failing, listed_passed);
    pc_open_cases_free(&sw.open);
    pc_test_checks += (int)sw.run;
    pc_test_failures += (int)sw.failed;
    return pc_test_finish("test_realdata_sweep");
}
