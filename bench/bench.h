/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench: shared declarations of the subcommands.
 *
 * Each subcommand prints a summary table on stdout, writes its figures as
 * JSON (--json FILE) and plots (--svg FILE), and returns 0 when every
 * measurement ran, 1 when one failed (the failure is printed and recorded),
 * 2 on a usage or file error. `--quick` runs a tiny size once-through so
 * that CI can check that the program works; its times mean nothing.
 */
#ifndef PCB_BENCH_H
#define PCB_BENCH_H

#include <stddef.h>

#include "projcurve.h"
#include "timing.h"

typedef struct pcb_args {
    const char *json_path;   /* NULL: no JSON */
    const char *svg_path;    /* NULL: no plot */
    const char *data_dir;  /* the shared data directory (cases/, real/) */
    int quick;               /* tiny sizes, few repetitions */
    const char *from_path;   /* profile: an occt JSON to take tolerances from */
    const char *only_case;   /* profile: run only the case of this name (NULL: all) */
    int pcurve_degree;       /* profile: PROJCURVE_OPT_PCURVE_DEGREE (0: the default) */
} pcb_args;

int pcb_cmd_eval(const pcb_args *args);
int pcb_cmd_rays(const pcb_args *args);
int pcb_cmd_table1(const pcb_args *args);
int pcb_cmd_cases(const pcb_args *args);
int pcb_cmd_scaling(const pcb_args *args);
int pcb_cmd_brep(const pcb_args *args);
int pcb_cmd_profile(const pcb_args *args);
int pcb_cmd_shape(const pcb_args *args);
#ifdef PCB_HAVE_OCCT
int pcb_cmd_occt(const pcb_args *args);
#endif

/* Timing settings: `reps` runs of at least `min_run_s` each, or one quick
 * run of a single call when args->quick. */
pcb_timing pcb_timing_for(const pcb_args *args, int reps, double min_run_s);

/* Prints "what: <status name>: <context message>" to stderr unless status
 * is OK; returns 1 when status is OK, else 0. */
int pcb_ok(projcurve_context *ctx, projcurve_status status, const char *what);

/* The CPU model name (from /proc/cpuinfo) or "unknown". */
void pcb_machine_name(char *buf, size_t size);

/* Prints the machine, build type and date banner above a table. */
void pcb_print_banner(const char *title, const pcb_args *args);

/* Deterministic uniform numbers in [0, 1) (a 64-bit LCG): the same
 * sample points on every run and machine. */
double pcb_rand01(unsigned long long *state);

/* path = dir + "/" + name, truncated to size. */
void pcb_join_path(char *path, size_t size, const char *dir, const char *name);

#endif /* PCB_BENCH_H */
