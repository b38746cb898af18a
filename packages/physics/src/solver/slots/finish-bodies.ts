/**
 * The argument slots of finishBodies (2D and 3D) and its loops (solver/stages-kernel.ts), filled by
 * finishStage (solver/stages-threads.ts): where each array sits in the kernel's `A` and
 * each number in its `P`, imported as `FINISH` (`A[FINISH.NAME]`) by the kernel and by its caller.
 * A module of numeric constants only, which every build folds into the code (threads/worker-
 * source.ts).
 */

// A: the arrays.
/** Position x, m (Float64, by entity), written. */
export const PX = 0;
/** Position y, m, written. */
export const PY = 1;
/** Velocity x, m/s, written. */
export const VX = 2;
/** Velocity y, m/s, written. */
export const VY = 3;
/** AngularVelocity z, rad/s, written. */
export const WZ = 4;
/** Angle, rad, written. */
export const ANGLE = 5;
/** The collision state's body type (Uint8, by entity). */
export const BODY_TYPE = 6;
/** The solver body state (rows of BS2_STRIDE). */
export const BODY_STATE = 7;
/** The solver body extra rows (rows of BX_STRIDE). */
export const BODY_EXTRA = 8;
/** The solver bodies' impact rows (rows of P[FINISH.IMPACT_STRIDE]). */
export const BODY_IMPACT = 9;
/** Ball radius, m (by entity). */
export const RADIUS = 10;
/** Material restitution (by entity). */
export const RESTITUTION = 11;
/** The deepest overlap each thread found, m (one slot a thread), written. */
export const DEEPEST = 12;
/** Solver index of body A of each contact row (Int32). */
export const IA = 13;
/** Solver index of body B (Int32). */
export const IB = 14;
/** Separation at the start of the step, m. */
export const SEPARATION = 15;
/** Contact normal x. */
export const NX = 16;
/** Contact normal y. */
export const NY = 17;
/** Position z, m, written (3D). */
export const PZ = 18;
/** Velocity z, m/s, written (3D). */
export const VZ = 19;
/** Angular velocity x, rad/s, written (3D). */
export const WX = 20;
/** Angular velocity y, rad/s, written (3D). */
export const WY = 21;
/** Orientation quaternion x, turned by the rotation owed (3D). */
export const QX = 22;
/** Orientation quaternion y (3D). */
export const QY = 23;
/** Orientation quaternion z (3D). */
export const QZ = 24;
/** Orientation quaternion w (3D). */
export const QW = 25;
/** Contact normal z (3D). */
export const NZ = 26;
// P: the numbers.
/** Free flight's correction -g_x h h_s / 2, m. */
export const FREE_X = 0;
/** Free flight's correction -g_y h h_s / 2, m. */
export const FREE_Y = 1;
/** Free flight's correction -g_z h h_s / 2, m (3D). */
export const FREE_Z = 2;
/** BodyType.Dynamic. */
export const DYNAMIC = 3;
/** Numbers an impact row (IMPACT_STRIDE). */
export const IMPACT_STRIDE = 4;
/** 1: the boundary box is on (contain the bodies), 0: off. */
export const CONTAIN = 5;
/** The box's min x, m (min y and z follow at FINISH.MIN_X + 1 and + 2). */
export const MIN_X = 6;
/** The box's min y, m. */
export const MIN_Y = 7;
/** The box's min z, m (3D). */
export const MIN_Z = 8;
/** The box's max x, m (max y and z follow at FINISH.MAX_X + 1 and + 2). */
export const MAX_X = 9;
/** The box's max y, m. */
export const MAX_Y = 10;
/** The box's max z, m (3D). */
export const MAX_Z = 11;
/** The box's restitution. */
export const BOX_RESTITUTION = 12;
/** Gravity x, m/s^2 (y and z follow at FINISH.GX + 1 and + 2). */
export const GX = 13;
/** Gravity y, m/s^2. */
export const GY = 14;
/** Gravity z, m/s^2 (3D). */
export const GZ = 15;
/** Contact rows. */
export const ROWS = 16;
/** Solver bodies - 1 (the loop's length). */
export const BODIES = 17;
/** 1 for a 3D world (rows of BS3_STRIDE, the z stores, orientations), 0 for 2D. */
export const THREE_D = 18;
