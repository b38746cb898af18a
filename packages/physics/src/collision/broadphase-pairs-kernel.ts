/**
 * The broadphase's cell pass as a thread kernel (threads/kernels.ts: a self-contained function the
 * worker threads also run as source text); broadphase-pairs.ts runs it and says when.
 */

import type { KernelArray } from '../threads/kernel-types.js';

/**
 * The cell pass over grid bodies lo .. hi - 1 (see broadphase.ts, whose loop this is, without the
 * waking of sleeping balls). A: 0 sorted (grid order), 1 cellX, 2 cellY, 3 cellZ, 4 bucketStart,
 * 5 ox, 6 oy, 7 oz (PreviousPosition), 8 radius, 9 margin, 10 bodyType (Uint8), 11 counts (Int32: the
 * pairs each range found, at `part`; -1 when its buffer was too small), then per range p: 12 + 2p
 * first and 13 + 2p second entity of each pair (the smaller id first). P: 0 hash mask, 1 dimensions,
 * 2 capacity of a range's buffer, 3 spanX and 4 spanXZ of a dense grid (0: the hash), 5-7 its origin
 * cell (see GridScratch in state.ts: bucket (cx - 5) + (cz - 7) spanX + (6 - cy) spanXZ). Returns 0.
 */
export function ballPairs(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const sorted = A[0] as Int32Array, cellX = A[1] as Int32Array, cellY = A[2] as Int32Array, cellZ = A[3] as Int32Array;
  const start = A[4] as Int32Array, ox = A[5] as Float64Array, oy = A[6] as Float64Array, oz = A[7] as Float64Array;
  const radius = A[8] as Float64Array, margin = A[9] as Float64Array, type = A[10] as Uint8Array, counts = A[11] as Int32Array;
  const outA = A[12 + 2 * part] as Int32Array, outB = A[13 + 2 * part] as Int32Array;
  const mask = P[0]!, is3D = P[1] === 3, cap = P[2]!;
  const sX = P[3]!, sXZ = P[4]!, gx0 = P[5]!, gy0 = P[6]!, gz0 = P[7]!, dense = sX > 0;
  // The half neighbourhood (broadphase.ts HALF_2D, HALF_3D), as (dx, dy, dz) triples.
  const off = is3D
    ? [1, 0, 0, -1, 1, 0, 0, 1, 0, 1, 1, 0, -1, -1, 1, 0, -1, 1, 1, -1, 1, -1, 0, 1, 0, 0, 1, 1, 0, 1, -1, 1, 1, 0, 1, 1, 1, 1, 1]
    : [1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0];
  const nOff = off.length / 3;
  let count = 0;
  for (let p = lo; p < hi && count >= 0; p++) {
    const e = sorted[p]!;
    const cx = cellX[p]!, cy = cellY[p]!, cz = cellZ[p]!;
    const x = ox[e]!, y = oy[e]!, z = oz[e]!;
    const reach = radius[e]! + margin[e]!;
    const te = type[e]!;
    // Own cell (later entries only), then the half neighbourhood.
    for (let k = -1; k < nOff && count >= 0; k++) {
      const nx = k < 0 ? cx : cx + off[3 * k]!, ny = k < 0 ? cy : cy + off[3 * k + 1]!, nz = k < 0 ? cz : is3D ? cz + off[3 * k + 2]! : 0;
      const bucket = dense ? nx - gx0 + (nz - gz0) * sX + (gy0 - ny) * sXZ : ((Math.imul(nx, 73856093) ^ Math.imul(ny, 19349663) ^ Math.imul(nz, 83492791)) >>> 0) & mask;
      for (let q = k < 0 ? p + 1 : start[bucket]!, end = start[bucket + 1]!; q < end; q++) {
        if (cellX[q] !== nx || cellY[q] !== ny || cellZ[q] !== nz) continue;
        const f = sorted[q]!;
        if (te !== 0 && type[f] !== 0) continue; // neither dynamic (no ball sleeps, so none wakes another)
        const dx = ox[f]! - x, dy = oy[f]! - y, dz = oz[f]! - z;
        const rr = reach + radius[f]! + margin[f]!;
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          if (count >= cap) { count = -1; break; }
          outA[count] = e < f ? e : f; outB[count] = e < f ? f : e;
          count++;
        }
      }
    }
  }
  counts[part] = count;
  return ids === null ? 0 : 0;
}

