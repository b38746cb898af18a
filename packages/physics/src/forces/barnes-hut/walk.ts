/**
 * The evaluation half of the Barnes-Hut tree code (forces/barnes-hut/tree.ts): the dual-tree walk and the
 * downward pass, written as thread kernels (step/kernel-table.ts: self-contained functions whose
 * source text the worker threads also run), so that the field can be evaluated on several threads.
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
 * Arrays `A` (all indexed as in forces/barnes-hut/tree-store.ts's GravityTree):
 *   0 x, 1 y, 2 z, 3 m (bodies in tree order; z unused in 2D), 4 node (moments, stride 12),
 *   5 start, 6 end, 7 skip (Int32), 8 ax, 9 ay, 10 az (output field, m/s^2, tree order; az = 0 in 2D),
 *   11 cut (Int32: part p holds slots cut[p] .. cut[p + 1] - 1), 12 info (Float64, stride 4 a part:
 *   cell pairs, body pairs and visits counted by the part that holds the first cell's first slot, so
 *   they sum to the one-part walk's counts; then the part's own work, duplicates included, in the
 *   units of `WORK_*`), 13 + p: scratch of part p (Float64: the field polynomials of every node,
 *   stride NL, from 0, then the direct-sum accumulators x, y, z of every slot from P[5], P[6], P[7]);
 *   with P[8] = 1, from index P[9] on (after the scratch arrays): fx, fy, fz (the Force store, N),
 *   perm (Int32: input index of each slot), ents (Int32: entity of each input index).
 * Parameters `P`: 0 G (m^3 kg^-1 s^-2), 1 eps^2 (m^2), 2 1 / min(theta, 1)^2, 3 node count, 4 body
 * count, 5, 6, 7 offsets of the accumulators in the scratch arrays, 8 forces (1: the downward pass
 * also adds m g to the force of each of the part's bodies, entity ents[perm[s]], as it writes the
 * field; in 2D to x and y only. Each body is written once, so the order does not matter), 9 index
 * of the force arrays in A.
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
