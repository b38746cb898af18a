/**
 * The argument slots of stripPlan2D (solver/strip-plan-kernel.ts), filled by planArguments and
 * planParameters (solver/coloring.ts): its arrays start with solveColored2D's (SOLVE), then
 * stripCut2D's (CUT) from CUT_ARRAYS; its parameters' slots 0 to 6 are stripCut2D's (CUT), and 11
 * and 12 are coloredPack2D's (SOLVE.ROWS, SOLVE.GROUP_SLOTS): where each
 * array sits in the kernel's `A` and each number in its `P`, imported as `STRIP_PLAN`
 * (`A[STRIP_PLAN.NAME]`) by the kernel and by its caller. A module of numeric constants only, which
 * every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** Where stripCut2D's arrays start in the strip plan's A. */
export const CUT_ARRAYS = 31;
/** Rows a group (Int32, MAX_COLORS + 2 slots), scratch. */
export const COUNTS = 42;
/** Each group's first row (Int32), scratch. */
export const START = 43;
/** Each row's next row in its group (Int32), scratch. */
export const NEXT = 44;
// P: the numbers.
/** Packing ranges. */
export const PARTS = 7;
/** 1: pack the rows here, 0: not. */
export const PACK = 8;
/** 1: cut the strips here, 0: the cut is made. */
export const CUT_HERE = 9;
/** The most rows the overflow group may take. */
export const MAX_OVERFLOW = 10;
/** PLAN_HEAD (solver/coloring.ts): where the colours' blocks start in the plan. */
export const PLAN_HEAD = 13;
/** MAX_COLORS (solver/coloring.ts). */
export const MAX_COLORS = 14;
/** Rows a block. */
export const BLOCK_ROWS = 15;
