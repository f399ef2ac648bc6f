/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Least squares over a knot vector (fit/lsq.h):
 *   - samples of a spline of the fit's own space (degree 5, 9 spans,
 *     uneven knots, 3D) are reproduced: poles to 1e-10 (the ridge pulls at
 *     1e-12 of the differences), values to 1e-10 at 1,001 parameters;
 *   - the precomputed-basis path (pc_lsq_rows_fill, pc_lsq_fit_rows,
 *     pc_lsq_eval_row) gives the same poles and values as the direct one
 *     bit for bit, with a fixed pole, rational and polynomial, and with
 *     rows reused from a larger fill;
 *   - 10 samples for 14 poles (the ridge alone makes the system
 *     definite): both paths give the same status and the same poles.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "fit/lsq.h"

/* A check with a message of its own. */
#define EXPECT(cond, ...)                                       \
    do {                                                        \
        ++pc_test_checks;                                       \
        if (!(cond))                                            \
            pc_test_fail_at(__FILE__, __LINE__, __VA_ARGS__);   \
    } while (0)

#define DEGREE 5
#define N_POLES 14
#define N_SAMPLES 200

static const double knots[N_POLES + DEGREE + 1] = {
    0, 0, 0, 0, 0, 0, 0.05, 0.1, 0.3, 0.35, 0.5, 0.62, 0.8, 0.9, 1, 1, 1, 1, 1, 1};

static void reference_poles(double *poles)
{
    for (int i = 0; i < N_POLES; ++i) {
        poles[3 * i] = i + 0.3 * sin(i);
        poles[3 * i + 1] = cos(0.7 * i);
        poles[3 * i + 2] = 0.1 * i * i;
    }
}

/* rows of (t, x, y, z) as the fits read them */
static void samples(const pc_lsq_space *sp, const double *poles, double *rows)
{
    size_t hint = 0;
    for (int i = 0; i < N_SAMPLES; ++i) {
        const double t = pow((double)i / (N_SAMPLES - 1), 1.3);
        rows[4 * i] = t;
        pc_lsq_eval(sp, 3, poles, t, &hint, rows + 4 * i + 1);
    }
}

static void check_space(const double *weights, const char *what)
{
    const pc_lsq_space sp = {DEGREE, N_POLES, knots, weights};
    double ref[3 * N_POLES], rows[4 * N_SAMPLES];
    reference_poles(ref);
    samples(&sp, ref, rows);
    const size_t fixed_index[1] = {6};
    double direct[3 * N_POLES], cached[3 * N_POLES];
    CHECK(pc_lsq_fit(NULL, &sp, 3, rows, rows + 1, 4, N_SAMPLES, fixed_index, ref + 18, 1,
                     direct) == PROJCURVE_OK);
    double worst = 0.0;
    for (int i = 0; i < 3 * N_POLES; ++i)
        worst = fmax(worst, fabs(direct[i] - ref[i]));
    EXPECT(worst < 1e-10, "%s: poles off by %.3g", what, worst);

    pc_lsq_rows r;
    memset(&r, 0, sizeof r);
    /* a larger fill first: the second reuses its arrays */
    CHECK(pc_lsq_rows_fill(NULL, &sp, rows, 4, N_SAMPLES, &r) == PROJCURVE_OK);
    CHECK(pc_lsq_rows_fill(NULL, &sp, rows, 8, N_SAMPLES / 2, &r) == PROJCURVE_OK);
    CHECK(r.n == N_SAMPLES / 2);
    CHECK(pc_lsq_rows_fill(NULL, &sp, rows, 4, N_SAMPLES, &r) == PROJCURVE_OK);
    CHECK(pc_lsq_fit_rows(NULL, &sp, 3, &r, rows + 1, 4, N_SAMPLES, fixed_index, ref + 18, 1,
                          cached) == PROJCURVE_OK);
    EXPECT(memcmp(direct, cached, sizeof direct) == 0, "%s: the two paths differ", what);
    size_t hint = 0;
    int same = 1;
    double off = 0.0;
    for (size_t i = 0; i < r.n; ++i) {
        double a[3], b[3];
        pc_lsq_eval(&sp, 3, direct, rows[4 * i], &hint, a);
        pc_lsq_eval_row(&r, i, 3, cached, b);
        same &= memcmp(a, b, sizeof a) == 0;
        for (int c = 0; c < 3; ++c)
            off = fmax(off, fabs(b[c] - rows[4 * i + 1 + (size_t)c]));
    }
    EXPECT(same, "%s: row values differ from pc_lsq_eval", what);
    EXPECT(off < 1e-10, "%s: the fit is %.3g off its samples", what, off);
    for (int i = 0; i <= 1000; ++i) {
        double a[3], b[3];
        pc_lsq_eval(&sp, 3, direct, i / 1000.0, &hint, a);
        pc_lsq_eval(&sp, 3, ref, i / 1000.0, &hint, b);
        for (int c = 0; c < 3; ++c)
            off = fmax(off, fabs(a[c] - b[c]));
    }
    EXPECT(off < 1e-10, "%s: the fit is %.3g off the spline", what, off);

    /* 10 samples cannot fix 14 poles but for the ridge */
    double few[3 * N_POLES];
    CHECK(pc_lsq_rows_fill(NULL, &sp, rows, 4 * 20, 10, &r) == PROJCURVE_OK);
    const projcurve_status a = pc_lsq_fit(NULL, &sp, 3, rows, rows + 1, 4 * 20, 10, NULL, NULL,
                                          0, few);
    const projcurve_status b = pc_lsq_fit_rows(NULL, &sp, 3, &r, rows + 1, 4 * 20, 10, NULL,
                                               NULL, 0, cached);
    EXPECT(a == b, "%s: the two paths disagree on an underdetermined fit", what);
    if (a == PROJCURVE_OK)
        CHECK(memcmp(few, cached, sizeof few) == 0);
    pc_lsq_rows_free(&r);
    CHECK(r.first == NULL && r.values == NULL && r.n == 0);
}

int main(void)
{
    check_space(NULL, "polynomial");
    double weights[N_POLES];
    for (int i = 0; i < N_POLES; ++i)
        weights[i] = 1.0 + 0.5 * sin(1.7 * i) * sin(1.7 * i);
    check_space(weights, "rational");
    return pc_test_finish("test_fit_lsq");
}
