/**
 * The argument slots of finishBodies2D and its loops (solver/stages-kernel.ts), filled by
 * finishBodies2DStage (solver/stages-threads.ts): where each array sits in the kernel's `A` and
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
// P: the numbers.
/** Free flight's correction -g_x h h_s / 2, m. */
export const FREE_X = 0;
/** Free flight's correction -g_y h h_s / 2, m. */
export const FREE_Y = 1;
/** BodyType.Dynamic. */
export const DYNAMIC = 2;
/** Numbers an impact row (IMPACT_STRIDE). */
export const IMPACT_STRIDE = 3;
/** 1: the boundary box is on (contain the bodies), 0: off. */
export const CONTAIN = 4;
/** The box's min x, m (min y follows at FINISH.MIN_X + 1). */
export const MIN_X = 5;
/** The box's min y, m. */
export const MIN_Y = 6;
/** The box's max x, m (max y follows at FINISH.MAX_X + 1). */
export const MAX_X = 7;
/** The box's max y, m. */
export const MAX_Y = 8;
/** The box's restitution. */
export const BOX_RESTITUTION = 9;
/** Gravity x, m/s^2. */
export const GX = 10;
/** Gravity y, m/s^2. */
export const GY = 11;
/** Contact rows. */
export const ROWS = 12;
/** Solver bodies - 1 (the loop's length). */
export const BODIES = 13;
