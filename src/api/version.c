/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The version of the library actually loaded: compiled in from the generated
 * projcurve_version.h, so that a program can compare it with the header it
 * was built against (PROJCURVE_VERSION_NUMBER).
 */
#include "projcurve.h"

unsigned projcurve_version_number(void) { return (unsigned)PROJCURVE_VERSION_NUMBER; }

const char *projcurve_version_string(void) { return PROJCURVE_VERSION_STRING; }
