/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve.h — the public interface of libprojcurve.
 *
 * libprojcurve projects curves onto B-spline and NURBS surfaces:
 *   - directional projection (every q on S with (q - p) x Dir = 0, (q - p).Dir > 0),
 *   - orthogonal projection (every foot point q on S whose normal passes through p),
 *   - point projection (closest point of a curve or a surface to a point).
 * Results are traced branches in the surface's parameter domain and, composed
 * with the surface by blossoming, Bezier/NURBS curves lying exactly on it.
 *
 * Conventions (apply to every function below unless its comment says otherwise):
 *   - Every fallible function takes a projcurve_context first and returns a
 *     projcurve_status; PROJCURVE_OK is 0. On failure a message describing the
 *     problem is stored in the context (projcurve_context_message) and the
 *     caller's objects and output pointers are left untouched.
 *   - The context may be NULL: the call then behaves the same, but no message
 *     is kept. A context must not be used by two threads at the same time.
 *   - Handles (surfaces, curves, results, models) are immutable after creation
 *     and may be shared read-only between threads. Options handles are mutable
 *     and must not be modified while another thread reads them.
 *   - *_destroy functions accept NULL and never fail.
 *   - Arrays are copied at creation: the caller keeps ownership of its memory.
 *   - Points are 3 doubles (x, y, z). Surface control nets are stored with the
 *     u index running fastest: point (i, j) is at ctrl[3 * (j * n_u + i)].
 */
#ifndef PROJCURVE_H
#define PROJCURVE_H

#include <stddef.h>

#include "projcurve_version.h"

#if defined(_WIN32) && !defined(PROJCURVE_STATIC)
#  ifdef PROJCURVE_BUILDING
#    define PROJCURVE_API __declspec(dllexport)
#  else
#    define PROJCURVE_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && defined(PROJCURVE_BUILDING)
#  define PROJCURVE_API __attribute__((visibility("default")))
#else
#  define PROJCURVE_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ======================================================================== */
/* Version                                                                   */
/* ======================================================================== */

/* Version of the library actually loaded, as
 * MAJOR * 10000 + MINOR * 100 + PATCH. Compare with PROJCURVE_VERSION_NUMBER
 * (the version of the header compiled against). Thread-safe. */
PROJCURVE_API unsigned projcurve_version_number(void);

/* The same as a string "MAJOR.MINOR.PATCH" (static storage). Thread-safe. */
PROJCURVE_API const char *projcurve_version_string(void);

/* ======================================================================== */
/* Status codes                                                              */
/* ======================================================================== */

typedef enum projcurve_status {
    PROJCURVE_OK = 0,
    PROJCURVE_ERR_NULL_ARGUMENT = 1,   /* a required pointer was NULL */
    PROJCURVE_ERR_INVALID_ARGUMENT = 2,/* a value that makes no sense */
    PROJCURVE_ERR_OUT_OF_RANGE = 3,    /* a value outside its documented bounds */
    PROJCURVE_ERR_UNKNOWN_OPTION = 4,  /* an option key the library does not know */
    PROJCURVE_ERR_NOT_FINITE = 5,      /* NaN or infinity in coordinates/values */
    PROJCURVE_ERR_BAD_KNOTS = 6,       /* knot vector decreasing, too short, empty domain */
    PROJCURVE_ERR_BAD_COUNT = 7,       /* counts that do not match each other */
    PROJCURVE_ERR_BAD_WEIGHT = 8,      /* a weight <= 0 or not finite */
    PROJCURVE_ERR_BAD_DEGREE = 9,      /* degree 0 or above PROJCURVE_MAX_DEGREE */
    PROJCURVE_ERR_OVERFLOW = 10,       /* sizes whose product overflows */
    PROJCURVE_ERR_OUT_OF_DOMAIN = 11,  /* parameter outside the domain */
    PROJCURVE_ERR_ZERO_DIRECTION = 12, /* projection/ray direction of length 0 */
    PROJCURVE_ERR_NO_MEMORY = 13,      /* an allocation failed */
    PROJCURVE_ERR_VERSION = 14,        /* header/library major versions differ */
    PROJCURVE_ERR_NOT_CONVERGED = 15,  /* an iteration hit its bound */
    PROJCURVE_ERR_LIMIT_REACHED = 16,  /* a size, time or work limit was hit; partial result kept */
    PROJCURVE_ERR_CALLBACK = 17,       /* a user callback failed or returned NaN */
    PROJCURVE_ERR_SINGULAR = 18,       /* a degenerate configuration (zero gradient, ...) */
    PROJCURVE_ERR_IO = 19,             /* a file could not be opened/read/written */
    PROJCURVE_ERR_PARSE = 20,          /* malformed file contents */
    PROJCURVE_ERR_UNSUPPORTED = 21,    /* valid input the library does not handle */
    PROJCURVE_ERR_INDEX = 22,          /* an index past the end */
    PROJCURVE_ERR_WRONG_KIND = 23,     /* the handle is of another kind (e.g. not NURBS) */
    PROJCURVE_ERR_CANCELLED = 24       /* the progress callback asked to stop; partial result kept */
} projcurve_status;

/* A short, static English name for every status (never NULL; unknown codes
 * give "unknown status"). Thread-safe. */
PROJCURVE_API const char *projcurve_status_string(projcurve_status status);

/* Highest degree accepted for curves and surfaces. */
#define PROJCURVE_MAX_DEGREE 30

/* ======================================================================== */
/* Context: error messages                                                   */
/* ======================================================================== */

typedef struct projcurve_context projcurve_context;

/* Creates a context. Pass PROJCURVE_VERSION_MAJOR as abi_major: a caller built
 * against another major version gets PROJCURVE_ERR_VERSION.
 * Statuses: OK, NULL_ARGUMENT (out), VERSION, NO_MEMORY; on failure *out is
 * untouched and, as no context exists yet, projcurve_status_string() is the
 * message. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_context_create(unsigned abi_major,
                                                        projcurve_context **out);

/* Releases a context (NULL is accepted). */
PROJCURVE_API void projcurve_context_destroy(projcurve_context *ctx);

/* Message of the last failed call made with ctx ("" if none; NULL ctx gives
 * "no context"). Valid until the next call with ctx. */
PROJCURVE_API const char *projcurve_context_message(const projcurve_context *ctx);

/* Status of the last failed call made with ctx (OK if none; NULL ctx gives
 * NULL_ARGUMENT). */
PROJCURVE_API projcurve_status projcurve_context_status(const projcurve_context *ctx);

/* Forgets the last failure. */
PROJCURVE_API void projcurve_context_clear(projcurve_context *ctx);

/* Size limits a context puts on the calls made with it (as SQLite's
 * sqlite3_limit on a connection). A call with a NULL context uses the
 * defaults. */
typedef enum projcurve_limit {
    /* Control points of one curve, or of one surface (n_u * n_v), at
     * creation and when a model is read. Creating a surface costs about
     * 1.7 KB per control point (the Bezier patches, their boxes and the
     * BVH; a 1000 x 1000 net takes 1.7 GB and 5 s), a curve far less. A
     * larger input is refused with PROJCURVE_ERR_OUT_OF_RANGE and a message
     * naming the limit. Default PROJCURVE_DEFAULT_MAX_CONTROL_POINTS. */
    PROJCURVE_LIMIT_CONTROL_POINTS = 0
} projcurve_limit;

/* 2^18: a 512 x 512 net, about 450 MB to create. */
#define PROJCURVE_DEFAULT_MAX_CONTROL_POINTS 262144

/* Sets a limit of ctx. The value must be >= 2 (the smallest curve);
 * sizes whose arrays overflow the address space stay refused
 * (PROJCURVE_ERR_OVERFLOW) whatever the limit.
 * Statuses: OK, NULL_ARGUMENT (ctx), UNKNOWN_OPTION (limit), OUT_OF_RANGE
 * (value); on failure the limit is unchanged. */
PROJCURVE_API projcurve_status projcurve_context_set_limit(projcurve_context *ctx,
                                                           projcurve_limit limit, size_t value);

/* The current value of a limit (the default for a NULL ctx).
 * Statuses: OK, NULL_ARGUMENT (value), UNKNOWN_OPTION (limit). */
PROJCURVE_API projcurve_status projcurve_context_get_limit(projcurve_context *ctx,
                                                           projcurve_limit limit, size_t *value);

/* ======================================================================== */
/* Options                                                                   */
/* ======================================================================== */

typedef struct projcurve_options projcurve_options;

/* Option keys. Each has a type (double or integer), bounds and a default;
 * projcurve_option_info tells them. */
typedef enum projcurve_option {
    /* double: Hausdorff tolerance eps_D in model units, (0, 1e300]: 0 and
     * negative values give OUT_OF_RANGE, NaN and infinities NOT_FINITE.
     * Unset (the default of a new handle) it is automatic: 1e-4 of the
     * surface's bounding-box diagonal (projcurve_surface_bounds), which the
     * result reports as PROJCURVE_STAT_TOL_DISTANCE. While unset, the getter
     * and projcurve_option_info's default give 0. A projection refuses, with
     * OUT_OF_RANGE, a value below max(NEWTON_TOL, 1e-12) times the model
     * size: its exact points are not placed more closely than that. */
    PROJCURVE_OPT_TOL_DISTANCE = 1,
    /* double: joint angle tolerance eps_T in degrees, (0, 90]. Default 1. */
    PROJCURVE_OPT_TOL_ANGLE_DEG = 2,
    /* double: Newton tolerance eps1 = eps2 of [SY13] s3.3, relative to the
     * model size. Default 1e-12, bounds [1e-15, 1e-3]. */
    PROJCURVE_OPT_NEWTON_TOL = 3,
    /* integer: Newton iteration cap per correction. Default 20, [1, 200]. */
    PROJCURVE_OPT_NEWTON_MAX_ITER = 4,
    /* integer: PROJCURVE_METHOD_SECOND_ORDER (default) or PROJCURVE_METHOD_RK4. */
    PROJCURVE_OPT_METHOD = 5,
    /* double: constant parameter increment dt for tracing; 0 = automatic
     * arc-length step (default). Bounds [0, 1e300]. */
    PROJCURVE_OPT_PARAM_STEP = 6,
    /* double: arc-length step as a fraction of the estimated total length
     * of the projection, used when PARAM_STEP is 0. Default 1/64, [1e-7, 1]. */
    PROJCURVE_OPT_ARC_STEP_FRACTION = 7,
    /* integer: maximum number of traced points per projection.
     * Default 100,000, [16, 2^40]. Both size limits are checked before
     * the allocation that would pass them, and they bound the memory of a
     * call: at most about 600 bytes per point of MAX_POINTS plus
     * 1,100 + 32 (d + 1) bytes per piece of MAX_PIECES (d the pieces'
     * degree, p + q, or 3 (p + q) with cubic pcurves, at most
     * 2 PROJCURVE_MAX_DEGREE = 60), plus tables of the size of the surface
     * (a few hundred bytes per Bezier patch); arrays grow by doubling,
     * which this counts. The defaults are chosen for 256 MiB: 100,000
     * points take at most 60 MB and 50,000 pieces at most 153 MB (at
     * d = 60; measured: ~300 bytes per piece on a bilinear plane, 14 MiB
     * for a call stopped at 50,000 pieces). A projection that needs more
     * returns PROJCURVE_ERR_LIMIT_REACHED with the partial result described
     * at projcurve_project_directional; raise the limits for it. The
     * largest real-data call of the test suite makes about 8,000 pieces. */
    PROJCURVE_OPT_MAX_POINTS = 8,
    /* integer: maximum number of composed pieces per projection.
     * Default 50,000, [1, 2^40] (see MAX_POINTS for the memory it bounds).
     * A projection that needs more returns PROJCURVE_ERR_LIMIT_REACHED with
     * the partial result described at projcurve_project_directional. */
    PROJCURVE_OPT_MAX_PIECES = 9,
    /* integer: 1 = compose pieces exactly on S (default), 0 = trace only
     * (polylines, no eps_D / eps_T refinement). */
    PROJCURVE_OPT_COMPOSE = 10,
    /* integer: 1 = detect branches born in mid-curve (default), 0 = trace
     * only the branches seeded at the start of the curve. */
    PROJCURVE_OPT_JUMP_DETECTION = 11,
    /* integer: degree of each composed piece's pcurve (u, v)(s), 1 or 3
     * (2 is rejected with OUT_OF_RANGE; projcurve_option_info gives the
     * bounds [1, 3]). 1: straight segments in (u, v), composed pieces of
     * degree p + q ([SY13] s4). 3 (default): the cubic Hermite through two
     * exact points of the projection with the exact tangents there,
     * composed pieces of degree 3 (p + q); far fewer pieces at tight eps_D
     * (error O(h^4) instead of O(h^2)) and joints G1 wherever S is smooth.
     * The rule: with 3, a surface of degrees p x q gets cubic pcurves where
     * 3 (p + q) <= PROJCURVE_MAX_DEGREE (p + q <= 10, e.g. bicubic and
     * biquintic surfaces) and straight ones (degree 1) above, where each
     * cubic piece costs too much (degree 6 x 8, composed degree 42: calls
     * of the real-data sweep (tests/realdata) ran past 2 s of CPU where
     * straight pieces take 0.3 s); also a piece whose cubic would leave its
     * Bezier patch, or where q' is not available or not usable (a fold, a
     * pole of S), is a straight segment: read each piece's degree with
     * projcurve_result_piece_pcurve. Cubic pcurves took 0.5-0.9 of the
     * time of straight ones on 11 of the benchmark's 12 projecting cases
     * at their eps_D (1.13 on the last) and 0.04-0.19 at 1e-4 of it
     * (docs/refine_compose.md, "Cubic pcurves"). */
    PROJCURVE_OPT_PCURVE_DEGREE = 12,
    /* integer: which foot points projcurve_project_orthogonal returns,
     * PROJCURVE_FOOT_POINTS_MINIMA or PROJCURVE_FOOT_POINTS_ALL.
     * PROJCURVE_FOOT_POINTS_MINIMA (0, the default): only the feet where the
     * distance |S - P(t)| is locally smallest (K positive definite), what
     * pulling a curve onto a face gives; a branch ends where its foot
     * stops being a local minimum (P(t) at a centre of curvature,
     * PROJCURVE_END_CURVATURE_CENTRE). PROJCURVE_FOOT_POINTS_ALL (1): every
     * critical foot point, saddles and maxima of the distance too (e.g. the
     * far side of a torus tube). Ignored by the directional and the
     * implicit projections (the latter traces the one branch it is seeded
     * on). Bounds [0, 1]. */
    PROJCURVE_OPT_FOOT_POINTS = 13,
    /* double: wall time allowed per projection call, in seconds (a
     * monotonic clock); 0 = no limit (default), bounds [0, 1e9]. A call
     * that runs out returns PROJCURVE_ERR_LIMIT_REACHED with the partial
     * result described at projcurve_project_directional. The clock is read
     * every 256 units of work (see MAX_WORK): tens of microseconds apart on
     * a bicubic surface, up to ~20 ms on a rational one of degree 6 x 8
     * (linkrods.step: a 0.05 s limit returned after at most 0.08 s along
     * Dir and 0.12 s orthogonally, over its 1,854 pairs on a loaded
     * machine); a call stopped while composing still composes the
     * pieces it has refined, up to a third more time where a branch has
     * hundreds of thousands of pieces (limits of 0.2, 0.5 and 1 s returned
     * after 0.25, 0.64 and 1.34 s on such a branch). What a call
     * returns at the limit depends on the machine's speed and load: use
     * MAX_WORK for a reproducible cut. */
    PROJCURVE_OPT_TIME_LIMIT = 14,
    /* integer: units of work allowed per projection call; 0 = no limit
     * (default), bounds [0, 2^40]. A unit is one bounded piece of work: a
     * traced step (prediction and correction), a check of the jump sweep,
     * a segment of the refinement, a fitted piece. The count depends only
     * on the inputs and options, so a call cut by MAX_WORK returns the same
     * partial result (PROJCURVE_ERR_LIMIT_REACHED) on every machine. */
    PROJCURVE_OPT_MAX_WORK = 15,
    /* integer: degree of each branch's compact 3D curve
     * (projcurve_result_branch_compact_curve), [1, 25], default 5. 25 is
     * the largest degree Open CASCADE reads (Geom_BSplineCurve). Where
     * the projection is an affine image of a NURBS curve (onto a plane)
     * the compact curve keeps the curve's own degree when that is lower. */
    PROJCURVE_OPT_CURVE_DEGREE = 16,
    /* integer: which points of the projection are kept, [0, 1].
     * PROJCURVE_HITS_ALL (0, the default): every hit of the ray (every
     * foot point of the orthogonal projection, as FOOT_POINTS selects).
     * PROJCURVE_HITS_NEAREST (1): at each t only the point nearest to
     * P(t) (along the ray: the visible projection; orthogonally: the
     * nearest foot point). A branch is cut exactly where another becomes
     * nearer (the crossing of the two distances located to 1e-10 of the
     * model size) or where a nearer one is born; the part kept ends with
     * PROJCURVE_END_OCCLUDED and what becomes nearest again starts with
     * PROJCURVE_START_VISIBLE. See docs/hits.md. */
    PROJCURVE_OPT_HITS = 17,
    /* double: keep only the points within this distance of P(t) (along
     * the ray: lambda <= D; orthogonally |S - P(t)| <= D), model units,
     * [0, 1e300]; 0 (the default) or +inf (the setter stores 0) = no
     * limit. A branch is cut exactly where its distance reaches D (to
     * 1e-10 of the model size): PROJCURVE_END_MAX_DISTANCE /
     * PROJCURVE_START_MAX_DISTANCE. Combines with HITS. Both are ignored
     * by projcurve_project_orthogonal_implicit (one branch). */
    PROJCURVE_OPT_MAX_DISTANCE = 18,
    /* integer: worker threads of the many-curve calls
     * (projcurve_project_curves_directional, _orthogonal), [1, 1024],
     * default 1 (the calling thread only). The results are the same bit
     * for bit whatever the count. Single-curve calls ignore it. */
    PROJCURVE_OPT_THREADS = 19
} projcurve_option;

#define PROJCURVE_HITS_ALL 0
#define PROJCURVE_HITS_NEAREST 1

#define PROJCURVE_FOOT_POINTS_MINIMA 0
#define PROJCURVE_FOOT_POINTS_ALL 1

#define PROJCURVE_METHOD_SECOND_ORDER 0
#define PROJCURVE_METHOD_RK4 1

typedef enum projcurve_option_type {
    PROJCURVE_OPTION_DOUBLE = 0,
    PROJCURVE_OPTION_INTEGER = 1
} projcurve_option_type;

/* Creates options holding every default.
 * Statuses: OK, NULL_ARGUMENT, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_options_create(projcurve_context *ctx,
                                                        projcurve_options **out);

/* Releases options (NULL is accepted). */
PROJCURVE_API void projcurve_options_destroy(projcurve_options *opts);

/* Type, bounds and default of an option (any output pointer may be NULL).
 * Bounds are inclusive, except the lower bounds 0 of TOL_DISTANCE and
 * TOL_ANGLE_DEG, which are excluded. Statuses: OK, UNKNOWN_OPTION.
 * Thread-safe. */
PROJCURVE_API projcurve_status projcurve_option_info(projcurve_context *ctx,
                                                     projcurve_option key,
                                                     projcurve_option_type *type,
                                                     double *min_value,
                                                     double *max_value,
                                                     double *default_value);

/* Setters. Statuses: OK, NULL_ARGUMENT, UNKNOWN_OPTION, WRONG_KIND (the key
 * has the other type), NOT_FINITE, OUT_OF_RANGE. On failure opts is unchanged. */
PROJCURVE_API projcurve_status projcurve_options_set_double(projcurve_context *ctx,
                                                            projcurve_options *opts,
                                                            projcurve_option key,
                                                            double value);
PROJCURVE_API projcurve_status projcurve_options_set_int(projcurve_context *ctx,
                                                         projcurve_options *opts,
                                                         projcurve_option key,
                                                         long long value);
/* Getters. Statuses: OK, NULL_ARGUMENT, UNKNOWN_OPTION, WRONG_KIND. */
PROJCURVE_API projcurve_status projcurve_options_get_double(projcurve_context *ctx,
                                                            const projcurve_options *opts,
                                                            projcurve_option key,
                                                            double *value);
PROJCURVE_API projcurve_status projcurve_options_get_int(projcurve_context *ctx,
                                                         const projcurve_options *opts,
                                                         projcurve_option key,
                                                         long long *value);

/* Progress of a projection call: fraction_done in [0, 1], never smaller
 * than at the previous call within the same projection call. Return 0 to
 * go on; any other value stops the call, which then returns
 * PROJCURVE_ERR_CANCELLED with the partial result described at
 * projcurve_project_directional. */
typedef int (*projcurve_progress_fn)(void *user, double fraction_done);

/* Sets the progress callback of the projection calls made with opts (fn
 * NULL: none, the default; user is passed to fn). Each projection call
 * (directional, orthogonal and orthogonal implicit, with their refinement
 * and composition) calls fn only from within the call and on the caller's
 * thread: once after its first unit of work (see PROJCURVE_OPT_MAX_WORK),
 * then every 256 units (see PROJCURVE_OPT_TIME_LIMIT for how far apart
 * in time), and last with 1 when the work is complete (that call's return
 * value is ignored); a call stopped by a limit or by fn does not report 1.
 * Calls made with the same options on several threads call fn from each
 * of them: fn must then be thread-safe. fn must not modify opts.
 * Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_options_set_progress(projcurve_context *ctx,
                                                              projcurve_options *opts,
                                                              projcurve_progress_fn fn,
                                                              void *user);

/* The progress callback and its user pointer (either output may be NULL;
 * NULL when none is set). Statuses: OK, NULL_ARGUMENT (opts). */
PROJCURVE_API projcurve_status projcurve_options_get_progress(projcurve_context *ctx,
                                                              const projcurve_options *opts,
                                                              projcurve_progress_fn *fn,
                                                              void **user);

/* ======================================================================== */
/* Curves                                                                    */
/* ======================================================================== */

typedef struct projcurve_curve projcurve_curve;

/* Creates a B-spline (weights == NULL) or NURBS curve of the given degree
 * (1..PROJCURVE_MAX_DEGREE) from n_ctrl points (3 doubles each), n_ctrl
 * weights and n_ctrl + degree + 1 knots. The domain is
 * [knots[degree], knots[n_ctrl]]; unclamped and periodic knot vectors are
 * converted exactly to clamped form over that domain.
 * Limits (OUT_OF_RANGE, the message names the limit): parameters at most
 * 1e30 in magnitude; a domain at least 1e-30 wide and at least 2^-32 times
 * its largest end in magnitude; coordinates at most 1e30 in magnitude and,
 * unless all control points coincide, spanning at least 1e-30. Beyond them
 * squared derivatives and distances leave the double range or the domain
 * holds too few doubles for the tracer's steps.
 * Statuses: OK, NULL_ARGUMENT, BAD_DEGREE, BAD_COUNT, BAD_KNOTS, NOT_FINITE,
 * BAD_WEIGHT, OVERFLOW, OUT_OF_RANGE, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_curve_create_nurbs(projcurve_context *ctx,
                                                            int degree,
                                                            size_t n_ctrl,
                                                            const double *ctrl,
                                                            const double *weights,
                                                            const double *knots,
                                                            projcurve_curve **out);

/* A user-defined curve: fills out[0..8] with P(t), P'(t), P''(t) and returns 0;
 * any other return value is a failure. Must be callable from any thread that
 * uses the curve, and deterministic. */
typedef int (*projcurve_curve_fn)(void *user, double t, double out[9]);

/* Creates a curve from a callback over [t0, t1] (t0 < t1, both finite).
 * The callback is not called here. user must outlive the curve. The domain
 * limits of projcurve_curve_create_nurbs apply (OUT_OF_RANGE).
 * Statuses: OK, NULL_ARGUMENT, NOT_FINITE, INVALID_ARGUMENT, OUT_OF_RANGE,
 * NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_curve_create_callback(projcurve_context *ctx,
                                                               projcurve_curve_fn fn,
                                                               void *user,
                                                               double t0, double t1,
                                                               projcurve_curve **out);

PROJCURVE_API void projcurve_curve_destroy(projcurve_curve *curve);

/* Parameter domain. Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_curve_domain(projcurve_context *ctx,
                                                      const projcurve_curve *curve,
                                                      double *t0, double *t1);

/* Point and derivatives up to order n_deriv (0..3; callback curves 0..2):
 * out receives 3 * (n_deriv + 1) doubles: C, C', C'', C'''.
 * Statuses: OK, NULL_ARGUMENT, OUT_OF_RANGE (n_deriv), OUT_OF_DOMAIN,
 * NOT_FINITE (t), CALLBACK. */
PROJCURVE_API projcurve_status projcurve_curve_eval(projcurve_context *ctx,
                                                    const projcurve_curve *curve,
                                                    double t, int n_deriv,
                                                    double *out);

/* Shape of a NURBS curve (any output may be NULL): degree, control point
 * count, knot count, and 1 if rational. Statuses: OK, NULL_ARGUMENT,
 * WRONG_KIND (callback curve). */
PROJCURVE_API projcurve_status projcurve_curve_nurbs_info(projcurve_context *ctx,
                                                          const projcurve_curve *curve,
                                                          int *degree, size_t *n_ctrl,
                                                          size_t *n_knots, int *rational);

/* Copies the clamped NURBS data out: ctrl (3 * n_ctrl), weights (n_ctrl),
 * knots (n_knots); any may be NULL. Statuses: OK, NULL_ARGUMENT, WRONG_KIND. */
PROJCURVE_API projcurve_status projcurve_curve_nurbs_data(projcurve_context *ctx,
                                                          const projcurve_curve *curve,
                                                          double *ctrl, double *weights,
                                                          double *knots);

/* ======================================================================== */
/* Surfaces                                                                  */
/* ======================================================================== */

typedef struct projcurve_surface projcurve_surface;

/* Creates a B-spline (weights == NULL) or NURBS surface of degrees
 * (deg_u, deg_v) from an n_u x n_v control net (u fastest), n_u * n_v weights
 * and the knot vectors (n_u + deg_u + 1 and n_v + deg_v + 1 knots). Domain and
 * clamping as for curves. The Bezier patch decomposition and the patch
 * bounding-volume hierarchy are built here, once. The domain (in u and in
 * v) and coordinate limits of projcurve_curve_create_nurbs apply.
 * Statuses: OK, NULL_ARGUMENT, BAD_DEGREE, BAD_COUNT, BAD_KNOTS, NOT_FINITE,
 * BAD_WEIGHT, OVERFLOW, OUT_OF_RANGE, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_surface_create_nurbs(projcurve_context *ctx,
                                                              int deg_u, int deg_v,
                                                              size_t n_u, size_t n_v,
                                                              const double *ctrl,
                                                              const double *weights,
                                                              const double *knots_u,
                                                              const double *knots_v,
                                                              projcurve_surface **out);

PROJCURVE_API void projcurve_surface_destroy(projcurve_surface *surface);

/* Domain as {u0, u1, v0, v1}. Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_surface_domain(projcurve_context *ctx,
                                                        const projcurve_surface *surface,
                                                        double domain[4]);

/* Shape (any output may be NULL): degrees, net size, number of non-empty
 * knot spans in u and v (Bezier patches = spans_u * spans_v), rational flag.
 * Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_surface_info(projcurve_context *ctx,
                                                      const projcurve_surface *surface,
                                                      int *deg_u, int *deg_v,
                                                      size_t *n_u, size_t *n_v,
                                                      size_t *spans_u, size_t *spans_v,
                                                      int *rational);

/* Copies the clamped NURBS data of a surface out (any output may be NULL;
 * sizes from projcurve_surface_info): ctrl (3 n_u n_v, u fastest), weights
 * (n_u n_v, all 1 when not rational), knots_u (n_u + deg_u + 1) and
 * knots_v (n_v + deg_v + 1). Unclamped or periodic input comes back in the
 * clamped form it was converted to. Statuses: OK, NULL_ARGUMENT.
 * Thread-safe. */
PROJCURVE_API projcurve_status projcurve_surface_nurbs_data(projcurve_context *ctx,
                                                            const projcurve_surface *surface,
                                                            double *ctrl, double *weights,
                                                            double *knots_u,
                                                            double *knots_v);

/* Point and partial derivatives up to total order n_deriv (0..2): out receives
 * S (n_deriv 0), then Su, Sv (1), then Suu, Suv, Svv (2), 3 doubles each.
 * A parameter within 4 ulps of the domain's scale outside it (the rounding
 * of a pcurve point on its edge) is evaluated on the edge.
 * Statuses: OK, NULL_ARGUMENT, OUT_OF_RANGE (n_deriv), NOT_FINITE,
 * OUT_OF_DOMAIN. */
PROJCURVE_API projcurve_status projcurve_surface_eval(projcurve_context *ctx,
                                                      const projcurve_surface *surface,
                                                      double u, double v, int n_deriv,
                                                      double *out);

/* Axis-aligned bounding box {xmin, ymin, zmin, xmax, ymax, zmax} of the
 * control net (contains the surface). Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_surface_bounds(projcurve_context *ctx,
                                                        const projcurve_surface *surface,
                                                        double box[6]);

/* ======================================================================== */
/* Point projection ([Ook] and its surface analogue)                      */
/* ======================================================================== */

/* Closest point of the curve to p: parameter *t, point q (may be NULL) and
 * distance *dist (may be NULL). End points are candidates.
 * Statuses: OK, NULL_ARGUMENT, NOT_FINITE, CALLBACK, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_curve_closest_point(projcurve_context *ctx,
                                                             const projcurve_curve *curve,
                                                             const double p[3],
                                                             double *t, double q[3],
                                                             double *dist);

/* Closest point of the surface to p: parameters uv, point q and distance
 * (q, dist may be NULL). Edges and corners are candidates.
 * Statuses: OK, NULL_ARGUMENT, NOT_FINITE, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_surface_closest_point(projcurve_context *ctx,
                                                               const projcurve_surface *surface,
                                                               const double p[3],
                                                               double uv[2], double q[3],
                                                               double *dist);

/* Every interior local foot point of p on the surface ((S - p).Su =
 * (S - p).Sv = 0), sorted by distance. Up to `capacity` (u, v) pairs are
 * written to uv; *count receives the number found (which may exceed
 * capacity). Statuses: OK, NULL_ARGUMENT, NOT_FINITE, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_surface_foot_points(projcurve_context *ctx,
                                                             const projcurve_surface *surface,
                                                             const double p[3],
                                                             size_t capacity, double *uv,
                                                             size_t *count);

/* ======================================================================== */
/* Line / surface intersection                                               */
/* ======================================================================== */

/* Flags of a hit. */
#define PROJCURVE_HIT_TANGENT 1u  /* the line grazes S (Dir nearly in the tangent plane) */
#define PROJCURVE_HIT_BOUNDARY 2u /* the hit lies on the boundary of S's domain */

/* All intersections of the line origin + lambda * dir with the surface,
 * sorted by lambda; with ray_only != 0 only lambda > 0. Up to capacity hits
 * are written: hits[3k..3k+2] = (u, v, lambda) and flags[k] (flags may be
 * NULL; hits may be NULL when capacity is 0); *count gets the number found
 * (may exceed capacity). dir need not be unit length: lambda is in units of
 * dir. Each point of the line where it meets S is reported once: hits on
 * shared patch edges or corners, at poles (edges that collapse to a point),
 * on a closed surface's seam (u = u0 and u = u1, or v) and on sheets folded
 * onto each other are one hit when their lambda agree to 1e-8 of the model's
 * scale. On a seam the (u, v) reported is the domain's start (u0, or v0),
 * flagged PROJCURVE_HIT_BOUNDARY. A hit lies on the line to ~1e-12 of the
 * model's size (a line that misses by less touches it), plus |Su| ulp(u) +
 * |Sv| ulp(v) where knot spans are far narrower than their parameters (no
 * double (u, v) does better there); a grazing (tangent) hit is a double root,
 * known only to ~1e-7 of the model along the line. A line that misses gives
 * *count = 0 and OK.
 * Thread-safe for distinct contexts.
 * Statuses: OK, NULL_ARGUMENT, NOT_FINITE, ZERO_DIRECTION, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_surface_intersect_line(projcurve_context *ctx,
                                                                const projcurve_surface *surface,
                                                                const double origin[3],
                                                                const double dir[3],
                                                                int ray_only,
                                                                size_t capacity,
                                                                double *hits,
                                                                unsigned *flags,
                                                                size_t *count);

/* ======================================================================== */
/* Projection                                                                */
/* ======================================================================== */

typedef struct projcurve_result projcurve_result;

/* Directional projection of curve onto surface along dir ([SY13]). opts
 * may be NULL (defaults). On success *out holds every branch.
 * PROJCURVE_ERR_LIMIT_REACHED also sets *out: a partial result, readable
 * with every result function, whose truncated branches end with
 * PROJCURVE_END_LIMIT. When PROJCURVE_OPT_MAX_PIECES is reached, the
 * branches before the one being composed are complete; that branch keeps
 * its pieces from its start up to the limit (the same pieces as without the
 * limit: within eps_D and eps_T), its points (projcurve_result_branch_points)
 * are then the pcurve of those pieces only — the traced polyline beyond them
 * is dropped — and its t range ends with its last piece; every later branch
 * has no pieces and keeps its traced polyline.
 * PROJCURVE_OPT_TIME_LIMIT and PROJCURVE_OPT_MAX_WORK also give
 * LIMIT_REACHED, and a progress callback that asks to stop
 * (projcurve_options_set_progress) gives PROJCURVE_ERR_CANCELLED, both
 * with *out set to the partial result and the context's message saying
 * which: stopped while composing, the result is the one described above
 * for MAX_PIECES at that point; stopped while tracing, no branch is
 * composed (none has pieces), the branch being traced ends with
 * PROJCURVE_END_LIMIT (unless it had a single point, which is dropped) and
 * the branches born later in the curve are missing; stopped while
 * selecting the hits (PROJCURVE_OPT_HITS, PROJCURVE_OPT_MAX_DISTANCE), no
 * branch is composed, the parts kept so far remain, the last ending with
 * PROJCURVE_END_LIMIT, and the branches not yet selected are missing;
 * stopped while verifying, the branches verified so far remain, the one
 * being verified keeps its verified part up to the stop, ending with
 * PROJCURVE_END_LIMIT, and the later branches are missing; stopped while
 * fitting the compact forms (after verification), every branch has all
 * its pieces, the branches before the one being fitted keep their compact
 * forms, and from that one on each has the pieces' pcurves joined as its
 * compact pcurve (projcurve_result_branch_compact_info: not fitted) and
 * no compact 3D curve (projcurve_result_branch_compact_curve:
 * LIMIT_REACHED). (The message names the step: "... while selecting the
 * hits", "... while verifying the result".)
 * A curve that misses the surface gives OK and a result with no branches.
 * The projection holds in front of the curve, (q - p).Dir >= 0: a branch
 * ends where the curve meets S (PROJCURVE_END_CURVE_CROSSING) and one
 * starts where it leaves it (PROJCURVE_START_CURVE_CROSSING); lambda = 0
 * counts, so a curve lying on S is its own projection. Where the curve runs
 * along Dir its projection is a point: a branch whose image lies within
 * eps_D of one point is not returned; where the curve moved more than
 * eps_D over it, it counts as a failure (see projcurve_result_failure_count:
 * its rays do hit S). Where Dir is tangent to S along a
 * region (a plane seen edge-on) no branch is traced.
 * Every branch returned is verified (see projcurve_result_failure_count):
 * where the projection could not be followed or verified a branch ends
 * with PROJCURVE_END_FAILED and what follows starts with
 * PROJCURVE_START_FAILED.
 * Statuses: OK, LIMIT_REACHED, CANCELLED, NULL_ARGUMENT, NOT_FINITE,
 * ZERO_DIRECTION, OUT_OF_RANGE (tolerances: eps_D below the model's
 * precision, eps_T below 1e-3 degrees while composing), SINGULAR (the curve
 * is a point to the model's precision), CALLBACK, NO_MEMORY. Thread-safe for
 * distinct contexts; the inputs are only read. */
PROJCURVE_API projcurve_status projcurve_project_directional(projcurve_context *ctx,
                                                             const projcurve_surface *surface,
                                                             const projcurve_curve *curve,
                                                             const double dir[3],
                                                             const projcurve_options *opts,
                                                             projcurve_result **out);

/* Conical (central) projection of curve onto surface from the eye point
 * eye: P(t) maps to the points of S on the ray from the eye through P(t),
 * beyond P(t), S = P + lambda (P - eye) / |P - eye| with lambda >= 0 (the
 * analogue of (q - p).Dir >= 0 of the directional projection: a branch ends
 * where the curve meets S, PROJCURVE_END_CURVE_CROSSING, and one starts
 * where it leaves it, PROJCURVE_START_CURVE_CROSSING; lambda = 0 counts).
 * The same tracing, jump detection, tolerance control (eps_D, eps_T),
 * verification, composition and compact forms as
 * projcurve_project_directional, whose description of the result (partial
 * results included) holds here with the ray of each point in place of Dir;
 * where the curve runs along its own ray (a line through the eye) its
 * projection is a point, treated as there. Where a ray is tangent to S a
 * branch ends at the fold (PROJCURVE_END_SILHOUETTE, PROJCURVE_START_SILHOUETTE
 * for one born there) as along a direction.
 * The eye may lie on S or anywhere off the curve: the points of S at or
 * near the eye are behind the curve (lambda < 0) and never projections;
 * a check of the jump detection whose ray meets the box of a patch whose
 * control net's box holds the eye then always runs the full ray search
 * (slower, not less complete). A
 * curve through the eye (its closest point to the eye within the model's
 * precision) is refused with PROJCURVE_ERR_SINGULAR (the ray of that point
 * has no direction), as is a curve that is a point. Where the curve passes
 * just above that precision from the eye, the rays of the points near it
 * turn through 180 degrees within a t interval of about that distance: a
 * branch that cannot be followed through it ends there with
 * PROJCURVE_END_FAILED (see projcurve_result_failure_count).
 * Statuses: OK, LIMIT_REACHED, CANCELLED, NULL_ARGUMENT, NOT_FINITE (eye
 * not finite), OUT_OF_RANGE (tolerances, as directional), SINGULAR (the
 * curve is a point, or passes through the eye), CALLBACK, NO_MEMORY.
 * *out is set for OK, LIMIT_REACHED and CANCELLED and owned by the caller
 * (projcurve_result_destroy). Thread-safe for distinct contexts; the
 * inputs are only read. */
PROJCURVE_API projcurve_status projcurve_project_conical(projcurve_context *ctx,
                                                         const projcurve_surface *surface,
                                                         const projcurve_curve *curve,
                                                         const double eye[3],
                                                         const projcurve_options *opts,
                                                         projcurve_result **out);

/* Orthogonal projection of curve onto surface ([PW96], parametric form):
 * every continuous branch of foot points (minima, saddles and maxima of the
 * distance alike). A branch that reaches a centre of curvature of S ends
 * there with PROJCURVE_END_CURVATURE_CENTRE; one born there starts with
 * PROJCURVE_START_SILHOUETTE. A branch through an edge of the domain
 * collapsed to a point (the pole of a NURBS sphere) or across the seam of
 * a closed surface stays one branch whose pcurve jumps there (see
 * projcurve_result_branch_seam_count). Same result and statuses as the
 * directional projection (ZERO_DIRECTION aside), CANCELLED included. */
PROJCURVE_API projcurve_status projcurve_project_orthogonal(projcurve_context *ctx,
                                                            const projcurve_surface *surface,
                                                            const projcurve_curve *curve,
                                                            const projcurve_options *opts,
                                                            projcurve_result **out);

/* Many curves onto one surface in one call (a text, a wire): curves[i]
 * (n of them) projected along dir (as projcurve_project_directional) or
 * orthogonally (as projcurve_project_orthogonal), each with the same
 * options, results[i] receiving the result of curves[i] exactly as the
 * single-curve call would give it (NULL where that call keeps none:
 * every status but OK, LIMIT_REACHED and CANCELLED). opts may be NULL.
 * Each curve is its own call: TIME_LIMIT and MAX_WORK apply per curve,
 * the progress callback reports each curve's fractions.
 * Threads: PROJCURVE_OPT_THREADS (default 1) workers, the calling thread
 * among them, share out the curves; the results are the same bit for bit
 * whatever the count (each curve is projected independently, every worker
 * with its own state). With more than one, curve callbacks and the
 * progress callback run on the worker threads: curve callbacks
 * concurrently (they must be thread-safe), the progress callback never
 * concurrently (the call serialises it).
 * Per-curve failures: statuses[i] (statuses may be NULL) gets the status
 * of curve i (a NULL curves[i] is NULL_ARGUMENT there, the other curves
 * are still projected). The call returns OK when every curve gave OK;
 * otherwise the status of the lowest-index curve that did not, ctx
 * recording that curve's message as "curve i: <message>". Statuses of the
 * call itself (nothing projected, results untouched): NULL_ARGUMENT (ctx,
 * surface, dir, or curves / results with n > 0), NOT_FINITE,
 * ZERO_DIRECTION, OUT_OF_RANGE (options), NO_MEMORY. n = 0 is OK.
 * Thread-safe for distinct contexts; the inputs are only read. */
PROJCURVE_API projcurve_status projcurve_project_curves_directional(
    projcurve_context *ctx, const projcurve_surface *surface,
    const projcurve_curve *const *curves, size_t n, const double dir[3],
    const projcurve_options *opts, projcurve_result **results, projcurve_status *statuses);

/* The same for the orthogonal projection (see above). */
PROJCURVE_API projcurve_status projcurve_project_curves_orthogonal(
    projcurve_context *ctx, const projcurve_surface *surface,
    const projcurve_curve *const *curves, size_t n, const projcurve_options *opts,
    projcurve_result **results, projcurve_status *statuses);

/* An implicit surface f(x) = 0: fills *value, grad[3] and hess[9] (row-major)
 * at x and returns 0; any other return value is a failure. */
typedef int (*projcurve_implicit_fn)(void *user, const double x[3], double *value,
                                     double grad[3], double hess[9]);

/* Orthogonal projection onto an implicit surface ([PW96], eq. 32): traces the
 * foot point curve in 3-space starting from the foot point of P(t0) nearest
 * to it. One branch only: the other foot points of P(t0) and branches born
 * in mid-curve are not traced (the callback gives no global view of the
 * surface to find them; projcurve_project_orthogonal traces every branch on
 * a NURBS surface). Branches carry 3D points instead of (u, v) and composed pieces are a
 * cubic B-spline approximation within eps_D (degree-3 pieces over
 * [t_i, t_i+1], C1 at the joins; their uv_range is 0). The branch ends at
 * the end of the curve, at a centre of curvature, or where the corrector
 * cannot continue. model_size sets the scale for relative tolerances (> 0).
 * Statuses: as projcurve_project_orthogonal, plus INVALID_ARGUMENT
 * (model_size <= 0), CALLBACK (fn failed or gave NaN/inf), SINGULAR
 * (zero gradient) and NOT_CONVERGED (no foot point of P(t0) found). A
 * limit or a cancel while fitting keeps the pieces made up to it; the
 * branch then ends with PROJCURVE_END_LIMIT. */
PROJCURVE_API projcurve_status projcurve_project_orthogonal_implicit(projcurve_context *ctx,
                                                                     projcurve_implicit_fn fn,
                                                                     void *user,
                                                                     double model_size,
                                                                     const projcurve_curve *curve,
                                                                     const projcurve_options *opts,
                                                                     projcurve_result **out);

/* ======================================================================== */
/* Results                                                                   */
/* ======================================================================== */

/* Why a branch starts. */
typedef enum projcurve_branch_start {
    PROJCURVE_START_CURVE_START = 0, /* seeded at the start of the curve */
    PROJCURVE_START_JUMP = 1,        /* born in mid-curve (jump detection) */
    PROJCURVE_START_BOUNDARY = 2,    /* enters through the boundary of S */
    PROJCURVE_START_SILHOUETTE = 3,  /* born at a fold where Dir is tangent to S
                                        (orthogonal: at a centre of curvature) */
    PROJCURVE_START_CURVE_CROSSING = 4, /* directional, conical: the curve meets S here;
                                         before it the surface lies behind the
                                         curve ((q - p).Dir < 0) */
    PROJCURVE_START_FAILED = 5,      /* resumes after a stretch the library could
                                        not follow or not verify (the branch
                                        before it ends PROJCURVE_END_FAILED) */
    PROJCURVE_START_TRIM = 6,        /* onto a face: enters the face through one
                                        of its trimming loops */
    PROJCURVE_START_VISIBLE = 8,     /* PROJCURVE_OPT_HITS nearest: becomes the
                                        nearest point again here */
    PROJCURVE_START_MAX_DISTANCE = 9 /* comes within PROJCURVE_OPT_MAX_DISTANCE
                                        of P(t) here */
} projcurve_branch_start;

/* Why a branch ends. */
typedef enum projcurve_branch_end {
    PROJCURVE_END_CURVE_END = 0,     /* reached the end of the curve */
    PROJCURVE_END_BOUNDARY = 1,      /* left S through its boundary */
    PROJCURVE_END_SILHOUETTE = 2,    /* met a fold (det J = 0) */
    PROJCURVE_END_CURVATURE_CENTRE = 3, /* orthogonal: P(t) at a centre of curvature */
    PROJCURVE_END_LIMIT = 4,         /* a size limit stopped it */
    PROJCURVE_END_FAILED = 5,        /* the corrector could not continue, or what
                                        follows could not be verified */
    PROJCURVE_END_CURVE_CROSSING = 6, /* directional, conical: the curve meets S here;
                                        beyond it the surface lies behind the
                                        curve ((q - p).Dir < 0) */
    PROJCURVE_END_TRIM = 7,          /* onto a face: leaves the face through one
                                        of its trimming loops */
    PROJCURVE_END_OCCLUDED = 8,      /* PROJCURVE_OPT_HITS nearest: another
                                        point becomes nearer here */
    PROJCURVE_END_MAX_DISTANCE = 9   /* leaves PROJCURVE_OPT_MAX_DISTANCE of
                                        P(t) here */
} projcurve_branch_end;

/* Statistics keys for projcurve_result_stat. */
typedef enum projcurve_stat {
    PROJCURVE_STAT_POINTS = 0,        /* traced points, all branches */
    PROJCURVE_STAT_STEPS = 1,         /* predictor steps attempted */
    PROJCURVE_STAT_NEWTON_ITERATIONS = 2,
    PROJCURVE_STAT_AVG_ERROR = 3,     /* [SY13] eq. (3.8): mean estimation error of the
                                         predicted points, |Dir x (S - P)| / |S - P| */
    PROJCURVE_STAT_JUMPS = 4,         /* branches found in mid-curve */
    PROJCURVE_STAT_PIECES = 5,        /* composed pieces, all branches */
    PROJCURVE_STAT_TOL_DISTANCE = 6,  /* eps_D actually used (model units) */
    PROJCURVE_STAT_MAX_ERROR = 7      /* largest estimation error (3.8) */
} projcurve_stat;

PROJCURVE_API void projcurve_result_destroy(projcurve_result *result);

/* Number of branches (0 for NULL). Thread-safe. */
PROJCURVE_API size_t projcurve_result_branch_count(const projcurve_result *result);

/* A statistic. Statuses: OK, NULL_ARGUMENT, UNKNOWN_OPTION (key). */
PROJCURVE_API projcurve_status projcurve_result_stat(projcurve_context *ctx,
                                                     const projcurve_result *result,
                                                     projcurve_stat key, double *value);

/* Branch summary (outputs may be NULL): curve parameter range, how it
 * started and ended, number of traced points and of composed pieces.
 * Statuses: OK, NULL_ARGUMENT, INDEX. */
PROJCURVE_API projcurve_status projcurve_result_branch_info(projcurve_context *ctx,
                                                            const projcurve_result *result,
                                                            size_t branch,
                                                            double t_range[2],
                                                            projcurve_branch_start *start,
                                                            projcurve_branch_end *end,
                                                            size_t *n_points,
                                                            size_t *n_pieces);

/* The traced polyline (the 2D pcurve) of a branch: up to capacity vertices
 * are written as (t, u, v) triples ((t, x, y, z) quadruples for implicit
 * results, see projcurve_result_point_dim); *count receives the vertex count.
 * Statuses: OK, NULL_ARGUMENT, INDEX. */
PROJCURVE_API projcurve_status projcurve_result_branch_points(projcurve_context *ctx,
                                                              const projcurve_result *result,
                                                              size_t branch,
                                                              size_t capacity,
                                                              double *points,
                                                              size_t *count);

/* 3 for (t, u, v) results of parametric surfaces, 4 for (t, x, y, z)
 * results of implicit surfaces (0 for NULL). */
PROJCURVE_API int projcurve_result_point_dim(const projcurve_result *result);

/* One composed piece of a branch: a Bezier curve of degree *degree with
 * *degree + 1 control points (3 doubles each) and weights (all 1 when not
 * rational), over the curve-parameter range range[2]; uv_range[4] gives
 * (u, v) at its start and end. Output arrays must hold
 * PROJCURVE_MAX_PIECE_POINTS points. Any output may be NULL.
 * Statuses: OK, NULL_ARGUMENT, INDEX. */
#define PROJCURVE_MAX_PIECE_POINTS (2 * PROJCURVE_MAX_DEGREE + 1)
PROJCURVE_API projcurve_status projcurve_result_piece(projcurve_context *ctx,
                                                      const projcurve_result *result,
                                                      size_t branch, size_t piece,
                                                      int *degree, double *ctrl,
                                                      double *weights, double range[2],
                                                      double uv_range[4]);

/* The pcurve of one composed piece: the piece is S(u(s), v(s)) for s in
 * [0, 1], where (u, v)(s) is the Bezier curve of degree *degree (1 or 3, see
 * PROJCURVE_OPT_PCURVE_DEGREE) with the *degree + 1 control points written
 * to uv_ctrl as (u, v) pairs; uv_ctrl must hold PROJCURVE_MAX_PCURVE_POINTS
 * pairs. s runs the same way as the piece's curve parameter range. Either
 * output may be NULL. Statuses: OK, NULL_ARGUMENT, INDEX, INVALID_ARGUMENT
 * (a result of an implicit surface: no (u, v)). Thread-safe for distinct
 * contexts (the result is only read). */
#define PROJCURVE_MAX_PCURVE_POINTS 4
PROJCURVE_API projcurve_status projcurve_result_piece_pcurve(projcurve_context *ctx,
                                                             const projcurve_result *result,
                                                             size_t branch, size_t piece,
                                                             int *degree, double *uv_ctrl);

/* The number of places where the library could not continue or could not
 * verify the projection: branches that start with PROJCURVE_START_FAILED or
 * end with PROJCURVE_END_FAILED (one that does both counts once), plus
 * traced stretches of which nothing could be verified (they are not
 * returned). Every branch returned is verified (each vertex satisfies the
 * projection condition to the corrector's tolerance, each composed piece is
 * within eps_D of the exact projection), so a count of 0 means the result
 * is the whole projection as far as the seeds found it; otherwise parts of
 * it are missing between the FAILED ends. A caller that needs the whole
 * projection should treat a non-zero count as an error (the projcurve
 * command exits 1), or retry with other options (a looser eps_D or eps_T,
 * PROJCURVE_OPT_PCURVE_DEGREE 1). 0 for NULL. Thread-safe (the result is
 * only read). */
PROJCURVE_API size_t projcurve_result_failure_count(const projcurve_result *result);

/* The whole branch as one NURBS curve handle (pieces joined, knots at the
 * joins: exactly on S, degree p + q or 3 (p + q), hundreds or thousands of
 * poles; for CAD output the compact forms below are the default), usable
 * with the curve functions; release with projcurve_curve_destroy.
 * Statuses: OK, NULL_ARGUMENT, INDEX, NO_MEMORY, INVALID_ARGUMENT (branch
 * without composed pieces), OUT_OF_RANGE (a branch over a t range narrower
 * than a curve's domain may be, see projcurve_curve_create_nurbs: read its
 * pieces with projcurve_result_piece; the IGES writer writes its traced
 * pcurve). */
PROJCURVE_API projcurve_status projcurve_result_branch_curve(projcurve_context *ctx,
                                                             const projcurve_result *result,
                                                             size_t branch,
                                                             projcurve_curve **out);

/* Compact results. A composing projection (PROJCURVE_OPT_COMPOSE 1) also
 * gives each branch on a parametric surface two light B-splines over the
 * branch's curve-parameter range (t increasing, whichever way the branch
 * was traced), the output meant for CAD systems: what the IGES writer
 * writes and the projcurve command reports.
 *
 * The compact pcurve q(t): one cubic B-spline in (u, v) with as few poles
 * as it takes for S(q(t)) to lie within eps_D of the exact projection at
 * the same t, measured against exact points of the projection (20 per
 * knot span, and the samples it was fitted to). S o q lies exactly on S.
 * It is C2 but at the knot lines of S that the branch crosses where S is
 * C^k, k < 2 (there C^k: a knot of multiplicity 3 - k), at the knots of
 * the curve P where P is C^k, k < 2 (the same), and at the branch's
 * creases (pieces meeting at more than max(5, 4 eps_T) degrees: C0).
 * Where the projection is an affine image of the NURBS curve P over its
 * whole domain (onto an affinely parametrised plane) it is P's own spline
 * space instead (P's degree, knots and weights, so a circle stays a
 * circle), when that has at most 32 poles or the fit needs more. When the fit does not meet eps_D within 3 n_pieces + 1 poles
 * (e.g. where the exact points cannot be had) or the call's budget
 * stopped it, the pcurve is the pieces' pcurves joined (cubic, knots of
 * multiplicity 3 at the joins), which verification checked:
 * projcurve_result_branch_compact_info tells which.
 *
 * The compact 3D curve C(t): one polynomial B-spline of degree
 * PROJCURVE_OPT_CURVE_DEGREE (default 5) with the fewest poles the fit
 * finds within eps_D of the exact projection at the same t (the same
 * check); not exactly on S, but within eps_D of it. C^(degree - 1) but at
 * the same places (C^k there, also where 2 <= k < degree - 1 while there
 * are at most 16 such places, e.g. a cubic curve's knots). In P's space too where exact (as above,
 * when P's degree is at most PROJCURVE_OPT_CURVE_DEGREE).
 *
 * On request, projcurve_result_branch_compact_exact composes the compact
 * pcurve with S exactly: one NURBS curve on S to rounding, of degree
 * 3 (p + q).
 *
 * Fitting happens in the projection call, after verification, under its
 * budget; results stay read-only afterwards (thread-safe). */

/* The compact pcurve of a branch as a new curve handle whose control
 * points are (u, v, 0) (weights only in P's rational space); release with
 * projcurve_curve_destroy. Its domain is the branch's t range.
 * Statuses: OK, NULL_ARGUMENT, INDEX, INVALID_ARGUMENT (no compact forms:
 * the branch is not composed, or the result is implicit), NO_MEMORY.
 * Thread-safe (the result is only read). */
PROJCURVE_API projcurve_status projcurve_result_branch_compact_pcurve(
    projcurve_context *ctx, const projcurve_result *result, size_t branch,
    projcurve_curve **out);

/* The compact 3D curve of a branch as a new curve handle; release with
 * projcurve_curve_destroy. Statuses: OK, NULL_ARGUMENT, INDEX,
 * INVALID_ARGUMENT (as above), LIMIT_REACHED (the fit found no curve
 * within eps_D with at most n_pieces * degree + 1 poles, or the call's
 * budget stopped it: the pieces and the compact pcurve remain), NO_MEMORY.
 * Thread-safe. */
PROJCURVE_API projcurve_status projcurve_result_branch_compact_curve(
    projcurve_context *ctx, const projcurve_result *result, size_t branch,
    projcurve_curve **out);

/* Seams and poles. On a surface closed in u (S(u0, v) = S(u1, v) for every
 * v: a full cylinder, sphere, torus, surface of revolution) or in v, and
 * through an edge of the domain collapsed to a point (a pole), a branch
 * that crosses the seam or passes the pole is ONE branch (see
 * docs/seams.md for the closure test, read on the control net to 1e-9 of
 * the model size): its pcurve jumps there, at a recorded curve parameter
 * t_k, by (du_k, dv_k) = (u, v) just after minus just before (by the
 * period across a seam: du = -(u1 - u0) going from u1 to u0; at a pole
 * in the coordinate the collapsed edge runs along, e.g. du = +-1/2 of
 * the period through the pole of a sphere along a meridian). Where it
 * jumps:
 * - the traced points hold both sides: two vertices at t_k (the last of
 *   the side before and the first of the side after, each where its own
 *   trace reached the seam: their t agree to the tracer's resolution,
 *   ~1e-10 of the curve's domain, not bit for bit; t_k is the second);
 * - each composed piece lies on one side (no piece spans a jump), in
 *   increasing t;
 * - the compact pcurve is one B-spline in unwrapped (u, v): continuous
 *   across t_k, where the (u, v) on S is the compact pcurve's value plus
 *   the sum of (du_k, dv_k) over the jumps with t_k <= t;
 * - the compact 3D curve and projcurve_result_branch_curve are one curve
 *   across t_k.
 * Before these joins such a branch came back as one ending with
 * PROJCURVE_END_BOUNDARY and one starting with PROJCURVE_START_BOUNDARY
 * at the same t and point; those reasons now remain only for the real
 * boundary of S.
 * Face pieces (the branches of the per-face results of
 * projcurve_project_face / projcurve_project_shape) are parts of such
 * branches, and these functions mean the same on them: a piece that
 * crosses its face's seam (or passes a pole) within the face has the
 * jumps strictly inside its own t range, and its compact pcurve is
 * unwrapped from the piece's start, which lies in the domain (the jumps
 * of the untrimmed branch before the piece are applied to it); a piece
 * between two jumps has none and its pcurve lies in the domain. The
 * writers write a piece with jumps as one curve on surface per seam
 * segment, as any branch. */

/* The number of jumps of a branch's pcurve (0 on a branch that crosses no
 * seam or pole). Statuses: OK, NULL_ARGUMENT, INDEX. Thread-safe (the
 * result is only read). */
PROJCURVE_API projcurve_status projcurve_result_branch_seam_count(projcurve_context *ctx,
                                                                  const projcurve_result *result,
                                                                  size_t branch, size_t *count);

/* Jump k (0 <= k < the count above, in increasing t) of a branch: the
 * curve parameter *t and the jump (*du, *dv) of its pcurve there (see
 * above). Outputs may be NULL. Statuses: OK, NULL_ARGUMENT, INDEX.
 * Thread-safe. */
PROJCURVE_API projcurve_status projcurve_result_branch_seam(projcurve_context *ctx,
                                                            const projcurve_result *result,
                                                            size_t branch, size_t k, double *t,
                                                            double *du, double *dv);

/* What the fit of a branch's compact forms measured (outputs may be
 * NULL): *pcurve_fitted 1 for a fitted pcurve, 0 for the joined pieces'
 * pcurves; the largest distance of S o q (*pcurve_error) and of the 3D
 * curve (*curve_error) from the exact projection over the dense check,
 * model units, -1 where there is no fit. Statuses: OK, NULL_ARGUMENT,
 * INDEX, INVALID_ARGUMENT (as above). Thread-safe. */
PROJCURVE_API projcurve_status projcurve_result_branch_compact_info(
    projcurve_context *ctx, const projcurve_result *result, size_t branch,
    int *pcurve_fitted, double *pcurve_error, double *curve_error);

/* The exact composition of a branch's compact pcurve with the surface it
 * was projected onto, S o q, as a new NURBS curve handle (release with
 * projcurve_curve_destroy), over the branch's t range: on S to rounding,
 * where the compact 3D curve is only within eps_D of it, at the cost of
 * its degree. q is cut at its knots, at its seam jumps (the unwrapped
 * pcurve moved back into the domain, see Seams above: one curve across
 * them) and where it crosses a knot line of S; each piece of degree d
 * composed with its Bezier patch is a Bezier curve of degree d (p + q)
 * (rational when S is); the pieces are joined with knots of
 * multiplicity that degree, then copies of each join's knot are removed
 * where S o q is smoother than C0 there (C^(d - m) at a knot of q of
 * multiplicity m inside a patch, C^(p - m) across a knot line of S of
 * multiplicity m) while the curve moves by at most 256 ulps of its
 * largest pole: on S to rounding still, with fewer poles. Joins where the
 * two sides meet only C0 by construction (seam and pole jumps, creases of
 * q, knot lines where S may be only C0) keep their full multiplicity.
 * For the fitted cubic (d = 3): degree 18 on a bicubic surface, 6 on
 * a plane of degrees (1, 1), 9 on the rational cylinder (2, 1), 12 on the
 * sphere (2, 2); degrees above 25 (surfaces with p + q > 8) are given but
 * cannot be read by Open CASCADE (Geom_BSplineCurve's limit). surface must be the one the result was
 * projected onto (for a face result, the face's surface): its start is
 * checked against the branch's pieces. Computed on each call (no cache).
 * Statuses: OK, NULL_ARGUMENT, INDEX, INVALID_ARGUMENT (no compact forms,
 * as projcurve_result_branch_compact_pcurve; or another surface),
 * UNSUPPORTED (the compact pcurve is in the curve's own space above
 * cubic: read projcurve_result_branch_curve; or the degree
 * d (p + q) is above PROJCURVE_MAX_DEGREE), NO_MEMORY, OVERFLOW,
 * NOT_CONVERGED (a piece crossing one knot line more often than a cubic
 * can: not expected). Thread-safe (the result and the surface are only
 * read). */
PROJCURVE_API projcurve_status projcurve_result_branch_compact_exact(
    projcurve_context *ctx, const projcurve_result *result, const projcurve_surface *surface,
    size_t branch, projcurve_curve **out);

/* ======================================================================== */
/* Files: IGES, STEP and G+Smo XML                                           */
/* ======================================================================== */

typedef struct projcurve_model projcurve_model;

/* Reads a file: IGES (.igs/.iges), STEP (.stp/.step) or G+Smo XML (.xml),
 * recognised by content. Surfaces become surface handles, curves curve
 * handles; entities that are not read are listed (projcurve_model_skipped).
 * Statuses: OK, NULL_ARGUMENT, IO, PARSE (with line/entity in the message),
 * UNSUPPORTED, NO_MEMORY, and any surface/curve creation status. */
PROJCURVE_API projcurve_status projcurve_model_read_file(projcurve_context *ctx,
                                                         const char *path,
                                                         projcurve_model **out);

/* The same from memory (len bytes; need not be NUL-terminated). */
PROJCURVE_API projcurve_status projcurve_model_read_memory(projcurve_context *ctx,
                                                           const char *data, size_t len,
                                                           projcurve_model **out);

PROJCURVE_API void projcurve_model_destroy(projcurve_model *model);

/* Counts (0 for NULL). */
PROJCURVE_API size_t projcurve_model_surface_count(const projcurve_model *model);
PROJCURVE_API size_t projcurve_model_curve_count(const projcurve_model *model);
PROJCURVE_API size_t projcurve_model_skipped_count(const projcurve_model *model);

/* Borrowed handles, valid while the model lives (NULL past the end). */
PROJCURVE_API const projcurve_surface *projcurve_model_surface(const projcurve_model *model,
                                                               size_t index);
PROJCURVE_API const projcurve_curve *projcurve_model_curve(const projcurve_model *model,
                                                           size_t index);
/* Description of a skipped entity, e.g. "IGES entity 144 at DE 21"
 * (NULL past the end). */
PROJCURVE_API const char *projcurve_model_skipped(const projcurve_model *model,
                                                  size_t index);

/* The kind of surface index as the file gave it, a static string: "bspline"
 * (B-spline and NURBS surfaces, Bezier patches), or for the analytic
 * surfaces of STEP and IGES, read as exact rational NURBS, "plane",
 * "cylinder", "cone", "sphere", "torus", "revolution", "extrusion" and
 * (IGES 118) "ruled" (NULL past the end). In a STEP model the B-spline
 * surfaces come first, in file order, then the analytic ones, in file
 * order; in an IGES model all are in directory order. Thread-safe. */
PROJCURVE_API const char *projcurve_model_surface_kind(const projcurve_model *model,
                                                       size_t index);

/* The file's length unit: returns 1 and sets *metres_per_unit (may be NULL)
 * when the file states one (STEP: the SI_UNIT with its prefix or the
 * CONVERSION_BASED_UNIT of the geometric context; IGES: the global
 * section's units flag or name), else 0 with *metres_per_unit untouched.
 * Coordinates are not scaled: they stay in this unit. Thread-safe. */
PROJCURVE_API int projcurve_model_length_unit(const projcurve_model *model,
                                              double *metres_per_unit);

/* The file's distance precision in model units: returns 1 and sets
 * *precision (may be NULL) when the file states one (STEP: the
 * UNCERTAINTY_MEASURE_WITH_UNIT of the context; IGES: the global section's
 * minimum resolution), else 0. Thread-safe. */
PROJCURVE_API int projcurve_model_precision(const projcurve_model *model, double *precision);

/* ======================================================================== */
/* Faces and shapes: trimmed surfaces and the edges they share               */
/* ======================================================================== */

/* A face is a surface with trimming loops in its (u, v) domain: one outer
 * loop (the domain's boundary when none is given) and any number of holes,
 * each a closed chain of 2D NURBS pieces. A shape is a set of faces of a
 * model (a solid, a shell, or faces sewn by geometry) with the edges they
 * share. Both are immutable and may be read by many threads at once; a
 * face borrows its surface, which must outlive it. */
typedef struct projcurve_face projcurve_face;
typedef struct projcurve_shape projcurve_shape;

/* Where a (u, v) point is with respect to a face. ON: within the face's
 * (u, v) tolerance (projcurve_face_tolerance) of a loop. */
typedef enum projcurve_where {
    PROJCURVE_OUT = 0,
    PROJCURVE_IN = 1,
    PROJCURVE_ON = 2
} projcurve_where;

typedef enum projcurve_shape_kind {
    PROJCURVE_SHAPE_SOLID = 0,        /* MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS, IGES 186 */
    PROJCURVE_SHAPE_CLOSED_SHELL = 1, /* a CLOSED_SHELL of a surface model */
    PROJCURVE_SHAPE_OPEN_SHELL = 2,   /* an OPEN_SHELL */
    PROJCURVE_SHAPE_FACE_SET = 3      /* independent faces (IGES 144/143, untrimmed surfaces) */
} projcurve_shape_kind;

/* Piece flags (projcurve_face_piece_edge). */
#define PROJCURVE_PIECE_SEAM 1u       /* its edge appears twice in the loop */
#define PROJCURVE_PIECE_DEGENERATE 2u /* its edge is a point in 3D (a pole) */
#define PROJCURVE_PIECE_NATURAL 4u    /* a side of the domain, not an edge of the file */

/* Creates a face on surface from n_loops loops, the first the outer one
 * (n_loops = 0: the whole domain). Loop k has loop_pieces[k] pieces; piece
 * j (counted over all loops) is a 2D NURBS curve of degree degrees[j] with
 * n_ctrl[j] (u, v) control points ctrl[j] (2 doubles each), weights[j]
 * (NULL, or weights itself NULL, for polynomial pieces) and n_ctrl[j] +
 * degrees[j] + 1 knots[j]; each runs from the end of the one before, the
 * last back to the start of the first, within 100 tol_uv. tol_uv (> 0) is the width of ON;
 * 0 takes 1e-9 of the domain's size. Arrays are copied; the surface is
 * borrowed. Statuses: OK, NULL_ARGUMENT, OUT_OF_RANGE (tol_uv negative,
 * not finite or wider than the domain), BAD_DEGREE,
 * BAD_COUNT, BAD_KNOTS, NOT_FINITE, BAD_WEIGHT, INVALID_ARGUMENT (an open
 * loop, a loop of no area, a loop crossing another or itself, a hole
 * outside the outer loop or inside another hole, an outer loop leaving the
 * surface's domain by more than 100 tol_uv), LIMIT_REACHED
 * (a piece that needs more than 2^20 segments), NO_MEMORY; the message
 * names the loop and piece. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_face_create(
    projcurve_context *ctx, const projcurve_surface *surface, size_t n_loops,
    const size_t *loop_pieces, const int *degrees, const size_t *n_ctrl,
    const double *const *ctrl, const double *const *weights, const double *const *knots,
    double tol_uv, projcurve_face **out);

/* Releases a face made by projcurve_face_create (NULL is ignored). Faces of
 * a model belong to the model. */
PROJCURVE_API void projcurve_face_destroy(projcurve_face *face);

/* The face's surface (borrowed; NULL for NULL). */
PROJCURVE_API const projcurve_surface *projcurve_face_surface(const projcurve_face *face);
/* Loops, the outer one first (0 for NULL). */
PROJCURVE_API size_t projcurve_face_loop_count(const projcurve_face *face);
/* Statuses of the queries below: OK, NULL_ARGUMENT, INDEX (a loop or piece
 * past the end). Thread-safe. */
PROJCURVE_API projcurve_status projcurve_face_loop_piece_count(projcurve_context *ctx,
                                                               const projcurve_face *face,
                                                               size_t loop, size_t *count);
/* A piece's curve as stored (borrowed arrays, valid while the face lives;
 * ctrl has 2 doubles a point, *weights is NULL for a polynomial piece). Any
 * output pointer may be NULL. *sense is +1 when the loop runs along the
 * curve's parameter, -1 against it. */
PROJCURVE_API projcurve_status projcurve_face_piece_curve(
    projcurve_context *ctx, const projcurve_face *face, size_t loop, size_t piece, int *degree,
    size_t *n_ctrl, const double **ctrl, const double **weights, const double **knots,
    int *sense);
/* The 3D edge of a piece: *edge the model's id (the STEP instance number of
 * its EDGE_CURVE, or -1 when the piece has no edge), *edge_sense +1 when
 * the curve runs along the edge, *flags PROJCURVE_PIECE_*. Any output
 * pointer may be NULL. */
PROJCURVE_API projcurve_status projcurve_face_piece_edge(projcurve_context *ctx,
                                                         const projcurve_face *face, size_t loop,
                                                         size_t piece, long *edge,
                                                         int *edge_sense, unsigned *flags);
/* Where (u, v) is: IN, OUT, or ON within the face's (u, v) tolerance of a
 * loop (exactly: within tol_uv of the loops' polygons, which lie within
 * tol_uv / 4 of the loops). A point outside the domain is OUT unless it is
 * ON. Statuses: OK, NULL_ARGUMENT, NOT_FINITE. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_face_classify(projcurve_context *ctx,
                                                       const projcurve_face *face, double u,
                                                       double v, projcurve_where *where);
/* The box of the outer loop in (u, v), {u0, u1, v0, v1}, and a 3D box
 * {x0, y0, z0, x1, y1, z1} that holds the face; either may be NULL. */
PROJCURVE_API projcurve_status projcurve_face_bounds(projcurve_context *ctx,
                                                     const projcurve_face *face,
                                                     double box_uv[4], double box[6]);
/* The face's tolerances: *tol_uv the width of ON in (u, v), *tol_model the
 * model precision it was made for (0 for a caller's face). Either may be
 * NULL. */
PROJCURVE_API projcurve_status projcurve_face_tolerance(projcurve_context *ctx,
                                                        const projcurve_face *face,
                                                        double *tol_uv, double *tol_model);
/* *same_sense +1 when the face's normal is Su x Sv, -1 when opposite;
 * periodic[0], periodic[1]: the surface closes on itself across u, across
 * v; *kind the surface kind as read from the file ("bspline", "plane",
 * ...; borrowed). Any output pointer may be NULL. */
PROJCURVE_API projcurve_status projcurve_face_info(projcurve_context *ctx,
                                                   const projcurve_face *face, int *same_sense,
                                                   int periodic[2], const char **kind);

/* Faces and shapes of a model (borrowed, valid while the model lives; NULL
 * past the end, counts 0 for NULL). A face the reader could not build is
 * listed with its reason instead ("STEP #53 ADVANCED_FACE: surface kind
 * plane not built"). */
PROJCURVE_API size_t projcurve_model_face_count(const projcurve_model *model);
PROJCURVE_API const projcurve_face *projcurve_model_face(const projcurve_model *model,
                                                         size_t index);
PROJCURVE_API size_t projcurve_model_shape_count(const projcurve_model *model);
PROJCURVE_API const projcurve_shape *projcurve_model_shape(const projcurve_model *model,
                                                           size_t index);
PROJCURVE_API size_t projcurve_model_unbuilt_face_count(const projcurve_model *model);
PROJCURVE_API const char *projcurve_model_unbuilt_face(const projcurve_model *model,
                                                       size_t index);
/* The file's surface kind of an unbuilt face ("plane", ...; NULL past the end). */
PROJCURVE_API const char *projcurve_model_unbuilt_face_kind(const projcurve_model *model,
                                                            size_t index);

/* A shape's kind and, for faces sewn by geometry, the tolerance their
 * edges were matched with (0 when the file gave the edges); either may be
 * NULL. Statuses: OK, NULL_ARGUMENT. */
PROJCURVE_API projcurve_status projcurve_shape_info(projcurve_context *ctx,
                                                    const projcurve_shape *shape,
                                                    projcurve_shape_kind *kind, double *sew_tol);
/* Faces of a shape (0 / NULL past the end), and the model's index of each. */
PROJCURVE_API size_t projcurve_shape_face_count(const projcurve_shape *shape);
PROJCURVE_API const projcurve_face *projcurve_shape_face(const projcurve_shape *shape,
                                                         size_t index);
PROJCURVE_API projcurve_status projcurve_shape_face_model_index(projcurve_context *ctx,
                                                                const projcurve_shape *shape,
                                                                size_t index, size_t *model_index);
/* Edges of a shape, by increasing id: edge i has id *id and is used by
 * *n_uses face pieces (2 for an edge between two faces, 1 on a free
 * border, 2 in one face for a seam; 3 or more for an edge sewn by geometry
 * that one face splits where its neighbour does not). Use k of it is piece *piece of loop
 * *loop of the shape's face *face; *sense +1 when that loop runs along the
 * edge. Output pointers may be NULL. Statuses: OK, NULL_ARGUMENT, INDEX. */
PROJCURVE_API size_t projcurve_shape_edge_count(const projcurve_shape *shape);
PROJCURVE_API projcurve_status projcurve_shape_edge(projcurve_context *ctx,
                                                    const projcurve_shape *shape, size_t edge,
                                                    long *id, size_t *n_uses);
PROJCURVE_API projcurve_status projcurve_shape_edge_use(projcurve_context *ctx,
                                                        const projcurve_shape *shape,
                                                        size_t edge, size_t use, size_t *face,
                                                        size_t *loop, size_t *piece, int *sense);

/* ======================================================================== */
/* Projection onto faces and shapes                                          */
/* ======================================================================== */

/* The kind of a projection onto faces and shapes, and the vector it takes. */
typedef enum projcurve_projection_kind {
    PROJCURVE_PROJECT_DIRECTIONAL = 0, /* vec: the direction Dir (as projcurve_project_directional) */
    PROJCURVE_PROJECT_CONICAL = 1,     /* vec: the eye point (as projcurve_project_conical) */
    PROJCURVE_PROJECT_ORTHOGONAL = 2   /* vec: unused (may be NULL) */
} projcurve_projection_kind;

/* The projection of a curve onto a face or a shape: per face, a
 * projcurve_result of the branches clipped to the face's loops, and the
 * face pieces chained across shared edges into connected curves. Immutable
 * once made; may be read by many threads at once; released with
 * projcurve_shape_result_destroy, which releases the per-face results too. */
typedef struct projcurve_shape_result projcurve_shape_result;

/* Projects curve onto face: the projection onto the face's untrimmed
 * surface (projcurve_project_directional / _conical / _orthogonal with
 * opts, NULL for defaults), clipped to the face's loops. Where a branch crosses a loop the
 * crossing is located on the exact projection (Newton on q(t) = c(tau), the
 * loop's 2D curve, to 1e-10 of the model size in 3D) and the branch is cut
 * there: it ends with PROJCURVE_END_TRIM or starts with PROJCURVE_START_TRIM
 * (also where the untrimmed projection ends on a loop, e.g. the domain's
 * side), its traced points end at the crossing, its composed pieces are cut
 * there by subdivision (still exactly on S) and its compact forms are
 * restricted to the kept t range by knot insertion, its seam records (see
 * Seams above) are those inside that range; the parts outside are
 * dropped. The result has one face (index 0) and its connected curves are
 * its branches, chained as projcurve_project_shape chains (across a seam
 * edge of the face, and the end of a closed curve into its start).
 * Statuses: OK, NULL_ARGUMENT (face, curve, out; vec for DIRECTIONAL and
 * CONICAL), NOT_FINITE (vec), ZERO_DIRECTION, INVALID_ARGUMENT (kind),
 * SINGULAR (CONICAL: the curve passes through the eye to the model's
 * precision, as projcurve_project_conical), and those of the
 * projection onto the surface (LIMIT_REACHED and CANCELLED with the
 * partial result set in *out). The progress callback of opts is not
 * called by this function and projcurve_project_shape; TIME_LIMIT and
 * MAX_WORK bound the whole call. Thread-safe for distinct contexts. */
PROJCURVE_API projcurve_status projcurve_project_face(projcurve_context *ctx,
                                                      const projcurve_face *face,
                                                      const projcurve_curve *curve,
                                                      projcurve_projection_kind kind,
                                                      const double vec[3],
                                                      const projcurve_options *opts,
                                                      projcurve_shape_result **out);

/* Projects curve onto every face of shape that it can reach (directional:
 * the faces whose 3D boxes meet the curve's box swept along +Dir;
 * conical: those whose boxes meet the cone from the eye over the curve's
 * box, beyond the curve; orthogonal: every face), each as projcurve_project_face, with one eps_D
 * for all (unset: 1e-4 of the diagonal of the shape's box), then chains
 * the face pieces into connected curves: a piece ending with
 * PROJCURVE_END_TRIM on an edge continues with the piece starting with
 * PROJCURVE_START_TRIM on the same edge of the shape
 * (projcurve_shape_edge_use) whose start lies within the chaining
 * tolerance of its end, in 3D and on the curve (|P(t1) - P(t2)|): the
 * largest of the shape's sewing tolerance, the faces' model precision
 * (projcurve_face_tolerance) and 1e-9 of the shape's size. On a closed
 * curve (P(t0) and P(t1) within that tolerance) the piece that ends the
 * curve continues into the piece of the same face that starts it, and the
 * connected curve is closed (projcurve_shape_result_curve_info). Connected
 * curves come in increasing order of their first curve parameter, then of
 * the distance of their first point along Dir (orthogonal: from the curve).
 * With PROJCURVE_OPT_HITS nearest the nearest hit is chosen across all the
 * projected faces after clipping (a part of a face's surface outside its
 * loops hides nothing; a piece hidden by another face's piece ends with
 * PROJCURVE_END_OCCLUDED / starts with PROJCURVE_START_VISIBLE there, and
 * is not chained at that end); projcurve_project_face does the same among
 * its branches. PROJCURVE_OPT_MAX_DISTANCE applies to each face.
 * A face whose projection fails is kept with its status and message
 * (projcurve_shape_result_face) and the others are still projected and
 * chained; a piece that ends on an edge with no continuation (the other
 * face is missing, e.g. not built by the reader, or lies beyond the
 * chaining tolerance) ends its connected curve, and is counted in
 * projcurve_shape_result_open_end_count (see there).
 * With PROJCURVE_OPT_HITS nearest, a stop by TIME_LIMIT or MAX_WORK while
 * selecting the nearest hits across the faces keeps the nearest parts of
 * the face pieces selected so far and drops the others (LIMIT_REACHED, the
 * message saying "... while selecting the nearest hits across faces");
 * each face whose pieces were not all selected then has that status too
 * in projcurve_shape_result_face, the faces selected in full keep theirs.
 * Statuses: those of projcurve_project_face; a failed face alone does not
 * fail the call. Thread-safe for distinct contexts. */
PROJCURVE_API projcurve_status projcurve_project_shape(projcurve_context *ctx,
                                                       const projcurve_shape *shape,
                                                       const projcurve_curve *curve,
                                                       projcurve_projection_kind kind,
                                                       const double vec[3],
                                                       const projcurve_options *opts,
                                                       projcurve_shape_result **out);

/* Releases a shape result and its per-face results (NULL is ignored). */
PROJCURVE_API void projcurve_shape_result_destroy(projcurve_shape_result *result);

/* Connected curves (0 for NULL). Thread-safe. */
PROJCURVE_API size_t projcurve_shape_result_curve_count(const projcurve_shape_result *result);

/* A connected curve (outputs may be NULL): its number of face pieces, its
 * curve-parameter range (t of its first piece's start, t of its last
 * piece's end) and *closed 1 when its last piece chains into its first.
 * Statuses: OK, NULL_ARGUMENT, INDEX. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_shape_result_curve_info(
    projcurve_context *ctx, const projcurve_shape_result *result, size_t curve,
    size_t *n_pieces, double t_range[2], int *closed);

/* Face piece `piece` of connected curve `curve` (outputs may be NULL):
 * *face the index of its face in the shape (0 for projcurve_project_face;
 * projcurve_shape_face_model_index gives the model's), and the piece as a
 * branch of that face's result: *face_result (borrowed, valid while the
 * shape result lives) and *branch, to be read with the projcurve_result
 * functions (points = pcurve on that face, pieces, compact forms); its t
 * range and start / end reasons as projcurve_result_branch_info gives them.
 * Statuses: OK, NULL_ARGUMENT, INDEX. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_shape_result_piece(
    projcurve_context *ctx, const projcurve_shape_result *result, size_t curve, size_t piece,
    size_t *face, const projcurve_result **face_result, size_t *branch, double t_range[2],
    projcurve_branch_start *start, projcurve_branch_end *end);

/* Faces that were projected (0 for NULL): those whose box the swept curve
 * meets, in the order of the shape. */
PROJCURVE_API size_t projcurve_shape_result_face_count(const projcurve_shape_result *result);

/* Projected face i (outputs may be NULL): *face its index in the shape,
 * *face_result its clipped result (borrowed; NULL when its projection
 * failed), *status the status of its projection and *message its message
 * ("" on OK; borrowed). Statuses: OK, NULL_ARGUMENT, INDEX. Thread-safe. */
PROJCURVE_API projcurve_status projcurve_shape_result_face(
    projcurve_context *ctx, const projcurve_shape_result *result, size_t index, size_t *face,
    const projcurve_result **face_result, projcurve_status *status, const char **message);

/* Gaps between faces (0 for NULL): ends of face pieces on an edge that
 * found no continuation where one was due, either because the edge's other
 * face is missing (the edge has one use in a solid or closed shell: e.g. a
 * face the reader could not build) or because a piece of the other face
 * starts (ends) on the same edge within 1000 chaining tolerances but not
 * within one (faces that do not meet within the model's precision). An end
 * on a free border, or on a silhouette edge beyond which Dir grazes the
 * next face, is not a gap. Thread-safe. */
PROJCURVE_API size_t projcurve_shape_result_open_end_count(const projcurve_shape_result *result);

/* The chaining tolerance the result was made with, model units (0 for NULL). */
PROJCURVE_API double projcurve_shape_result_chain_tolerance(const projcurve_shape_result *result);

/* An IGES writer: collect surfaces, curves and projection results, then
 * write them as one IGES 5.3 file. */
typedef struct projcurve_iges_writer projcurve_iges_writer;

/* Creates an empty writer in *out; release it with
 * projcurve_iges_writer_destroy. ctx receives the message of a failure and
 * may be NULL. Statuses: OK, NULL_ARGUMENT (out is NULL), NO_MEMORY.
 * Thread-safe; a writer itself is to be used by one thread at a time. */
PROJCURVE_API projcurve_status projcurve_iges_writer_create(projcurve_context *ctx,
                                                            projcurve_iges_writer **out);
/* Releases a writer (NULL is ignored). */
PROJCURVE_API void projcurve_iges_writer_destroy(projcurve_iges_writer *writer);

/* Adds a surface (entity 128); the surface is copied.
 * Statuses: OK, NULL_ARGUMENT, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_iges_writer_add_surface(projcurve_context *ctx,
                                                                 projcurve_iges_writer *w,
                                                                 const projcurve_surface *s);
/* Adds a NURBS curve (entity 126). Statuses: OK, NULL_ARGUMENT, WRONG_KIND
 * (callback curve), NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_iges_writer_add_curve(projcurve_context *ctx,
                                                               projcurve_iges_writer *w,
                                                               const projcurve_curve *c);
/* Adds every branch of a projection result onto s: a 3D curve (126) and a
 * curve on surface (142, preference 3: both describe the projection) with
 * its 2D pcurve (126 in z = 0, status "parametric"); s is written too if it
 * was not added before. A composed branch is written in its compact forms
 * (projcurve_result_branch_compact_pcurve and _compact_curve, each within
 * eps_D of the projection, of degree at most 25; where the compact 3D curve
 * is missing, the pieces joined); a branch not composed, or over a t range
 * narrower than a curve's domain may be, as its traced points (a degree-1
 * pcurve, no 3D curve). On failure the writer is left as it was (none of
 * the result's entities added). Statuses: OK, NULL_ARGUMENT,
 * INVALID_ARGUMENT (an implicit result, or a result of another surface: a
 * branch starting outside s's domain, or its first composed point more
 * than 4 eps_D from S there), NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_iges_writer_add_result(projcurve_context *ctx,
                                                                projcurve_iges_writer *w,
                                                                const projcurve_surface *s,
                                                                const projcurve_result *r);
/* The same with the composed pieces: the 3D curve is the pieces joined
 * (projcurve_result_branch_curve) and the pcurve their pcurves joined, so
 * that S composed with the pcurve is the 3D curve exactly (degree p + q,
 * or 3 (p + q) with cubic pcurves; hundreds of pieces). Statuses: those of
 * projcurve_iges_writer_add_result. */
PROJCURVE_API projcurve_status projcurve_iges_writer_add_result_pieces(
    projcurve_context *ctx, projcurve_iges_writer *w, const projcurve_surface *s,
    const projcurve_result *r);
/* The length unit of the file, in metres per unit (the default of a new
 * writer is millimetres, 0.001): give the unit of the model the geometry
 * came from (projcurve_model_length_unit) so that a CAD system imports it
 * at its size. It is written as the IGES units flag and name (global
 * parameters 14 and 15) of inch, mm, foot, mile, metre, km, mil, micron,
 * cm or microinch, matched to 1e-9 relative. Nothing is scaled.
 * Statuses: OK, NULL_ARGUMENT, NOT_FINITE, OUT_OF_RANGE (none of those
 * units); on failure the writer keeps its unit. */
PROJCURVE_API projcurve_status projcurve_iges_writer_set_length_unit(projcurve_context *ctx,
                                                                     projcurve_iges_writer *w,
                                                                     double metres_per_unit);
/* Writes the file. Statuses: OK, NULL_ARGUMENT, IO, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_iges_writer_write(projcurve_context *ctx,
                                                           const projcurve_iges_writer *w,
                                                           const char *path);
/* Adds every connected curve of a shape result
 * (projcurve_shape_result_curve_count) as one composite curve (entity
 * 102, independent) whose members are its face pieces' 3D curves
 * (entity 126, physically dependent) in chain order
 * (projcurve_shape_result_piece): each the piece's compact 3D curve
 * (projcurve_result_branch_compact_curve; where its fit found none, the
 * composed pieces joined, projcurve_result_branch_curve), over the
 * piece's t range; a piece the chain runs along with t decreasing is
 * written reversed (parameter t0 + t1 - t), so that each member starts
 * where the one before ends (within the fits' errors). A connected curve
 * of one piece is a 102 of one member too, so that every connected curve
 * is one 102 in the file. Neither the faces' surfaces nor pcurves are
 * written (add them with projcurve_iges_writer_add_surface /
 * _add_result). A result without connected curves adds nothing (OK). On
 * failure the writer is left as it was. Statuses: OK, NULL_ARGUMENT (w or
 * r, with a message), INVALID_ARGUMENT (a piece without composed pieces:
 * PROJCURVE_OPT_COMPOSE 0, or a limit reached before it; the message names
 * the connected curve and piece), OUT_OF_RANGE (a piece over a t range
 * too narrow for a curve, as projcurve_result_branch_curve), NO_MEMORY.
 * The result may be read by
 * other threads meanwhile; the writer is used by one thread at a time. */
PROJCURVE_API projcurve_status projcurve_iges_writer_add_shape_result(
    projcurve_context *ctx, projcurve_iges_writer *w, const projcurve_shape_result *r);

/* A STEP writer: collect surfaces, curves and projection results, then
 * write them as one STEP file (ISO 10303-21, schema AP214
 * AUTOMOTIVE_DESIGN): a product whose shape is a geometric set of the
 * surfaces (B_SPLINE_SURFACE_WITH_KNOTS), the curves
 * (B_SPLINE_CURVE_WITH_KNOTS) and, per branch of a result, a
 * SURFACE_CURVE; the rational complex entities where a weight is not 1.
 * Every real is written with 17 significant digits: the file holds the
 * doubles of the geometry exactly. */
typedef struct projcurve_step_writer projcurve_step_writer;

/* Creates an empty writer in *out (millimetres, uncertainty 1e-7);
 * release it with projcurve_step_writer_destroy. ctx receives the message
 * of a failure and may be NULL. Statuses: OK, NULL_ARGUMENT (out is NULL),
 * NO_MEMORY. Thread-safe; a writer itself is to be used by one thread at a
 * time. */
PROJCURVE_API projcurve_status projcurve_step_writer_create(projcurve_context *ctx,
                                                            projcurve_step_writer **out);
/* Releases a writer (NULL is ignored). */
PROJCURVE_API void projcurve_step_writer_destroy(projcurve_step_writer *writer);

/* Adds a surface (B_SPLINE_SURFACE_WITH_KNOTS); the surface is copied
 * into the writer's text, and written once however often it is added
 * (surfaces are compared by their data, exactly). Statuses: OK,
 * NULL_ARGUMENT, NO_MEMORY; on failure the writer is left as it was. */
PROJCURVE_API projcurve_status projcurve_step_writer_add_surface(projcurve_context *ctx,
                                                                 projcurve_step_writer *w,
                                                                 const projcurve_surface *s);
/* Adds a NURBS curve (B_SPLINE_CURVE_WITH_KNOTS). Statuses: OK,
 * NULL_ARGUMENT, WRONG_KIND (callback curve), NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_step_writer_add_curve(projcurve_context *ctx,
                                                               projcurve_step_writer *w,
                                                               const projcurve_curve *c);
/* Adds every branch of a projection result onto s as a SURFACE_CURVE: its
 * compact 3D curve (projcurve_result_branch_compact_curve; where the fit
 * found none, the pieces joined, projcurve_result_branch_curve) with its
 * compact pcurve (projcurve_result_branch_compact_pcurve) as the PCURVE
 * on s (a 2D B-spline in a DEFINITIONAL_REPRESENTATION), the pcurve the
 * master representation; s is written too if it was not added before.
 * The curves run over the branch's t range, t increasing. Unless an
 * uncertainty was set, the file's uncertainty becomes at least the
 * largest distance between the two forms the fits measured (each is
 * within its measured error of the exact projection). On failure the
 * writer is left as it was (none of the result added). Statuses: OK,
 * NULL_ARGUMENT, INVALID_ARGUMENT (an implicit result, a branch without
 * compact forms: not composed, or a result of another surface, as
 * projcurve_iges_writer_add_result), NO_MEMORY, and those of
 * projcurve_result_branch_curve. */
PROJCURVE_API projcurve_status projcurve_step_writer_add_result(projcurve_context *ctx,
                                                                projcurve_step_writer *w,
                                                                const projcurve_surface *s,
                                                                const projcurve_result *r);
/* The length unit of the file, in metres per unit (default millimetres,
 * 0.001): give the unit of the model the geometry came from
 * (projcurve_model_length_unit). Metre with an SI prefix (mm, cm, dm, m,
 * km, um, nm, matched to 1e-9 relative) is written as an SI_UNIT, any
 * other size (inch, foot, ...) as a CONVERSION_BASED_UNIT of exactly this
 * many metres. Nothing is scaled. Statuses: OK, NULL_ARGUMENT, NOT_FINITE,
 * OUT_OF_RANGE (not positive); on failure the writer keeps its unit. */
PROJCURVE_API projcurve_status projcurve_step_writer_set_length_unit(projcurve_context *ctx,
                                                                     projcurve_step_writer *w,
                                                                     double metres_per_unit);
/* The distance uncertainty of the file (the context's
 * UNCERTAINTY_MEASURE_WITH_UNIT), in model units; written as given, no
 * longer raised by projcurve_step_writer_add_result. Statuses: OK,
 * NULL_ARGUMENT, NOT_FINITE, OUT_OF_RANGE (not positive). */
PROJCURVE_API projcurve_status projcurve_step_writer_set_uncertainty(projcurve_context *ctx,
                                                                     projcurve_step_writer *w,
                                                                     double distance);
/* Writes the file; the writer stays usable (more may be added and
 * written again). Statuses: OK, NULL_ARGUMENT, IO, NO_MEMORY. */
PROJCURVE_API projcurve_status projcurve_step_writer_write(projcurve_context *ctx,
                                                           const projcurve_step_writer *w,
                                                           const char *path);

/* Adds every connected curve of a shape result as one COMPOSITE_CURVE
 * (self_intersect .U.), an element of the geometric set, of one
 * COMPOSITE_CURVE_SEGMENT per face piece in chain order, each over the
 * piece's 3D curve as projcurve_iges_writer_add_shape_result takes it
 * (B_SPLINE_CURVE_WITH_KNOTS, the rational complex entity where a weight
 * is not 1; t increasing, same_sense .F. where the chain runs along it
 * with t decreasing, else .T.). A segment's transition is .CONTINUOUS.
 * where its last point and the next segment's first lie within the
 * result's chaining tolerance (projcurve_shape_result_chain_tolerance),
 * else .DISCONTINUOUS.; the last segment's is .CONTINUOUS. only on a
 * closed connected curve whose ends meet so. Surfaces and pcurves are not
 * written; the uncertainty is not changed. A result without connected
 * curves adds nothing (OK). On failure the writer is left as it was.
 * Statuses: OK, NULL_ARGUMENT (w or r, with a message), INVALID_ARGUMENT
 * and OUT_OF_RANGE (a piece without a 3D curve, as there), NOT_FINITE,
 * NO_MEMORY.
 * The result may be read by other threads meanwhile; the writer is used
 * by one thread at a time. */
PROJCURVE_API projcurve_status projcurve_step_writer_add_shape_result(
    projcurve_context *ctx, projcurve_step_writer *w, const projcurve_shape_result *r);

#ifdef __cplusplus
}
#endif

#endif /* PROJCURVE_H */
