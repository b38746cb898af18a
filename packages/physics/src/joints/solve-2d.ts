import { ROW_FLOATS, ROW_INTS } from '../world/joint-state-2d.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import {
  AB,
  AI,
  AM,
  AXX,
  AXY,
  DANG,
  DCX,
  DCY,
  FMAX,
  IA,
  IANG,
  IB,
  ILOW,
  ILX,
  ILY,
  IMOT,
  ISPR,
  IUP,
  JB,
  JI,
  JM,
  KAX,
  KMOT,
  LEN,
  LOW,
  MAXL,
  MINL,
  MMAX,
  MSPD,
  PIN,
  POINT_LINK,
  RAX,
  RAY,
  RBX,
  RBY,
  SB,
  SI,
  SM,
  TF,
  UP,
  WELD_ANGULAR_SOFT,
} from './layout-2d.js';
import { solvePins, solvePointLinks } from './pins-2d.js';
import { unwind } from './prepare-2d.js';

/** The 2D joint solve of a substep (stage 3 of joints/solver-2d.ts): every general row (distance, revolute, prismatic, weld, wheel, mouse, motor) once, then the pins and point links. */

/**
 * The impulse of a fixed-stiffness spring row (see `fixedSpring`): `cdot` the velocity along the
 * row, `c` its position error, `k` the inverse effective mass of the moment, `lambda` the impulse the
 * row holds, `bias` and `gamma` from `fixedSpring`.
 */
function springImpulse(cdot: number, c: number, k: number, lambda: number, bias: number, gamma: number): number {
  if (!(gamma < Infinity)) return -lambda;
  const den = k + gamma;
  return den > 0 ? -(cdot + bias * c + gamma * lambda) / den : 0;
}

/**
 * Passes over every joint row (sequential impulses): `world.joints.settings.iterations` with `useBias`,
 * in which the rigid parts push out their position error as soft constraints; one without it (relax),
 * in which they only remove relative velocity. `hs` is the substep, s. Velocities of the static world
 * (solver index 0) stay zero: its inverse mass is 0.
 * @category Joints and ropes
 */
export function solveJoints(world: PhysicsWorld, hs: number, useBias: boolean): void {
  if (world.joints.rowCount === 0) return;
  const passes = useBias ? Math.max(1, Math.floor(world.joints.settings.iterations)) : 1;
  for (let i = 0; i < passes; i++) solveJointRows(world, hs, useBias);
}

/**
 * One update of a weld whose linear and angular parts are both soft: the implicit (backward Euler)
 * step of its three springs solved as one 3 x 3 system, so a long lever, which couples the anchor's
 * motion to the rotation, cannot make the rows feed each other energy (solved one after the other,
 * a 5 Hz weld with damping 0 on a 10 m lever spun up to 1e4 rad/s). With constraint
 * C = (anchor separation x, y, relative angle), its rate Cdot, A = J M^-1 J^T and per part p
 * (linear: hertz, dampingRatio; angular: angularHertz, angularDampingRatio) the stiffness
 * omega_p^2 A_pp^-1 and damping 2 zeta_p omega_p A_pp^-1 (each part alone is Box2D's soft constraint),
 * the impulse's change d solves (A + G) d = -(Cdot + beta C + G lambda), lambda the impulse so far this
 * substep, beta_p the bias rate and G_p = A_pp impulseScale_p / massScale_p (one part alone: exactly
 * the soft row's update). Reads the bodies' velocities from `sb` at oA, oB and writes them back with
 * the pushed marks; returns false (nothing done) when a part has no spring (mass scale 0) or the
 * system is singular, for the row-by-row update.
 */
function solveSoftWeld(
  rows: Float64Array,
  o: number,
  sb: Float64Array,
  oA: number,
  oB: number,
  rAx: number,
  rAy: number,
  rBx: number,
  rBy: number,
  dx: number,
  dy: number,
  relAngle: number,
): boolean {
  const msL = rows[o + JM]!,
    msA = rows[o + AM]!;
  if (!(msL > 0 && msA > 0)) return false;
  const mA0 = sb[oA + 5]!,
    iA0 = sb[oA + 6]!,
    mB0 = sb[oB + 5]!,
    iB0 = sb[oB + 6]!;
  // The linear spring's reference: half the trace of its 2 x 2 block of A, which no rotation changes,
  // so the spring has a potential (k |separation|^2 / 2 with k = omega^2 / aRef) and cannot do work
  // around a closed path; the block itself turns with the anchors. impulseScale / massScale = 1 / a.
  const aRef = mA0 + mB0 + 0.5 * (iA0 * (rAx * rAx + rAy * rAy) + iB0 * (rBx * rBx + rBy * rBy));
  const gL = (aRef * rows[o + JI]!) / msL,
    gA = ((iA0 + iB0) * rows[o + AI]!) / msA;
  const mA = mA0,
    iA = iA0,
    mB = mB0,
    iB = iB0;
  const vAx = sb[oA]!,
    vAy = sb[oA + 1]!,
    wA = sb[oA + 2]!,
    vBx = sb[oB]!,
    vBy = sb[oB + 1]!,
    wB = sb[oB + 2]!;
  // A = J M^-1 J^T for the rows (x, y, angle); Box2D v2's weld matrix.
  const a11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB,
    a12 = -rAy * rAx * iA - rBy * rBx * iB,
    a22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB,
    a13 = -rAy * iA - rBy * iB,
    a23 = rAx * iA + rBx * iB,
    a33 = iA + iB;
  const lx = rows[o + ILX]!,
    ly = rows[o + ILY]!,
    lt = rows[o + IANG]!;
  const m11 = a11 + gL,
    m12 = a12,
    m22 = a22 + gL,
    m33 = a33 + gA;
  const bL = rows[o + JB]!,
    bA = rows[o + AB]!;
  const r1 = -(vBx - wB * rBy - vAx + wA * rAy + bL * dx + gL * lx),
    r2 = -(vBy + wB * rBx - vAy - wA * rAx + bL * dy + gL * ly),
    r3 = -(wB - wA + bA * relAngle + gA * lt);
  // Cramer's rule on the symmetric 3 x 3 (m11 m12 a13; m12 m22 a23; a13 a23 m33).
  const c11 = m22 * m33 - a23 * a23,
    c12 = a13 * a23 - m12 * m33,
    c13 = m12 * a23 - m22 * a13;
  const det = m11 * c11 + m12 * c12 + a13 * c13;
  if (!(det > 0) || !Number.isFinite(det)) return false;
  const c22 = m11 * m33 - a13 * a13,
    c23 = m12 * a13 - m11 * a23,
    c33 = m11 * m22 - m12 * m12;
  const inv = 1 / det;
  const ix = inv * (c11 * r1 + c12 * r2 + c13 * r3),
    iy = inv * (c12 * r1 + c22 * r2 + c23 * r3),
    it = inv * (c13 * r1 + c23 * r2 + c33 * r3);
  if (!(Number.isFinite(ix) && Number.isFinite(iy) && Number.isFinite(it))) return false;
  rows[o + ILX] = lx + ix;
  rows[o + ILY] = ly + iy;
  rows[o + IANG] = lt + it;
  sb[oA] = vAx - mA * ix;
  sb[oA + 1] = vAy - mA * iy;
  sb[oA + 2] = wA - iA * (rAx * iy - rAy * ix + it);
  sb[oB] = vBx + mB * ix;
  sb[oB + 1] = vBy + mB * iy;
  sb[oB + 2] = wB + iB * (rBx * iy - rBy * ix + it);
  // The joint pushes its bodies (the contact solver's `pushed` slot: they are not in free flight).
  sb[oA + 7] = 1;
  sb[oB + 7] = 1;
  return true;
}

/** One pass over every joint row (see solveJoints). */
function solveJointRows(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const js = world.joints;
  const n = js.rowCount;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    rows = js.rows,
    ri = js.rowInts;
  const invH = 1 / hs;
  solvePointLinks(world, invH, useBias);
  solvePins(world, useBias);
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + IA]!,
      ib = ri[q + IB]!,
      tf = ri[q + TF]!;
    const type = tf & 255,
      flags = tf >> 8;
    if (type === POINT_LINK || type === PIN) continue;
    const oA = ia * 8,
      oB = ib * 8;
    const mA = sb[oA + 5]!,
      iA = sb[oA + 6]!,
      mB = sb[oB + 5]!,
      iB = sb[oB + 6]!;
    let vAx = sb[oA]!,
      vAy = sb[oA + 1]!,
      wA = sb[oA + 2]!,
      vBx = sb[oB]!,
      vBy = sb[oB + 1]!,
      wB = sb[oB + 2]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * rows[o + RAX]! - sA * rows[o + RAY]!,
      rAy = sA * rows[o + RAX]! + cA * rows[o + RAY]!;
    const rBx = cB * rows[o + RBX]! - sB * rows[o + RBY]!,
      rBy = sB * rows[o + RBX]! + cB * rows[o + RBY]!;
    // Current separation of the anchors, B minus A.
    const dx = sb[oB + 3]! - sb[oA + 3]! + rows[o + DCX]! + rBx - rAx;
    const dy = sb[oB + 4]! - sb[oA + 4]! + rows[o + DCY]! + rBy - rAy;

    if (type === JointType.Distance) {
      const L = Math.sqrt(dx * dx + dy * dy);
      if (L < 1e-12) continue;
      const ux = dx / L,
        uy = dy / L;
      const crA = rAx * uy - rAy * ux,
        crB = rBx * uy - rBy * ux;
      const k = rows[o + KAX]!;
      const minL = rows[o + MINL]!,
        maxL = rows[o + MAXL]!;
      let total = 0;
      // Relative velocity of the anchors along u.
      let vr = (vBx - wB * rBy - vAx + wA * rAy) * ux + (vBy + wB * rBx - vAy - wA * rAx) * uy;
      if (minL < maxL) {
        if (flags & JointFlag.Spring) {
          const C = L - rows[o + LEN]!;
          const impulse = springImpulse(vr, C, mA + mB + iA * crA * crA + iB * crB * crB, rows[o + ISPR]!, rows[o + SB]!, rows[o + SM]!);
          rows[o + ISPR] = rows[o + ISPR]! + impulse;
          total += impulse;
          vr += impulse * (mA + mB + iA * crA * crA + iB * crB * crB);
        }
        if (minL > 0) {
          const C = L - minL;
          let bias = 0,
            ms = 1,
            is = 0;
          if (C > 0) bias = C * invH;
          else if (useBias) {
            bias = rows[o + JB]! * C;
            ms = rows[o + JM]!;
            is = rows[o + JI]!;
          }
          const old = rows[o + ILOW]!;
          let next = old - ms * k * (vr + bias) - is * old;
          if (next < 0) next = 0;
          const impulse = next - old;
          rows[o + ILOW] = next;
          total += impulse;
          vr += impulse * (mA + mB + iA * crA * crA + iB * crB * crB);
        }
        if (maxL < Infinity) {
          const C = maxL - L;
          let bias = 0,
            ms = 1,
            is = 0;
          if (C > 0) bias = C * invH;
          else if (useBias) {
            bias = rows[o + JB]! * C;
            ms = rows[o + JM]!;
            is = rows[o + JI]!;
          }
          const old = rows[o + IUP]!;
          let next = old - ms * k * (-vr + bias) - is * old;
          if (next < 0) next = 0;
          const impulse = next - old;
          rows[o + IUP] = next;
          total -= impulse;
        }
      } else {
        const C = L - rows[o + LEN]!;
        let bias = 0,
          ms = 1,
          is = 0;
        if (useBias) {
          bias = rows[o + JB]! * C;
          ms = rows[o + JM]!;
          is = rows[o + JI]!;
        }
        const impulse = -ms * k * (vr + bias) - is * rows[o + ISPR]!;
        rows[o + ISPR] = rows[o + ISPR]! + impulse;
        total = impulse;
      }
      const Px = total * ux,
        Py = total * uy;
      sb[oA] = vAx - mA * Px;
      sb[oA + 1] = vAy - mA * Py;
      sb[oA + 2] = wA - iA * (rAx * Py - rAy * Px);
      sb[oB] = vBx + mB * Px;
      sb[oB + 1] = vBy + mB * Py;
      sb[oB + 2] = wB + iB * (rBx * Py - rBy * Px);
      // A taut (or sprung) link pushes its bodies; a slack rope leaves them in free flight.
      if (rows[o + ISPR] !== 0 || rows[o + ILOW] !== 0 || rows[o + IUP] !== 0) {
        sb[oA + 7] = 1;
        sb[oB + 7] = 1;
      }
      continue;
    }

    const fixedRotation = iA + iB === 0;
    // Relative angle since the joint was made, minus the reference.
    const relAngle = rows[o + DANG]! + rot[ib * 3 + 2]! - rot[ia * 3 + 2]!;

    if (type === JointType.Weld && flags & WELD_ANGULAR_SOFT && flags & JointFlag.Spring && !fixedRotation) {
      // Both parts soft: the three rows solved together (solveSoftWeld), in both passes.
      if (solveSoftWeld(rows, o, sb, oA, oB, rAx, rAy, rBx, rBy, dx, dy, relAngle)) continue;
    }
    if (type === JointType.Revolute || type === JointType.Weld) {
      const kax = rows[o + KAX]!;
      if (type === JointType.Revolute && !fixedRotation) {
        if (flags & JointFlag.Spring) {
          const impulse = -rows[o + SM]! * kax * (wB - wA + rows[o + SB]! * relAngle) - rows[o + SI]! * rows[o + ISPR]!;
          rows[o + ISPR] = rows[o + ISPR]! + impulse;
          wA -= iA * impulse;
          wB += iB * impulse;
        }
        if (flags & JointFlag.Motor) {
          const max = rows[o + MMAX]!;
          const old = rows[o + IMOT]!;
          let next = old - kax * (wB - wA - rows[o + MSPD]!);
          next = next < -max ? -max : next > max ? max : next;
          rows[o + IMOT] = next;
          wA -= iA * (next - old);
          wB += iB * (next - old);
        }
        if (flags & JointFlag.Limit) {
          const angle = unwind(relAngle);
          {
            const C = angle - rows[o + LOW]!;
            let bias = 0,
              ms = 1,
              is = 0;
            if (C > 0) bias = C * invH;
            else if (useBias) {
              bias = rows[o + JB]! * C;
              ms = rows[o + JM]!;
              is = rows[o + JI]!;
            }
            const old = rows[o + ILOW]!;
            let next = old - ms * kax * (wB - wA + bias) - is * old;
            if (next < 0) next = 0;
            rows[o + ILOW] = next;
            wA -= iA * (next - old);
            wB += iB * (next - old);
          }
          {
            const C = rows[o + UP]! - angle;
            let bias = 0,
              ms = 1,
              is = 0;
            if (C > 0) bias = C * invH;
            else if (useBias) {
              bias = rows[o + JB]! * C;
              ms = rows[o + JM]!;
              is = rows[o + JI]!;
            }
            const old = rows[o + IUP]!;
            let next = old - ms * kax * (wA - wB + bias) - is * old;
            if (next < 0) next = 0;
            rows[o + IUP] = next;
            wA += iA * (next - old);
            wB -= iB * (next - old);
          }
        }
      } else if (type === JointType.Weld) {
        let bias = 0,
          ms = 1,
          is = 0;
        if (useBias || flags & WELD_ANGULAR_SOFT) {
          bias = rows[o + AB]! * relAngle;
          ms = rows[o + AM]!;
          is = rows[o + AI]!;
        }
        const impulse = -ms * kax * (wB - wA + bias) - is * rows[o + IANG]!;
        rows[o + IANG] = rows[o + IANG]! + impulse;
        wA -= iA * impulse;
        wB += iB * impulse;
      }
      // Point-to-point: the anchors coincide (2 x 2 block).
      const cdx = vBx - wB * rBy - vAx + wA * rAy,
        cdy = vBy + wB * rBx - vAy - wA * rAx;
      let bx = 0,
        by = 0,
        ms = 1,
        is = 0;
      if (useBias || (type === JointType.Weld && flags & JointFlag.Spring)) {
        bx = rows[o + JB]! * dx;
        by = rows[o + JB]! * dy;
        ms = rows[o + JM]!;
        is = rows[o + JI]!;
      }
      const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
      const k12 = -rAy * rAx * iA - rBy * rBx * iB;
      const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
      let det = k11 * k22 - k12 * k12;
      if (det !== 0) det = 1 / det;
      const ex = cdx + bx,
        ey = cdy + by;
      const sx = det * (k22 * ex - k12 * ey),
        sy = det * (k11 * ey - k12 * ex);
      const ix = -ms * sx - is * rows[o + ILX]!,
        iy = -ms * sy - is * rows[o + ILY]!;
      rows[o + ILX] = rows[o + ILX]! + ix;
      rows[o + ILY] = rows[o + ILY]! + iy;
      vAx -= mA * ix;
      vAy -= mA * iy;
      wA -= iA * (rAx * iy - rAy * ix);
      vBx += mB * ix;
      vBy += mB * iy;
      wB += iB * (rBx * iy - rBy * ix);
    } else if (type === JointType.Prismatic || type === JointType.Wheel) {
      const axx = cA * rows[o + AXX]! - sA * rows[o + AXY]!,
        axy = sA * rows[o + AXX]! + cA * rows[o + AXY]!;
      const translation = axx * dx + axy * dy;
      const a1 = (dx + rAx) * axy - (dy + rAy) * axx,
        a2 = rBx * axy - rBy * axx;
      const kax = rows[o + KAX]!;
      const kA = iA * a1,
        kB = iB * a2;
      // Axial impulses: P = lambda axis on B (minus on A), angular lambda a1 on A and lambda a2 on B.
      if (type === JointType.Wheel && flags & JointFlag.Motor && !fixedRotation) {
        const max = rows[o + MMAX]!;
        const old = rows[o + IMOT]!;
        let next = old - rows[o + KMOT]! * (wB - wA - rows[o + MSPD]!);
        next = next < -max ? -max : next > max ? max : next;
        rows[o + IMOT] = next;
        wA -= iA * (next - old);
        wB += iB * (next - old);
      }
      if (flags & JointFlag.Spring) {
        const cdot = axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA;
        const impulse = springImpulse(cdot, translation, mA + mB + kA * a1 + kB * a2, rows[o + ISPR]!, rows[o + SB]!, rows[o + SM]!);
        rows[o + ISPR] = rows[o + ISPR]! + impulse;
        vAx -= mA * impulse * axx;
        vAy -= mA * impulse * axy;
        wA -= kA * impulse;
        vBx += mB * impulse * axx;
        vBy += mB * impulse * axy;
        wB += kB * impulse;
      }
      if (type === JointType.Prismatic && flags & JointFlag.Motor) {
        const cdot = axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA;
        const max = rows[o + MMAX]!;
        const old = rows[o + IMOT]!;
        let next = old + kax * (rows[o + MSPD]! - cdot);
        next = next < -max ? -max : next > max ? max : next;
        rows[o + IMOT] = next;
        const impulse = next - old;
        vAx -= mA * impulse * axx;
        vAy -= mA * impulse * axy;
        wA -= kA * impulse;
        vBx += mB * impulse * axx;
        vBy += mB * impulse * axy;
        wB += kB * impulse;
      }
      if (flags & JointFlag.Limit) {
        for (let side = 0; side < 2; side++) {
          // Lower: C = translation - lower >= 0. Upper (signs flipped): C = upper - translation >= 0.
          const sign = side === 0 ? 1 : -1;
          const C = side === 0 ? translation - rows[o + LOW]! : rows[o + UP]! - translation;
          let bias = 0,
            ms = 1,
            is = 0;
          if (C > 0) bias = C * invH;
          else if (useBias) {
            bias = rows[o + JB]! * C;
            ms = rows[o + JM]!;
            is = rows[o + JI]!;
          }
          const cdot = sign * (axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA);
          const slot = side === 0 ? ILOW : IUP;
          const old = rows[o + slot]!;
          let next = old - ms * kax * (cdot + bias) - is * old;
          if (next < 0) next = 0;
          rows[o + slot] = next;
          const impulse = sign * (next - old);
          vAx -= mA * impulse * axx;
          vAy -= mA * impulse * axy;
          wA -= kA * impulse;
          vBx += mB * impulse * axx;
          vBy += mB * impulse * axy;
          wB += kB * impulse;
        }
      }
      // Perpendicular to the axis (and, for prismatic, the relative angle).
      const pxx = -axy,
        pxy = axx;
      const s1 = (dx + rAx) * pxy - (dy + rAy) * pxx,
        s2 = rBx * pxy - rBy * pxx;
      const cd1 = pxx * (vBx - vAx) + pxy * (vBy - vAy) + s2 * wB - s1 * wA;
      let ms = 1,
        is = 0,
        b1 = 0,
        b2 = 0;
      if (useBias) {
        ms = rows[o + JM]!;
        is = rows[o + JI]!;
        b1 = rows[o + JB]! * (pxx * dx + pxy * dy);
        b2 = rows[o + JB]! * relAngle;
      }
      const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      if (type === JointType.Prismatic) {
        const k12 = iA * s1 + iB * s2;
        let k22 = iA + iB;
        if (k22 === 0) k22 = 1;
        let det = k11 * k22 - k12 * k12;
        if (det !== 0) det = 1 / det;
        const e1 = cd1 + b1,
          e2 = wB - wA + b2;
        const x1 = det * (k22 * e1 - k12 * e2),
          x2 = det * (k11 * e2 - k12 * e1);
        const i1 = -ms * x1 - is * rows[o + ILX]!,
          i2 = -ms * x2 - is * rows[o + IANG]!;
        rows[o + ILX] = rows[o + ILX]! + i1;
        rows[o + IANG] = rows[o + IANG]! + i2;
        const Px = i1 * pxx,
          Py = i1 * pxy;
        vAx -= mA * Px;
        vAy -= mA * Py;
        wA -= iA * (i1 * s1 + i2);
        vBx += mB * Px;
        vBy += mB * Py;
        wB += iB * (i1 * s2 + i2);
      } else {
        const mass = k11 > 0 ? 1 / k11 : 0;
        const i1 = -ms * mass * (cd1 + b1) - is * rows[o + ILX]!;
        rows[o + ILX] = rows[o + ILX]! + i1;
        const Px = i1 * pxx,
          Py = i1 * pxy;
        vAx -= mA * Px;
        vAy -= mA * Py;
        wA -= iA * i1 * s1;
        vBx += mB * Px;
        vBy += mB * Py;
        wB += iB * i1 * s2;
      }
    } else if (type === JointType.Mouse) {
      // Damp B's spin softly, then pull its anchor toward the target with at most maxForce.
      const kax = rows[o + KAX]!;
      {
        const impulse = -rows[o + AM]! * kax * wB - rows[o + AI]! * rows[o + IANG]!;
        rows[o + IANG] = rows[o + IANG]! + impulse;
        wB += iB * impulse;
      }
      const cdx = vBx - wB * rBy,
        cdy = vBy + wB * rBx;
      const bx = rows[o + SB]! * dx,
        by = rows[o + SB]! * dy,
        ms = rows[o + SM]!,
        is = rows[o + SI]!;
      const k11 = mB + rBy * rBy * iB,
        k12 = -rBy * rBx * iB,
        k22 = mB + rBx * rBx * iB;
      let det = k11 * k22 - k12 * k12;
      if (det !== 0) det = 1 / det;
      const ex = cdx + bx,
        ey = cdy + by;
      const sx = det * (k22 * ex - k12 * ey),
        sy = det * (k11 * ey - k12 * ex);
      const oldX = rows[o + ILX]!,
        oldY = rows[o + ILY]!;
      let nx = oldX - ms * sx - is * oldX,
        ny = oldY - ms * sy - is * oldY;
      const max = rows[o + FMAX]!;
      const mag2 = nx * nx + ny * ny;
      if (mag2 > max * max) {
        const s = max / Math.sqrt(mag2);
        nx *= s;
        ny *= s;
      }
      rows[o + ILX] = nx;
      rows[o + ILY] = ny;
      const ix = nx - oldX,
        iy = ny - oldY;
      vBx += mB * ix;
      vBy += mB * iy;
      wB += iB * (rBx * iy - rBy * ix);
    }
    sb[oA] = vAx;
    sb[oA + 1] = vAy;
    sb[oA + 2] = wA;
    sb[oB] = vBx;
    sb[oB + 1] = vBy;
    sb[oB + 2] = wB;
    // The joint pushes its bodies (the contact solver's `pushed` slot: they are not in free flight).
    sb[oA + 7] = 1;
    sb[oB + 7] = 1;
  }
  // The static world's row must stay at rest whatever a fixed body's joint wrote into it.
  sb[0] = 0;
  sb[1] = 0;
  sb[2] = 0;
}
