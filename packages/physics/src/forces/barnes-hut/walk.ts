/**
 * The evaluation half of the Barnes-Hut tree code (forces/barnes-hut/tree.ts): the dual-tree walk and the
 * downward pass, written as one thread kernel (walk-kernel.ts; step/kernel-table.ts: a self-contained function
 * whose source text the worker threads also run), so that the field can be evaluated on several threads.
 * The one-thread evaluation runs the very same kernel with one part.
 *
 * Parts. The bodies' slots (tree order) are cut into contiguous parts [s0, s1) at leaf boundaries.
 * Every part replays the whole walk in the same order but skips each cell pair in which neither
 * cell holds a slot of the part (none of that pair's descendants can touch the part either), and
 * accumulates into its own scratch (field polynomials per node, direct sums per slot), so no two
 * threads ever write the same memory. Each cell or body of the part therefore receives exactly the
 * contributions of the one-part walk, in exactly the same order (a skipped pair touches none of
 * them): the field of every body is identical to the bit whatever the number of parts and wherever
 * they are cut. The price is that pairs straddling a cut are evaluated by both parts (a few per cent).
 * The downward pass of a part visits only the nodes that hold some of its slots and writes the
 * fields of its own slots to the output arrays.
 *
 * The kernel's arguments are named below (imported as `WALK`: `A[WALK.NODE]`, `P[WALK.G]`); the
 * arrays are indexed as in forces/barnes-hut/tree-store.ts's GravityTree. The counts a part writes to
 * `info` (INFO_ offsets) are counted by the part that holds the first cell's first slot, so they sum
 * to the one-part walk's counts; its work counts its own, duplicates included, in the units of `WORK_*`.
 * The range [lo, hi) of a call is a range of parts. Returns 0.
 */

/**
 * Relative cost of one walk visit, one direct body pair and one cell-cell expansion (the `info` work units).
 * @category Forces
 */
export const WORK_VISIT = 1,
  WORK_BODY_PAIR = 1,
  WORK_CELL_PAIR = 8;

/**
 * Slots of `info` a part.
 * @category Forces
 */
export const INFO_STRIDE = 4;

// A: the arrays.
/** Bodies' position x in tree order, m (Float64). */
export const X = 0;
/** Bodies' position y, m. */
export const Y = 1;
/** Bodies' position z, m (unused in 2D). */
export const Z = 2;
/** Bodies' mass in tree order, kg (Float64). */
export const MASS = 3;
/** The nodes' moments (Float64, forces/barnes-hut/node-2d.ts or node-3d.ts). */
export const NODE = 4;
/** Each node's first slot (Int32). */
export const START = 5;
/** Each node's end slot, exclusive (Int32). */
export const END = 6;
/** The node after each node's subtree (Int32; k + 1 for a leaf). */
export const SKIP = 7;
/** The field x at each slot, m/s^2 (Float64, out, tree order). */
export const AX = 8;
/** The field y at each slot, m/s^2 (out). */
export const AY = 9;
/** The field z at each slot, m/s^2 (out; 0 in 2D). */
export const AZ = 10;
/** The parts' slot ranges (Int32: part p holds slots cut[p] .. cut[p + 1] - 1). */
export const CUT = 11;
/** The parts' counts (Float64, INFO_STRIDE a part, out). */
export const INFO = 12;
/**
 * Part p's scratch is A[SCRATCH + p] (Float64): the field polynomials of every node from 0
 * (forces/barnes-hut/field-2d.ts or field-3d.ts), then the direct-sum accumulators x, y, z of every slot
 * from P[ACC_X], P[ACC_Y], P[ACC_Z].
 */
export const SCRATCH = 13;
// With P[ADD_FORCES] = 1, from A[P[FORCES_AT]] on (after the scratch arrays):
/** The Force store x, N (Float64, by entity), at P[FORCES_AT] + FORCE_X. */
export const FORCE_X = 0;
/** The Force store y, N. */
export const FORCE_Y = 1;
/** The Force store z, N (unused in 2D). */
export const FORCE_Z = 2;
/** The input index of each slot (Int32, the tree's perm). */
export const PERM = 3;
/** The entity of each input index (Int32). */
export const ENTS = 4;

// P: the numbers.
/** The gravitational constant G, m^3 kg^-1 s^-2. */
export const G = 0;
/** The softening squared eps^2, m^2. */
export const EPS2 = 1;
/** 1 / min(theta, 1)^2: cells interact by expansion when |R|^2 > (r_A + r_B)^2 times this. */
export const OPEN = 2;
/** The tree's node count. */
export const NODE_COUNT = 3;
/** The body count. */
export const BODY_COUNT = 4;
/** Where the direct sums x start in each scratch array. */
export const ACC_X = 5;
/** Where the direct sums y start. */
export const ACC_Y = 6;
/** Where the direct sums z start. */
export const ACC_Z = 7;
/**
 * 1: the downward pass also adds m g to the force of each of the part's bodies, entity ents[perm[s]],
 * as it writes the field (in 2D to x and y only; each body is written once, so the order does not
 * matter); 0: not.
 */
export const ADD_FORCES = 8;
/** The index in A of the force arrays (FORCE_X ...). */
export const FORCES_AT = 9;
/** The dimensions, 2 or 3: which expansions, direct sums and downward pass the kernel runs. */
export const DIMENSIONS = 10;
/** Numbers in P. */
export const PARAMS = 11;

// info: a part's counts, INFO_STRIDE a part.
/** Cell pairs expanded. */
export const INFO_CELL_PAIRS = 0;
/** Body pairs summed directly. */
export const INFO_BODY_PAIRS = 1;
/** Cell pairs visited. */
export const INFO_VISITS = 2;
/** The part's own work, in the units of WORK_*. */
export const INFO_WORK = 3;
