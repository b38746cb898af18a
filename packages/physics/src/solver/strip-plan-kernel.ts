/**
 * The strip plan of the coloured 2D contact solve (solver/coloring.ts: which pack group each row joins,
 * the blocks, each even block's bodies) as a thread kernel and kernel helpers (step/kernel-table.ts
 * rules: self-contained, the worker threads run their source text). A worker makes the plan and packs
 * the rows while the calling thread runs the impact stage (solver/coloring.ts startStripPlan); the
 * calling thread runs the same functions when it plans itself, so the plan is the same either way.
 */

import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import type { coloredPack2D } from './coloring-kernel.js';
import type { stripCut2D } from './strips-kernel.js';

/**
 * Thread kernel: plans the coloured solve of the contact buffer's rows by `P[2]` strips, on the thread
 * whose range is not empty (lo < hi; other ranges do nothing). In order:
 * 1. the strip cut (solver/strips-kernel.ts stripCut2D, when P[9] = 1; else the cut in `strip` is
 *    already one of P[2] strips);
 * 2. each row's pack group, that of its lower strip (even strips first: strip 2j is group j, strip
 *    2j + 1 group P[2] / 2 + j; P[14] (MAX_COLORS) the overflow group, rows joining bodies more than one
 *    strip apart; 255 not packed: a row that can do nothing, no mass and no impulse), counted per group
 *    and per packing range; if more than P[10] rows overflow, stops and returns -1 (fewer strips may do);
 * 3. the movable bodies by strip pair (a counting sort into `bodyOrder`) and each even block's range of
 *    them (`bodyBounds`: block m covers the pairs from its own, or 0 for the first, to the next
 *    block's, so an even strip without rows passes its bodies to the block before it);
 * 4. the layout (stripLayout2D: two colours, even and odd groups, a group one block);
 * 5. when P[8] = 1, the packing of every row into the pack (solver/coloring-kernel.ts coloredPack2D,
 *    each of the P[7] packing ranges), and plan[11] = 1 to say so.
 * A: 0 to 29 as solveColored2D's (solver/coloring-kernel.ts: 0 pack, 1 solver state, 2 solver extra,
 * 3 dyn, 4 plan, 6 groups, 7 offsets, 8 ia, 9 ib, 15 normalMass, 16 tangentMass, 18 normalImpulse,
 * 19 tangentImpulse1, 23 bounds, 24 bodyOrder, 25 bodyBounds, 26 pair, 27 tot, 28 row), 30 slot (Int32,
 * a buffer row: its pack row), 31 to 41 stripCut2D's arrays in its order (solver/strips-kernel.ts:
 * 36 strip, Uint8, a solver body's strip, 255 not movable), 42 counts, 43 start, 44 next (Int32,
 * P[14] + 2 each: rows a group, and scratch). P: 0 solver bodies, 1 rows, 2 strips (even, 2 .. P[14]),
 * 3 bins, 4 BodyType.Dynamic, 5 the "no bin" mark, 6 where stripCut2D's arrays start in A (31),
 * 7 packing ranges, 8 pack here (1) or not (0), 9 cut here (1) or not (0), 10 the most rows the
 * overflow group may take, 11 rows (again, for coloredPack2D), 12 group slots a packing range
 * (P[14] + 1), 13 PLAN_HEAD (solver/coloring.ts), 14 MAX_COLORS, 15 rows a block (graph colours; unused
 * here). `H` is KERNEL_HELPERS: 0 coloredPack2D, 10 stripCut2D,
 * 11 stripLayout2D. Returns 1 when planned, -1 when too many rows overflow.
 * @category Collision
 */
export function stripPlan2D(
  A: KernelArray[],
  P: Float64Array,
  _ids: Int32Array | null,
  lo: number,
  hi: number,
  _part: number,
  H: readonly KernelHelper[],
): number {
  if (lo >= hi) return 0;
  const plan = A[4] as Int32Array;
  const bodies = P[0]!,
    n = P[1]!,
    strips = P[2]!,
    parts = P[7]!,
    W = P[12]!,
    MAXC = P[14]!;
  if (P[9] === 1) (H[10] as typeof stripCut2D)(A, P, null, 0, 1);
  // Each row's group, counted per group and per packing range.
  const IA = A[8] as Int32Array,
    IB = A[9] as Int32Array,
    NM = A[15] as Float64Array,
    TM = A[16] as Float64Array;
  const LN = A[18] as Float64Array,
    LT = A[19] as Float64Array,
    color = A[6] as Uint8Array,
    partCounts = A[7] as Int32Array;
  const strip = A[36] as Uint8Array,
    counts = A[42] as Int32Array,
    start = A[43] as Int32Array,
    next = A[44] as Int32Array;
  const half = strips >> 1;
  partCounts.fill(0, 0, parts * W);
  counts.fill(0);
  let overflow = 0;
  for (let p = 0; p < parts; p++) {
    const r0 = Math.floor((n * p) / parts),
      r1 = Math.floor((n * (p + 1)) / parts),
      base = p * W;
    for (let i = r0; i < r1; i++) {
      if (NM[i] === 0 && TM[i] === 0 && LN[i] === 0 && LT[i] === 0) {
        color[i] = 255;
        continue;
      }
      const sa = strip[IA[i]!]!,
        sbb = strip[IB[i]!]!;
      let low: number, high: number;
      if (sa === 255) {
        low = sbb === 255 ? 0 : sbb;
        high = low;
      } else if (sbb === 255) {
        low = sa;
        high = sa;
      } else {
        low = sa < sbb ? sa : sbb;
        high = sa < sbb ? sbb : sa;
      }
      let c: number;
      if (high - low > 1) {
        c = MAXC;
        overflow++;
      } else c = (low & 1) === 0 ? low >> 1 : half + (low >> 1);
      color[i] = c;
      counts[c] = counts[c]! + 1;
      partCounts[base + c] = partCounts[base + c]! + 1;
    }
  }
  if (overflow > P[10]!) return -1;
  // The movable bodies by strip pair (counting sort), for the even blocks' body stages.
  const bb = A[25] as Int32Array,
    order = A[24] as Int32Array;
  bb.fill(0, 0, half + 1);
  for (let k = 1; k < bodies; k++) if (strip[k] !== 255) bb[(strip[k]! >> 1) + 1]++;
  for (let j = 0; j < half; j++) bb[j + 1] = bb[j + 1]! + bb[j]!;
  for (let j = 0; j <= half; j++) next[j] = bb[j]!;
  for (let k = 1; k < bodies; k++) {
    if (strip[k] === 255) continue;
    const j = strip[k]! >> 1;
    order[next[j]!] = k;
    next[j] = next[j]! + 1;
  }
  // The even blocks (strip pairs with rows; `start` as scratch), and each one's bodies: block m takes
  // the pairs from its own (0 for m = 0) to the next block's (half for the last). Written in place:
  // block m reads bb at a pair index >= m, which no earlier block has overwritten.
  let blocks = 0;
  for (let j = 0; j < half; j++) if (counts[j]! > 0) start[blocks++] = j;
  for (let m = 0; m <= blocks; m++) bb[m] = bb[m === 0 ? 0 : m === blocks ? half : start[m]!]!;
  plan[9] = blocks === 0 ? 0 : 1;
  plan[10] = blocks;
  (H[11] as typeof stripLayout2D)(A, P, strips, half);
  if (P[8] === 1) {
    for (let blk = 0; blk < parts; blk++) (H[0] as typeof coloredPack2D)(A, P, blk, parts);
    plan[11] = 1;
  }
  return 1;
}

/**
 * Kernel helper: lays the pack out from the rows' groups (counted by stripPlan2D or solver/coloring.ts
 * colorRows): groups 0 .. `groups` - 1 in order, then the overflow group (P[14]); turns the offsets
 * (A[7], P[12] slots a packing range) into each packing range's first slot of each group (a range's
 * rows of a group follow the earlier ranges' rows of it, so the pack is in buffer order within each
 * group however many threads pack it) and fills the blocks (A[23]). With `half` > 0 (strips) group g
 * has colour 0 below `half` and 1 from it, and is one block; with `half` = 0 (graph colours) group g is
 * colour g, cut into blocks of P[15] rows. The plan (A[4]) gets colour c's first block at P[13] + c (the
 * overflow colour, after the others, one block), the colours at slot 4 and the rows to pack at slot 8.
 * A and P as stripPlan2D's (42 counts, 43 start, 44 next). Returns the rows to pack.
 * @category Collision
 */
export function stripLayout2D(A: KernelArray[], P: Float64Array, groups: number, half: number): number {
  const plan = A[4] as Int32Array,
    partCounts = A[7] as Int32Array,
    bounds = A[23] as Int32Array;
  const counts = A[42] as Int32Array,
    start = A[43] as Int32Array,
    next = A[44] as Int32Array;
  const parts = P[7]!,
    W = P[12]!,
    HEAD = P[13]!,
    MAXC = P[14]!,
    blockRows = P[15]!;
  const colors = half > 0 ? 2 : groups;
  start.fill(0);
  let at = 0;
  for (let g = 0; g < groups; g++) {
    start[g] = at;
    at += counts[g]!;
  }
  start[groups] = at;
  at += counts[MAXC]!;
  start[groups + 1] = at;
  next.set(start);
  next[MAXC] = start[groups]!;
  for (let p = 0; p < parts; p++) {
    const base = p * W;
    for (let c = 0; c < W; c++) {
      const k = partCounts[base + c]!;
      partCounts[base + c] = next[c]!;
      next[c] = next[c]! + k;
    }
  }
  // Blocks, colour by colour.
  let nb = 0,
    color = -1;
  for (let g = 0; g < groups; g++) {
    const c = half > 0 ? (g < half ? 0 : 1) : g;
    while (color < c) plan[HEAD + ++color] = nb;
    const r0 = start[g]!,
      r1 = start[g + 1]!;
    if (half > 0) {
      if (r1 > r0) bounds[nb++] = r0;
    } else for (let r = r0; r < r1; r += blockRows) bounds[nb++] = r;
  }
  while (color < colors) plan[HEAD + ++color] = nb;
  if (start[groups + 1]! > start[groups]!) bounds[nb++] = start[groups]!;
  plan[HEAD + colors + 1] = nb;
  bounds[nb] = at;
  plan[4] = colors;
  plan[8] = at;
  return at;
}
