/**
 * The argument slots of approachSpeeds (solver/stages-kernel.ts), filled by approachArguments
 * (solver/coloring.ts) and approachStage (solver/stages-threads.ts); its arrays may follow
 * another kernel's, from A[P[BASE]]: where each array sits in the kernel's `A` and each number in
 * its `P`, imported as `APPROACH` (`A[APPROACH.NAME]`) by the kernel and by its caller. A module of
 * numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** Solver index of body A of each contact row (Int32). */
export const IA = 0;
/** Solver index of body B (Int32). */
export const IB = 1;
/** Entity of body A, 0 for the static world (Int32). */
export const A = 2;
/** Entity of body B (Int32). */
export const B = 3;
/** Contact normal x, from A to B. */
export const NX = 4;
/** Contact normal y. */
export const NY = 5;
/** Contact normal z. */
export const NZ = 6;
/** Normal relative velocity after the impact stage, m/s (written). */
export const RELATIVE_VELOCITY = 7;
/** Normal speed at impact, m/s (written). */
export const IMPACT_VELOCITY = 8;
/** Separation at the start of the step, m. */
export const SEPARATION = 9;
/** The impact stage's impulse on the row, N s. */
export const IMPULSE = 10;
/** The collision state's body type (Uint8, by entity). */
export const BODY_TYPE = 11;
/** The solver body state (rows of BS2_STRIDE in 2D, BS3_STRIDE in 3D). */
export const BODY_STATE = 12;
/** Arrays approachSpeeds takes. */
export const ARRAYS = 13;
// P: the numbers.
/** Gravity x, m/s^2. */
export const GX = 0;
/** Gravity y, m/s^2. */
export const GY = 1;
/** Gravity z, m/s^2. */
export const GZ = 2;
/** BodyType.Dynamic. */
export const DYNAMIC = 3;
/** Where approachSpeeds's arrays start in A. */
export const BASE = 4;
/** 1 for a 3D world's rows (BS3_STRIDE, the normal's z read), 0 for 2D. */
export const THREE_D = 5;
/** Numbers approachSpeeds takes. */
export const PARAMS = 6;
