/**
 * The narrowphase's ball-ball contacts (collision/narrowphase/balls.ts) as a thread kernel (step/kernel-table.ts: a
 * self-contained function the worker threads also run as source text), their only code: collision/narrowphase/balls-threads.ts
 * runs it on the threads or inline and says when.
 */

import type { KernelArray } from '../../threads/kernel-types.js';
import * as CONTACT from './ball-contact-slots.js';

/**
 * Ball-ball contacts of pairs lo .. hi - 1 (all BallBall pairs): the normal where the balls first
 * touch this step (swept test, Ericson 5.5.7), the separation where they were at the start of the
 * step, kept when the gap can close this step; pairs whose skip flag is set (a joint keeps the bodies
 * apart) make none. A and P: the CONTACT slots (collision/narrowphase/ball-contact-slots.ts); range p
 * writes its contacts to its own output arrays, range 0 from row P[CONTACT.FIRST_ROW] (its arrays are the
 * contact buffer's own, so its rows need no copy), the others from row 0. Returns 0.
 * @category Collision
 */
export function ballContacts(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const pairA = A[CONTACT.PAIR_A] as Int32Array,
    pairB = A[CONTACT.PAIR_B] as Int32Array;
  const ox = A[CONTACT.OX] as Float64Array,
    oy = A[CONTACT.OY] as Float64Array,
    oz = A[CONTACT.OZ] as Float64Array;
  const vx = A[CONTACT.VX] as Float64Array,
    vy = A[CONTACT.VY] as Float64Array,
    vz = A[CONTACT.VZ] as Float64Array;
  const radius = A[CONTACT.RADIUS] as Float64Array,
    type = A[CONTACT.BODY_TYPE] as Uint8Array,
    counts = A[CONTACT.COUNTS] as Int32Array;
  const o = CONTACT.OUT + CONTACT.OUT_FIELDS * part;
  const K = A[o + CONTACT.OUT_KIND] as Uint8Array,
    NX = A[o + CONTACT.OUT_NX] as Float64Array,
    NY = A[o + CONTACT.OUT_NY] as Float64Array,
    NZ = A[o + CONTACT.OUT_NZ] as Float64Array;
  const SEP = A[o + CONTACT.OUT_SEPARATION] as Float64Array,
    RA = A[o + CONTACT.OUT_RA] as Float64Array,
    RB = A[o + CONTACT.OUT_RB] as Float64Array;
  const CA = A[o + CONTACT.OUT_A] as Int32Array,
    CB = A[o + CONTACT.OUT_B] as Int32Array,
    FE = A[o + CONTACT.OUT_FEATURE] as Int32Array;
  const h = P[CONTACT.H]!,
    spec = P[CONTACT.SPECULATIVE]!,
    STATIC = P[CONTACT.STATIC]!,
    BALL = P[CONTACT.BALL]!,
    STATIC_BALL = P[CONTACT.STATIC_BALL]!,
    cap = part === 0 ? P[CONTACT.CAPACITY_0]! : P[CONTACT.CAPACITY]!;
  const is3D = P[CONTACT.DIMENSIONS] === 3;
  const base = part === 0 ? P[CONTACT.FIRST_ROW]! : 0,
    skip = P[CONTACT.SKIP]! >= 0 ? (A[P[CONTACT.SKIP]!] as Uint8Array) : null;
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
    // A static ball is the row's feature, its moving partner the row's b; a static b turns the normal round.
    const aStatic = ta === STATIC,
      bStatic = !aStatic && tb === STATIC,
      moving = !aStatic && !bStatic;
    K[r] = moving ? BALL : STATIC_BALL;
    NX[r] = bStatic ? -dx : dx;
    NY[r] = bStatic ? -dy : dy;
    NZ[r] = bStatic ? -dz : dz;
    RA[r] = moving ? ra : 0;
    RB[r] = bStatic ? ra : rb;
    CA[r] = moving ? a : 0;
    CB[r] = bStatic ? a : b;
    FE[r] = aStatic ? a : bStatic ? b : 0;
    SEP[r] = sep;
    count++;
  }
  counts[part] = count;
  return ids === null ? 0 : 0;
}
