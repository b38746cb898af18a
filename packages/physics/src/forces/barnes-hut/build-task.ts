/**
 * The layout of a task of the Barnes-Hut build's stack (GravityTree.taskI and taskF,
 * forces/barnes-hut/tree-store.ts; splitCells in tree-build.ts): a cell still to be made a node, task t's
 * integers at t * INT_STRIDE in taskI and its numbers at t * FLOAT_STRIDE in taskF. Imported as `TASK`
 * (`ti[o + TASK.HI]`). A module of numeric constants only, which every build folds into the code that
 * reads it.
 */

// taskI (Int32).
/** The cell's first slot. */
export const LO = 0;
/** The slot after the cell's last. */
export const HI = 1;
/** 1 if the cell's bodies are in the tree's first buffer (x, y, z, m, perm), 0 if in the second (x2 ...). */
export const IN_FIRST = 2;
/** The cell's depth (the root 0). */
export const DEPTH = 3;
/** The cell's parent node (-1 for the root). */
export const PARENT = 4;
/** Numbers a task in taskI. */
export const INT_STRIDE = 5;

// taskF (Float64).
/** The cell's centre x, m. */
export const CX = 0;
/** The cell's centre y, m. */
export const CY = 1;
/** The cell's centre z, m (0 in 2D). */
export const CZ = 2;
/** The cell's half edge, m. */
export const HALF = 3;
/** Numbers a task in taskF. */
export const FLOAT_STRIDE = 4;
