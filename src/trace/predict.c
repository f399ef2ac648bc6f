/*
 * The second-order predictor of seed 000 s3.3.
 */
#include "trace/tracer.h"

/* seed 000 eq. (3.5): q(t0 + h) ~ q(t0) + q'(t0) h + q''(t0) h^2 / 2 */
void pc_predict_taylor(const pc_proj_point *pt, double h, double uv[2])
{
    const double half_h2 = 0.5 * h * h;
    uv[0] = pt->u + pt->du * h + pt->ddu * half_h2;
    uv[1] = pt->v + pt->dv * h + pt->ddv * half_h2;
}
