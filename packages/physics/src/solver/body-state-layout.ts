/**
 * The layout of the packed solver body rows (CollisionState.bodyState, bodyExtra and bodyImpact,
 * collision/state.ts, and in 3D Contact3DState.invInertia, collision/manifolds-3d.ts): one row per
 * solver body of the step, row k at k * stride, row 0 the static world. Each offset and stride is named here once.
 *
 * A module of numeric constants only (scripts/build.mjs isConstantModule): every build folds them into
 * the code that reads them, so the range kernels (solver/*-kernel.ts) may use them too, though the
 * workers get the kernels' source text (threads/worker-source.ts checks that none is left as a name).
 */

// bodyState, 2D: rows of BS2_STRIDE. vx and vy sit at 0 and 1 in both dimensions: code written for both
// names them BS2_VX and BS2_VY (and BS3_VZ for z).
/** 2D: linear velocity x, m/s. */
export const BS2_VX = 0;
/** 2D: linear velocity y, m/s. */
export const BS2_VY = 1;
/** 2D: angular velocity, rad/s. */
export const BS2_W = 2;
/** 2D: displacement x within the step (added to the bodyExtra base), m. */
export const BS2_DX = 3;
/** 2D: displacement y within the step, m. */
export const BS2_DY = 4;
/** 2D: inverse mass this step (0 for static and kinematic bodies), 1/kg. */
export const BS2_INV_MASS = 5;
/** 2D: inverse moment of inertia this step, 1/(kg m^2). */
export const BS2_INV_INERTIA = 6;
/** 2D: 1 once a solver row has applied an impulse to the body this step, 0 while in free flight. */
export const BS2_PUSHED = 7;
/** 2D: numbers a bodyState row. */
export const BS2_STRIDE = 8;

// bodyState, 3D: rows of BS3_STRIDE.
/** 3D: linear velocity x, m/s. */
export const BS3_VX = 0;
/** 3D: linear velocity y, m/s. */
export const BS3_VY = 1;
/** 3D: linear velocity z, m/s. */
export const BS3_VZ = 2;
/** 3D: angular velocity x, world frame, rad/s. */
export const BS3_WX = 3;
/** 3D: angular velocity y, world frame, rad/s. */
export const BS3_WY = 4;
/** 3D: angular velocity z, world frame, rad/s. */
export const BS3_WZ = 5;
/** 3D: displacement x within the step (added to the bodyExtra base), m. */
export const BS3_DX = 6;
/** 3D: displacement y within the step, m. */
export const BS3_DY = 7;
/** 3D: displacement z within the step, m. */
export const BS3_DZ = 8;
/** 3D: inverse mass this step (0 for static and kinematic bodies), 1/kg. */
export const BS3_INV_MASS = 9;
/** 3D: inverse moment of inertia this step (a scalar), 1/(kg m^2). */
export const BS3_INV_INERTIA = 10;
/** 3D: 1 once a solver row has applied an impulse to the body this step, 0 while in free flight. */
export const BS3_PUSHED = 11;
/** 3D: numbers a bodyState row. */
export const BS3_STRIDE = 12;

// bodyExtra, 2D and 3D: rows of BX_STRIDE.
/** The base x the displacement is added to (where the integrator put the body, less v h), m. */
export const BX_BASE_X = 0;
/** The base y the displacement is added to, m. */
export const BX_BASE_Y = 1;
/** The base z the displacement is added to (3D), m. */
export const BX_BASE_Z = 2;
/** The rotation still to apply about x (3D), rad. */
export const BX_ROT_X = 3;
/** The rotation still to apply about y (3D), rad. */
export const BX_ROT_Y = 4;
/** The rotation still to apply about z (in 2D, the angle still to apply), rad. */
export const BX_ROT_Z = 5;
/** Numbers a bodyExtra row. */
export const BX_STRIDE = 6;

// Contact3DState.invInertia (collision/manifolds-3d.ts), 3D: rows of II3_STRIDE, the world inverse inertia
// tensor I^-1 = R diag(1 / I_k) R^T of each solver body (symmetric: six numbers), 1/(kg m^2), written by
// prepareSolverBodies3D (solver/manifold-prepare-3d.ts).
/** 3D: the inverse inertia tensor's xx. */
export const II3_XX = 0;
/** 3D: the inverse inertia tensor's yy. */
export const II3_YY = 1;
/** 3D: the inverse inertia tensor's zz. */
export const II3_ZZ = 2;
/** 3D: the inverse inertia tensor's xy (= yx). */
export const II3_XY = 3;
/** 3D: the inverse inertia tensor's xz (= zx). */
export const II3_XZ = 4;
/** 3D: the inverse inertia tensor's yz (= zy). */
export const II3_YZ = 5;
/** 3D: numbers an invInertia row. */
export const II3_STRIDE = 6;

// bodyImpact, 2D and 3D: rows of IMPACT_STRIDE (the impact stage, solver/impacts.ts).
/** The end-position correction x of this step's impacts (-dv t* summed over impacts), m. */
export const BI_CORR_X = 0;
/** The end-position correction y of this step's impacts, m. */
export const BI_CORR_Y = 1;
/** The end-position correction z of this step's impacts, m. */
export const BI_CORR_Z = 2;
/** The time of the body's latest impact this step, s (-1: the body carried a load and is left to the substeps). */
export const BI_TIME = 3;
/**
 * Whether the soft substeps leave the body alone (1, clean) or not (0), set by `separateImpactedBodies`;
 * -1 from `applyImpacts` until then: a loaded row that starts touching makes the body unclean.
 */
export const BI_ALONE = 4;
/**
 * Row length of `CollisionState.bodyImpact`: the end-position correction (x, y, z), m; the time of the
 * body's latest impact this step, s (-1: the body carried a load and is left to the substeps); and
 * whether the soft substeps leave the body alone (1) or not (0), set by `separateImpactedBodies`.
 * @category Collision
 */
export const IMPACT_STRIDE = 5;
