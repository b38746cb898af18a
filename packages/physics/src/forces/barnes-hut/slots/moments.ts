/**
 * The argument slots of treeMoments (forces/barnes-hut/moments.ts), filled by
 * treeMomentsAll (forces/barnes-hut/tree-build.ts): where each array sits in the kernel's `A` and each
 * number in its `P`, imported as `MOMENTS` (`A[MOMENTS.NODE]`) by the kernels and by their caller. A
 * module of numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays, indexed as in GravityTree (forces/barnes-hut/tree-store.ts).
/** Bodies' position x in tree order, m (Float64). */
export const X = 0;
/** Bodies' position y, m. */
export const Y = 1;
/** Bodies' position z, m (unused in 2D). */
export const Z = 2;
/** Bodies' mass in tree order, kg (Float64). */
export const MASS = 3;
/** The nodes' moments (Float64, written: forces/barnes-hut/node-2d.ts or node-3d.ts). */
export const NODE = 4;
/** The nodes' tight boxes (Float64, written: BOX.NODE_STRIDE a node, forces/barnes-hut/bounds.ts). */
export const BOX = 5;
/** Each node's first slot (Int32). */
export const START = 6;
/** Each node's end slot, exclusive (Int32). */
export const END = 7;
/** The node after each node's subtree (Int32; k + 1 for a leaf), complete. */
export const SKIP = 8;
/** The input index of each slot (Int32). */
export const PERM = 9;
/** The slot of each input index (Int32, written for the bodies of the leaves). */
export const SLOT = 10;
/** The listed nodes (Int32). */
export const LIST = 11;
/** The parts' runs of the list (Int32: part p takes list[cut[p]] .. list[cut[p + 1] - 1]). */
export const CUT = 12;

// P: the numbers.
/** 0: each listed node's whole subtree, children before parents; 1: each listed node alone, in list order. */
export const ALONE = 0;
/** The tree's dimensions, 2 or 3 (the node layout: forces/barnes-hut/node-2d.ts or node-3d.ts). */
export const DIMENSIONS = 1;
/** Numbers in P. */
export const PARAMS = 2;
