/**
 * The argument slots of the semi-implicit Euler kernels (sie2 and sie3 in
 * integrators/semi-implicit-euler.ts), one layout for the two: where each array sits in a kernel's
 * `A` and each number in its `P`, imported as `SIE` (`A[SIE.PX]`) by the kernels and by their caller.
 * A 2D kernel reads no z slot, a free-particle kernel no force or mass. A module of numeric constants
 * only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays (Float64, by entity).
/** Position x, m. */
export const PX = 0;
/** Position y, m. */
export const PY = 1;
/** Position z, m. */
export const PZ = 2;
/** Velocity x, m/s. */
export const VX = 3;
/** Velocity y, m/s. */
export const VY = 4;
/** Velocity z, m/s. */
export const VZ = 5;
/** PreviousPosition x, m (written). */
export const OX = 6;
/** PreviousPosition y, m (written). */
export const OY = 7;
/** PreviousPosition z, m (written). */
export const OZ = 8;
/** Force x, N. */
export const FX = 9;
/** Force y, N. */
export const FY = 10;
/** Force z, N. */
export const FZ = 11;
/** Mass.inv, 1/kg. */
export const INV_MASS = 12;
// P: the numbers.
/** The step h, s. */
export const H = 0;
/** g_x h, m/s. */
export const GX_H = 1;
/** g_y h, m/s. */
export const GY_H = 2;
/** g_z h, m/s. */
export const GZ_H = 3;
/** Half of g_x h, m/s: taken off the drift velocity of a body in free flight (exact parabola). */
export const HALF_GX_H = 4;
/** Half of g_y h, m/s. */
export const HALF_GY_H = 5;
/** Half of g_z h, m/s. */
export const HALF_GZ_H = 6;
/** 1: keep PreviousPosition (free particles of a world that interpolates), 0: not. */
export const SAVE = 7;
/** 1: the bodies with a force accumulator (ids given), 0: bare particles (no force or mass slot). */
export const FORCED = 8;
/** Numbers in P. */
export const PARAMS = 9;
