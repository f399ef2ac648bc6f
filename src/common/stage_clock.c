/* SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L
#include "common/stage_clock.h"

#include <time.h>

double pc_stage_clock_now(const pc_stage_clock *c)
{
    if (c == NULL)
        return 0.0;
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0; /* no CPU clock: the profile reads 0 */
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double pc_stage_clock_lap(pc_stage_clock *c, pc_stage s, double since)
{
    if (c == NULL)
        return 0.0;
    const double now = pc_stage_clock_now(c);
    if (s >= 0 && s < PC_STAGE_COUNT && now > since)
        c->seconds[s] += now - since;
    return now;
}

const char *pc_stage_name(pc_stage s)
{
    static const char *const names[PC_STAGE_COUNT] = {
        "seeding", "tracing", "jumps", "refinement", "composition", "verification", "fitting",
        "other"};
    return s >= 0 && s < PC_STAGE_COUNT ? names[s] : "?";
}
