/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve info [--json] FILE: surfaces (degrees, nets, spans, rational,
 * domain, box), curves (the same), the model's box, shapes, faces, loops and edges, and the skipped entities
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
          "surface and curve with its degrees, control points, knot spans, domain\n"
          "and bounding box, the box of the whole model, the shapes, faces (with the faces that could not be built and why), loops\n"
          "and edges, and the entities that were not read, counted by kind.\n"
          "--json prints one JSON object: the counts (surfaces, curves, faces, loops,\n"
          "edges, shapes, face_kinds {\"bspline\": 18, ...}), surface_list and\n"
          "curve_list (degree, poles, spans, domain, box of each), box (the model's)\n"
          "and more.\n",
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
        cli_print_info_json(ctx, path, m);
        projcurve_model_destroy(m);
        projcurve_context_destroy(ctx);
        return CLI_EXIT_OK;
    }
    printf("%s: %zu surface(s), %zu curve(s), %zu skipped entit%s\n", path,
           projcurve_model_surface_count(m), projcurve_model_curve_count(m),
           projcurve_model_skipped_count(m), projcurve_model_skipped_count(m) == 1 ? "y" : "ies");
    cli_print_sizes(ctx, m);
    cli_print_topology(m);
    print_skipped(m);
    projcurve_model_destroy(m);
    projcurve_context_destroy(ctx);
    return CLI_EXIT_OK;
}
