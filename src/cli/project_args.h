/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The arguments of projcurve project: what the user asked for, filled from
 * a table of options (project_args.c) so that a new option is one row and
 * one small function.
 */
#ifndef PC_CLI_PROJECT_ARGS_H
#define PC_CLI_PROJECT_ARGS_H

#include <stdio.h>

#include "cli.h"

typedef struct project_args {
    char **files;
    size_t n_files;
    /* projection kind */
    int have_dir, have_eye, orthogonal;
    double dir[3], eye[3];
    /* options of the library */
    double tol, angle, timeout;
    long long pcurve_degree;
    int have_tol, have_angle, have_pcurve_degree, have_timeout;
    /* which hits: the nearest only, those within max_distance */
    int nearest, have_max_distance;
    double max_distance;
    /* which pairs: one surface / one curve of the files (by number) */
    int have_surface, have_curve;
    size_t surface, curve;
    /* a curve given on the command line instead of the files' curves */
    int have_line;
    double line[6];
    const char *points_path;
    int interpolate;
    /* whole-model mode: project onto the files' shapes (--faces), with the
     * curves of --curves FILE instead of those of the files */
    int faces;
    const char *curves_path;
    /* what is printed */
    int quiet, progress;
    /* outputs */
    const char *iges, *svg, *json;
} project_args;

/* Fills a from argv (argv[0] is "project"); a->files is allocated (free
 * it, also on failure). CLI_EXIT_OK or CLI_EXIT_USAGE after a message. */
int project_args_parse(int argc, char **argv, project_args *a);
void project_args_usage(FILE *out);

#endif /* PC_CLI_PROJECT_ARGS_H */
