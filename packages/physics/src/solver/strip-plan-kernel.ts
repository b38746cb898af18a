/**
 * The strip plan of the coloured 2D contact solve (solver/coloring.ts: which pack group each row joins,
 * the blocks, each even block's bodies) as a thread kernel and kernel helpers (step/kernel-table.ts
 * rules: self-contained, the worker threads run their source text). A worker makes the plan and packs
 * the rows while the calling thread runs the impact stage (solver/coloring.ts startStripPlan); the
 * calling thread runs the same functions when it plans itself, so the plan is the same either way.
 */

import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import type { coloredPack2D } from './coloring-kernel.js';
import * as PLAN from './slots/colored-plan.js';
import * as SOLVE from './slots/colored-solve.js';
import * as CUT from './slots/strip-cut.js';
import * as STRIP_PLAN from './slots/strip-plan.js';
import type { stripCut2D } from './strips-kernel.js';

/**
 * Thread kernel: plans the coloured solve of the contact buffer's rows by `P[CUT.P_STRIPS]` strips, on the thread
 * whose range is not empty (lo < hi; other ranges do nothing). In order:
 * 1. the strip cut (solver/strips-kernel.ts stripCut2D, when P[STRIP_PLAN.CUT_HERE] = 1; else the cut in `strip` is
 *    already one of P[CUT.P_STRIPS] strips);
 * 2. each row's pack group, that of its lower strip (even strips first: strip 2j is group j, strip
 *    2j + 1 group strips / 2 + j; P[STRIP_PLAN.MAX_COLORS] the overflow group, rows joining bodies more than one
 *    strip apart; 255 not packed: a row that can do nothing, no mass and no impulse), counted per group
 *    and per packing range; if more than P[STRIP_PLAN.MAX_OVERFLOW] rows overflow, stops and returns -1 (fewer strips may do);
 * 3. the movable bodies by strip pair (a counting sort into `bodyOrder`) and each even block's range of
 *    them (`bodyBounds`: block m covers the pairs from its own, or 0 for the first, to the next
 *    block's, so an even strip without rows passes its bodies to the block before it);
 * 4. the layout (stripLayout2D: two colours, even and odd groups, a group one block);
 * 5. when P[STRIP_PLAN.PACK] = 1, the packing of every row into the pack (solver/coloring-kernel.ts coloredPack2D,
 *    each of the P[STRIP_PLAN.PARTS] packing ranges), and plan[PLAN.PACKED] = 1 to say so.
 * A and P: the STRIP_PLAN slots (solver/slots/strip-plan.ts: A starts with solveColored2D's SOLVE
 * arrays, then stripCut2D's CUT arrays from STRIP_PLAN.CUT_ARRAYS; P's first slots are stripCut2D's). `H` is KERNEL_HELPERS: 0 coloredPack2D, 10 stripCut2D,
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
  const plan = A[SOLVE.PLAN] as Int32Array;
  const bodies = P[CUT.P_BODIES]!,
    n = P[CUT.P_ROWS]!,
    strips = P[CUT.P_STRIPS]!,
    parts = P[STRIP_PLAN.PARTS]!,
    W = P[SOLVE.GROUP_SLOTS]!,
    MAXC = P[STRIP_PLAN.MAX_COLORS]!;
  if (P[STRIP_PLAN.CUT_HERE] === 1) (H[10] as typeof stripCut2D)(A, P, null, 0, 1);
  // Each row's group, counted per group and per packing range.
  const IA = A[SOLVE.IA] as Int32Array,
    IB = A[SOLVE.IB] as Int32Array,
    NM = A[SOLVE.NORMAL_MASS] as Float64Array,
    TM = A[SOLVE.TANGENT_MASS] as Float64Array;
  const LN = A[SOLVE.NORMAL_IMPULSE] as Float64Array,
    LT = A[SOLVE.TANGENT_IMPULSE] as Float64Array,
    color = A[SOLVE.GROUP] as Uint8Array,
    partCounts = A[SOLVE.OFFSETS] as Int32Array;
  const strip = A[STRIP_PLAN.CUT_ARRAYS + CUT.STRIP] as Uint8Array,
    counts = A[STRIP_PLAN.COUNTS] as Int32Array,
    start = A[STRIP_PLAN.START] as Int32Array,
    next = A[STRIP_PLAN.NEXT] as Int32Array;
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
  if (overflow > P[STRIP_PLAN.MAX_OVERFLOW]!) return -1;
  // The movable bodies by strip pair (counting sort), for the even blocks' body stages.
  const bb = A[SOLVE.BODY_BOUNDS] as Int32Array,
    order = A[SOLVE.BODY_ORDER] as Int32Array;
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
  plan[PLAN.STRIPS] = blocks === 0 ? 0 : 1;
  plan[PLAN.EVEN_BLOCKS] = blocks;
  (H[11] as typeof stripLayout2D)(A, P, strips, half);
  if (P[STRIP_PLAN.PACK] === 1) {
    for (let blk = 0; blk < parts; blk++) (H[0] as typeof coloredPack2D)(A, P, blk, parts);
    plan[PLAN.PACKED] = 1;
  }
  return 1;
}

/**
 * Kernel helper: lays the pack out from the rows' groups (counted by stripPlan2D or solver/coloring.ts
 * colorRows): groups 0 .. `groups` - 1 in order, then the overflow group (P[STRIP_PLAN.MAX_COLORS]); turns the offsets
 * (A[SOLVE.OFFSETS], P[SOLVE.GROUP_SLOTS] slots a packing range) into each packing range's first slot of each group (a range's
 * rows of a group follow the earlier ranges' rows of it, so the pack is in buffer order within each
 * group however many threads pack it) and fills the blocks (A[SOLVE.BOUNDS]). With `half` > 0 (strips) group g
 * has colour 0 below `half` and 1 from it, and is one block; with `half` = 0 (graph colours) group g is
 * colour g, cut into blocks of P[STRIP_PLAN.BLOCK_ROWS] rows. The plan (A[SOLVE.PLAN]) gets colour c's first block at P[STRIP_PLAN.PLAN_HEAD] + c (the
 * overflow colour, after the others, one block), the colours at slot 4 and the rows to pack at slot 8.
 * A and P as stripPlan2D's (42 counts, 43 start, 44 next). Returns the rows to pack.
 * @category Collision
 */
export function stripLayout2D(A: KernelArray[], P: Float64Array, groups: number, half: number): number {
  const plan = A[SOLVE.PLAN] as Int32Array,
    partCounts = A[SOLVE.OFFSETS] as Int32Array,
    bounds = A[SOLVE.BOUNDS] as Int32Array;
  const counts = A[STRIP_PLAN.COUNTS] as Int32Array,
    start = A[STRIP_PLAN.START] as Int32Array,
    next = A[STRIP_PLAN.NEXT] as Int32Array;
  const parts = P[STRIP_PLAN.PARTS]!,
    W = P[SOLVE.GROUP_SLOTS]!,
    HEAD = P[STRIP_PLAN.PLAN_HEAD]!,
    MAXC = P[STRIP_PLAN.MAX_COLORS]!,
    blockRows = P[STRIP_PLAN.BLOCK_ROWS]!;
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
  plan[PLAN.COLORS] = colors;
  plan[PLAN.PACKED_ROWS] = at;
  return at;
}
