/**
 * The contact solver's preparation of ball contact rows (solver/ball-prepare.ts prepareContacts), 2D
 * and 3D, as a thread kernel (step/kernel-table.ts: self-contained, also run by the workers as source
 * text). Each row is prepared on its own (effective masses, tangent, combined material, stick or
 * slip, the predicted approach, the warm start found in last step's rows), so the rows are identical
 * to the bit whichever thread prepares them. It is the preparation's only code: solver/ball-prepare.ts
 * (prepareStage) runs it on the threads or inline.
 */

import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import * as BS from './body-state-layout.js';
import type { rigidPartner } from './rigid-partner.js';
import * as PREPARE from './slots/prepare-contacts.js';

/**
 * Prepares contact rows lo .. hi - 1 of a 2D or a 3D world (P[PREPARE.THREE_D]; rows of BS2_STRIDE or
 * BS3_STRIDE in the solver state), in two passes over the range, each a function of its own
 * (KERNEL_HELPERS 13 and 14, solver/kernel-helpers.ts): prepareRowMasses, then prepareRowWarmStart.
 * A and P: the PREPARE slots (solver/slots/prepare-contacts.ts: the contact buffer's rows, the Material
 * stores, last step's rows and the warm-start hash slots). Returns 0.
 * @category Collision
 */
export function prepareContactRows(
  A: KernelArray[],
  P: Float64Array,
  _ids: Int32Array | null,
  lo: number,
  hi: number,
  _part: number,
  H: readonly KernelHelper[],
): number {
  (H[13] as typeof prepareRowMasses)(A, P, lo, hi, H);
  (H[14] as typeof prepareRowWarmStart)(A, P, lo, hi);
  return 0;
}

/**
 * prepareContactRows' first pass over rows lo .. hi - 1: effective masses, the tangent ((-ny, nx) in 2D;
 * in 3D t1 perpendicular to the normal, built from its two components away from the smallest, t2 = n x t1
 * recomputed where needed), combined material, stick or slip, the predicted approach; the step's
 * impulse sums zeroed; whether each row is against an infinite-mass partner (solver/rigid-partner.ts, reached
 * in `H`). A, P and H as prepareContactRows'.
 * @category Collision
 */
export function prepareRowMasses(A: KernelArray[], P: Float64Array, lo: number, hi: number, H: readonly KernelHelper[]): void {
  const CA = A[PREPARE.A] as Int32Array,
    CB = A[PREPARE.B] as Int32Array,
    IA = A[PREPARE.IA] as Int32Array,
    IB = A[PREPARE.IB] as Int32Array;
  const K = A[PREPARE.KIND] as Uint8Array,
    F = A[PREPARE.FEATURE] as Int32Array,
    NX = A[PREPARE.NX] as Float64Array,
    NY = A[PREPARE.NY] as Float64Array,
    NZ = A[PREPARE.NZ] as Float64Array;
  const RA = A[PREPARE.RA] as Float64Array,
    RB = A[PREPARE.RB] as Float64Array,
    sb = A[PREPARE.BODY_STATE] as Float64Array;
  const eM = A[PREPARE.RESTITUTION_OF] as Float64Array,
    fM = A[PREPARE.FRICTION_OF] as Float64Array,
    sM = A[PREPARE.STATIC_FRICTION_OF] as Float64Array;
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
    MAXN = A[PREPARE.MAX_NORMAL_IMPULSE] as Float64Array;
  // Whether a row is against an infinite-mass partner: the one rule of every row family (KERNEL_HELPERS 19).
  const rigidOf = H[19] as typeof rigidPartner;
  const stick = P[PREPARE.STICK_SPEED]!,
    boxE = P[PREPARE.BOX_RESTITUTION]!,
    boxF = P[PREPARE.BOX_FRICTION]!,
    boxS = P[PREPARE.BOX_STATIC_FRICTION]!;
  const BALL = P[PREPARE.BALL]!,
    BOUNDARY = P[PREPARE.BOUNDARY]!;
  // The solver state's layout: vx and vy sit at the same offsets in both.
  const is3D = P[PREPARE.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE,
    IM = is3D ? BS.BS3_INV_MASS : BS.BS2_INV_MASS,
    II = is3D ? BS.BS3_INV_INERTIA : BS.BS2_INV_INERTIA;
  for (let i = lo; i < hi; i++) {
    const a = CA[i]!,
      b = CB[i]!,
      kind = K[i]!,
      f = F[i]!;
    const oa = IA[i]! * S,
      ob = IB[i]! * S;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[oa + IM]!,
      imB = sb[ob + IM]!;
    const iiA = sb[oa + II]!,
      iiB = sb[ob + II]!;
    const ra = RA[i]!,
      rb = RB[i]!;
    const k = imA + imB;
    NM[i] = k > 0 ? 1 / k : 0;
    const kt = k + iiA * ra * ra + iiB * rb * rb;
    TM[i] = kt > 0 ? 1 / kt : 0;
    RP[i] = rigidOf(imA, imB);
    const dvx = sb[ob + BS.BS2_VX]! - sb[oa + BS.BS2_VX]!,
      dvy = sb[ob + BS.BS2_VY]! - sb[oa + BS.BS2_VY]!;
    // The tangential speed at the contact point at the start of the step (gravity rewound): stick or
    // slip; and the predicted approach, for the impact stage's ordering (measureApproach recomputes it).
    let vt: number, rv: number;
    if (is3D) {
      const nz = NZ[i]!;
      let t1x: number, t1y: number, t1z: number;
      if (Math.abs(nx) < 0.57735) {
        const inv = 1 / Math.sqrt(ny * ny + nz * nz);
        t1x = 0;
        t1y = nz * inv;
        t1z = -ny * inv;
      } else {
        const inv = 1 / Math.sqrt(nx * nx + ny * ny);
        t1x = ny * inv;
        t1y = -nx * inv;
        t1z = 0;
      }
      T1X[i] = t1x;
      T1Y[i] = t1y;
      T1Z[i] = t1z;
      const dvz = sb[ob + BS.BS3_VZ]! - sb[oa + BS.BS3_VZ]!;
      // Contact-point velocity: v + w x r with r_A = ra n, r_B = -rb n.
      const sx = -rb * sb[ob + BS.BS3_WX]! - ra * sb[oa + BS.BS3_WX]!,
        sy = -rb * sb[ob + BS.BS3_WY]! - ra * sb[oa + BS.BS3_WY]!,
        sz = -rb * sb[ob + BS.BS3_WZ]! - ra * sb[oa + BS.BS3_WZ]!;
      const cx = dvx + sy * nz - sz * ny,
        cy = dvy + sz * nx - sx * nz,
        cz = dvz + sx * ny - sy * nx;
      const t2x = ny * t1z - nz * t1y,
        t2y = nz * t1x - nx * t1z,
        t2z = nx * t1y - ny * t1x;
      const u1 = cx * t1x + cy * t1y + cz * t1z,
        u2 = cx * t2x + cy * t2y + cz * t2z;
      vt = Math.sqrt(u1 * u1 + u2 * u2);
      rv = dvx * nx + dvy * ny + dvz * nz;
    } else {
      T1X[i] = -ny;
      T1Y[i] = nx;
      T1Z[i] = 0;
      vt = Math.abs(dvx * -ny + dvy * nx - sb[ob + BS.BS2_W]! * rb - sb[oa + BS.BS2_W]! * ra);
      rv = dvx * nx + dvy * ny + 0;
    }
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
    RV[i] = rv;
    TOT[i] = 0;
    IMP[i] = 0;
    FB[i] = vt < stick ? Math.max(mus, mu) : mu;
    MAXN[i] = 0;
  }
}

/**
 * prepareContactRows' second pass over rows lo .. hi - 1: the bodies' spawn stamps, and the warm start,
 * last step's impulses of the same row (kind, bodies, feature and stamps; -1 in PREVIOUS for a new row).
 * The rows come in much the same order every step: the row after the previous match is tried first
 * (one comparison, read in order) before the hash table (collision/contacts.ts findWarmStart and
 * hashKey; the same row, keys are unique). A and P as prepareContactRows'.
 * @category Collision
 */
export function prepareRowWarmStart(A: KernelArray[], P: Float64Array, lo: number, hi: number): void {
  const CA = A[PREPARE.A] as Int32Array,
    CB = A[PREPARE.B] as Int32Array,
    K = A[PREPARE.KIND] as Uint8Array,
    F = A[PREPARE.FEATURE] as Int32Array;
  const stamp = A[PREPARE.SPAWN_STAMP] as Uint32Array,
    SA = A[PREPARE.STAMP_A] as Uint32Array,
    SB = A[PREPARE.STAMP_B] as Uint32Array,
    PREV = A[PREPARE.PREVIOUS] as Int32Array;
  const LN = A[PREPARE.NORMAL_IMPULSE] as Float64Array,
    L1 = A[PREPARE.TANGENT_IMPULSE_1] as Float64Array,
    L2 = A[PREPARE.TANGENT_IMPULSE_2] as Float64Array;
  const pK = A[PREPARE.PREV_KIND] as Uint8Array,
    pA = A[PREPARE.PREV_A] as Int32Array,
    pB = A[PREPARE.PREV_B] as Int32Array,
    pF = A[PREPARE.PREV_FEATURE] as Int32Array;
  const pSA = A[PREPARE.PREV_STAMP_A] as Uint32Array,
    pSB = A[PREPARE.PREV_STAMP_B] as Uint32Array;
  const pN = A[PREPARE.PREV_NORMAL_IMPULSE] as Float64Array,
    p1 = A[PREPARE.PREV_TANGENT_IMPULSE_1] as Float64Array,
    p2 = A[PREPARE.PREV_TANGENT_IMPULSE_2] as Float64Array,
    slots = A[PREPARE.SLOTS] as Int32Array;
  const prevCount = P[PREPARE.PREV_ROWS]!,
    size = P[PREPARE.SLOT_COUNT]!,
    BALL = P[PREPARE.BALL]!,
    BOUNDARY = P[PREPARE.BOUNDARY]!;
  const mask = size - 1;
  let next = 0;
  for (let i = lo; i < hi; i++) {
    const a = CA[i]!,
      b = CB[i]!,
      kind = K[i]!,
      f = F[i]!;
    const sA = stamp[kind === BALL ? a : kind === BOUNDARY ? 0 : f]!;
    const sB = stamp[b]!;
    SA[i] = sA;
    SB[i] = sB;
    // The previous row with this key (one at most: a key is one contact): first the guess `next` and,
    // with a table, the rows up to six places either side (next + 1, 2, -2, 3, -3, ..., 6, -6: rows the
    // guess misses have mostly moved by a few places since the last step), then the hash table. Its row, or -1 if
    // none or its bodies' stamps differ (a body in its slot was respawned).
    let j = -1,
      known = false;
    for (let t = 0, tries = size === 0 ? 1 : 12; t < tries; t++) {
      const q = next + (t < 2 ? t : ((t + 2) >> 1) * (t & 1 ? -1 : 1));
      if (q >= 0 && q < prevCount && pK[q] === kind && pA[q] === a && pB[q] === b && pF[q] === f) {
        j = pSA[q] === sA && pSB[q] === sB ? q : -1;
        known = true;
        break;
      }
    }
    if (!known && size !== 0) {
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
}
