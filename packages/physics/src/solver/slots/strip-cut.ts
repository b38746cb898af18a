/**
 * The argument slots of stripCut2D (solver/strips-kernel.ts), whose arrays may follow another
 * kernel's, from A[P[BASE]]: where each array sits in the kernel's `A` and each number in its `P`,
 * imported as `CUT` (`A[CUT.NAME]`) by the kernel and by its caller. A module of numeric constants
 * only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** The solver body state (rows of BS2_STRIDE). */
export const BODY_STATE = 0;
/** The solver body extra rows (rows of BX_STRIDE). */
export const BODY_EXTRA = 1;
/** The collision state's body type (Uint8, by entity). */
export const BODY_TYPE = 2;
/** The solver bodies' entity ids (Int32, by solver index). */
export const BODIES = 3;
/** 1 where the solver body takes gravity (Uint8, written). */
export const DYN = 4;
/** Each solver body's strip (Uint8, written; 255: not movable). */
export const STRIP = 5;
/** Each solver body's bin (Uint16, written; P[CUT.NO_BIN]: not movable). */
export const BIN = 6;
/** Rows a bin (Int32, written). */
export const BIN_ROWS = 7;
/** Each bin's strip (Uint8, written). */
export const BIN_STRIP = 8;
/** Solver index of body A of each row (Int32). */
export const IA = 9;
/** Solver index of body B (Int32). */
export const IB = 10;
/** Arrays stripCut2D takes. */
export const ARRAYS = 11;
// P: the numbers.
/** Solver bodies. */
export const P_BODIES = 0;
/** Contact rows. */
export const P_ROWS = 1;
/** Strips (2 .. 255). */
export const P_STRIPS = 2;
/** Bins (<= P[CUT.NO_BIN]). */
export const BINS = 3;
/** BodyType.Dynamic. */
export const P_DYNAMIC = 4;
/** The "no bin" mark. */
export const NO_BIN = 5;
/** Where stripCut2D's arrays start in A. */
export const BASE = 6;
