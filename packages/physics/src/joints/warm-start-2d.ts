import { BS2_DX, BS2_DY, BS2_INV_INERTIA, BS2_INV_MASS, BS2_STRIDE, BS2_VX, BS2_VY, BS2_W } from '../solver/body-state-layout.js';
import { JointType } from '../world/joint-store-2d.js';
import { ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { warmStartPointLinks } from './distance-joint.js';
import { AXX, AXY, DCX, DCY, IA, IANG, IB, ILOW, ILX, ILY, IMOT, ISPR, IUP, PIN, POINT_LINK, RAX, RAY, RBX, RBY, TF } from './layout-2d.js';
import { warmStartPins } from './revolute-joint.js';

/** Per substep, 2D joints (stage 3 of joints/solver-2d.ts): the joints' rotations integrated after the positions move, and last step's impulses applied again (warm start) before the solve. */

/**
 * Advances each solver body's rotation since the start of the step by w h_s (once per substep, after
 * the positions move): the angle exactly, its cos and sin as a normalised first-order update of the
 * unit complex number (Box2D v3 b2IntegrateRotation).
 * @category Joints and ropes
 */
export function integrateJointRotations(world: PhysicsWorld, hs: number): void {
  if (world.joints.rowCount === 0) return;
  const cs = world.collision;
  const sb = cs.bodyState,
    rot = world.joints.rotation;
  for (let k = 1, n = cs.solverBodyCount; k < n; k++) {
    const o = k * BS2_STRIDE;
    if (sb[o + BS2_INV_INERTIA]! === 0) continue;
    const w = sb[o + BS2_W]! * hs;
    if (w === 0) continue;
    const r = k * 3;
    const c0 = rot[r]!,
      s0 = rot[r + 1]!;
    const c1 = c0 - w * s0,
      s1 = s0 + w * c0;
    const inv = 1 / Math.sqrt(c1 * c1 + s1 * s1);
    rot[r] = c1 * inv;
    rot[r + 1] = s1 * inv;
    rot[r + 2] = rot[r + 2]! + w;
  }
}

/**
 * Applies every joint's accumulated impulses to its bodies (warm start, once per substep, before the contacts').
 * @category Joints and ropes
 */
export function warmStartJoints(world: PhysicsWorld): void {
  const js = world.joints;
  const n = js.rowCount;
  if (n === 0) return;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    rows = js.rows,
    ri = js.rowInts;
  warmStartPointLinks(world);
  warmStartPins(world);
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + IA]!,
      ib = ri[q + IB]!,
      type = ri[q + TF]! & 255;
    if (type === POINT_LINK || type === PIN) continue;
    const oA = ia * BS2_STRIDE,
      oB = ib * BS2_STRIDE;
    const mA = sb[oA + BS2_INV_MASS]!,
      iA = sb[oA + BS2_INV_INERTIA]!,
      mB = sb[oB + BS2_INV_MASS]!,
      iB = sb[oB + BS2_INV_INERTIA]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * rows[o + RAX]! - sA * rows[o + RAY]!,
      rAy = sA * rows[o + RAX]! + cA * rows[o + RAY]!;
    const rBx = cB * rows[o + RBX]! - sB * rows[o + RBY]!,
      rBy = sB * rows[o + RBX]! + cB * rows[o + RBY]!;
    let Px = 0,
      Py = 0,
      LA = 0,
      LB = 0;
    switch (type) {
      case JointType.Distance: {
        const axial = rows[o + ISPR]! + rows[o + ILOW]! - rows[o + IUP]!;
        if (axial === 0) continue;
        const dx = sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + rows[o + DCX]! + rBx - rAx,
          dy = sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + rows[o + DCY]! + rBy - rAy;
        const L = Math.sqrt(dx * dx + dy * dy);
        if (L < 1e-12) continue;
        Px = (axial * dx) / L;
        Py = (axial * dy) / L;
        LA = rAx * Py - rAy * Px;
        LB = rBx * Py - rBy * Px;
        break;
      }
      case JointType.Revolute:
      case JointType.Weld:
      case JointType.Mouse: {
        Px = rows[o + ILX]!;
        Py = rows[o + ILY]!;
        const axial = type === JointType.Revolute ? rows[o + ISPR]! + rows[o + IMOT]! + rows[o + ILOW]! - rows[o + IUP]! : rows[o + IANG]!;
        LA = rAx * Py - rAy * Px + axial;
        LB = rBx * Py - rBy * Px + axial;
        break;
      }
      case JointType.Prismatic:
      case JointType.Wheel: {
        const dx = sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + rows[o + DCX]! + rBx - rAx,
          dy = sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + rows[o + DCY]! + rBy - rAy;
        const axx = cA * rows[o + AXX]! - sA * rows[o + AXY]!,
          axy = sA * rows[o + AXX]! + cA * rows[o + AXY]!;
        const px = -axy,
          py = axx;
        const a1 = (dx + rAx) * axy - (dy + rAy) * axx,
          a2 = rBx * axy - rBy * axx;
        const s1 = (dx + rAx) * py - (dy + rAy) * px,
          s2 = rBx * py - rBy * px;
        const axial =
          type === JointType.Prismatic
            ? rows[o + ISPR]! + rows[o + IMOT]! + rows[o + ILOW]! - rows[o + IUP]!
            : rows[o + ISPR]! + rows[o + ILOW]! - rows[o + IUP]!;
        const perp = rows[o + ILX]!;
        const angular = type === JointType.Prismatic ? rows[o + IANG]! : rows[o + IMOT]!;
        Px = axial * axx + perp * px;
        Py = axial * axy + perp * py;
        LA = axial * a1 + perp * s1 + angular;
        LB = axial * a2 + perp * s2 + angular;
        break;
      }
    }
    sb[oA + BS2_VX] = sb[oA + BS2_VX]! - mA * Px;
    sb[oA + BS2_VY] = sb[oA + BS2_VY]! - mA * Py;
    sb[oA + BS2_W] = sb[oA + BS2_W]! - iA * LA;
    sb[oB + BS2_VX] = sb[oB + BS2_VX]! + mB * Px;
    sb[oB + BS2_VY] = sb[oB + BS2_VY]! + mB * Py;
    sb[oB + BS2_W] = sb[oB + BS2_W]! + iB * LB;
  }
}
