/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Morse index of the squared distance |x - P|^2 / 2 at a foot point x: the
 * number of negative eigenvalues of the orthogonal projective tensor K
 * (its Hessian on the surface; [PW96] eq. (5)), i.e. of principal
 * centres of curvature lying between x and P: 0 at a local minimum of the
 * distance, 1 at a saddle, 2 at a local maximum.
 *
 * Crossing a centre of curvature changes the index. The sign of det K
 * ([PW96] s6) sees only odd changes: at an umbilic (every point of a
 * sphere) both eigenvalues vanish together, det K touches zero without
 * changing sign, and only the index notices.
 */
#ifndef PC_ORTHO_MORSE_INDEX_H
#define PC_ORTHO_MORSE_INDEX_H

/* Index of a symmetric 2x2 matrix from its determinant and trace. */
static inline int pc_morse_index(double det, double trace)
{
    if (det < 0.0)
        return 1;
    return trace > 0.0 ? 0 : 2;
}

#endif /* PC_ORTHO_MORSE_INDEX_H */
