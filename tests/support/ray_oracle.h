/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Brute-force line / surface intersection for tests, independent of the
 * library's Bezier clipping: a dense triangulation of the surface (blocks of
 * cells with padded boxes to skip most triangles), a ray/triangle test per
 * triangle, and a 3x3 Newton polish of S(u, v) = o + lambda dir from each
 * triangle hit, using only a point-and-derivatives evaluator.
 *
 * It can miss a pair of hits of a line passing closer to a fold than the
 * mesh's chord error; tests accept such a hit from the library only after
 * checking it independently (pc_oracle_check_hit) and that it is grazing.
 */
#ifndef PC_TEST_RAY_ORACLE_H
#define PC_TEST_RAY_ORACLE_H

#include <stddef.h>

/* S (n_deriv 0: out[0..2]), or S, Su, Sv (n_deriv 1: out[0..8]) at (u, v).
 * The mesh needs points only, the polish derivatives too. */
typedef void (*pc_oracle_eval_fn)(void *user, double u, double v, int n_deriv, double out[9]);

typedef struct pc_oracle_hit {
    double u, v, lambda;
    double lambda_lo, lambda_hi; /* the run of copies merged into it */
    double cos_dir;   /* |dir . n| / (|dir| |n|) at the hit; the smallest over
                       * the copies merged into it; NaN where no copy has a
                       * normal */
    double edge;      /* distance to the domain's edge, fraction of the
                       * domain; the smallest over the copies */
} pc_oracle_hit;

typedef struct pc_oracle_mesh {
    pc_oracle_eval_fn eval;
    void *user;
    double domain[4];
    int cells_u, cells_v, block; /* cells per block side */
    double *us, *vs;             /* the samples: cells_u + 1, cells_v + 1 */
    double *points;              /* (cells_u + 1) * (cells_v + 1) * 3 */
    double *block_boxes;         /* 6 per block */
    int blocks_u, blocks_v;
    double *group_boxes;         /* 6 per group of blocks */
    int groups_u, groups_v;
    double scale;                /* diagonal of the points' box */
    double model_size;           /* the size pc_oracle_same_point uses: scale
                                  * unless the caller sets another */
    double centre[3];            /* of the points' box, or as the caller sets
                                  * it (pc_oracle_same_point's magnitude) */
} pc_oracle_mesh;

/* Samples the surface on a uniform cells_u x cells_v grid. Returns 0 on
 * allocation failure. */
int pc_oracle_mesh_build(pc_oracle_mesh *mesh, pc_oracle_eval_fn eval, void *user,
                         const double domain[4], int cells_u, int cells_v);

/* Samples the surface at the given parameters (increasing, from the
 * domain's start to its end: cells_u + 1 values of u, cells_v + 1 of v),
 * e.g. a few cells per knot span. Returns 0 on allocation failure. */
int pc_oracle_mesh_build_samples(pc_oracle_mesh *mesh, pc_oracle_eval_fn eval, void *user,
                                 const double *us, int cells_u, const double *vs, int cells_v);
void pc_oracle_mesh_free(pc_oracle_mesh *mesh);

/* Every hit of origin + lambda dir (lambda > 0 only if ray_only), polished,
 * with copies of one point of space merged (the same (u, v); then runs of
 * hits each within pc_oracle_same_point of the next along the line: the two
 * sides of a seam, sheets of a surface folded onto itself), sorted by
 * lambda; up to capacity are stored, the number found is returned. */
size_t pc_oracle_line_hits(const pc_oracle_mesh *mesh, const double origin[3],
                           const double dir[3], int ray_only, pc_oracle_hit *hits,
                           size_t capacity);

/* Two hits whose lambda differ by at most this are one point of space: 1e-8
 * of the model's size (mesh->model_size: the library's is the diagonal of
 * the control net's box) plus its coordinates' magnitude (where the model
 * is and how far the origin is from it), over |dir|. */
double pc_oracle_same_point(const pc_oracle_mesh *mesh, const double origin[3],
                            const double dir[3]);

/* How far S moves when (u, v) are rounded to doubles: |Su| ulp(u) +
 * |Sv| ulp(v). No double (u, v) need put S closer than half this to a
 * point of S; it matters where knot spans are far narrower than their
 * parameters' magnitude (knot clusters). */
double pc_oracle_resolution(double u, double v, const double f[9]);

/* Checks a claimed hit independently: Newton from it must stay within
 * param_tol and the polished point lie on the line to 1e-11 of the model
 * scale plus the parameters' resolution (pc_oracle_resolution). Fills *polished (may be NULL). Returns 1 if it is a hit. */
int pc_oracle_check_hit(const pc_oracle_mesh *mesh, const double origin[3], const double dir[3],
                        double u, double v, double param_tol, pc_oracle_hit *polished);

/* Counts kept by pc_oracle_compare. */
typedef struct pc_oracle_stats {
    long lines, hits, oracle_hits, grazing_extra;
    long missed, duplicated; /* oracle hits found 0 times, more than once */
    long in_run;             /* oracle hits that a claimed hit within 100 times
                              * pc_oracle_same_point stands for (a run of
                              * sheets cut differently) */
    long extra_sheets;       /* claimed hits on the line among two or more
                              * oracle hits within 100 same-point distances
                              * (sheets of a fold the mesh did not all see) */
    long cluster_sheets;     /* hits seen by one side only where one ulp of the
                              * parameters moves S by more than 1e-12 of the
                              * model (knot clusters folding many sheets) */
    long run_split;          /* runs of the oracle that the library reports
                              * as several hits, each farther than
                              * pc_oracle_same_point from the next */
    long flags_checked;   /* flags the oracle could decide, all checked */
    double max_residual;  /* largest distance of a claimed hit's S to the line */
    double max_excess;    /* largest (that distance) / (1e-12 scale + resolution) */
} pc_oracle_stats;

/* Compares the n hits of a line claimed by the library (hits[3k..3k+2] =
 * u, v, lambda, sorted by lambda; flags[k]) with the oracle's, failing the
 * test (pc_test_fail_at, with the line) when an oracle hit is not found
 * exactly once, a claimed hit is not on the line or its lambda is wrong,
 * the order is wrong, a claimed hit unknown to the oracle is not grazing
 * (|cos| >= 0.05, where the mesh cannot miss it), or a flag the oracle can
 * decide is wrong: PROJCURVE_HIT_BOUNDARY where some copy lies on the
 * domain's edge (to 1e-12) or none within 1e-7 of it; PROJCURVE_HIT_TANGENT
 * where |cos| <= 1e-9 or not where |cos| >= 1e-3 over the copies (the
 * library's threshold is 1e-6; between, the position's error decides). */
void pc_oracle_compare(const pc_oracle_mesh *mesh, const double origin[3], const double dir[3],
                       int ray_only, size_t n, const double *hits, const unsigned *flags,
                       pc_oracle_stats *stats);

#endif /* PC_TEST_RAY_ORACLE_H */
