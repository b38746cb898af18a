/**
 * The layout of the Barnes-Hut bounding boxes: a node's tight box (GravityTree.box,
 * forces/barnes-hut/tree-store.ts; node k's at k * NODE_STRIDE, written by treeMoments), and a gathered
 * range's box (the gather's box array, forces/barnes-hut/tree.ts; range p's at p * RANGE_STRIDE, written
 * by treeGather), which adds a flag for a non-finite position. In 2D the z bounds are 0. Imported as
 * `BOX` (`B[b + BOX.MAX_X]`). A module of numeric constants only, which every build folds into the code
 * that reads it, the thread kernels included (threads/worker-source.ts).
 */

/** Smallest x of the bodies, m. */
export const MIN_X = 0;
/** Smallest y, m. */
export const MIN_Y = 1;
/** Smallest z, m (0 in 2D). */
export const MIN_Z = 2;
/** Largest x, m. */
export const MAX_X = 3;
/** Largest y, m. */
export const MAX_Y = 4;
/** Largest z, m (0 in 2D). */
export const MAX_Z = 5;
/** A gathered range's only: 1 if a position in it is NaN or infinite, else 0. */
export const NON_FINITE = 6;
/** Numbers a node's box. */
export const NODE_STRIDE = 6;
/** Numbers a gathered range's box (the seventh is NON_FINITE, the eighth unused). */
export const RANGE_STRIDE = 8;
