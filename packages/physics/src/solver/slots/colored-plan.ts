/**
 * The argument slots of the coloured solve's plan, the Int32 array at A[SOLVE.PLAN] that the
 * coloured kernels share (solver/coloring.ts fills it): where each array sits in the kernel's `A`
 * and each number in its `P`, imported as `PLAN` (`A[PLAN.NAME]`) by the kernel and by its caller.
 * A module of numeric constants only, which every build folds into the code (threads/worker-
 * source.ts).
 */

/** Substeps. */
export const SUBSTEPS = 0;
/** Biased passes a substep. */
export const ITERATIONS = 1;
/** Relax passes a substep. */
export const RELAX = 2;
/** Threads running the kernel. */
export const THREADS = 3;
/** Colours C. */
export const COLORS = 4;
/** Solver bodies. */
export const BODIES = 5;
/** 1: the calling thread may block in Atomics.wait. */
export const MAY_WAIT = 6;
/** Packing ranges (0: the rows are packed already). */
export const PARTS = 7;
/** Rows packed. */
export const PACKED_ROWS = 8;
/** 1: strips (the body stages fused into colour 0's blocks). */
export const STRIPS = 9;
/** Even blocks. */
export const EVEN_BLOCKS = 10;
/** 1 when the strip plan packed the rows. */
export const PACKED = 11;
/**
 * Colour c's first block is plan[PLAN.COLOR_BLOCKS + c], c = 0 .. C (C the overflow colour);
 * plan[PLAN.COLOR_BLOCKS + C + 1] the end.
 */
export const COLOR_BLOCKS = 12;
