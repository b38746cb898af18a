/**
 * The ball contacts' Gauss-Seidel sweeps (solver/ball-rows.ts): the warm start of each substep and the
 * solve with soft bias, then relaxed, for 2D discs (rows of 8 in the packed solver state) and 3D spheres
 * (rows of 12).
 */

import type { ContactBuffer } from '../collision/contacts.js';
import type { CollisionState } from '../collision/state.js';
import * as BS from './body-state-layout.js';
import { storeBody3D, storeVelocities2D } from './body-velocities.js';
import { heldSupportBall } from './support.js';
/** Applies every contact's accumulated impulse (Box2D v3 warm start, once per substep), 2D. */
export function warmStart2D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      lt = LT[i]!;
    if (ln === 0 && lt === 0) continue;
    const a = IA[i]! * BS.BS2_STRIDE,
      b = IB[i]! * BS.BS2_STRIDE;
    sb[a + BS.BS2_PUSHED] = 1;
    sb[b + BS.BS2_PUSHED] = 1;
    const nx = NX[i]!,
      ny = NY[i]!;
    const Px = ln * nx - lt * ny,
      Py = ln * ny + lt * nx;
    const imA = sb[a + BS.BS2_INV_MASS]!,
      imB = sb[b + BS.BS2_INV_MASS]!;
    sb[a + BS.BS2_VX] = sb[a + BS.BS2_VX]! - imA * Px;
    sb[a + BS.BS2_VY] = sb[a + BS.BS2_VY]! - imA * Py;
    sb[b + BS.BS2_VX] = sb[b + BS.BS2_VX]! + imB * Px;
    sb[b + BS.BS2_VY] = sb[b + BS.BS2_VY]! + imB * Py;
    sb[a + BS.BS2_W] = sb[a + BS.BS2_W]! - sb[a + BS.BS2_INV_INERTIA]! * RA[i]! * lt;
    sb[b + BS.BS2_W] = sb[b + BS.BS2_W]! - sb[b + BS.BS2_INV_INERTIA]! * RB[i]! * lt;
  }
}

/** Applies every contact's accumulated impulse, 3D. Angular: dw_A = -I_A^-1 (ra n x P), dw_B = I_B^-1 (-rb n x P). */
export function warmStart3D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      l1 = L1[i]!,
      l2 = L2[i]!;
    if (ln === 0 && l1 === 0 && l2 === 0) continue;
    const a = IA[i]! * BS.BS3_STRIDE,
      b = IB[i]! * BS.BS3_STRIDE;
    sb[a + BS.BS3_PUSHED] = 1;
    sb[b + BS.BS3_PUSHED] = 1;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!,
      t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const Px = ln * nx + l1 * t1x + l2 * t2x,
      Py = ln * ny + l1 * t1y + l2 * t2y,
      Pz = ln * nz + l1 * t1z + l2 * t2z;
    const imA = sb[a + BS.BS3_INV_MASS]!,
      imB = sb[b + BS.BS3_INV_MASS]!;
    sb[a + BS.BS3_VX] = sb[a + BS.BS3_VX]! - imA * Px;
    sb[a + BS.BS3_VY] = sb[a + BS.BS3_VY]! - imA * Py;
    sb[a + BS.BS3_VZ] = sb[a + BS.BS3_VZ]! - imA * Pz;
    sb[b + BS.BS3_VX] = sb[b + BS.BS3_VX]! + imB * Px;
    sb[b + BS.BS3_VY] = sb[b + BS.BS3_VY]! + imB * Py;
    sb[b + BS.BS3_VZ] = sb[b + BS.BS3_VZ]! + imB * Pz;
    const cx = ny * Pz - nz * Py,
      cy = nz * Px - nx * Pz,
      cz = nx * Py - ny * Px;
    const ka = sb[a + BS.BS3_INV_INERTIA]! * RA[i]!,
      kb = sb[b + BS.BS3_INV_INERTIA]! * RB[i]!;
    sb[a + BS.BS3_WX] = sb[a + BS.BS3_WX]! - ka * cx;
    sb[a + BS.BS3_WY] = sb[a + BS.BS3_WY]! - ka * cy;
    sb[a + BS.BS3_WZ] = sb[a + BS.BS3_WZ]! - ka * cz;
    sb[b + BS.BS3_WX] = sb[b + BS.BS3_WX]! - kb * cx;
    sb[b + BS.BS3_WY] = sb[b + BS.BS3_WY]! - kb * cy;
    sb[b + BS.BS3_WZ] = sb[b + BS.BS3_WZ]! - kb * cz;
  }
}

/**
 * One Gauss-Seidel sweep over the 2D ball contacts, on the packed solver body state `sb` (CollisionState.bodyState): with soft bias if `useBias`, else the relax sweep,
 * which takes the rows against static bodies first and last and solves the support rows (frictionless,
 * or with the heavier ball above) with the lower ball held when that only slows the upper one
 * (solver/support.ts; (downX, downY) is the unit vector along gravity, (0, 0) without). The substep,
 * push-out cap, down vector and soft coefficients are read from `sp` (ball-rows.ts solveParams); the relax
 * sweep takes the rows in `order`'s first `count` entries (solver/support.ts relaxOrderInto).
 */
export function solve2D(sb: Float64Array, buf: ContactBuffer, useBias: boolean, sp: Float64Array, order: Int32Array, count: number): void {
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[2]!,
    downY = sp[3]!;
  const n = buf.count;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1,
    MAXN = buf.maxNormalImpulse;
  const dBias = sp[4]!,
    dMass = sp[5]!,
    dImp = sp[6]!;
  const rBias = sp[7]!,
    rMass = sp[8]!,
    rImp = sp[9]!;

  // The sweep with bias takes the rows in order. The relax sweep takes first the touching rows that
  // hold a ball under a heavier one against a static body (solver/support.ts markFirstRelaxRows), so that ball
  // is at rest when the support row above it is relaxed and may hold it, taking the heavy ball's
  // push-out speed away; then the rows between two balls; then the rows against static bodies (walls,
  // floor, segments), which take out what the others pushed into them.
  const end = useBias ? n : count;
  for (let k = 0; k < end; k++) {
    const i = useBias ? k : order[k]!;
    const a = IA[i]! * BS.BS2_STRIDE,
      b = IB[i]! * BS.BS2_STRIDE;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[a + BS.BS2_INV_MASS]!,
      imB = sb[b + BS.BS2_INV_MASS]!;
    let vax = sb[a + BS.BS2_VX]!,
      vay = sb[a + BS.BS2_VY]!,
      vbx = sb[b + BS.BS2_VX]!,
      vby = sb[b + BS.BS2_VY]!;
    // The normal impulse's inverse masses and effective mass: a support row of the relax sweep, one
    // without friction or one whose upper ball is the heavier, may hold its lower ball (solver/support.ts).
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const held = heldSupportBall(-(downX * nx + downY * ny), FB[i]!, imA, imB, vax * nx + vay * ny, vbx * nx + vby * ny);
      if (held !== 0) {
        if (held === 1) jmA = 0;
        else jmB = 0;
        nm = 1 / (jmA + jmB);
      }
    }

    // Non-penetration, soft when overlapping and useBias, speculative when apart.
    const s = S0[i]! + (sb[b + BS.BS2_DX]! - sb[a + BS.BS2_DX]!) * nx + (sb[b + BS.BS2_DY]! - sb[a + BS.BS2_DY]!) * ny;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      if (RP[i] === 1) {
        bias = rBias * s;
        massScale = rMass;
        impulseScale = rImp;
      } else {
        bias = dBias * s;
        massScale = dMass;
        impulseScale = dImp;
      }
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny;
    const oldN = LN[i]!;
    // A speculative row with no impulse whose gap stays open this substep does nothing (every impulse below is 0).
    if (s > 0 && oldN === 0 && vn + bias >= 0 && LT[i] === 0) continue;
    let lambda = -nm * massScale * (vn + bias) - impulseScale * oldN;
    let newN = oldN + lambda;
    if (newN < 0) newN = 0;
    lambda = newN - oldN;
    LN[i] = newN;
    if (lambda > MAXN[i]!) MAXN[i] = lambda;
    let Px = lambda * nx,
      Py = lambda * ny;
    vax -= jmA * Px;
    vay -= jmA * Py;
    vbx += jmB * Px;
    vby += jmB * Py;

    // Coulomb friction along t = (-ny, nx) at the contact point.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wa = sb[a + BS.BS2_W]!,
      wb = sb[b + BS.BS2_W]!;
    const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
    lambda = -TM[i]! * vt;
    const maxF = FB[i]! * newN;
    const oldT = LT[i]!;
    let newT = oldT + lambda;
    newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
    lambda = newT - oldT;
    LT[i] = newT;
    Px = -lambda * ny;
    Py = lambda * nx;
    vax -= imA * Px;
    vay -= imA * Py;
    vbx += imB * Px;
    vby += imB * Py;
    wa -= sb[a + BS.BS2_INV_INERTIA]! * ra * lambda;
    wb -= sb[b + BS.BS2_INV_INERTIA]! * rb * lambda;

    storeVelocities2D(sb, a, b, vax, vay, wa, vbx, vby, wb);
    if (newN !== 0 || newT !== 0) {
      sb[a + BS.BS2_PUSHED] = 1;
      sb[b + BS.BS2_PUSHED] = 1;
    }
  }
}

/**
 * One Gauss-Seidel sweep over the 3D ball contacts (with soft bias if `useBias`); parameters from
 * `sp`, `order` and `count` as solve2D, and its relax sweep as solve2D's: static rows first and last, support rows
 * (frictionless or with the heavier ball above) holding their lower ball when that only slows the upper.
 */
export function solve3D(sb: Float64Array, buf: ContactBuffer, useBias: boolean, sp: Float64Array, order: Int32Array, count: number): void {
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[10]!,
    downY = sp[11]!,
    downZ = sp[12]!;
  const n = buf.count;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2,
    MAXN = buf.maxNormalImpulse;

  // Row order as in solve2D: the relax sweep takes the rows under heavier balls, the ball pairs, the static rows.
  const end = useBias ? n : count;
  for (let k = 0; k < end; k++) {
    const i = useBias ? k : order[k]!;
    const a = IA[i]! * BS.BS3_STRIDE,
      b = IB[i]! * BS.BS3_STRIDE;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[a + BS.BS3_INV_MASS]!,
      imB = sb[b + BS.BS3_INV_MASS]!;
    let vax = sb[a + BS.BS3_VX]!,
      vay = sb[a + BS.BS3_VY]!,
      vaz = sb[a + BS.BS3_VZ]!,
      vbx = sb[b + BS.BS3_VX]!,
      vby = sb[b + BS.BS3_VY]!,
      vbz = sb[b + BS.BS3_VZ]!;
    const s =
      S0[i]! +
      (sb[b + BS.BS3_DX]! - sb[a + BS.BS3_DX]!) * nx +
      (sb[b + BS.BS3_DY]! - sb[a + BS.BS3_DY]!) * ny +
      (sb[b + BS.BS3_DZ]! - sb[a + BS.BS3_DZ]!) * nz;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      const at = RP[i] === 1 ? 7 : 4;
      bias = sp[at]! * s;
      massScale = sp[at + 1]!;
      impulseScale = sp[at + 2]!;
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz;
    const oldN = LN[i]!;
    // A speculative row with no impulse whose gap stays open does nothing (as in solve2D: every impulse is 0).
    if (s > 0 && oldN === 0 && vn + bias >= 0 && L1[i] === 0 && L2[i] === 0) continue;
    // A support row of the relax sweep may hold its lower ball (solver/support.ts), as in solve2D.
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny + downZ * nz);
      const held = heldSupportBall(up, FB[i]!, imA, imB, vax * nx + vay * ny + vaz * nz, vbx * nx + vby * ny + vbz * nz);
      if (held !== 0) {
        if (held === 1) jmA = 0;
        else jmB = 0;
        nm = 1 / (jmA + jmB);
      }
    }

    let newN = oldN - nm * massScale * (vn + bias) - impulseScale * oldN;
    if (newN < 0) newN = 0;
    const dl = newN - oldN;
    LN[i] = newN;
    if (dl > MAXN[i]!) MAXN[i] = dl;
    vax -= jmA * dl * nx;
    vay -= jmA * dl * ny;
    vaz -= jmA * dl * nz;
    vbx += jmB * dl * nx;
    vby += jmB * dl * ny;
    vbz += jmB * dl * nz;

    // Friction in the tangent plane, clamped to the Coulomb cone.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wax = sb[a + BS.BS3_WX]!,
      way = sb[a + BS.BS3_WY]!,
      waz = sb[a + BS.BS3_WZ]!,
      wbx = sb[b + BS.BS3_WX]!,
      wby = sb[b + BS.BS3_WY]!,
      wbz = sb[b + BS.BS3_WZ]!;
    let ux = vbx - vax,
      uy = vby - vay,
      uz = vbz - vaz;
    const sx = -rb * wbx - ra * wax,
      sy = -rb * wby - ra * way,
      sz = -rb * wbz - ra * waz;
    ux += sy * nz - sz * ny;
    uy += sz * nx - sx * nz;
    uz += sx * ny - sy * nx;
    const t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const tm = TM[i]!;
    const o1 = L1[i]!,
      o2 = L2[i]!;
    let n1 = o1 - tm * (ux * t1x + uy * t1y + uz * t1z);
    let n2 = o2 - tm * (ux * t2x + uy * t2y + uz * t2z);
    const maxF = FB[i]! * newN;
    const mag2 = n1 * n1 + n2 * n2;
    if (mag2 > maxF * maxF) {
      const k = maxF / Math.sqrt(mag2);
      n1 *= k;
      n2 *= k;
    }
    const d1 = n1 - o1,
      d2 = n2 - o2;
    L1[i] = n1;
    L2[i] = n2;
    if (d1 !== 0 || d2 !== 0) {
      const Px = d1 * t1x + d2 * t2x,
        Py = d1 * t1y + d2 * t2y,
        Pz = d1 * t1z + d2 * t2z;
      vax -= imA * Px;
      vay -= imA * Py;
      vaz -= imA * Pz;
      vbx += imB * Px;
      vby += imB * Py;
      vbz += imB * Pz;
      const cx = ny * Pz - nz * Py,
        cy = nz * Px - nx * Pz,
        cz = nx * Py - ny * Px;
      const ka = sb[a + BS.BS3_INV_INERTIA]! * ra,
        kb = sb[b + BS.BS3_INV_INERTIA]! * rb;
      wax -= ka * cx;
      way -= ka * cy;
      waz -= ka * cz;
      wbx -= kb * cx;
      wby -= kb * cy;
      wbz -= kb * cz;
    }
    storeBody3D(sb, a, vax, vay, vaz, wax, way, waz);
    storeBody3D(sb, b, vbx, vby, vbz, wbx, wby, wbz);
    if (newN !== 0 || n1 !== 0 || n2 !== 0) {
      sb[a + BS.BS3_PUSHED] = 1;
      sb[b + BS.BS3_PUSHED] = 1;
    }
  }
}
