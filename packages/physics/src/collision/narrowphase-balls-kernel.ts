/**
 * The narrowphase's ball-ball contacts (narrowphase.ts) as a thread kernel (threads/kernels.ts: a
 * self-contained function the worker threads also run as source text); narrowphase-balls.ts runs it
 * and says when.
 */

import type { KernelArray } from '../threads/kernel-types.js';

/** Float64 slots of a contact in a range's buffer: kind, nx, ny, nz, separation, ra, rb. */
export const CONTACT_F = 7;
/** Int32 slots of a contact in a range's buffer: a, b, feature. */
export const CONTACT_I = 3;

/**
 * Ball-ball contacts of pairs lo .. hi - 1 (all BallBall pairs of bodies no joint keeps apart), with
 * the arithmetic of narrowphase.ts's loop: the normal where the balls first touch this step (swept
 * test, Ericson 5.5.7), the separation where they were at the start of the step, kept when the gap
 * can close this step. A: 0 pairA, 1 pairB, 2 ox, 3 oy, 4 oz, 5 vx, 6 vy, 7 vz, 8 radius, 9 bodyType
 * (Uint8), 10 counts (Int32, the contacts of each range at `part`; -1: its buffer was too small),
 * then per range p: 11 + 2p Float64 (CONTACT_F slots a contact), 12 + 2p Int32 (CONTACT_I slots).
 * P: 0 h (s), 1 speculative distance (m), 2 the Static body type, 3 ContactKind.Ball, 4
 * ContactKind.StaticBall, 5 contacts a range's buffer holds. Returns 0.
 */
export function ballContacts(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const pairA = A[0] as Int32Array, pairB = A[1] as Int32Array;
  const ox = A[2] as Float64Array, oy = A[3] as Float64Array, oz = A[4] as Float64Array;
  const vx = A[5] as Float64Array, vy = A[6] as Float64Array, vz = A[7] as Float64Array;
  const radius = A[8] as Float64Array, type = A[9] as Uint8Array, counts = A[10] as Int32Array;
  const OF = A[11 + 2 * part] as Float64Array, OI = A[12 + 2 * part] as Int32Array;
  const h = P[0]!, spec = P[1]!, STATIC = P[2]!, BALL = P[3]!, STATIC_BALL = P[4]!, cap = P[5]!;
  let count = 0;
  for (let i = lo; i < hi; i++) {
    const a = pairA[i]!, b = pairB[i]!;
    const rx = ox[b]! - ox[a]!, ry = oy[b]! - oy[a]!, rz = oz[b]! - oz[a]!;
    const ra = radius[a]!, rb = radius[b]!;
    const R = ra + rb;
    const ta = type[a]!, tb = type[b]!;
    const wx = (tb === STATIC ? 0 : vx[b]!) - (ta === STATIC ? 0 : vx[a]!);
    const wy = (tb === STATIC ? 0 : vy[b]!) - (ta === STATIC ? 0 : vy[a]!);
    const wz = (tb === STATIC ? 0 : vz[b]!) - (ta === STATIC ? 0 : vz[a]!);
    let dx = rx, dy = ry, dz = rz;
    // Swept sphere: the smaller root of |r + w t|^2 = R^2 in (0, h], else 0.
    let t = 0;
    const c = rx * rx + ry * ry + rz * rz - R * R;
    if (c > 0) {
      const bb = rx * wx + ry * wy + rz * wz;
      if (bb < 0) {
        const aa = wx * wx + wy * wy + wz * wz;
        const disc = bb * bb - aa * c;
        if (disc >= 0) { const tt = (-bb - Math.sqrt(disc)) / aa; t = tt > 0 && tt <= h ? tt : 0; }
      }
    }
    if (t > 0) { dx += wx * t; dy += wy * t; dz += wz * t; }
    const d = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (d > 1e-12) { const inv = 1 / d; dx *= inv; dy *= inv; dz *= inv; } else { dx = 0; dy = 1; dz = 0; }
    const sep = rx * dx + ry * dy + rz * dz - R;
    const vn = wx * dx + wy * dy + wz * dz;
    if (sep >= (vn < 0 ? -vn * h : 0) + (spec < 0.25 * R ? spec : 0.25 * R)) continue;
    if (count >= cap) { count = -1; break; }
    const f = count * 7, k = count * 3;
    if (ta === STATIC) {
      OF[f] = STATIC_BALL; OF[f + 1] = dx; OF[f + 2] = dy; OF[f + 3] = dz; OF[f + 5] = 0; OF[f + 6] = rb;
      OI[k] = 0; OI[k + 1] = b; OI[k + 2] = a;
    } else if (tb === STATIC) {
      OF[f] = STATIC_BALL; OF[f + 1] = -dx; OF[f + 2] = -dy; OF[f + 3] = -dz; OF[f + 5] = 0; OF[f + 6] = ra;
      OI[k] = 0; OI[k + 1] = a; OI[k + 2] = b;
    } else {
      OF[f] = BALL; OF[f + 1] = dx; OF[f + 2] = dy; OF[f + 3] = dz; OF[f + 5] = ra; OF[f + 6] = rb;
      OI[k] = a; OI[k + 1] = b; OI[k + 2] = 0;
    }
    OF[f + 4] = sep;
    count++;
  }
  counts[part] = count;
  return ids === null ? 0 : 0;
}
