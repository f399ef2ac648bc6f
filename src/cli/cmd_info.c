/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve info [--json] FILE: surfaces (degrees, nets, spans, rational,
 * domain), curves, shapes, faces, loops and edges, and the skipped entities
 * summarised by kind; --json the counts as one JSON object.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define INFO_MAX_KINDS 64
#define INFO_KIND_TEXT 64

static void info_usage(FILE *out)
{
    fputs("usage: projcurve info [--json] FILE\n"
          "\n"
          "Lists what FILE (IGES, STEP, G+Smo XML or Newell teapot text) holds: each\n"
          "surface with its degrees, control net, knot spans and domain, each curve,\n"
          "the shapes, faces (with the faces that could not be built and why), loops\n"
          "and edges, and the entities that were not read, counted by kind.\n"
          "--json prints the counts as one JSON object: surfaces, curves, faces,\n"
          "loops, edges, shapes, face_kinds ({\"bspline\": 18, ...}) and more.\n",
          out);
}

/* "IGES entity 144 at DE 3 (...)" -> "IGES entity 144"; "STEP #30 PLANE" -> "STEP PLANE". */
static void skipped_kind(const char *text, char *kind, size_t cap)
{
    const char *at = strstr(text, " at ");
    if (at != NULL) {
        snprintf(kind, cap, "%.*s%s", (int)(at - text), text,
                 strstr(text, "(a part of") ? " (parts of others)" : "");
        return;
    }
    const char *hash = strchr(text, '#');
    if (hash != NULL) {
        const char *space = strchr(hash, ' ');
        snprintf(kind, cap, "%.*s%s", (int)(hash - text), text, space ? space + 1 : "");
        return;
    }
    snprintf(kind, cap, "%s", text);
}

static void print_skipped(const projcurve_model *m)
{
    char kinds[INFO_MAX_KINDS][INFO_KIND_TEXT];
    size_t counts[INFO_MAX_KINDS], n_kinds = 0, other = 0;
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i) {
        char kind[INFO_KIND_TEXT];
        skipped_kind(projcurve_model_skipped(m, i), kind, sizeof kind);
        size_t k = 0;
        while (k < n_kinds && strcmp(kinds[k], kind) != 0)
            ++k;
        if (k == n_kinds) {
            if (n_kinds == INFO_MAX_KINDS) {
                ++other;
                continue;
            }
            snprintf(kinds[n_kinds], INFO_KIND_TEXT, "%s", kind);
            counts[n_kinds++] = 0;
        }
        ++counts[k];
    }
    for (size_t k = 0; k < n_kinds; ++k)
        printf("  skipped %5zu x %s\n", counts[k], kinds[k]);
    if (other)
        printf("  skipped %5zu others\n", other);
}

int cli_cmd_info(int argc, char **argv)
{
    if (argc == 2 && cli_is_help(argv[1])) {
        info_usage(stdout);
        return CLI_EXIT_OK;
    }
    const int json = argc == 3 && strcmp(argv[1], "--json") == 0;
    if (argc != 2 && !json) {
        info_usage(stderr);
        return cli_usage_error("info takes one file (and --json)");
    }
    const char *path = argv[argc - 1];
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return cli_usage_error("cannot create a context");
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(ctx, path, &m) != PROJCURVE_OK) {
        const int code = cli_usage_error("%s", projcurve_context_message(ctx));
        projcurve_context_destroy(ctx);
        return code;
    }
    if (json) {
        cli_print_info_json(path, m);
        projcurve_model_destroy(m);
        projcurve_context_destroy(ctx);
        return CLI_EXIT_OK;
    }
    printf("%s: %zu surface(s), %zu curve(s), %zu skipped entit%s\n", path,
           projcurve_model_surface_count(m), projcurve_model_curve_count(m),
           projcurve_model_skipped_count(m), projcurve_model_skipped_count(m) == 1 ? "y" : "ies");
    for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
        int du, dv, rational;
        size_t nu, nv, su, sv;
        double d[4];
        const projcurve_surface *s = projcurve_model_surface(m, i);
        projcurve_surface_info(ctx, s, &du, &dv, &nu, &nv, &su, &sv, &rational);
        projcurve_surface_domain(ctx, s, d);
        printf("  surface %zu: degree %dx%d, %zux%zu control points, %zux%zu spans, %s, "
               "domain [%g, %g] x [%g, %g]\n",
               i, du, dv, nu, nv, su, sv, rational ? "rational" : "polynomial", d[0], d[1], d[2],
               d[3]);
    }
    for (size_t i = 0; i < projcurve_model_curve_count(m); ++i) {
        int deg = 0, rational = 0;
        size_t n = 0;
        double t0 = 0.0, t1 = 0.0;
        const projcurve_curve *c = projcurve_model_curve(m, i);
        projcurve_curve_nurbs_info(ctx, c, &deg, &n, NULL, &rational);
        projcurve_curve_domain(ctx, c, &t0, &t1);
        printf("  curve %zu: degree %d, %zu control points, %s, domain [%g, %g]\n", i, deg, n,
               rational ? "rational" : "polynomial", t0, t1);
    }
    cli_print_topology(m);
    print_skipped(m);
    projcurve_model_destroy(m);
    projcurve_context_destroy(ctx);
    return CLI_EXIT_OK;
}
