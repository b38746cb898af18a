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
import * as PREPARE from './slots/prepare-contacts.js';

/**
 * Prepares 2D contact rows lo .. hi - 1.
 * A and P: the PREPARE slots (solver/slots/prepare-contacts.ts: the contact buffer's rows, the Material
 * stores, last step's rows and the warm-start hash slots). Returns 0.
 * @category Collision
 */
export function prepareContacts2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  const CA = A[PREPARE.A] as Int32Array,
    CB = A[PREPARE.B] as Int32Array,
    IA = A[PREPARE.IA] as Int32Array,
    IB = A[PREPARE.IB] as Int32Array;
  const K = A[PREPARE.KIND] as Uint8Array,
    F = A[PREPARE.FEATURE] as Int32Array,
    NX = A[PREPARE.NX] as Float64Array,
    NY = A[PREPARE.NY] as Float64Array;
  const RA = A[PREPARE.RA] as Float64Array,
    RB = A[PREPARE.RB] as Float64Array,
    sb = A[PREPARE.BODY_STATE] as Float64Array;
  const eM = A[PREPARE.RESTITUTION_OF] as Float64Array,
    fM = A[PREPARE.FRICTION_OF] as Float64Array,
    sM = A[PREPARE.STATIC_FRICTION_OF] as Float64Array,
    stamp = A[PREPARE.SPAWN_STAMP] as Uint32Array;
  const NM = A[PREPARE.NORMAL_MASS] as Float64Array,
    TM = A[PREPARE.TANGENT_MASS] as Float64Array,
    RP = A[PREPARE.RIGID_PARTNER] as Uint8Array;
  const T1X = A[PREPARE.T1X] as Float64Array,
    T1Y = A[PREPARE.T1Y] as Float64Array,
    T1Z = A[PREPARE.T1Z] as Float64Array;
  const E = A[PREPARE.RESTITUTION] as Float64Array,
    MU = A[PREPARE.FRICTION] as Float64Array,
    FB = A[PREPARE.FRICTION_BOUND] as Float64Array,
    RV = A[PREPARE.RELATIVE_VELOCITY] as Float64Array;
  const TOT = A[PREPARE.TOTAL_NORMAL_IMPULSE] as Float64Array,
    IMP = A[PREPARE.IMPULSE] as Float64Array,
    LN = A[PREPARE.NORMAL_IMPULSE] as Float64Array,
    L1 = A[PREPARE.TANGENT_IMPULSE_1] as Float64Array;
  const L2 = A[PREPARE.TANGENT_IMPULSE_2] as Float64Array,
    MAXN = A[PREPARE.MAX_NORMAL_IMPULSE] as Float64Array,
    SA = A[PREPARE.STAMP_A] as Uint32Array,
    SB = A[PREPARE.STAMP_B] as Uint32Array;
  const pK = A[PREPARE.PREV_KIND] as Uint8Array,
    pA = A[PREPARE.PREV_A] as Int32Array,
    pB = A[PREPARE.PREV_B] as Int32Array,
    pF = A[PREPARE.PREV_FEATURE] as Int32Array;
  const pSA = A[PREPARE.PREV_STAMP_A] as Uint32Array,
    pSB = A[PREPARE.PREV_STAMP_B] as Uint32Array;
  const pN = A[PREPARE.PREV_NORMAL_IMPULSE] as Float64Array,
    p1 = A[PREPARE.PREV_TANGENT_IMPULSE_1] as Float64Array,
    p2 = A[PREPARE.PREV_TANGENT_IMPULSE_2] as Float64Array,
    slots = A[PREPARE.SLOTS] as Int32Array,
    PREV = A[PREPARE.PREVIOUS] as Int32Array;
  const stick = P[PREPARE.STICK_SPEED]!,
    boxE = P[PREPARE.BOX_RESTITUTION]!,
    boxF = P[PREPARE.BOX_FRICTION]!,
    boxS = P[PREPARE.BOX_STATIC_FRICTION]!,
    prevCount = P[PREPARE.PREV_ROWS]!,
    size = P[PREPARE.SLOT_COUNT]!;
  const BALL = P[PREPARE.BALL]!,
    BOUNDARY = P[PREPARE.BOUNDARY]!;
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
    PREV[i] = j;
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
