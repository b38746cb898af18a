/**
 * The ball contacts' Gauss-Seidel sweeps (solver/ball-rows.ts): the warm start of each substep and the
 * solve with soft bias, then relaxed, for 2D discs (rows of 8 in the packed solver state) and 3D spheres
 * (rows of 12).
 */
import type { ContactBuffer } from '../collision/contacts.js';
import type { CollisionState } from '../collision/state.js';
import { heavierAbove, holdsLower, SUPPORT_COS } from './support.js';
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
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    sb[a + 7] = 1;
    sb[b + 7] = 1;
    const nx = NX[i]!,
      ny = NY[i]!;
    const Px = ln * nx - lt * ny,
      Py = ln * ny + lt * nx;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[a + 2] = sb[a + 2]! - sb[a + 6]! * RA[i]! * lt;
    sb[b + 2] = sb[b + 2]! - sb[b + 6]! * RB[i]! * lt;
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
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    sb[a + 11] = 1;
    sb[b + 11] = 1;
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
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[a + 2] = sb[a + 2]! - imA * Pz;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[b + 2] = sb[b + 2]! + imB * Pz;
    const cx = ny * Pz - nz * Py,
      cy = nz * Px - nx * Pz,
      cz = nx * Py - ny * Px;
    const ka = sb[a + 10]! * RA[i]!,
      kb = sb[b + 10]! * RB[i]!;
    sb[a + 3] = sb[a + 3]! - ka * cx;
    sb[a + 4] = sb[a + 4]! - ka * cy;
    sb[a + 5] = sb[a + 5]! - ka * cz;
    sb[b + 3] = sb[b + 3]! - kb * cx;
    sb[b + 4] = sb[b + 4]! - kb * cy;
    sb[b + 5] = sb[b + 5]! - kb * cz;
  }
}

/**
 * One Gauss-Seidel sweep over the 2D ball contacts: with soft bias if `useBias`, else the relax sweep,
 * which takes the rows against static bodies first and last and solves the support rows (frictionless,
 * or with the heavier ball above) with the lower ball held when that only slows the upper one
 * (solver/support.ts; (downX, downY) is the unit vector along gravity, (0, 0) without). The substep,
 * push-out cap, down vector and soft coefficients are read from `sp` (ball-rows.ts solveParams); `first` marks the rows the relax sweep takes first (solver/support.ts markFirstRelaxRows).
 */
export function solve2D(cs: CollisionState, buf: ContactBuffer, useBias: boolean, sp: Float64Array, first: Uint8Array): void {
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[2]!,
    downY = sp[3]!;
  const n = buf.count,
    sb = cs.bodyState;
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
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!;
    // The normal impulse's inverse masses and effective mass: a support row of the relax sweep, one
    // without friction or one whose upper ball is the heavier, may hold its lower ball (solver/support.ts).
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny),
          vb = Math.abs(vbx * nx + vby * ny);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    // Non-penetration, soft when overlapping and useBias, speculative when apart.
    const s = S0[i]! + (sb[b + 3]! - sb[a + 3]!) * nx + (sb[b + 4]! - sb[a + 4]!) * ny;
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
    let wa = sb[a + 2]!,
      wb = sb[b + 2]!;
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
    wa -= sb[a + 6]! * ra * lambda;
    wb -= sb[b + 6]! * rb * lambda;

    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
    if (newN !== 0 || newT !== 0) {
      sb[a + 7] = 1;
      sb[b + 7] = 1;
    }
  }
}

/**
 * One Gauss-Seidel sweep over the 3D ball contacts (with soft bias if `useBias`); parameters from
 * `sp` and `first` as solve2D, and its relax sweep as solve2D's: static rows first and last, support rows
 * (frictionless or with the heavier ball above) holding their lower ball when that only slows the upper.
 */
export function solve3D(cs: CollisionState, buf: ContactBuffer, useBias: boolean, sp: Float64Array, first: Uint8Array): void {
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[10]!,
    downY = sp[11]!,
    downZ = sp[12]!;
  const n = buf.count,
    sb = cs.bodyState;
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
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vaz = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      vbz = sb[b + 2]!;
    // A support row of the relax sweep may hold its lower ball (solver/support.ts), as in solve2D.
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny + downZ * nz);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny + vaz * nz),
          vb = Math.abs(vbx * nx + vby * ny + vbz * nz);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    const s = S0[i]! + (sb[b + 6]! - sb[a + 6]!) * nx + (sb[b + 7]! - sb[a + 7]!) * ny + (sb[b + 8]! - sb[a + 8]!) * nz;
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
    let wax = sb[a + 3]!,
      way = sb[a + 4]!,
      waz = sb[a + 5]!,
      wbx = sb[b + 3]!,
      wby = sb[b + 4]!,
      wbz = sb[b + 5]!;
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
      const ka = sb[a + 10]! * ra,
        kb = sb[b + 10]! * rb;
      wax -= ka * cx;
      way -= ka * cy;
      waz -= ka * cz;
      wbx -= kb * cx;
      wby -= kb * cy;
      wbz -= kb * cz;
    }
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = vaz;
    sb[a + 3] = wax;
    sb[a + 4] = way;
    sb[a + 5] = waz;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = vbz;
    sb[b + 3] = wbx;
    sb[b + 4] = wby;
    sb[b + 5] = wbz;
    if (newN !== 0 || n1 !== 0 || n2 !== 0) {
      sb[a + 11] = 1;
      sb[b + 11] = 1;
    }
  }
}
