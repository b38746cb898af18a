import { BS2_INV_INERTIA, BS2_INV_MASS, BS2_STRIDE, BX_BASE_X, BX_BASE_Y, BX_ROT_Z, BX_STRIDE } from '../solver/body-state-layout.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import { IMPULSES, LINK_FLOATS, LINK_INTS, PIN_FLOATS, PIN_INTS, ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import * as R from './layout-2d.js';
import { soft, unwind } from './rows-2d.js';
import { fixedSpring } from './spring.js';

/** Preparation of the 2D joint rows at the start of a step (stage 2 of joints/solver-2d.ts): anchors, axes and centres, effective masses, spring and rigid softness, and last step's impulses. */

/** `a` if it holds `n` numbers, else a new array of at least n (twice a's length): its contents are not kept. */
function atLeast(a: Float64Array, n: number): Float64Array {
  return a.length >= n ? a : new Float64Array(Math.max(n, 2 * a.length));
}

/**
 * Fills every row from the joint components and the solver bodies (already gathered and filled by the
 * contact solver): start-of-step anchors (world frame, from each centre), centre difference, relative
 * angle, axis, effective masses, softness, and warm-start impulses. `hs` is the solver substep, s.
 * @category Joints and ropes
 */
export function prepareJoints(world: PhysicsWorld, hs: number): void {
  const js = world.joints;
  const n = js.rowCount;
  js.stats.rows = n;
  if (n === 0) return;
  const cs = world.collision;
  const c = world.components;
  const J = c.Joint;
  const sb = cs.bodyState,
    ex = cs.bodyExtra;
  const count = cs.solverBodyCount;
  js.rotation = atLeast(js.rotation, count * 3);
  const rot = js.rotation;
  for (let k = 0; k < count; k++) {
    rot[k * 3] = 1;
    rot[k * 3 + 1] = 0;
    rot[k * 3 + 2] = 0;
  }
  // Each solver body's angle at the start of the step (its angle less the rotation still owed), with
  // its cos and sin, once per body rather than once per joint.
  js.startPose = atLeast(js.startPose, count * 3);
  const pose = js.startPose,
    list = cs.solverBodies,
    angle = c.Angle.value;
  for (let k = 1; k < count; k++) {
    const t = angle[list[k]!]! + ex[k * BX_STRIDE + BX_ROT_Z]!;
    pose[k * 3] = Math.cos(t);
    pose[k * 3 + 1] = Math.sin(t);
    pose[k * 3 + 2] = t;
  }
  const rows = js.rows,
    ri = js.rowInts,
    imp = js.impulses;
  const lf = js.links,
    lint = js.linkInts,
    pf = js.pins,
    pint = js.pinInts;
  let links = 0,
    pins = 0;
  const px = c.Position.x,
    py = c.Position.y,
    ang = c.Angle.value;
  const jointHertz = Math.min(js.settings.hertz, 0.25 / hs),
    jointZeta = js.settings.dampingRatio;
  const warm = js.settings.warmStarting;
  const omega = 2 * Math.PI * jointHertz;
  const ja1 = 2 * jointZeta + hs * omega,
    ja2 = hs * omega * ja1,
    ja3 = 1 / (1 + ja2);
  const jBias = omega / ja1,
    jMass = ja2 * ja3,
    jImp = ja3;
  js.softness[0] = jBias;
  js.softness[1] = jMass;
  js.softness[2] = jImp;
  for (let r = 0; r < n; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const j = ri[q + R.EID]!,
      ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!;
    const type = ri[q + R.TF]! & 255;
    let flags = ri[q + R.TF]! >> 8;
    const a = J.a[j]!,
      b = J.b[j]!;
    const oA = ia * BS2_STRIDE,
      oB = ib * BS2_STRIDE;
    const mA = sb[oA + BS2_INV_MASS]!,
      iA = sb[oA + BS2_INV_INERTIA]!,
      mB = sb[oB + BS2_INV_MASS]!,
      iB = sb[oB + BS2_INV_INERTIA]!;
    // Start-of-step pose of A and B: solver bodies from their base and owed rotation; fixed bodies where they are.
    let cAx = 0,
      cAy = 0,
      tA = 0,
      cBx = 0,
      cBy = 0,
      tB = 0;
    let rAx: number, rAy: number;
    const lax = J.localAx[j]!,
      lay = J.localAy[j]!,
      lbx = J.localBx[j]!,
      lby = J.localBy[j]!;
    let cA = 1,
      sA = 0;
    if (ia !== 0) {
      cAx = ex[ia * BX_STRIDE + BX_BASE_X]!;
      cAy = ex[ia * BX_STRIDE + BX_BASE_Y]!;
      tA = pose[ia * 3 + 2]!;
      cA = pose[ia * 3]!;
      sA = pose[ia * 3 + 1]!;
      rAx = cA * lax - sA * lay;
      rAy = sA * lax + cA * lay;
    } else if (a !== 0) {
      tA = ang[a]!;
      cA = Math.cos(tA);
      sA = Math.sin(tA);
      rAx = px[a]! + cA * lax - sA * lay;
      rAy = py[a]! + sA * lax + cA * lay;
    } else {
      rAx = lax;
      rAy = lay;
    }
    let rBx: number, rBy: number;
    {
      let cb: number, sbn: number;
      if (ib !== 0) {
        cBx = ex[ib * BX_STRIDE + BX_BASE_X]!;
        cBy = ex[ib * BX_STRIDE + BX_BASE_Y]!;
        tB = pose[ib * 3 + 2]!;
        cb = pose[ib * 3]!;
        sbn = pose[ib * 3 + 1]!;
      } else {
        tB = ang[b]!;
        cb = Math.cos(tB);
        sbn = Math.sin(tB);
      }
      rBx = cb * lbx - sbn * lby;
      rBy = sbn * lbx + cb * lby;
      if (ib === 0) {
        rBx += px[b]!;
        rBy += py[b]!;
      }
    }
    rows[o + R.RAX] = rAx;
    rows[o + R.RAY] = rAy;
    rows[o + R.RBX] = rBx;
    rows[o + R.RBY] = rBy;
    const dcx = cBx - cAx,
      dcy = cBy - cAy;
    rows[o + R.DCX] = dcx;
    rows[o + R.DCY] = dcy;
    let dAng = tB - tA - J.referenceAngle[j]!;
    dAng = unwind(dAng);
    rows[o + R.DANG] = dAng;
    const axx = cA * J.axisX[j]! - sA * J.axisY[j]!,
      axy = sA * J.axisX[j]! + cA * J.axisY[j]!;
    rows[o + R.AXX] = axx;
    rows[o + R.AXY] = axy;
    rows[o + R.JB] = jBias;
    rows[o + R.JM] = jMass;
    rows[o + R.JI] = jImp;
    const hertz = J.hertz[j]!,
      zeta = J.dampingRatio[j]!;
    soft(rows, o + R.SB, hertz, zeta, hs);
    if (hertz > 0 && (type === JointType.Distance || type === JointType.Prismatic || type === JointType.Wheel)) {
      fixedSpring(rows, o + R.SB, hertz, zeta, hs, mA + mB + 0.5 * (iA * (lax * lax + lay * lay) + iB * (lbx * lbx + lby * lby)));
    }
    rows[o + R.LOW] = J.lower[j]!;
    rows[o + R.UP] = J.upper[j]!;
    rows[o + R.MSPD] = J.motorSpeed[j]!;
    rows[o + R.MMAX] = J.maxMotorForce[j]! * hs;
    const angularMass = iA + iB > 0 ? 1 / (iA + iB) : 0;
    const dx = dcx + rBx - rAx,
      dy = dcy + rBy - rAy;
    switch (type) {
      case JointType.Distance: {
        const L = Math.sqrt(dx * dx + dy * dy);
        const ux = L > 1e-12 ? dx / L : 1,
          uy = L > 1e-12 ? dy / L : 0;
        const crA = rAx * uy - rAy * ux,
          crB = rBx * uy - rBy * ux;
        const k = mA + mB + iA * crA * crA + iB * crB * crB;
        rows[o + R.KAX] = k > 0 ? 1 / k : 0;
        const minL = J.minLength[j]!,
          maxL = J.maxLength[j]!,
          rest = J.length[j]!;
        rows[o + R.LEN] = rest;
        rows[o + R.MINL] = minL;
        rows[o + R.MAXL] = maxL;
        // Neither body turns and no spring: a point link (anchors are fixed offsets within the step).
        if (iA === 0 && iB === 0 && !(flags & JointFlag.Spring) && (minL === maxL || (minL === 0 && maxL < Infinity))) {
          const l = links * LINK_FLOATS,
            li = links * LINK_INTS;
          lf[l] = dx;
          lf[l + 1] = dy;
          lf[l + 2] = rows[o + R.KAX]!;
          const rope = minL < maxL;
          lf[l + 3] = rope ? maxL : rest;
          lf[l + 4] = warm ? (rope ? -imp[j * IMPULSES + 6]! : imp[j * IMPULSES + 3]!) : 0;
          lf[l + 5] = rope ? 1 : 0;
          lint[li] = oA;
          lint[li + 1] = oB;
          lint[li + 2] = r;
          links++;
          ri[q + R.TF] = R.POINT_LINK;
        }
        break;
      }
      case JointType.Revolute:
        rows[o + R.KAX] = angularMass;
        if ((flags & (JointFlag.Spring | JointFlag.Motor | JointFlag.Limit)) === 0) ri[q + R.TF] = R.PIN;
        break;
      case JointType.Prismatic:
      case JointType.Wheel: {
        const a1 = (dx + rAx) * axy - (dy + rAy) * axx,
          a2 = rBx * axy - rBy * axx;
        const k = mA + mB + iA * a1 * a1 + iB * a2 * a2;
        rows[o + R.KAX] = k > 0 ? 1 / k : 0;
        rows[o + R.KMOT] = angularMass;
        break;
      }
      case JointType.Weld: {
        rows[o + R.KAX] = angularMass;
        // The linear part: its own softness if softened, else the rigid joint softness.
        if (hertz > 0) {
          rows[o + R.JB] = rows[o + R.SB]!;
          rows[o + R.JM] = rows[o + R.SM]!;
          rows[o + R.JI] = rows[o + R.SI]!;
          flags |= JointFlag.Spring;
        } else flags &= ~JointFlag.Spring;
        const ah = J.angularHertz[j]!;
        if (ah > 0) {
          soft(rows, o + R.AB, ah, J.angularDampingRatio[j]!, hs);
          flags |= R.WELD_ANGULAR_SOFT;
        } else {
          rows[o + R.AB] = jBias;
          rows[o + R.AM] = jMass;
          rows[o + R.AI] = jImp;
        }
        ri[q + R.TF] = type | (flags << 8);
        break;
      }
      case JointType.Mouse:
        rows[o + R.KAX] = iB > 0 ? 1 / iB : 0;
        rows[o + R.FMAX] = J.maxForce[j]! * hs;
        soft(rows, o + R.AB, hertz, zeta, hs);
        break;
    }
    const base = j * IMPULSES;
    for (let s = 0; s < IMPULSES; s++) rows[o + R.ILX + s] = warm ? imp[base + s]! : 0;
    if (ri[q + R.TF] === R.PIN) {
      const f = pins * PIN_FLOATS,
        i = pins * PIN_INTS;
      pf[f] = rAx;
      pf[f + 1] = rAy;
      pf[f + 2] = rBx;
      pf[f + 3] = rBy;
      pf[f + 4] = dcx;
      pf[f + 5] = dcy;
      pf[f + 6] = rows[o + R.ILX]!;
      pf[f + 7] = rows[o + R.ILY]!;
      pint[i] = ia;
      pint[i + 1] = ib;
      pint[i + 2] = r;
      pins++;
    }
  }
  js.linkCount = links;
  js.pinCount = pins;
  js.generalCount = n - links - pins;
}
