/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The topology part of projcurve info: shapes, faces, loops, edges, the
 * faces that could not be built, and the --json summary.
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"

#define INFO_MAX_FACE_KINDS 32

typedef struct topo_counts {
    size_t faces, loops, edges, pieces;
    const char *kinds[INFO_MAX_FACE_KINDS];
    size_t kind_count[INFO_MAX_FACE_KINDS], n_kinds;
} topo_counts;

static void count_kind(topo_counts *c, const char *kind)
{
    size_t k = 0;
    while (k < c->n_kinds && strcmp(c->kinds[k], kind) != 0)
        ++k;
    if (k == c->n_kinds) {
        if (c->n_kinds == INFO_MAX_FACE_KINDS)
            kind = "other", k = c->n_kinds - 1;
        else
            c->kinds[c->n_kinds] = kind, c->kind_count[c->n_kinds++] = 0;
    }
    ++c->kind_count[k];
}

/* Faces (built or not) by kind, loops and pieces of the built ones, and
 * edges: the distinct edges of every shape. */
static void count(const projcurve_model *m, topo_counts *c)
{
    memset(c, 0, sizeof *c);
    for (size_t i = 0; i < projcurve_model_face_count(m); ++i) {
        const projcurve_face *f = projcurve_model_face(m, i);
        const char *kind = "bspline";
        projcurve_face_info(NULL, f, NULL, NULL, &kind);
        count_kind(c, kind);
        c->loops += projcurve_face_loop_count(f);
        for (size_t l = 0; l < projcurve_face_loop_count(f); ++l) {
            size_t n = 0;
            projcurve_face_loop_piece_count(NULL, f, l, &n);
            c->pieces += n;
        }
    }
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i)
        count_kind(c, projcurve_model_unbuilt_face_kind(m, i));
    c->faces = projcurve_model_face_count(m) + projcurve_model_unbuilt_face_count(m);
    for (size_t s = 0; s < projcurve_model_shape_count(m); ++s)
        c->edges += projcurve_shape_edge_count(projcurve_model_shape(m, s));
}

static const char *shape_kind_name(projcurve_shape_kind k)
{
    switch (k) {
    case PROJCURVE_SHAPE_SOLID: return "solid";
    case PROJCURVE_SHAPE_CLOSED_SHELL: return "closed shell";
    case PROJCURVE_SHAPE_OPEN_SHELL: return "open shell";
    default: return "face set";
    }
}

void cli_print_topology(const projcurve_model *m)
{
    topo_counts c;
    count(m, &c);
    printf("  %zu shape(s), %zu face(s) (%zu not built), %zu loop(s), %zu edge(s)\n",
           projcurve_model_shape_count(m), c.faces, projcurve_model_unbuilt_face_count(m),
           c.loops, c.edges);
    for (size_t s = 0; s < projcurve_model_shape_count(m); ++s) {
        const projcurve_shape *sh = projcurve_model_shape(m, s);
        projcurve_shape_kind kind = PROJCURVE_SHAPE_FACE_SET;
        double sew = 0.0;
        projcurve_shape_info(NULL, sh, &kind, &sew);
        printf("  shape %zu: %s, %zu face(s), %zu edge(s)", s, shape_kind_name(kind),
               projcurve_shape_face_count(sh), projcurve_shape_edge_count(sh));
        if (sew > 0.0)
            printf(", edges sewn within %g", sew);
        printf("\n");
    }
    for (size_t i = 0; i < projcurve_model_face_count(m); ++i) {
        const projcurve_face *f = projcurve_model_face(m, i);
        const char *kind = "bspline";
        int periodic[2] = {0, 0}, same = 1;
        projcurve_face_info(NULL, f, &same, periodic, &kind);
        size_t pieces = 0;
        for (size_t l = 0; l < projcurve_face_loop_count(f); ++l) {
            size_t n = 0;
            projcurve_face_loop_piece_count(NULL, f, l, &n);
            pieces += n;
        }
        printf("  face %zu: %s, %zu loop(s), %zu edge piece(s)%s%s%s\n", i, kind,
               projcurve_face_loop_count(f), pieces, same < 0 ? ", reversed" : "",
               periodic[0] ? ", closed in u" : "", periodic[1] ? ", closed in v" : "");
    }
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i)
        printf("  face not built (%s): %s\n", projcurve_model_unbuilt_face_kind(m, i),
               projcurve_model_unbuilt_face(m, i));
    for (size_t k = 0; k < c.n_kinds; ++k)
        printf("  faces of kind %s: %zu\n", c.kinds[k], c.kind_count[k]);
}

static void json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s; ++s) {
        if (*s == '"' || *s == '\\')
            fprintf(out, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(out, "\\u%04x", (unsigned)(unsigned char)*s);
        else
            fputc(*s, out);
    }
    fputc('"', out);
}

void cli_print_info_json(projcurve_context *ctx, const char *path, const projcurve_model *m)
{
    topo_counts c;
    count(m, &c);
    printf("{\n  \"file\": ");
    json_string(stdout, path);
    printf(",\n  \"surfaces\": %zu,\n  \"curves\": %zu,\n  \"skipped\": %zu,\n",
           projcurve_model_surface_count(m), projcurve_model_curve_count(m),
           projcurve_model_skipped_count(m));
    cli_print_sizes_json(ctx, m, stdout);
    printf("  \"faces\": %zu,\n  \"faces_built\": %zu,\n  \"loops\": %zu,\n  \"edges\": %zu,\n"
           "  \"shapes\": %zu,\n  \"face_kinds\": {",
           c.faces, projcurve_model_face_count(m), c.loops, c.edges,
           projcurve_model_shape_count(m));
    for (size_t k = 0; k < c.n_kinds; ++k) {
        printf("%s", k ? ", " : "");
        json_string(stdout, c.kinds[k]);
        printf(": %zu", c.kind_count[k]);
    }
    printf("},\n  \"shape_list\": [");
    for (size_t s = 0; s < projcurve_model_shape_count(m); ++s) {
        const projcurve_shape *sh = projcurve_model_shape(m, s);
        projcurve_shape_kind kind = PROJCURVE_SHAPE_FACE_SET;
        double sew = 0.0;
        projcurve_shape_info(NULL, sh, &kind, &sew);
        printf("%s{\"kind\": \"%s\", \"faces\": %zu, \"edges\": %zu, \"sew_tol\": %.17g}",
               s ? ", " : "", shape_kind_name(kind), projcurve_shape_face_count(sh),
               projcurve_shape_edge_count(sh), sew);
    }
    printf("],\n  \"unbuilt\": [");
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i) {
        printf("%s", i ? ",\n    " : "\n    ");
        json_string(stdout, projcurve_model_unbuilt_face(m, i));
    }
    printf("]\n}\n");
}
