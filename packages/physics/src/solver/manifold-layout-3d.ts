/**
 * The layout of the 3D manifold rows' per-step packed arrays (Contact3DState's solveRecord, jacobiansInv
 * and frictionInv, collision/manifolds-3d.ts), written by prepareManifolds3D (solver/manifold-prepare-3d.ts)
 * and read by the warm start, the solve and restitution (solver/manifold-solve-3d.ts). A row of angular
 * parts along a direction u is body A's (ROW_AX ..) then body B's (ROW_BX ..): the crosses r x u (m), or
 * in `jacobiansInv` and `frictionInv` their products with the world inverse inertia tensor,
 * I^-1 (r x u) (1/(kg m)), kept only for a manifold whose bodies are not isotropic (a pile of cubes never
 * reads them). `solveRecord` holds everything else a pass reads of a manifold in one block of REC_STRIDE
 * numbers: its head (HEAD_*), its friction rows' crosses (REC_T1, REC_T2), then each point's separation,
 * effective mass and normal row (REC_POINTS, POINT_STRIDE, solver/contact-point-layout.ts CP_*), so a pass streams one run of memory a manifold
 * instead of a column each. The crosses and effective masses are kept rounded to single precision (as
 * Math.fround), the numbers the solve has always used.
 *
 * A module of numeric constants only, which every build folds into the code that reads it
 * (scripts/build.mjs isConstantModule).
 */

// A row of angular parts.
/** Body A's part, x. */
export const ROW_AX = 0;
/** Body A's part, y. */
export const ROW_AY = 1;
/** Body A's part, z. */
export const ROW_AZ = 2;
/** Body B's part, x. */
export const ROW_BX = 3;
/** Body B's part, y. */
export const ROW_BY = 4;
/** Body B's part, z. */
export const ROW_BZ = 5;

// A contact point's anchors in the manifold buffer's `anchors` (collision/manifolds-3d.ts), point q's at
// ANCHOR_STRIDE q: r_A then r_B, from each body's centre of mass to the point (m, world), side by side so
// the narrowphase writes and the prepare reads one run of memory a point.
/** r_A, x. */
export const ANCHOR_AX = 0;
/** r_A, y. */
export const ANCHOR_AY = 1;
/** r_A, z. */
export const ANCHOR_AZ = 2;
/** r_B, x. */
export const ANCHOR_BX = 3;
/** r_B, y. */
export const ANCHOR_BY = 4;
/** r_B, z. */
export const ANCHOR_BZ = 5;
/** Numbers a point keeps in `anchors`. */
export const ANCHOR_STRIDE = 6;

/** Numbers a contact point keeps in `jacobiansInv` (one row, u = n): point q's at q * JAC_STRIDE. */
export const JAC_STRIDE = 6;

// A manifold's friction rows in frictionInv, at FRICTION_INV_STRIDE i.
/** Where the t1 row of the friction anchor starts. */
export const FRICTION_T1 = 0;
/** Where the t2 row of the friction anchor starts. */
export const FRICTION_T2 = 6;
/** Where the twist row starts (I_A^-1 n, I_B^-1 n, 1/(kg m^2)). */
export const FRICTION_TWIST = 12;
/** Numbers a manifold keeps in frictionInv (the t1, t2 and twist rows). */
export const FRICTION_INV_STRIDE = 18;

// A manifold's record in `solveRecord` starts at REC_STRIDE i. Its head, the numbers the solve reads once
// per manifold and pass, at HEAD_* from the record's start:
/** The normal n, x (unit). */
export const HEAD_NX = 0;
/** n, y. */
export const HEAD_NY = 1;
/** n, z. */
export const HEAD_NZ = 2;
/** The first tangent t1, x (unit). */
export const HEAD_T1X = 3;
/** t1, y. */
export const HEAD_T1Y = 4;
/** t1, z. */
export const HEAD_T1Z = 5;
/** Friction coefficient. */
export const HEAD_MU = 6;
/** Twist arm, m. */
export const HEAD_ARM = 7;
/** Effective mass of the t1 row, kg. */
export const HEAD_MT1 = 8;
/** Effective mass of the t2 row, kg. */
export const HEAD_MT2 = 9;
/** Effective mass of the twist row, kg m^2. */
export const HEAD_MTW = 10;
/** Smallest separation of the points at the step's start, m (the speculative skip). */
export const HEAD_MIN_SEP = 11;
/** Body A's reach from its centre to the points, m (padded). */
export const HEAD_REACH_A = 12;
/** Body B's reach, m. */
export const HEAD_REACH_B = 13;
/** Body A's scalar inverse inertia when both bodies are isotropic, else 0, 1/(kg m^2). */
export const HEAD_INV_IA = 14;
/** Body B's, as HEAD_INV_IA. */
export const HEAD_INV_IB = 15;
/** Where the record's friction row along t1 starts (the anchor's r_A x t1, r_B x t1, m). */
export const REC_T1 = 16;
/** Where the record's friction row along t2 = n x t1 starts. */
export const REC_T2 = 22;
/** Where the record's first point starts (point k at REC_POINTS + POINT_STRIDE k). */
export const REC_POINTS = 28;
/** Numbers a manifold keeps in solveRecord (room for four points). */
export const REC_STRIDE = 60;

// A point in its manifold's record: separation and normal mass at CP_SEPARATION and CP_NORMAL_MASS
// (solver/contact-point-layout.ts, as a 2D point's), then its normal row r_A x n, r_B x n from
// CP_NORMAL_ROW on (ROW_*, m).
/** Numbers a point keeps in its manifold's record. */
export const POINT_STRIDE = 8;
