/**
 * The layout of the 2D manifolds' packed solver rows, `ShapeCollisionState.solverRows` (Box2D v3's
 * b2ContactConstraint): prepareManifolds (solver/manifold-prepare-2d.ts) fills one row of MR_STRIDE
 * numbers a manifold once a step, the substeps' stages (solver/manifold-rows-2d.ts) read and write only
 * the rows (one array, the fields of a manifold next to each other), and storeManifoldImpulses writes
 * the impulses back to the manifold buffer for the touch events and the next step's warm start.
 * A row holds its fields (MR_*) and then its two points' (MP_*, point p at MR_POINT0 + p * MP_STRIDE).
 *
 * A module of numeric constants only, which every build folds into the code that reads it
 * (scripts/build.mjs isConstantModule).
 */

// A row's fields.
/** Solver index of body A (0: the static world); its packed body state starts at BS2_STRIDE times it. */
export const MR_BODY_A = 0;
/** Solver index of body B. */
export const MR_BODY_B = 1;
/**
 * A solver index read from a row is masked with this (2^25 - 1): the indices are below a world's
 * capacity + 1 (MAX_CAPACITY, 2^24, at most), so the mask changes none, and V8, knowing the range, computes
 * the body offsets (index times a stride, plus a field) in 32-bit integers without overflow checks.
 * Written in decimal: scripts/build.mjs isConstantModule reads decimal numbers only.
 */
export const MR_BODY_MASK = 33554431;
/** Unit normal from A to B, x. */
export const MR_NX = 2;
/** Unit normal from A to B, y. */
export const MR_NY = 3;
/** Points, 1 or 2. */
export const MR_POINT_COUNT = 4;
/** 1 when the two points' normal rows are solved as one block (K well conditioned), else 0. */
export const MR_BLOCK_VALID = 5;
/** The block's inverse effective mass K^-1, entry 11, kg. */
export const MR_B11 = 6;
/** K^-1, entry 12, kg. */
export const MR_B12 = 7;
/** K^-1, entry 22, kg. */
export const MR_B22 = 8;
/** The block's K = J M^-1 J^T itself (the inverse of K^-1), entry 11, 1/kg. */
export const MR_K11 = 9;
/** K, entry 12, 1/kg. */
export const MR_K12 = 10;
/** K, entry 22, 1/kg. */
export const MR_K22 = 11;
/** Friction coefficient bounding |lambda_t| by mu lambda_n (the static one while sticking). */
export const MR_FRICTION_BOUND = 12;
/** Rolling resistance times the rolling radius, m (0: none). */
export const MR_ROLLING = 13;
/** Effective mass of the rolling row, kg m^2. */
export const MR_ROLLING_MASS = 14;
/** Accumulated rolling impulse, N m s. */
export const MR_ROLLING_IMPULSE = 15;
/** Mixed restitution coefficient. */
export const MR_RESTITUTION = 16;
/** Where the first point's fields start; the second's is MP_STRIDE further. */
export const MR_POINT0 = 17;
/** Numbers a manifold: MR_POINT0 + 2 * MP_STRIDE. */
export const MR_STRIDE = 41;

// A point's fields, from the point's start: separation and normal mass at CP_SEPARATION and
// CP_NORMAL_MASS (solver/contact-point-layout.ts, as a 3D point's), then the levers and the rest.
/**
 * r_A x n: the cross product of the anchor on body A (from its centre of mass at the start of the
 * step) with the normal, m; the normal row's first lever (CP_NORMAL_ROW). The rows never need the
 * anchors themselves: a point's normal velocity is (v_B - v_A) . n + w_B (r_B x n) - w_A (r_A x n), and
 * a normal impulse P n turns A by -P (r_A x n) / I_A, so the four cross products are worked out once a
 * step here instead of in every pass.
 */
export const MP_RNA = 2;
/** r_B x n, m (see MP_RNA). */
export const MP_RNB = 3;
/** r_A x t with the tangent t = (-n_y, n_x), which is r_A . n, m: the friction row's lever on A. */
export const MP_RTA = 4;
/** r_B x t, m (see MP_RTA). */
export const MP_RTB = 5;
/** Effective mass of the friction row, kg. */
export const MP_TANGENT_MASS = 6;
/** Accumulated normal impulse of this substep, N s, >= 0. */
export const MP_NORMAL_IMPULSE = 7;
/** Accumulated friction impulse of this substep, N s. */
export const MP_TANGENT_IMPULSE = 8;
/** Largest normal impulse a single pass added this step, N s (restitution applies only where it is > 0). */
export const MP_MAX_NORMAL_IMPULSE = 9;
/** Sum of the substeps' normal impulses, N s (touch events). */
export const MP_TOTAL_NORMAL_IMPULSE = 10;
/** Normal velocity at the start of the step, m/s (< 0: approaching). */
export const MP_RELATIVE_VELOCITY = 11;
/** Numbers a point. */
export const MP_STRIDE = 12;
