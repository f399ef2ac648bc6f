/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Helpers shared by the subcommands (see bench.h).
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#ifndef PCB_BUILD_TYPE
#define PCB_BUILD_TYPE "unknown"
#endif

/* A measurement (all its timed runs) should not take much longer. */
#define PCB_BUDGET_S 10.0

pcb_timing pcb_timing_for(const pcb_args *args, int reps, double min_run_s)
{
    pcb_timing t;
    t.budget_s = PCB_BUDGET_S;
    if (args->quick) {
        t.warmup = 0;
        t.reps = 1;
        t.min_run_s = 0.0;
    } else {
        t.warmup = 1;
        t.reps = reps;
        t.min_run_s = min_run_s;
    }
    return t;
}

int pcb_ok(projcurve_context *ctx, projcurve_status status, const char *what)
{
    if (status == PROJCURVE_OK)
        return 1;
    fprintf(stderr, "%s: %s: %s\n", what, projcurve_status_string(status),
            projcurve_context_message(ctx));
    return 0;
}

void pcb_machine_name(char *buf, size_t size)
{
    snprintf(buf, size, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[256];
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) != 0)
            continue;
        const char *colon = strchr(line, ':');
        if (!colon)
            continue;
        colon += colon[1] == ' ' ? 2 : 1;
        snprintf(buf, size, "%s", colon);
        buf[strcspn(buf, "\n")] = '\0';
        break;
    }
    fclose(f);
}

/* The 1-minute load average, or -1: figures taken on a busy machine say
 * so in their banner. */
static double load_average(void)
{
    double load = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &load) != 1)
            load = -1.0;
        fclose(f);
    }
    return load;
}

void pcb_print_banner(const char *title, const pcb_args *args)
{
    char machine[128];
    pcb_machine_name(machine, sizeof machine);
    char date[32] = "?";
    const time_t now = time(NULL);
    struct tm tm_utc;
    if (gmtime_r(&now, &tm_utc))
        strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", &tm_utc);
    printf("== %s  [%s; %s build; libprojcurve %s; %s; load %.1f%s]\n", title, machine,
           PCB_BUILD_TYPE, projcurve_version_string(), date, load_average(),
           args->quick ? "; QUICK: times mean nothing" : "");
}

void pcb_join_path(char *path, size_t size, const char *dir, const char *name)
{
    snprintf(path, size, "%s/%s", dir, name);
}

double pcb_rand01(unsigned long long *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}
