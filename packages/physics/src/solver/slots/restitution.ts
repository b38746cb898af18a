/**
 * The argument slots of restitutionColored and its loops restitutionTargets and restitutionRows
 * (solver/stages-kernel.ts), filled by restitutionStage (solver/stages-threads.ts): where each array sits in the kernel's `A` and
 * each number in its `P`, imported as `RESTITUTION` (`A[RESTITUTION.NAME]`) by the kernel and by
 * its caller. A module of numeric constants only, which every build folds into the code
 * (threads/worker-source.ts).
 */

// A: the arrays.
/** The coloured solve's plan (Int32, the PLAN slots of solver/slots/colored-plan.ts). */
export const PLAN = 0;
/** Counters (Int32, 0 on entry: 0 unused, 1 blocks done, 2 abort, 3 bouncing rows). */
export const COUNTERS = 1;
/** The solver body state (rows of BS2_STRIDE, or of BS3_STRIDE in 3D). */
export const BODY_STATE = 2;
/** Solver index of body A of each contact row (Int32). */
export const IA = 3;
/** Solver index of body B (Int32). */
export const IB = 4;
/** Contact normal x. */
export const NX = 5;
/** Contact normal y. */
export const NY = 6;
/** Normal effective mass, kg. */
export const NORMAL_MASS = 7;
/** Combined restitution. */
export const RESTITUTION = 8;
/** Normal relative velocity, m/s. */
export const RELATIVE_VELOCITY = 9;
/** Normal speed at impact, m/s. */
export const IMPACT_VELOCITY = 10;
/** Largest normal impulse of a pass, N s. */
export const MAX_NORMAL_IMPULSE = 11;
/** Normal impulse delivered over the step, N s. */
export const TOTAL_NORMAL_IMPULSE = 12;
/** The impact stage's impulse, N s. */
export const IMPULSE = 13;
/** Block j is the rows ROW[bounds[j] .. bounds[j + 1]) (Int32). */
export const BOUNDS = 14;
/** The contact buffer rows a pass visits, in its order (Int32): colour by colour, or in buffer order. */
export const ROW = 15;
/** A flag a block, numbered across the units (Int32, 0 on entry; restitutionBlocks of them). */
export const CLAIM = 16;
/** Contact normal z (read by restitutionTargets in 3D). */
export const NZ = 17;
// P: the numbers.
/** Contact rows. */
export const ROWS = 0;
/** restitutionThreshold, m/s. */
export const THRESHOLD = 1;
/** elasticRestitutionThreshold, m/s. */
export const ELASTIC_THRESHOLD = 2;
/** restitutionIterations. */
export const ITERATIONS = 3;
/** 1: the calling thread may block in Atomics.wait. */
export const MAY_WAIT = 4;
/** How long a thread spins before it blocks, microseconds. */
export const SPIN_US = 5;
/** 1 for a 3D world's rows (restitutionTargets: rows of BS3_STRIDE, the normal's z read), 0 for 2D. */
export const THREE_D = 6;
