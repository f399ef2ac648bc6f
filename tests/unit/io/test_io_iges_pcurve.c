/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The IGES writer's curve on surface (142) with cubic pcurves: its 2D curve
 * (the 126 in z = 0 it points to) is the pieces' pcurves, so S at the 2D
 * curve is each composed piece. The written file is read back through the
 * IGES reader's entity parsing (not the writer's code): at t = t0 + s
 * (t1 - t0) of every piece, S(pcurve(t)) must equal the piece at s. With
 * straight pcurves the 2D curve stays the degree-1 polyline through the
 * refined vertices, which passes the same check.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "common/arena.h"
#include "io/iges.h"
#include "piece_oracle.h"
#include "trace_shapes.h"

#define PIECE_SAMPLES 8
/* IGES reals are written with 17 significant digits; the composition is
 * exact to 1e-12 of the model size. */
#define ON_PIECE_REL 1e-11

static char path[256];

/* Checks S(pcurve(t)) against every piece of branch 0 of r; the pcurve is
 * the 2D curve of the written file's first 142. */
static void check_written_pcurve(const projcurve_surface *s, const projcurve_result *r,
                                 int expect_degree)
{
    size_t len = 0;
    char *text = pc_test_read_file(path, &len);
    CHECK(text != NULL);
    if (text == NULL)
        return;
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    size_t work_done = 0;
    pc_iges_file f;
    memset(&f, 0, sizeof f);
    f.arena = &arena;
    f.work_done = &work_done;
    f.work_limit = 1000 * len + 100000;
    CHECK_OK(pc_iges_split(&f, text, len));
    CHECK_OK(pc_iges_read_global(&f));
    CHECK_OK(pc_iges_read_directory(&f));
    long pcurve_de = 0;
    for (size_t i = 0; i < f.n_entries && pcurve_de == 0; ++i) {
        pc_iges_params p;
        if (f.entries[i].type == 142 && pc_iges_params_of(&f, 2 * i + 1, &p) == PROJCURVE_OK)
            CHECK_OK(pc_iges_int(&p, 3, &pcurve_de)); /* CRTN, SPTR, BPTR */
    }
    CHECK(pcurve_de > 0);
    pc_io_curve io = {0};
    const char *skip = NULL;
    projcurve_curve *c = NULL;
    if (pcurve_de > 0 && pc_iges_curve(&f, (size_t)pcurve_de, &io, &skip) == PROJCURVE_OK)
        CHECK_OK(projcurve_curve_create_nurbs(NULL, io.degree, io.n_ctrl, io.ctrl, io.weights,
                                              io.knots, &c));
    CHECK(c != NULL);
    if (c != NULL) {
        CHECK(io.degree == expect_degree);
        const pc_branch *b = &r->branches[0];
        double worst = 0.0;
        for (size_t k = 0; k < b->n_pieces; ++k) {
            const pc_piece *pc = &b->pieces[k];
            for (int j = 0; j <= PIECE_SAMPLES; ++j) {
                const double sp = (double)j / PIECE_SAMPLES;
                double q[3], x[3];
                pc_vec3 y;
                CHECK_OK(projcurve_curve_eval(NULL, c, pc->t0 + sp * (pc->t1 - pc->t0), 0, q));
                CHECK(fabs(q[2]) == 0.0);
                CHECK_OK(projcurve_surface_eval(NULL, s, q[0], q[1], 0, x));
                pc_oracle_piece_eval(pc, sp, &y, NULL);
                worst = fmax(worst, vec3_dist(y, vec3_load(x)));
            }
        }
        CHECK(worst <= ON_PIECE_REL * s->size);
        printf("pcurve degree %d: %zu pieces, S(pcurve) off the pieces by <= %.3g (size %.3g)\n",
               io.degree, b->n_pieces, worst, s->size);
    }
    projcurve_curve_destroy(c);
    pc_arena_release(&arena);
    free(text);
}

static void write_example1(int degree)
{
    projcurve_surface *s = shape_example1_surface();
    projcurve_curve *curve = shape_example1_curve();
    const double dir[3] = {-1.0, 0.0, 0.0};
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, degree));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-6 * s->size));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, curve, dir, o, &r));
    CHECK(r != NULL && projcurve_result_branch_count(r) == 1);
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(NULL, &w));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(NULL, w, s, r));
    CHECK_OK(projcurve_iges_writer_write(NULL, w, path));
    projcurve_iges_writer_destroy(w);
    if (r != NULL && projcurve_result_branch_count(r) == 1)
        check_written_pcurve(s, r, degree);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(s);
}

int main(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/projcurve_pcurve_%ld.igs", tmp ? tmp : "/tmp", (long)getpid());
    write_example1(3);
    write_example1(1);
    remove(path);
    return pc_test_finish("test_io_iges_pcurve");
}
