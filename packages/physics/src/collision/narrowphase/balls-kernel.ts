/**
 * The narrowphase's ball-ball contacts (collision/narrowphase/balls.ts) as a thread kernel (step/kernel-table.ts: a
 * self-contained function the worker threads also run as source text), their only code: collision/narrowphase/balls-threads.ts
 * runs it on the threads or inline and says when.
 */

import type { KernelArray } from '../../threads/kernel-types.js';
import {
  BC_BALL,
  BC_BODY_TYPE,
  BC_CAPACITY,
  BC_CAPACITY_0,
  BC_COUNTS,
  BC_DIMENSIONS,
  BC_FIRST_ROW,
  BC_H,
  BC_OUT,
  BC_OUT_A,
  BC_OUT_B,
  BC_OUT_FEATURE,
  BC_OUT_FIELDS,
  BC_OUT_KIND,
  BC_OUT_NX,
  BC_OUT_NY,
  BC_OUT_NZ,
  BC_OUT_RA,
  BC_OUT_RB,
  BC_OUT_SEPARATION,
  BC_OX,
  BC_OY,
  BC_OZ,
  BC_PAIR_A,
  BC_PAIR_B,
  BC_RADIUS,
  BC_SKIP,
  BC_SPECULATIVE,
  BC_STATIC,
  BC_STATIC_BALL,
  BC_VX,
  BC_VY,
  BC_VZ,
} from './ball-contact-slots.js';

/**
 * Ball-ball contacts of pairs lo .. hi - 1 (all BallBall pairs): the normal where the balls first
 * touch this step (swept test, Ericson 5.5.7), the separation where they were at the start of the
 * step, kept when the gap can close this step; pairs whose skip flag is set (a joint keeps the bodies
 * apart) make none. A and P: the BC_ slots of collision/narrowphase/ball-contact-slots.ts; range p
 * writes its contacts to its own output arrays, range 0 from row P[BC_FIRST_ROW] (its arrays are the
 * contact buffer's own, so its rows need no copy), the others from row 0. Returns 0.
 * @category Collision
 */
export function ballContacts(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const pairA = A[BC_PAIR_A] as Int32Array,
    pairB = A[BC_PAIR_B] as Int32Array;
  const ox = A[BC_OX] as Float64Array,
    oy = A[BC_OY] as Float64Array,
    oz = A[BC_OZ] as Float64Array;
  const vx = A[BC_VX] as Float64Array,
    vy = A[BC_VY] as Float64Array,
    vz = A[BC_VZ] as Float64Array;
  const radius = A[BC_RADIUS] as Float64Array,
    type = A[BC_BODY_TYPE] as Uint8Array,
    counts = A[BC_COUNTS] as Int32Array;
  const o = BC_OUT + BC_OUT_FIELDS * part;
  const K = A[o + BC_OUT_KIND] as Uint8Array,
    NX = A[o + BC_OUT_NX] as Float64Array,
    NY = A[o + BC_OUT_NY] as Float64Array,
    NZ = A[o + BC_OUT_NZ] as Float64Array;
  const SEP = A[o + BC_OUT_SEPARATION] as Float64Array,
    RA = A[o + BC_OUT_RA] as Float64Array,
    RB = A[o + BC_OUT_RB] as Float64Array;
  const CA = A[o + BC_OUT_A] as Int32Array,
    CB = A[o + BC_OUT_B] as Int32Array,
    FE = A[o + BC_OUT_FEATURE] as Int32Array;
  const h = P[BC_H]!,
    spec = P[BC_SPECULATIVE]!,
    STATIC = P[BC_STATIC]!,
    BALL = P[BC_BALL]!,
    STATIC_BALL = P[BC_STATIC_BALL]!,
    cap = part === 0 ? P[BC_CAPACITY_0]! : P[BC_CAPACITY]!;
  const is3D = P[BC_DIMENSIONS] === 3;
  const base = part === 0 ? P[BC_FIRST_ROW]! : 0,
    skip = P[BC_SKIP]! >= 0 ? (A[P[BC_SKIP]!] as Uint8Array) : null;
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
