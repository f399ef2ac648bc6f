/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Projections without the seam stage (src/seam/): the branches as traced,
 * split at the seams and poles of closed surfaces, for the tests of the
 * stages before it (tracing, refinement, fits) that check those ends.
 */
#ifndef PC_TEST_UNJOINED_H
#define PC_TEST_UNJOINED_H

#include "projcurve.h"

/* projcurve_project_directional (dir != NULL) or _orthogonal (dir NULL)
 * with the same arguments and statuses, the seams left unjoined. */
projcurve_status pc_test_project_unjoined(projcurve_context *ctx, const projcurve_surface *s,
                                          const projcurve_curve *c, const double *dir,
                                          const projcurve_options *o, projcurve_result **out);

#endif /* PC_TEST_UNJOINED_H */
