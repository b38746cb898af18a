/**
 * The broadphase's cell pass as a thread kernel (step/kernel-table.ts: a self-contained function the
 * worker threads also run as source text), its only code: collision/broadphase/grid-pairs.ts runs it,
 * on the threads or inline, and says when.
 */

import type { KernelArray } from '../../threads/kernel-types.js';

/**
 * The cell pass over grid bodies lo .. hi - 1 (collision/broadphase/grid.ts's grid bodies, with the body types as
 * they were when the pass began). A: 0 sorted (grid order), 1 cellX, 2 cellY, 3 cellZ,
 * 4 bucketStart, 5 ox, 6 oy, 7 oz (PreviousPosition), 8 radius, 9 margin, 10 bodyType (Uint8:
 * BodyType's 0 dynamic, 1 kinematic, 2 static, 3 sleeping), 11 counts (Int32: at `part` the pairs the
 * range found, at 16 + `part` its wake requests; -1 when a buffer was too small), 12 restTime (s, 0:
 * the body moves), then per range p: 13 + 3p first and 14 + 3p second entity of each pair (the
 * smaller id first), 15 + 3p the sleeping balls the range found met by a moving or kinematic ball, in
 * the order met (a ball may be named more than once), which the caller wakes in range order. P: 0 hash
 * mask, 1 dimensions, 2 capacity of a range's buffers, 3 spanX and 4 spanXZ of a dense grid (0: the
 * hash), 5-7 its origin cell (see GridScratch in state.ts: bucket (cx - 5) + (cz - 7) spanX + (6 - cy)
 * spanXZ). The pairs are those of collision/broadphase/grid.ts's loop (addBallPair: no pair of two sleeping balls, nor of
 * two balls neither of which is dynamic unless a kinematic one meets a sleeping one). The one-thread
 * loop wakes a ball as it meets it; the pass is run again whenever any ball woke, and the set of balls
 * woken, and their order, is the same either way (a woken ball has rested, so it wakes nobody itself).
 * Returns 0.
 * @category Collision
 */
export function ballPairs(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const sorted = A[0] as Int32Array,
    cellX = A[1] as Int32Array,
    cellY = A[2] as Int32Array,
    cellZ = A[3] as Int32Array;
  const start = A[4] as Int32Array,
    ox = A[5] as Float64Array,
    oy = A[6] as Float64Array,
    oz = A[7] as Float64Array;
  const radius = A[8] as Float64Array,
    margin = A[9] as Float64Array,
    type = A[10] as Uint8Array,
    counts = A[11] as Int32Array;
  const rest = A[12] as Float64Array;
  const outA = A[13 + 3 * part] as Int32Array,
    outB = A[14 + 3 * part] as Int32Array,
    outW = A[15 + 3 * part] as Int32Array;
  const mask = P[0]!,
    is3D = P[1] === 3,
    cap = P[2]!;
  const sX = P[3]!,
    sXZ = P[4]!,
    gx0 = P[5]!,
    gy0 = P[6]!,
    gz0 = P[7]!,
    dense = sX > 0;
  // The half neighbourhood, as (dx, dy, dz) triples: each unordered pair of neighbouring cells once
  // (2D: 4 of the 8 neighbours; 3D: 13 of the 26).
  const off = is3D
    ? [1, 0, 0, -1, 1, 0, 0, 1, 0, 1, 1, 0, -1, -1, 1, 0, -1, 1, 1, -1, 1, -1, 0, 1, 0, 0, 1, 1, 0, 1, -1, 1, 1, 0, 1, 1, 1, 1, 1]
    : [1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0];
  const nOff = off.length / 3;
  // A dense grid's neighbours are fixed bucket offsets (dx + dz spanX - dy spanXZ), and its buckets
  // hold one cell each, so no cell comparison; a hash bucket may hold other cells. A 2D world reads no
  // z (its cells' and stores' z are 0).
  const step = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];
  for (let k = 0; k < nOff; k++) step[k] = off[3 * k]! + off[3 * k + 2]! * sX - off[3 * k + 1]! * sXZ;
  let count = 0,
    woken = 0;
  for (let p = lo; p < hi && count >= 0; p++) {
    const e = sorted[p]!;
    const cx = cellX[p]!,
      cy = cellY[p]!,
      cz = cellZ[p]!;
    const x = ox[e]!,
      y = oy[e]!,
      z = is3D ? oz[e]! : 0;
    const reach = radius[e]! + margin[e]!;
    const te = type[e]!;
    const own = dense ? cx - gx0 + (cz - gz0) * sX + (gy0 - cy) * sXZ : 0;
    // Own cell (later entries only), then the half neighbourhood.
    for (let k = -1; k < nOff && count >= 0; k++) {
      let nx = cx,
        ny = cy,
        nz = cz,
        bucket = own;
      if (k >= 0) {
        nx = cx + off[3 * k]!;
        ny = cy + off[3 * k + 1]!;
        nz = cz + off[3 * k + 2]!;
        if (dense) bucket = own + step[k]!;
      }
      if (!dense) bucket = ((Math.imul(nx, 73856093) ^ Math.imul(ny, 19349663) ^ Math.imul(nz, 83492791)) >>> 0) & mask;
      for (let q = k < 0 ? p + 1 : start[bucket]!, end = start[bucket + 1]!; q < end; q++) {
        if (!dense && (cellX[q] !== nx || cellY[q] !== ny || cellZ[q] !== nz)) continue;
        const f = sorted[q]!,
          tf = type[f]!;
        // Neither dynamic: no pair, unless a kinematic ball meets a sleeping one.
        if (te !== 0 && tf !== 0 && !((te === 1 && tf === 3) || (te === 3 && tf === 1))) continue;
        const dx = ox[f]! - x,
          dy = oy[f]! - y,
          dz = is3D ? oz[f]! - z : 0;
        const rr = reach + radius[f]! + margin[f]!;
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          if (count >= cap || woken + 2 > cap) {
            count = -1;
            break;
          }
          // A sleeping ball met by a kinematic one or a moving one (no rest time) is to be woken.
          if (te === 3 && (tf === 1 || rest[f] === 0)) outW[woken++] = e;
          if (tf === 3 && (te === 1 || rest[e] === 0)) outW[woken++] = f;
          outA[count] = e < f ? e : f;
          outB[count] = e < f ? f : e;
          count++;
        }
      }
    }
  }
  counts[part] = count;
  counts[16 + part] = count < 0 ? -1 : woken;
  return ids === null ? 0 : 0;
}
