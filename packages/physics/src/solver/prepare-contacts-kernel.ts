/**
 * The contact solver's preparation of 2D contact rows (solver/contact-solver.ts prepareContacts) as a thread kernel
 * (step/kernel-table.ts: self-contained, also run by the workers as source text). Each row is prepared
 * on its own (effective masses, tangent, combined material, stick or slip, the predicted approach, the
 * warm start found in last step's rows), so the rows are identical to the bit whichever thread prepares
 * them. It is the 2D preparation's only code: solver/contact-solver.ts (prepare2DStage) runs it on the
 * threads or inline, and keeps the 3D loop.
 */

import type { KernelArray } from '../threads/kernel-types.js';
import { BS2_INV_INERTIA, BS2_INV_MASS, BS2_STRIDE, BS2_VX, BS2_VY, BS2_W } from './body-state-layout.js';

/**
 * Prepares 2D contact rows lo .. hi - 1.
 * A, the contact buffer's: 0 a, 1 b, 2 ia, 3 ib (Int32), 4 kind (Uint8), 5 feature (Int32), 6 nx, 7 ny,
 * 8 ra, 9 rb; 10 the solver state (rows of BS2_STRIDE, body-state-layout.ts); the Material stores 11 restitution, 12 friction,
 * 13 static friction; 14 the spawn stamps (Uint32, a copy); the buffer's outputs 15 normalMass,
 * 16 tangentMass, 17 rigidPartner (Uint8), 18 t1x, 19 t1y, 20 t1z, 21 restitution, 22 friction,
 * 23 frictionBound, 24 relativeVelocity, 25 totalNormalImpulse, 26 impulse, 27 normalImpulse,
 * 28 tangentImpulse1, 29 tangentImpulse2, 30 maxNormalImpulse, 31 stampA, 32 stampB (Uint32); last
 * step's rows 33 kind (Uint8), 34 a, 35 b, 36 feature (Int32), 37 stampA, 38 stampB (Uint32),
 * 39 normalImpulse, 40 tangentImpulse1, 41 tangentImpulse2, and 42 the warm-start hash slots (Int32,
 * row + 1, contacts.ts). P: 0 stick speed (m/s), 1-3 the boundary's restitution, friction and static
 * friction, 4 last step's rows (0: no cache), 5 hash slots (a power of two), 6 ContactKind.Ball,
 * 7 ContactKind.Boundary. Returns 0.
 * @category Collision
 */
export function prepareContacts2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  const CA = A[0] as Int32Array,
    CB = A[1] as Int32Array,
    IA = A[2] as Int32Array,
    IB = A[3] as Int32Array;
  const K = A[4] as Uint8Array,
    F = A[5] as Int32Array,
    NX = A[6] as Float64Array,
    NY = A[7] as Float64Array;
  const RA = A[8] as Float64Array,
    RB = A[9] as Float64Array,
    sb = A[10] as Float64Array;
  const eM = A[11] as Float64Array,
    fM = A[12] as Float64Array,
    sM = A[13] as Float64Array,
    stamp = A[14] as Uint32Array;
  const NM = A[15] as Float64Array,
    TM = A[16] as Float64Array,
    RP = A[17] as Uint8Array;
  const T1X = A[18] as Float64Array,
    T1Y = A[19] as Float64Array,
    T1Z = A[20] as Float64Array;
  const E = A[21] as Float64Array,
    MU = A[22] as Float64Array,
    FB = A[23] as Float64Array,
    RV = A[24] as Float64Array;
  const TOT = A[25] as Float64Array,
    IMP = A[26] as Float64Array,
    LN = A[27] as Float64Array,
    L1 = A[28] as Float64Array;
  const L2 = A[29] as Float64Array,
    MAXN = A[30] as Float64Array,
    SA = A[31] as Uint32Array,
    SB = A[32] as Uint32Array;
  const pK = A[33] as Uint8Array,
    pA = A[34] as Int32Array,
    pB = A[35] as Int32Array,
    pF = A[36] as Int32Array;
  const pSA = A[37] as Uint32Array,
    pSB = A[38] as Uint32Array;
  const pN = A[39] as Float64Array,
    p1 = A[40] as Float64Array,
    p2 = A[41] as Float64Array,
    slots = A[42] as Int32Array;
  const stick = P[0]!,
    boxE = P[1]!,
    boxF = P[2]!,
    boxS = P[3]!,
    prevCount = P[4]!,
    size = P[5]!;
  const BALL = P[6]!,
    BOUNDARY = P[7]!;
  const mask = size - 1;
  let next = 0;
  for (let i = lo; i < hi; i++) {
    const a = CA[i]!,
      b = CB[i]!,
      kind = K[i]!,
      f = F[i]!;
    const oa = IA[i]! * BS2_STRIDE,
      ob = IB[i]! * BS2_STRIDE;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[oa + BS2_INV_MASS]!,
      imB = sb[ob + BS2_INV_MASS]!;
    const iiA = sb[oa + BS2_INV_INERTIA]!,
      iiB = sb[ob + BS2_INV_INERTIA]!;
    const ra = RA[i]!,
      rb = RB[i]!;
    const k = imA + imB;
    NM[i] = k > 0 ? 1 / k : 0;
    const kt = k + iiA * ra * ra + iiB * rb * rb;
    TM[i] = kt > 0 ? 1 / kt : 0;
    RP[i] = imA === 0 || imB === 0 ? 1 : 0;
    const t1x = -ny,
      t1y = nx;
    T1X[i] = t1x;
    T1Y[i] = t1y;
    T1Z[i] = 0;
    let e: number, mu: number, mus: number;
    if (kind === BALL) {
      e = Math.max(eM[a]!, eM[b]!);
      mu = Math.sqrt(fM[a]! * fM[b]!);
      mus = Math.sqrt(sM[a]! * sM[b]!);
    } else if (kind === BOUNDARY) {
      e = Math.max(boxE, eM[b]!);
      mu = Math.sqrt(boxF * fM[b]!);
      mus = Math.sqrt(boxS * sM[b]!);
    } else {
      e = Math.max(eM[f]!, eM[b]!);
      mu = Math.sqrt(fM[f]! * fM[b]!);
      mus = Math.sqrt(sM[f]! * sM[b]!);
    }
    E[i] = e;
    MU[i] = mu;
    const dvx = sb[ob + BS2_VX]! - sb[oa + BS2_VX]!,
      dvy = sb[ob + BS2_VY]! - sb[oa + BS2_VY]!;
    const vt = Math.abs(dvx * t1x + dvy * t1y - sb[ob + BS2_W]! * rb - sb[oa + BS2_W]! * ra);
    RV[i] = (sb[ob + BS2_VX]! - sb[oa + BS2_VX]!) * nx + (sb[ob + BS2_VY]! - sb[oa + BS2_VY]!) * ny + 0;
    TOT[i] = 0;
    IMP[i] = 0;
    FB[i] = vt < stick ? Math.max(mus, mu) : mu;
    const sA = stamp[kind === BALL ? a : kind === BOUNDARY ? 0 : f]!;
    const sB = stamp[b]!;
    SA[i] = sA;
    SB[i] = sB;
    MAXN[i] = 0;
    // The row after the previous match first, then the hash table (contacts.ts findWarmStart and hashKey).
    let j = next;
    if (j < prevCount && pK[j] === kind && pA[j] === a && pB[j] === b && pF[j] === f) {
      j = pSA[j] === sA && pSB[j] === sB ? j : -1;
    } else if (size === 0) {
      j = -1;
    } else {
      let h = Math.imul(a ^ (kind << 28), 0x9e3779b1);
      h ^= Math.imul(b, 0x85ebca77);
      h ^= Math.imul(f, 0xc2b2ae3d);
      h ^= h >>> 15;
      let s = (Math.imul(h, 0x27d4eb2f) >>> 0) & mask;
      j = -1;
      for (;;) {
        const r = slots[s]!;
        if (r === 0) break;
        const q = r - 1;
        if (pK[q] === kind && pA[q] === a && pB[q] === b && pF[q] === f) {
          j = pSA[q] === sA && pSB[q] === sB ? q : -1;
          break;
        }
        s = (s + 1) & mask;
      }
    }
    if (j >= 0) {
      next = j + 1;
      LN[i] = pN[j]!;
      L1[i] = p1[j]!;
      L2[i] = p2[j]!;
    } else {
      LN[i] = 0;
      L1[i] = 0;
      L2[i] = 0;
    }
  }
  return 0;
}
