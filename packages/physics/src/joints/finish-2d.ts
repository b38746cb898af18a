import { BS2_DX, BS2_DY, BS2_STRIDE } from '../solver/body-state-layout.js';
import { currentHandle } from '../world/handles.js';
import { pushBreak } from '../world/joint-state-2d.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import { IMPULSES, ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { finishPointLinks } from './distance-joint.js';
import * as R from './layout-2d.js';
import { removeJointUnchecked } from './remove.js';
import { finishPins } from './revolute-joint.js';

/** The end of a step's 2D joint solve (stage 4 of joints/solver-2d.ts): forces and torques, the largest position error, impulses kept for warm starting, and joints past their break threshold removed. */

/**
 * After the bodies are written back: each joint's constraint force and torque (accumulated impulse
 * of the last substep / h_s), the largest position error left, the impulses kept for the next step's
 * warm start, and breaking: a joint whose force exceeds `breakForce`, torque `breakTorque` or strain
 * `breakStretch` is removed and reported in `world.joints.breaks`.
 * @category Joints and ropes
 */
export function finishJoints(world: PhysicsWorld, hs: number): void {
  const js = world.joints;
  const n = js.rowCount;
  js.stats.maxError = 0;
  js.stats.maxErrorJoint = 0;
  if (n === 0) return;
  const J = world.components.Joint;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    rows = js.rows,
    ri = js.rowInts,
    imp = js.impulses;
  const invH = 1 / hs;
  let maxError = 0,
    maxJoint = 0;
  let doomed: number[] | null = null;
  finishPointLinks(js);
  finishPins(js);
  for (let r = 0; r < n; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const j = ri[q + R.EID]!,
      ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!,
      tf = ri[q + R.TF]!;
    const type = tf === R.POINT_LINK ? JointType.Distance : tf === R.PIN ? JointType.Revolute : tf & 255,
      flags = tf >> 8;
    const oA = ia * BS2_STRIDE,
      oB = ib * BS2_STRIDE;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * rows[o + R.RAX]! - sA * rows[o + R.RAY]!,
      rAy = sA * rows[o + R.RAX]! + cA * rows[o + R.RAY]!;
    const rBx = cB * rows[o + R.RBX]! - sB * rows[o + R.RBY]!,
      rBy = sB * rows[o + R.RBX]! + cB * rows[o + R.RBY]!;
    const dx = sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + rows[o + R.DCX]! + rBx - rAx;
    const dy = sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + rows[o + R.DCY]! + rBy - rAy;
    let force = 0,
      torque = 0,
      error = 0,
      stretch = 0;
    switch (type) {
      case JointType.Distance: {
        const L = Math.sqrt(dx * dx + dy * dy);
        force = Math.abs(rows[o + R.ISPR]! + rows[o + R.ILOW]! - rows[o + R.IUP]!) * invH;
        const minL = rows[o + R.MINL]!,
          maxL = rows[o + R.MAXL]!,
          rest = rows[o + R.LEN]!;
        if (minL < maxL) error = Math.max(0, minL - L, L - maxL);
        else error = Math.abs(L - rest);
        stretch = rest > 0 ? (L - rest) / rest : 0;
        break;
      }
      case JointType.Revolute:
        force = Math.sqrt(rows[o + R.ILX]! * rows[o + R.ILX]! + rows[o + R.ILY]! * rows[o + R.ILY]!) * invH;
        torque = Math.abs(rows[o + R.ISPR]! + rows[o + R.IMOT]! + rows[o + R.ILOW]! - rows[o + R.IUP]!) * invH;
        error = Math.sqrt(dx * dx + dy * dy);
        break;
      case JointType.Weld:
        force = Math.sqrt(rows[o + R.ILX]! * rows[o + R.ILX]! + rows[o + R.ILY]! * rows[o + R.ILY]!) * invH;
        torque = Math.abs(rows[o + R.IANG]!) * invH;
        if (!(flags & JointFlag.Spring)) error = Math.sqrt(dx * dx + dy * dy);
        break;
      case JointType.Prismatic:
      case JointType.Wheel: {
        const axx = cA * rows[o + R.AXX]! - sA * rows[o + R.AXY]!,
          axy = sA * rows[o + R.AXX]! + cA * rows[o + R.AXY]!;
        const axial = rows[o + R.ISPR]! + rows[o + R.ILOW]! - rows[o + R.IUP]! + (type === JointType.Prismatic ? rows[o + R.IMOT]! : 0);
        force = Math.hypot(axial, rows[o + R.ILX]!) * invH;
        torque = Math.abs(type === JointType.Prismatic ? rows[o + R.IANG]! : rows[o + R.IMOT]!) * invH;
        error = Math.abs(-axy * dx + axx * dy);
        break;
      }
      case JointType.Mouse:
        force = Math.sqrt(rows[o + R.ILX]! * rows[o + R.ILX]! + rows[o + R.ILY]! * rows[o + R.ILY]!) * invH;
        torque = Math.abs(rows[o + R.IANG]!) * invH;
        break;
    }
    J.force[j] = force;
    J.torque[j] = torque;
    if (error > maxError) {
      maxError = error;
      maxJoint = j;
    }
    const base = j * IMPULSES;
    for (let s = 0; s < IMPULSES; s++) imp[base + s] = rows[o + R.ILX + s]!;
    if (force > J.breakForce[j]! || torque > J.breakTorque[j]! || stretch > J.breakStretch[j]!) {
      (doomed ??= []).push(j);
      const a = J.a[j]!;
      pushBreak(
        js.breaks,
        currentHandle(world, j),
        a === 0 ? 0 : currentHandle(world, a),
        currentHandle(world, J.b[j]!),
        force,
        torque,
        stretch,
      );
    }
  }
  js.stats.maxError = maxError;
  js.stats.maxErrorJoint = maxJoint;
  if (doomed) for (const j of doomed) removeJointUnchecked(world, j);
}
