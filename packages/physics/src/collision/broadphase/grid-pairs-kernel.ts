/**
 * The broadphase's cell pass as a thread kernel (step/kernel-table.ts: a self-contained function the
 * worker threads also run as source text), its only code: collision/broadphase/grid-pairs.ts runs it,
 * on the threads or inline, and says when.
 */

import type { KernelArray } from '../../threads/kernel-types.js';
import * as PAIRS from './ball-pair-slots.js';

/**
 * The cell pass over grid bodies lo .. hi - 1 (collision/broadphase/grid.ts's grid bodies, with the body types as
 * they were when the pass began). A and P: the PAIRS slots (collision/broadphase/ball-pair-slots.ts);
 * range p writes its pairs and its wake requests to its own output arrays, which the caller appends,
 * and wakes, in range order. The pairs are those of collision/broadphase/grid.ts's loop (addBallPair: no pair of two sleeping balls, nor of
 * two balls neither of which is dynamic unless a kinematic one meets a sleeping one). The one-thread
 * loop wakes a ball as it meets it; the pass is run again whenever any ball woke, and the set of balls
 * woken, and their order, is the same either way (a woken ball has rested, so it wakes nobody itself).
 * Returns 0.
 * @category Collision
 */
export function ballPairs(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const sorted = A[PAIRS.SORTED] as Int32Array,
    cellX = A[PAIRS.CELL_X] as Int32Array,
    cellY = A[PAIRS.CELL_Y] as Int32Array,
    cellZ = A[PAIRS.CELL_Z] as Int32Array;
  const start = A[PAIRS.BUCKET_START] as Int32Array,
    ox = A[PAIRS.OX] as Float64Array,
    oy = A[PAIRS.OY] as Float64Array,
    oz = A[PAIRS.OZ] as Float64Array;
  const radius = A[PAIRS.RADIUS] as Float64Array,
    margin = A[PAIRS.MARGIN] as Float64Array,
    type = A[PAIRS.BODY_TYPE] as Uint8Array,
    counts = A[PAIRS.COUNTS] as Int32Array;
  const rest = A[PAIRS.REST_TIME] as Float64Array;
  const out = PAIRS.OUT + PAIRS.OUT_FIELDS * part;
  const outA = A[out + PAIRS.OUT_A] as Int32Array,
    outB = A[out + PAIRS.OUT_B] as Int32Array,
    outW = A[out + PAIRS.OUT_WAKE] as Int32Array;
  const mask = P[PAIRS.HASH_MASK]!,
    is3D = P[PAIRS.DIMENSIONS] === 3,
    cap = P[PAIRS.CAPACITY]!;
  const sX = P[PAIRS.SPAN_X]!,
    sXZ = P[PAIRS.SPAN_XZ]!,
    gx0 = P[PAIRS.ORIGIN_X]!,
    gy0 = P[PAIRS.ORIGIN_Y]!,
    gz0 = P[PAIRS.ORIGIN_Z]!,
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
  // A dense 3D grid's half neighbourhood is five runs of consecutive buckets, each one run of the
  // sorted bodies: the own cell's later entries with the cell at +x, then the three cells at x - 1,
  // x, x + 1 of each of the rows (y + 1, z), (y - 1, z + 1), (y, z + 1) and (y + 1, z + 1), in the
  // order of `off`, so the pairs come out in the same order as cell by cell. Other grids go cell by
  // cell: the own cell (later entries only), then the half neighbourhood.
  const dense3D = dense && is3D,
    rowAt = [-sXZ, sX + sXZ, sX, sX - sXZ],
    runs = dense3D ? 5 : nOff + 1;
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
    // Whether e sleeps, and whether it would wake a sleeping partner (kinematic, or moving: no rest time).
    const sleepsE = +(te === 3),
      wakerE = +(te === 1) | +(rest[e] === 0);
    const own = dense ? cx - gx0 + (cz - gz0) * sX + (gy0 - cy) * sXZ : 0;
    for (let r = 0; r < runs && count >= 0; r++) {
      // Sorted bodies q to end - 1; in a hashed bucket only those of cell (nx, ny, nz).
      let q = p + 1,
        end = 0,
        nx = cx,
        ny = cy,
        nz = cz;
      if (dense3D) {
        const c = r === 0 ? own : own + rowAt[r - 1]!;
        if (r > 0) q = start[c - 1]!;
        end = start[c + 2]!;
      } else {
        const k = r - 1;
        let bucket = own;
        if (k >= 0) {
          nx = cx + off[3 * k]!;
          ny = cy + off[3 * k + 1]!;
          nz = cz + off[3 * k + 2]!;
          if (dense) bucket = own + step[k]!;
        }
        if (!dense) bucket = ((Math.imul(nx, 73856093) ^ Math.imul(ny, 19349663) ^ Math.imul(nz, 83492791)) >>> 0) & mask;
        if (k >= 0) q = start[bucket]!;
        end = start[bucket + 1]!;
      }
      for (; q < end; q++) {
        if (!dense && (cellX[q] !== nx || cellY[q] !== ny || cellZ[q] !== nz)) continue;
        const f = sorted[q]!,
          tf = type[f]!;
        // Neither dynamic: no pair, unless a kinematic ball meets a sleeping one. Every comparison is
        // made for every pair (bitwise, no short cut), as are the wake tests below: the compiled loop has
        // seen them all before the first ball sleeps, when they first matter.
        const sleepsF = +(tf === 3);
        const kinematicMeetsSleeper = (+(te === 1) & sleepsF) | (sleepsE & +(tf === 1));
        if ((+(te !== 0) & +(tf !== 0) & (kinematicMeetsSleeper ^ 1)) === 1) continue;
        const dx = ox[f]! - x,
          dy = oy[f]! - y,
          dz = is3D ? oz[f]! - z : 0;
        const rr = reach + radius[f]! + margin[f]!;
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          if (count >= cap || woken + 2 > cap) {
            count = -1;
            break;
          }
          // A sleeping ball met by a kinematic one or a moving one (no rest time) is to be woken: each
          // written at the next wake slot, which counts only if it is (room for two checked above).
          outW[woken] = e;
          woken += sleepsE & (+(tf === 1) | +(rest[f] === 0));
          outW[woken] = f;
          woken += sleepsF & wakerE;
          outA[count] = e < f ? e : f;
          outB[count] = e < f ? f : e;
          count++;
        }
      }
    }
  }
  counts[part] = count;
  counts[PAIRS.WAKE_COUNTS + part] = count < 0 ? -1 : woken;
  return ids === null ? 0 : 0;
}
