/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The options of projcurve project as one table: name, value shown in the
 * usage, the function that stores it, and its help text. The usage text is
 * printed from the table, and every option may be given once.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "project_args.h"

typedef struct project_option project_option;
/* Stores value (NULL for a flag) into a; CLI_EXIT_OK or a usage error. */
typedef int (*option_apply_fn)(project_args *a, const project_option *o, const char *value);

struct project_option {
    const char *name;  /* "--dir" */
    const char *value; /* what follows it in the usage ("X,Y,Z"), NULL: a flag */
    option_apply_fn apply;
    const char *help;  /* lines separated by '\n' */
};

static int want_number(const project_option *o, const char *v, double *out, int *have)
{
    if (!cli_parse_double(v, out))
        return cli_usage_error("%s wants a number, got '%s'", o->name, v);
    *have = 1;
    return CLI_EXIT_OK;
}

static int set_dir(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_vec3(v, a->dir))
        return cli_usage_error("%s wants X,Y,Z, got '%s'", o->name, v);
    a->have_dir = 1;
    return CLI_EXIT_OK;
}

static int set_eye(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_vec3(v, a->eye))
        return cli_usage_error("%s wants X,Y,Z (the eye point), got '%s'", o->name, v);
    a->have_eye = 1;
    return CLI_EXIT_OK;
}

static int set_orthogonal(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->orthogonal = 1;
    return CLI_EXIT_OK;
}

static int set_tol(project_args *a, const project_option *o, const char *v)
{
    return want_number(o, v, &a->tol, &a->have_tol);
}

static int set_angle(project_args *a, const project_option *o, const char *v)
{
    return want_number(o, v, &a->angle, &a->have_angle);
}

static int set_timeout(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_double(v, &a->timeout))
        return cli_usage_error("%s wants a number of seconds, got '%s'", o->name, v);
    a->have_timeout = 1;
    return CLI_EXIT_OK;
}

static int set_pcurve_degree(project_args *a, const project_option *o, const char *v)
{
    double d = 0.0;
    if (!cli_parse_double(v, &d) || d != floor(d) || fabs(d) > 1e9)
        return cli_usage_error("%s wants an integer, got '%s'", o->name, v);
    a->pcurve_degree = (long long)d;
    a->have_pcurve_degree = 1;
    return CLI_EXIT_OK;
}

static int set_surface(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_index(v, &a->surface))
        return cli_usage_error("%s wants a surface number (0, 1, ... as info prints them), "
                               "got '%s'",
                               o->name, v);
    a->have_surface = 1;
    return CLI_EXIT_OK;
}

static int set_curve(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_index(v, &a->curve))
        return cli_usage_error("%s wants a curve number (0, 1, ... as info prints them), "
                               "got '%s'",
                               o->name, v);
    a->have_curve = 1;
    return CLI_EXIT_OK;
}

static int set_line(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_reals(v, 6, a->line))
        return cli_usage_error("%s wants X,Y,Z,X,Y,Z (six numbers: the two end points), "
                               "got '%s'",
                               o->name, v);
    a->have_line = 1;
    return CLI_EXIT_OK;
}

static int set_points(project_args *a, const project_option *o, const char *v)
{
    (void)o;
    a->points_path = v;
    return CLI_EXIT_OK;
}

static int set_interpolate(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->interpolate = 1;
    return CLI_EXIT_OK;
}

static int set_faces(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->faces = 1;
    return CLI_EXIT_OK;
}

static int set_curves(project_args *a, const project_option *o, const char *v)
{
    (void)o;
    a->curves_path = v;
    return CLI_EXIT_OK;
}

static int set_nearest(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->nearest = 1;
    return CLI_EXIT_OK;
}

static int set_max_distance(project_args *a, const project_option *o, const char *v)
{
    if (!cli_parse_double(v, &a->max_distance) || !(a->max_distance > 0.0))
        return cli_usage_error("%s wants a positive distance in model units, got '%s'", o->name,
                               v);
    a->have_max_distance = 1;
    return CLI_EXIT_OK;
}

static int set_quiet(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->quiet = 1;
    return CLI_EXIT_OK;
}

static int set_progress(project_args *a, const project_option *o, const char *v)
{
    (void)o, (void)v;
    a->progress = 1;
    return CLI_EXIT_OK;
}

static int set_output(project_args *a, const project_option *o, const char *v)
{
    *(strcmp(o->name, "-o") == 0 ? &a->iges : strcmp(o->name, "--svg") == 0 ? &a->svg
                                                                            : &a->json) = v;
    return CLI_EXIT_OK;
}

static const project_option options[] = {
    {"--dir", "X,Y,Z", set_dir, "directional projection along (X, Y, Z)"},
    {"--eye", "X,Y,Z", set_eye,
     "conical projection from the eye point (X, Y, Z): each\n"
     "point maps along the ray from the eye through it"},
    {"--orthogonal", NULL, set_orthogonal, "orthogonal projection (foot points)"},
    {"--surface", "I", set_surface,
     "project onto surface I only (numbered from 0 across the\n"
     "files, as 'projcurve info' prints them)"},
    {"--curve", "J", set_curve, "project curve J only (numbered like --surface)"},
    {"--line", "X,Y,Z,X,Y,Z", set_line,
     "project the straight line between these two points\n"
     "instead of the files' curves"},
    {"--points", "FILE", set_points,
     "project the polyline through the points of FILE instead\n"
     "of the files' curves, one curve per segment (0, 1, ...):\n"
     "one point X Y Z per line, spaces or commas, '#' comments"},
    {"--interpolate", NULL, set_interpolate,
     "with --points: one interpolating cubic through the points\n"
     "(chord-length parameters) instead of the polyline"},
    {"--faces", NULL, set_faces,
     "project onto the shapes of the files (their trimmed\n"
     "faces, chained across shared edges into connected\n"
     "curves) instead of onto each surface"},
    {"--curves", "FILE", set_curves,
     "project the curves of FILE (numbered 0, 1, ... for\n"
     "--curve) instead of those of the other files"},
    {"--nearest", NULL, set_nearest,
     "keep only the point nearest to the curve on each ray (the\n"
     "visible projection; orthogonally: the nearest foot point)"},
    {"--max-distance", "D", set_max_distance,
     "keep only the points within D (model units) of the curve,\n"
     "along the ray (orthogonally: in space)"},
    {"--tol", "D", set_tol,
     "distance tolerance eps_D in model units (default: 1e-4\n"
     "of the surface size)"},
    {"--angle", "DEG", set_angle, "joint angle tolerance eps_T in degrees (default 1)"},
    {"--pcurve-degree", "N", set_pcurve_degree,
     "pieces' (u, v) curves: 1 straight (default), 3 cubic\n"
     "Hermite (far fewer pieces at tight eps_D)"},
    {"--timeout", "S", set_timeout,
     "stop each (curve, surface) projection after S seconds of\n"
     "wall time, keeping what it made (0: no limit, default);\n"
     "exit code 3 when that was the only failure"},
    {"--quiet", NULL, set_quiet, "print nothing but errors (no progress, no summary)"},
    {"--progress", NULL, set_progress,
     "show the progress from the start, also when stderr is not\n"
     "a terminal (default: on a terminal, after the first second)"},
    {"-o", "OUT.igs", set_output,
     "write surfaces, curves and branches as IGES 5.3\n"
     "(as STEP AP214 when OUT ends in .step or .stp)"},
    {"--svg", "OUT.svg", set_output, "write a picture (see docs/cli.md)"},
    {"--json", "OUT.json", set_output, "write the branches as JSON (see docs/cli.md)"},
};
#define N_OPTIONS (sizeof options / sizeof *options)

void project_args_usage(FILE *out)
{
    fputs("usage: projcurve project FILE... (--dir X,Y,Z | --eye X,Y,Z | --orthogonal)\n"
          "                         [OPTION]...\n"
          "\n"
          "Projects every curve of the files (or the curve of --line / --points)\n"
          "onto every surface of the files (or the ones --surface / --curve pick);\n"
          "with --faces onto every shape (solid, shell, face set) of the files.\n"
          "\n",
          out);
    for (size_t i = 0; i < N_OPTIONS; ++i) {
        char head[64];
        snprintf(head, sizeof head, "%s%s%s", options[i].name, options[i].value ? " " : "",
                 options[i].value ? options[i].value : "");
        const char *line = options[i].help;
        int first = 1;
        /* one usage line per help line; the help is a constant of this
         * table, so the loop ends at its terminating '\0' */
        while (*line) {
            const char *nl = strchr(line, '\n');
            const int len = nl ? (int)(nl - line) : (int)strlen(line);
            fprintf(out, "  %-18s %.*s\n", first ? head : "", len, line);
            first = 0;
            line += len + (nl ? 1 : 0);
        }
    }
    fputs("\n"
          "Exit codes: 0 ok, 1 a projection failed, 2 bad usage or unreadable input,\n"
          "3 a projection was stopped by --timeout (what it made is still written).\n",
          out);
}

static const project_option *find_option(const char *name)
{
    for (size_t i = 0; i < N_OPTIONS; ++i)
        if (strcmp(options[i].name, name) == 0)
            return &options[i];
    return NULL;
}

/* The combinations the table cannot express. */
static int check_combinations(const project_args *a)
{
    if (a->n_files == 0)
        return cli_usage_error("project needs at least one file (for the surfaces)");
    if (a->have_dir + a->have_eye + a->orthogonal != 1)
        return cli_usage_error("give exactly one of --dir X,Y,Z, --eye X,Y,Z and --orthogonal");
    if (a->have_line && a->points_path)
        return cli_usage_error("give one of --line and --points, not both");
    if (a->have_curve && (a->have_line || a->points_path))
        return cli_usage_error("--curve picks a curve of the files; --%s gives the curve "
                               "instead: use one of them",
                               a->have_line ? "line" : "points");
    if (a->faces && a->have_surface)
        return cli_usage_error("--faces projects onto whole shapes; --surface picks one "
                               "surface: use one of them");
    if (a->curves_path && (a->have_line || a->points_path))
        return cli_usage_error("give one of --curves and --%s, not both",
                               a->have_line ? "line" : "points");
    if (a->interpolate && !a->points_path)
        return cli_usage_error("--interpolate needs --points FILE");
    if (a->quiet && a->progress)
        return cli_usage_error("give one of --quiet and --progress, not both");
    return CLI_EXIT_OK;
}

int project_args_parse(int argc, char **argv, project_args *a)
{
    memset(a, 0, sizeof *a);
    a->files = calloc((size_t)argc + 1, sizeof *a->files);
    if (a->files == NULL)
        return cli_usage_error("out of memory");
    unsigned char seen[N_OPTIONS];
    memset(seen, 0, sizeof seen);
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i];
        if (arg[0] != '-' || arg[1] == '\0') {
            a->files[a->n_files++] = argv[i];
            continue;
        }
        const project_option *o = find_option(arg);
        if (o == NULL)
            return cli_usage_error("unknown option '%s' (see projcurve project --help)", arg);
        if (seen[o - options]++)
            return cli_usage_error("%s is given twice", o->name);
        const char *value = NULL;
        if (o->value != NULL) {
            if (i + 1 >= argc)
                return cli_usage_error("%s needs a value (%s)", o->name, o->value);
            value = argv[++i];
        }
        const int code = o->apply(a, o, value);
        if (code != CLI_EXIT_OK)
            return code;
    }
    return check_combinations(a);
}
