/**
 * The layouts the 2D and 3D manifold rows share (Box2D v3's b2ContactConstraintPoint and
 * b2Softness, contact_solver.c and solver.h).
 *
 * A contact point's packed fields begin alike in both dimensions (the 2D rows' points, MP_*,
 * solver/manifold-layout-2d.ts, and the 3D records' points, POINT_*, solver/manifold-layout-3d.ts): its
 * separation, its normal row's effective mass, then the normal row's levers r_A x n and r_B x n from
 * CP_NORMAL_ROW on (two numbers in 2D, two vectors in 3D); each dimension's own fields follow.
 *
 * The contact softness table (SN_*, filled once a step by prepareContactSoftness,
 * solver/contact-point.ts): a normal row's mass and impulse scales at SN_SCALES + SN_RIGID rigid +
 * SN_SOFT_ROW soft (rigid: the row's partner has infinite mass, solver/rigid-partner.ts; soft: the row overlaps
 * in a biased pass),
 * then the two bias rates.
 *
 * A module of numeric constants only, which every build folds into the code that reads it
 * (scripts/build.mjs isConstantModule).
 */

// A contact point's leading fields, from the point's start.
/** Separation at the start of the step, relative to where the solver starts the bodies, m (< 0: overlap). */
export const CP_SEPARATION = 0;
/** Effective mass of the normal row, kg. */
export const CP_NORMAL_MASS = 1;
/** Where the normal row's levers start: r_A x n then r_B x n, m (2D: scalars; 3D: vectors, ROW_*). */
export const CP_NORMAL_ROW = 2;

// The contact softness table.
/** Where the scales start: mass scale then impulse scale, (1, 0) for a speculative or relaxed row. */
export const SN_SCALES = 0;
/** Added for a row against an infinite-mass partner (the stiffer softness). */
export const SN_RIGID = 4;
/** Added for a soft row (overlap in a biased pass). */
export const SN_SOFT_ROW = 2;
/** Bias rate of a soft row between two moving bodies, 1/s. */
export const SN_BIAS = 8;
/** Bias rate of a soft row against an infinite-mass partner, 1/s. */
export const SN_RIGID_BIAS = 9;
/** Numbers a softness table. */
export const SN_STRIDE = 10;
