import {
  BS2_DX,
  BS2_DY,
  BS2_INV_INERTIA,
  BS2_INV_MASS,
  BS2_PUSHED,
  BS2_STRIDE,
  BS2_VX,
  BS2_VY,
  BS2_W,
} from '../solver/body-state-layout.js';
import { LINK_FLOATS, LINK_INTS, PIN_FLOATS, PIN_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';

/** The 2D joints' fast rows: pins (revolute joints with no spring, motor or limit) and point links (rigid distance joints between centres), solved as packed point constraints. */

/**
 * The pins' pass: the revolute joint's point-to-point block (2 x 2 effective mass from the current
 * anchors), soft while `useBias` (Box2D's joint softness), exactly as the general loop solves it.
 */
export function solvePins(world: PhysicsWorld, useBias: boolean): void {
  const js = world.joints;
  const m = js.pinCount;
  if (m === 0) return;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    pf = js.pins,
    pint = js.pinInts;
  const jb = useBias ? js.softness[0]! : 0,
    jm = useBias ? js.softness[1]! : 1,
    ji = useBias ? js.softness[2]! : 0;
  for (let l = 0; l < m; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const ia = pint[i]!,
      ib = pint[i + 1]!,
      oA = ia * BS2_STRIDE,
      oB = ib * BS2_STRIDE;
    const mA = sb[oA + BS2_INV_MASS]!,
      iA = sb[oA + BS2_INV_INERTIA]!,
      mB = sb[oB + BS2_INV_MASS]!,
      iB = sb[oB + BS2_INV_INERTIA]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f]! - sA * pf[f + 1]!,
      rAy = sA * pf[f]! + cA * pf[f + 1]!;
    const rBx = cB * pf[f + 2]! - sB * pf[f + 3]!,
      rBy = sB * pf[f + 2]! + cB * pf[f + 3]!;
    let vAx = sb[oA + BS2_VX]!,
      vAy = sb[oA + BS2_VY]!,
      wA = sb[oA + BS2_W]!,
      vBx = sb[oB + BS2_VX]!,
      vBy = sb[oB + BS2_VY]!,
      wB = sb[oB + BS2_W]!;
    const cdx = vBx - wB * rBy - vAx + wA * rAy,
      cdy = vBy + wB * rBx - vAy - wA * rAx;
    let bx = 0,
      by = 0;
    if (useBias) {
      bx = jb * (sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + pf[f + 4]! + rBx - rAx);
      by = jb * (sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + pf[f + 5]! + rBy - rAy);
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
    const ix = -jm * sx - ji * pf[f + 6]!,
      iy = -jm * sy - ji * pf[f + 7]!;
    pf[f + 6] = pf[f + 6]! + ix;
    pf[f + 7] = pf[f + 7]! + iy;
    vAx -= mA * ix;
    vAy -= mA * iy;
    wA -= iA * (rAx * iy - rAy * ix);
    vBx += mB * ix;
    vBy += mB * iy;
    wB += iB * (rBx * iy - rBy * ix);
    sb[oA + BS2_VX] = vAx;
    sb[oA + BS2_VY] = vAy;
    sb[oA + BS2_W] = wA;
    sb[oA + BS2_PUSHED] = 1;
    sb[oB + BS2_VX] = vBx;
    sb[oB + BS2_VY] = vBy;
    sb[oB + BS2_W] = wB;
    sb[oB + BS2_PUSHED] = 1;
  }
}

/**
 * The point links' pass: the distance joint's rod (soft while `useBias`, Box2D's joint softness) or
 * rope (pulls only, speculative while slack), with the anchors' offset fixed within the step.
 */
export function solvePointLinks(world: PhysicsWorld, invH: number, useBias: boolean): void {
  const js = world.joints;
  const m = js.linkCount;
  if (m === 0) return;
  const sb = world.collision.bodyState,
    lf = js.links,
    lint = js.linkInts;
  // The rigid joint softness of this step (the same for every row; see prepareJoints).
  const jb = useBias ? js.softness[0]! : 0,
    jm = useBias ? js.softness[1]! : 1,
    ji = useBias ? js.softness[2]! : 0;
  for (let l = 0; l < m; l++) {
    const f = l * LINK_FLOATS,
      i = l * LINK_INTS;
    const oA = lint[i]!,
      oB = lint[i + 1]!;
    const dx = sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + lf[f]!,
      dy = sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + lf[f + 1]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const ux = dx / L,
      uy = dy / L;
    const vAx = sb[oA + BS2_VX]!,
      vAy = sb[oA + BS2_VY]!,
      vBx = sb[oB + BS2_VX]!,
      vBy = sb[oB + BS2_VY]!;
    const vr = (vBx - vAx) * ux + (vBy - vAy) * uy;
    const C = L - lf[f + 3]!;
    const acc = lf[f + 4]!;
    let impulse: number;
    if (lf[f + 5] === 0) {
      impulse = -jm * lf[f + 2]! * (vr + jb * C) - ji * acc;
      lf[f + 4] = acc + impulse;
    } else {
      // Rope: C = maxLength - L >= 0; the accumulated impulse (stored negated: pulling) <= 0.
      let bias = 0,
        ms = 1,
        is = 0;
      if (C < 0) bias = -C * invH;
      else if (useBias) {
        bias = -jb * C;
        ms = jm;
        is = ji;
      }
      const old = -acc;
      let next = old - ms * lf[f + 2]! * (-vr + bias) - is * old;
      if (next < 0) next = 0;
      lf[f + 4] = -next;
      impulse = old - next;
    }
    const Px = impulse * ux,
      Py = impulse * uy,
      mA = sb[oA + BS2_INV_MASS]!,
      mB = sb[oB + BS2_INV_MASS]!;
    sb[oA + BS2_VX] = vAx - mA * Px;
    sb[oA + BS2_VY] = vAy - mA * Py;
    sb[oB + BS2_VX] = vBx + mB * Px;
    sb[oB + BS2_VY] = vBy + mB * Py;
    if (lf[f + 4] !== 0) {
      sb[oA + BS2_PUSHED] = 1;
      sb[oB + BS2_PUSHED] = 1;
    }
  }
}
