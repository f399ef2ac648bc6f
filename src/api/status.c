/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Names of the status codes. The table is indexed by the enum value, so a
 * new code needs one line here; test_api_basics checks that every code up
 * to PC_STATUS_LAST has a distinct, non-generic name.
 */
#include "projcurve.h"

#include <stddef.h>

static const char *const pc_status_names[] = {
    [PROJCURVE_OK] = "ok",
    [PROJCURVE_ERR_NULL_ARGUMENT] = "null argument",
    [PROJCURVE_ERR_INVALID_ARGUMENT] = "invalid argument",
    [PROJCURVE_ERR_OUT_OF_RANGE] = "value out of range",
    [PROJCURVE_ERR_UNKNOWN_OPTION] = "unknown option",
    [PROJCURVE_ERR_NOT_FINITE] = "value not finite",
    [PROJCURVE_ERR_BAD_KNOTS] = "bad knot vector",
    [PROJCURVE_ERR_BAD_COUNT] = "inconsistent counts",
    [PROJCURVE_ERR_BAD_WEIGHT] = "bad weight",
    [PROJCURVE_ERR_BAD_DEGREE] = "bad degree",
    [PROJCURVE_ERR_OVERFLOW] = "size overflow",
    [PROJCURVE_ERR_OUT_OF_DOMAIN] = "parameter outside the domain",
    [PROJCURVE_ERR_ZERO_DIRECTION] = "zero direction",
    [PROJCURVE_ERR_NO_MEMORY] = "out of memory",
    [PROJCURVE_ERR_VERSION] = "version mismatch",
    [PROJCURVE_ERR_NOT_CONVERGED] = "iteration did not converge",
    [PROJCURVE_ERR_LIMIT_REACHED] = "size, time or work limit reached",
    [PROJCURVE_ERR_CALLBACK] = "callback failed",
    [PROJCURVE_ERR_SINGULAR] = "singular configuration",
    [PROJCURVE_ERR_IO] = "input/output error",
    [PROJCURVE_ERR_PARSE] = "malformed file",
    [PROJCURVE_ERR_UNSUPPORTED] = "unsupported input",
    [PROJCURVE_ERR_INDEX] = "index out of range",
    [PROJCURVE_ERR_WRONG_KIND] = "wrong kind of handle or value",
    [PROJCURVE_ERR_CANCELLED] = "cancelled by the progress callback",
};

#define PC_STATUS_COUNT (sizeof pc_status_names / sizeof pc_status_names[0])

const char *projcurve_status_string(projcurve_status status)
{
    /* Compare as unsigned: a negative value forged by a caller is unknown too. */
    const unsigned index = (unsigned)status;
    if (index >= PC_STATUS_COUNT || pc_status_names[index] == NULL)
        return "unknown status";
    return pc_status_names[index];
}
