/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * CPU time per stage of one projection call, for the benchmark's profile
 * (bench/README.md, "profile"). The engine reads the thread's CPU clock
 * at the boundaries of its stages only when pc_params.stages is set,
 * which no public entry point does: a call made through the API reads no
 * clock and pays one pointer test per stage.
 */
#ifndef PC_COMMON_STAGE_CLOCK_H
#define PC_COMMON_STAGE_CLOCK_H

/* The stages, in the order a call runs them. */
typedef enum pc_stage {
    PC_STAGE_SEEDING,      /* the seed search at the start of the curve */
    PC_STAGE_TRACING,      /* tracing every branch (born in the sweep too) */
    PC_STAGE_JUMPS,        /* the jump sweep, without the branches it starts */
    PC_STAGE_REFINEMENT,   /* tolerance control: the exact vertices */
    PC_STAGE_COMPOSITION,  /* the pieces composed on S */
    PC_STAGE_VERIFICATION, /* the independent check of the pieces */
    PC_STAGE_FITTING,      /* the compact pcurve and 3D curve (fit/) */
    PC_STAGE_OTHER,        /* the rest: splits, duplicates, setup */
    PC_STAGE_COUNT
} pc_stage;

typedef struct pc_stage_clock {
    double seconds[PC_STAGE_COUNT]; /* accumulated over calls */
} pc_stage_clock;

/* The thread's CPU time in seconds when c is set, else 0 (no clock read). */
double pc_stage_clock_now(const pc_stage_clock *c);

/* Adds the CPU time since `since` (pc_stage_clock_now) to stage s and
 * returns the present time, the start of the next stage; 0 without c. */
double pc_stage_clock_lap(pc_stage_clock *c, pc_stage s, double since);

/* The stage's name, for tables. */
const char *pc_stage_name(pc_stage s);

#endif /* PC_COMMON_STAGE_CLOCK_H */
