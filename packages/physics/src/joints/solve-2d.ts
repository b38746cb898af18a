import * as BS from '../solver/body-state-layout.js';
import { JointType } from '../world/joint-store-2d.js';
import { ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { solveDistanceRow, solvePointLinks } from './distance-joint.js';
import * as R from './layout-2d.js';
import { solveMouseRow } from './mouse-joint.js';
import { solvePins, solveRevoluteRow } from './revolute-joint.js';
import { solveAxisRow } from './rows-2d.js';
import { solveWeldRow } from './weld-joint.js';

/**
 * The 2D joint solve of a substep (stage 3 of joints/solver-2d.ts): the point links (distance-joint.ts)
 * and the pins (revolute-joint.ts), then every general row once, each by its type's row solve
 * (distance-joint.ts, revolute-joint.ts, weld-joint.ts, mouse-joint.ts; the prismatic and wheel joints'
 * axis rows in rows-2d.ts) on the frame of layout-2d.ts, in row order.
 */

/** The frame of the row being solved (layout-2d.ts F_*). */
const frame = new Float64Array(R.FRAME_SIZE);

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
 * One pass over every joint row (see solveJoints): each row's frame (its bodies' velocities, inverse
 * masses, anchors, separation and relative angle) filled from the packed body state, its type's row
 * solve run, and the velocities it leaves written back with the `pushed` marks.
 */
function solveJointRows(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const js = world.joints;
  const n = js.rowCount;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    rows = js.rows,
    ri = js.rowInts,
    f = frame;
  const invH = 1 / hs;
  solvePointLinks(world, invH, useBias);
  solvePins(world, useBias);
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!,
      tf = ri[q + R.TF]!;
    const type = tf & 255,
      flags = tf >> 8;
    if (type === R.POINT_LINK || type === R.PIN) continue;
    const oA = ia * BS.BS2_STRIDE,
      oB = ib * BS.BS2_STRIDE;
    f[R.F_MA] = sb[oA + BS.BS2_INV_MASS]!;
    f[R.F_IA] = sb[oA + BS.BS2_INV_INERTIA]!;
    f[R.F_MB] = sb[oB + BS.BS2_INV_MASS]!;
    f[R.F_IB] = sb[oB + BS.BS2_INV_INERTIA]!;
    f[R.F_VAX] = sb[oA + BS.BS2_VX]!;
    f[R.F_VAY] = sb[oA + BS.BS2_VY]!;
    f[R.F_WA] = sb[oA + BS.BS2_W]!;
    f[R.F_VBX] = sb[oB + BS.BS2_VX]!;
    f[R.F_VBY] = sb[oB + BS.BS2_VY]!;
    f[R.F_WB] = sb[oB + BS.BS2_W]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * rows[o + R.RAX]! - sA * rows[o + R.RAY]!,
      rAy = sA * rows[o + R.RAX]! + cA * rows[o + R.RAY]!;
    const rBx = cB * rows[o + R.RBX]! - sB * rows[o + R.RBY]!,
      rBy = sB * rows[o + R.RBX]! + cB * rows[o + R.RBY]!;
    f[R.F_RAX] = rAx;
    f[R.F_RAY] = rAy;
    f[R.F_RBX] = rBx;
    f[R.F_RBY] = rBy;
    // Current separation of the anchors, B minus A.
    f[R.F_DX] = sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + rows[o + R.DCX]! + rBx - rAx;
    f[R.F_DY] = sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + rows[o + R.DCY]! + rBy - rAy;
    f[R.F_CA] = cA;
    f[R.F_SA] = sA;
    // Relative angle since the joint was made, minus the reference.
    f[R.F_REL] = rows[o + R.DANG]! + rot[ib * 3 + 2]! - rot[ia * 3 + 2]!;
    f[R.F_INVH] = invH;
    let done = R.ROW_PUSHED;
    if (type === JointType.Distance) done = solveDistanceRow(rows, o, flags, useBias, f);
    else if (type === JointType.Revolute) done = solveRevoluteRow(rows, o, flags, useBias, f);
    else if (type === JointType.Weld) done = solveWeldRow(rows, o, flags, useBias, f);
    else if (type === JointType.Prismatic || type === JointType.Wheel)
      done = solveAxisRow(rows, o, flags, useBias, f, type === JointType.Prismatic);
    else if (type === JointType.Mouse) done = solveMouseRow(rows, o, flags, useBias, f);
    if (done === R.ROW_SKIPPED) continue;
    sb[oA + BS.BS2_VX] = f[R.F_VAX]!;
    sb[oA + BS.BS2_VY] = f[R.F_VAY]!;
    sb[oA + BS.BS2_W] = f[R.F_WA]!;
    sb[oB + BS.BS2_VX] = f[R.F_VBX]!;
    sb[oB + BS.BS2_VY] = f[R.F_VBY]!;
    sb[oB + BS.BS2_W] = f[R.F_WB]!;
    // The joint pushes its bodies (the contact solver's `pushed` slot: they are not in free flight).
    if (done === R.ROW_PUSHED) {
      sb[oA + BS.BS2_PUSHED] = 1;
      sb[oB + BS.BS2_PUSHED] = 1;
    }
  }
  // The static world's row must stay at rest whatever a fixed body's joint wrote into it.
  sb[BS.BS2_VX] = 0;
  sb[BS.BS2_VY] = 0;
  sb[BS.BS2_W] = 0;
}
