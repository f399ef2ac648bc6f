/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Writes a seed of fuzz_project / fuzz_iges_write for each case of
 * tests/data/cases/MANIFEST.tsv: the bytes that fuzz_shapes.c maps to the
 * case's first surface and curve, approximately (degrees capped at 3, the
 * net resampled to at most 8 x 8 points and the curve to 8, coordinates
 * scaled into the targets' box), with the case's direction, kind and
 * angle tolerance. Run by hand when the byte format changes; the seeds,
 * minimised with libFuzzer's -merge=1, are tests/fuzz/corpus/.
 *   fuzz_seed_cases tests/data/cases OUT_DIR
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/curve.h"
#include "geom/surface.h"
#include "projcurve.h"

#define MAX_SEED 1024

typedef struct seed {
    unsigned char bytes[MAX_SEED];
    size_t n;
} seed;

static void put(seed *s, double signed_unit)
{
    /* inverse of fuzz_shapes.c's signed_unit: (byte - 128) / 128 */
    const double b = fmin(255.0, fmax(0.0, round(128.0 + 128.0 * signed_unit)));
    if (s->n < MAX_SEED)
        s->bytes[s->n++] = (unsigned char)b;
}

static void put_byte(seed *s, unsigned b)
{
    if (s->n < MAX_SEED)
        s->bytes[s->n++] = (unsigned char)b;
}

/* Clamped knots with unit interior increments at scale 1 (mode 0x80). */
static void put_knots(seed *s, int degree, size_t n)
{
    put_byte(s, 0x80);
    for (size_t i = (size_t)degree + 1; i <= n; ++i)
        put_byte(s, 1);
}

static int cap(int v, int hi) { return v < hi ? v : hi; }

static void encode(const projcurve_surface *sf, const projcurve_curve *cv, const double dir[3],
                   int orthogonal, double angle, seed *s)
{
    const pc_nurbs_surface *ns = &sf->nurbs;
    const pc_nurbs_curve *nc = &cv->nurbs;
    const int du = cap(ns->deg_u, 3), dv = cap(ns->deg_v, 3);
    const size_t nu = (size_t)cap((int)ns->n_u, du + 5), nv = (size_t)cap((int)ns->n_v, dv + 5);
    put_byte(s, (unsigned)((du - 1) + 3 * (dv - 1)));
    put_byte(s, (unsigned)((nu - (size_t)du - 1) + 5 * (nv - (size_t)dv - 1)));
    /* the net's box mapped onto [0, nu - 1] x [0, nv - 1] x [-2, 2] */
    const double *box = sf->box;
    const double sx = (double)(nu - 1) / fmax(box[3] - box[0], 1e-300);
    const double sy = (double)(nv - 1) / fmax(box[4] - box[1], 1e-300);
    const double sz = 4.0 / fmax(box[5] - box[2], 1e-300);
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            const size_t ci = i * (ns->n_u - 1) / (nu - 1), cj = j * (ns->n_v - 1) / (nv - 1);
            const double *h = ns->cw + 4 * (cj * ns->n_u + ci);
            const double x = (h[0] / h[3] - box[0]) * sx, y = (h[1] / h[3] - box[1]) * sy;
            const double z = (h[2] / h[3] - box[2]) * sz - 2.0;
            put(s, (x - (double)i) / 0.45);
            put(s, (y - (double)j) / 0.45);
            put(s, z / 2.0);
        }
    put_knots(s, du, nu);
    put_knots(s, dv, nv);
    const int deg = cap(nc->degree, 3);
    const size_t n = (size_t)cap((int)nc->n_ctrl, deg + 5);
    put_byte(s, (unsigned)((deg - 1) + 3 * (int)(n - (size_t)deg - 1)) | 0x40u);
    for (size_t i = 0; i < n; ++i) {
        const double *h = nc->cw + 4 * (i * (nc->n_ctrl - 1) / (n - 1));
        const double x = (h[0] / h[3] - box[0]) * sx, y = (h[1] / h[3] - box[1]) * sy;
        const double z = (h[2] / h[3] - box[2]) * sz - 2.0;
        /* inverse of 3 (u + 1) - 0.5 and of 3 u */
        put(s, (x + 0.5) / 3.0 - 1.0);
        put(s, (y + 0.5) / 3.0 - 1.0);
        put(s, z / 3.0);
    }
    put_knots(s, deg, n);
    /* direction: mode 1 (free), components scaled like the coordinates */
    const double d[3] = {dir[0] * sx, dir[1] * sy, dir[2] * sz};
    const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    put_byte(s, 1);
    for (int k = 0; k < 3; ++k)
        put(s, len > 0.0 ? d[k] / len : 0.0);
    put_byte(s, 0);                                       /* flags: defaults */
    put_byte(s, 0);                                       /* eps_D automatic */
    put_byte(s, (unsigned)fmax(0.0, round(angle) - 1.0)); /* eps_T */
    put_byte(s, orthogonal ? 2 : 1);                      /* kinds */
    put_byte(s, 0);                                       /* the writer's projection flag */
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: fuzz_seed_cases CASES_DIR OUT_DIR\n");
        return 2;
    }
    char path[4096], line[4096];
    snprintf(path, sizeof path, "%s/MANIFEST.tsv", argv[1]);
    FILE *manifest = fopen(path, "r");
    if (manifest == NULL)
        return 1;
    int written = 0;
    while (fgets(line, sizeof line, manifest)) {
        char name[256], mode[64];
        double dir[3], tol, angle;
        if (line[0] == '#' ||
            sscanf(line, "%255s %63s %lf %lf %lf %lf %lf", name, mode, &dir[0], &dir[1], &dir[2],
                   &tol, &angle) != 7)
            continue;
        snprintf(path, sizeof path, "%s/%s.igs", argv[1], name);
        projcurve_model *m = NULL;
        if (projcurve_model_read_file(NULL, path, &m) != PROJCURVE_OK ||
            projcurve_model_surface_count(m) == 0 || projcurve_model_curve_count(m) == 0) {
            projcurve_model_destroy(m);
            continue;
        }
        const projcurve_curve *c = projcurve_model_curve(m, 0);
        if (c->kind == PC_CURVE_NURBS) {
            seed s = {{0}, 0};
            encode(projcurve_model_surface(m, 0), c, dir, strcmp(mode, "orthogonal") == 0, angle,
                   &s);
            snprintf(path, sizeof path, "%s/%s", argv[2], name);
            FILE *out = fopen(path, "wb");
            if (out != NULL && fwrite(s.bytes, 1, s.n, out) == s.n)
                ++written;
            if (out != NULL)
                fclose(out);
        }
        projcurve_model_destroy(m);
    }
    fclose(manifest);
    printf("%d seeds written\n", written);
    return written > 0 ? 0 : 1;
}
