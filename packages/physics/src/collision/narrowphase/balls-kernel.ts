/**
 * The narrowphase's ball-ball contacts (collision/narrowphase/balls.ts) as a thread kernel (step/kernel-table.ts: a
 * self-contained function the worker threads also run as source text), their only code: collision/narrowphase/balls-threads.ts
 * runs it on the threads or inline and says when.
 */

import type { KernelArray } from '../../threads/kernel-types.js';

/**
 * Ball-ball contacts of pairs lo .. hi - 1 (all BallBall pairs): the normal where the balls first
 * touch this step (swept test, Ericson 5.5.7), the separation where they were at the start of the
 * step, kept when the gap can close this step; pairs whose skip flag is set (a joint keeps the bodies
 * apart) make none. A: 0 pairA, 1 pairB, 2 ox, 3 oy, 4 oz, 5 vx, 6 vy, 7 vz, 8 radius, 9 bodyType
 * (Uint8), 10 counts (Int32, the contacts of each range at `part`; -1: its arrays were too small),
 * then per range p the 10 arrays it writes its contacts to at 11 + 10 p: kind (Uint8), nx, ny, nz,
 * separation, ra, rb (Float64), a, b, feature (Int32), range 0 from row P[8], the others from row 0
 * (range 0's are the contact buffer's own, so its rows need no copy); at A[P[9]] (when P[9] >= 0) the
 * skip flags (Uint8, one a pair). P: 0 h (s), 1 speculative distance (m), 2 the Static body type, 3
 * ContactKind.Ball, 4 ContactKind.StaticBall, 5 rows range p > 0's arrays hold, 6 rows range 0's hold,
 * 7 dimensions (2: z is not read; a 2D world's z stores hold 0, so the arithmetic is the same), 8 range
 * 0's first row, 9 the skip flags' index in A (-1: none). Returns 0.
 * @category Collision
 */
export function ballContacts(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const pairA = A[0] as Int32Array,
    pairB = A[1] as Int32Array;
  const ox = A[2] as Float64Array,
    oy = A[3] as Float64Array,
    oz = A[4] as Float64Array;
  const vx = A[5] as Float64Array,
    vy = A[6] as Float64Array,
    vz = A[7] as Float64Array;
  const radius = A[8] as Float64Array,
    type = A[9] as Uint8Array,
    counts = A[10] as Int32Array;
  const o = 11 + 10 * part;
  const K = A[o] as Uint8Array,
    NX = A[o + 1] as Float64Array,
    NY = A[o + 2] as Float64Array,
    NZ = A[o + 3] as Float64Array;
  const SEP = A[o + 4] as Float64Array,
    RA = A[o + 5] as Float64Array,
    RB = A[o + 6] as Float64Array;
  const CA = A[o + 7] as Int32Array,
    CB = A[o + 8] as Int32Array,
    FE = A[o + 9] as Int32Array;
  const h = P[0]!,
    spec = P[1]!,
    STATIC = P[2]!,
    BALL = P[3]!,
    STATIC_BALL = P[4]!,
    cap = part === 0 ? P[6]! : P[5]!;
  const is3D = P[7] === 3;
  const base = part === 0 ? P[8]! : 0,
    skip = P[9]! >= 0 ? (A[P[9]!] as Uint8Array) : null;
  let count = 0;
  for (let i = lo; i < hi; i++) {
    if (skip !== null && skip[i] === 1) continue;
    const a = pairA[i]!,
      b = pairB[i]!;
    const rx = ox[b]! - ox[a]!,
      ry = oy[b]! - oy[a]!,
      rz = is3D ? oz[b]! - oz[a]! : 0;
    const ra = radius[a]!,
      rb = radius[b]!;
    const R = ra + rb;
    const ta = type[a]!,
      tb = type[b]!;
    const wx = (tb === STATIC ? 0 : vx[b]!) - (ta === STATIC ? 0 : vx[a]!);
    const wy = (tb === STATIC ? 0 : vy[b]!) - (ta === STATIC ? 0 : vy[a]!);
    const wz = is3D ? (tb === STATIC ? 0 : vz[b]!) - (ta === STATIC ? 0 : vz[a]!) : 0;
    let dx = rx,
      dy = ry,
      dz = rz;
    // Swept sphere: the smaller root of |r + w t|^2 = R^2 in (0, h], else 0.
    let t = 0;
    const c = rx * rx + ry * ry + rz * rz - R * R;
    if (c > 0) {
      const bb = rx * wx + ry * wy + rz * wz;
      if (bb < 0) {
        const aa = wx * wx + wy * wy + wz * wz;
        const disc = bb * bb - aa * c;
        if (disc >= 0) {
          const tt = (-bb - Math.sqrt(disc)) / aa;
          t = tt > 0 && tt <= h ? tt : 0;
        }
      }
    }
    if (t > 0) {
      dx += wx * t;
      dy += wy * t;
      dz += wz * t;
    }
    const d = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (d > 1e-12) {
      const inv = 1 / d;
      dx *= inv;
      dy *= inv;
      dz *= inv;
    } else {
      dx = 0;
      dy = 1;
      dz = 0;
    }
    const sep = rx * dx + ry * dy + rz * dz - R;
    const vn = wx * dx + wy * dy + wz * dz;
    if (sep >= (vn < 0 ? -vn * h : 0) + (spec < 0.25 * R ? spec : 0.25 * R)) continue;
    if (base + count >= cap) {
      count = -1;
      break;
    }
    const r = base + count;
    if (ta === STATIC) {
      K[r] = STATIC_BALL;
      NX[r] = dx;
      NY[r] = dy;
      NZ[r] = dz;
      RA[r] = 0;
      RB[r] = rb;
      CA[r] = 0;
      CB[r] = b;
      FE[r] = a;
    } else if (tb === STATIC) {
      K[r] = STATIC_BALL;
      NX[r] = -dx;
      NY[r] = -dy;
      NZ[r] = -dz;
      RA[r] = 0;
      RB[r] = ra;
      CA[r] = 0;
      CB[r] = a;
      FE[r] = b;
    } else {
      K[r] = BALL;
      NX[r] = dx;
      NY[r] = dy;
      NZ[r] = dz;
      RA[r] = ra;
      RB[r] = rb;
      CA[r] = a;
      CB[r] = b;
      FE[r] = 0;
    }
    SEP[r] = sep;
    count++;
  }
  counts[part] = count;
  return ids === null ? 0 : 0;
}
