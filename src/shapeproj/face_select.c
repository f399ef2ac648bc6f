/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The faces a projection can reach (shapeproj/face_select.h).
 */
#include "shapeproj/face_select.h"


int pc_curve_box(const projcurve_curve *curve, double box[6])
{
    if (curve->kind != PC_CURVE_NURBS)
        return 0;
    box_empty(box);
    for (size_t i = 0; i < curve->nurbs.n_ctrl; ++i) {
        const double *h = curve->nurbs.cw + 4 * i;
        const double p[3] = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
        box_add_point(box, p);
    }
    return 1;
}
