/**
 * The layouts of the cloth solver's packed arrays (ClothState, world/cloth-state.ts; cloth/solver.ts). A
 * module of numeric constants only, which every build folds into the code that reads it
 * (scripts/build.mjs isConstantModule).
 *
 * `buffer` holds the n packed points in three sections: the points' records (PT_ offsets, PT_STRIDE a
 * point) from 0; each point's x, y before the substep (m) from BEFORE_AT n, two a point; its vx, vy at the
 * start of the step (m/s) from VELOCITY_AT n, two a point; BUFFER_STRIDE n numbers in all.
 */

// A point's record in `buffer`.
/** Position x, m. */
export const PT_X = 0;
/** Position y, m. */
export const PT_Y = 1;
/** Inverse mass, 1/kg (0: a fixed point: pinned, static or kinematic). */
export const PT_INV_MASS = 2;
/** Numbers a point's record. */
export const PT_STRIDE = 3;
/** Where the positions before the substep start, in units of the point count. */
export const BEFORE_AT = 3;
/** Where the velocities at the start of the step start, in units of the point count. */
export const VELOCITY_AT = 5;
/** Numbers a point keeps in `buffer`, all sections together. */
export const BUFFER_STRIDE = 7;

// `pair`: a link's two points, as the offsets of their records in `buffer` (PT_STRIDE times the point's compact index).
/** Point a's record. */
export const PAIR_A = 0;
/** Point b's record. */
export const PAIR_B = 1;
/** Numbers a link in `pair`. */
export const PAIR_STRIDE = 2;

// `solve`: a link's factors for the projection, once a step (prepareLinks).
/** p = r^2 / 3, r the rest length, m^2. */
export const SOLVE_P = 0;
/** k = (2/3) / D, D = w_a + w_b + alpha~ (alpha~ = compliance / h_s^2), kg. */
export const SOLVE_K = 1;
/** Numbers a link in `solve`. */
export const SOLVE_STRIDE = 2;

// `scalars`: this step's numbers for the passes.
/** The substep h_s, s. */
export const SC_HS = 0;
/** 1 / h_s, 1/s. */
export const SC_INV_HS = 1;
/** g_x h_s, m/s. */
export const SC_GX_HS = 2;
/** g_y h_s, m/s. */
export const SC_GY_HS = 3;
/** g_x h, m/s. */
export const SC_GX_H = 4;
/** g_y h, m/s. */
export const SC_GY_H = 5;
/** 1 / h_s^2, 1/s^2 (the last: `scalars` holds 7 numbers, world/cloth-state.ts). */
export const SC_INV_HS2 = 6;
