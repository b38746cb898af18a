/**
 * The argument slots of treeGather (forces/barnes-hut/gather.ts), filled by worldTreeFields
 * (forces/barnes-hut/tree.ts): where each array sits in the kernel's `A` and each number in its `P`,
 * imported as `TREE_GATHER` (`A[TREE_GATHER.PX]`) by the kernel and by its caller. A module of numeric
 * constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** Position x, m (Float64, by entity). */
export const PX = 0;
/** Position y, m. */
export const PY = 1;
/** Position z, m (unused in 2D). */
export const PZ = 2;
/** Mass, kg (Float64, by entity). */
export const MASS = 3;
/** The gathered x, m (Float64, out, by index into the body list). */
export const GX = 4;
/** The gathered y, m (out). */
export const GY = 5;
/** The gathered z, m (out; 3D only). */
export const GZ = 6;
/** The gathered mass, kg (out). */
export const GM = 7;
/** The ranges' bounding boxes (Float64, out: BOX.RANGE_STRIDE a range, forces/barnes-hut/bounds.ts). */
export const BOX = 8;
/** The gathered entity of each index (Int32, out). */
export const ENTS = 9;

// P: the numbers.
/** The world's dimensions, 2 or 3. */
export const DIMENSIONS = 0;
/** Numbers in P. */
export const PARAMS = 1;
