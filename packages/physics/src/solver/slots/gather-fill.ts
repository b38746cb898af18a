/**
 * The argument slots of gatherFill (solver/stages-kernel.ts), filled by gatherFillStage
 * (solver/stages-threads.ts): where each array sits in the kernel's `A` and each number in its `P`,
 * imported as `GATHER` (`A[GATHER.NAME]`) by the kernel and by its caller. A module of numeric
 * constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** Position x, m (Float64, by entity). */
export const PX = 0;
/** Position y, m. */
export const PY = 1;
/** Velocity x, m/s (Float64, by entity). */
export const VX = 2;
/** Velocity y, m/s. */
export const VY = 3;
/** AngularVelocity z, rad/s (Float64, by entity). */
export const WZ = 4;
/** Force x, N (Float64, by entity). */
export const FX = 5;
/** Force y, N. */
export const FY = 6;
/** Force z, N (a body with any force is not in free flight). */
export const FZ = 7;
/** The collision state's body type (Uint8, by entity: BodyType). */
export const BODY_TYPE = 8;
/** The collision state's inverse mass, 1/kg (Float64, by entity). */
export const INV_MASS = 9;
/** The collision state's inverse moment of inertia, 1/(kg m^2) (Float64, by entity). */
export const INV_INERTIA = 10;
/** The solver body state (rows of BS2_STRIDE in 2D, BS3_STRIDE in 3D, solver/body-state-layout.ts), written. */
export const BODY_STATE = 11;
/** The solver body extra rows (rows of BX_STRIDE), written. */
export const BODY_EXTRA = 12;
/** Position z, m (read in 3D). */
export const PZ = 13;
/** Velocity z, m/s (read in 3D). */
export const VZ = 14;
/** Angular velocity x, rad/s (read in 3D). */
export const WX = 15;
/** Angular velocity y, rad/s (read in 3D). */
export const WY = 16;
// P: the numbers.
/** The step h, s. */
export const H = 0;
/** g_x h, m/s. */
export const GX_H = 1;
/** g_y h, m/s. */
export const GY_H = 2;
/** 1: joints are in the step, so every body counts as pushed; 0: not. */
export const PUSHED = 3;
/** BodyType.Dynamic. */
export const DYNAMIC = 4;
/** BodyType.Kinematic. */
export const KINEMATIC = 5;
/** g_z h, m/s (3D). */
export const GZ_H = 6;
/** 1 for a 3D world (rows of BS3_STRIDE), 0 for 2D. */
export const THREE_D = 7;
