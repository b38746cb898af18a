import { rankedLists, rankedListType } from '../collision/body-class.js';
import { BodyType } from '../collision/broadphase/grid.js';
import * as BS from '../solver/body-state-layout.js';
import { atLeast } from '../solver/manifold-rows-2d.js';
import { withRoom } from '../solver/solver-bodies.js';
import { currentHandle } from '../world/handles.js';
import { ensureRows, pushBreak } from '../world/joint-state-2d.js';
import { JointType } from '../world/joint-store-2d.js';
import { IMPULSES, ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { removeJointUnchecked } from './api-2d.js';
import {
  DISTANCE_ROWS_2D,
  distanceReading,
  finishPointLinks,
  solvePointLinks,
  warmStartDistanceRow,
  warmStartPointLinks,
} from './distance-joint.js';
import * as R from './layout-2d.js';
import { MOUSE_ROWS_2D, mouseReading } from './mouse-joint.js';
import { PRISMATIC_ROWS_2D } from './prismatic-joint.js';
import { finishPins, REVOLUTE_ROWS_2D, revoluteReading, solvePins, warmStartPins } from './revolute-joint.js';
import { anchorsFrame, axisReading, type JointPass2D, separationFrame, unwind, warmStartAxis, warmStartPoint } from './rows-2d.js';
import { soft } from './softness.js';
import { WELD_ROWS_2D, weldReading } from './weld-joint.js';
import { WHEEL_ROWS_2D } from './wheel-joint.js';

/**
 * The 2D joint solver: Box2D v3's soft-step joints (Catto, "Solver2D", 2024, and "Soft Constraints",
 * GDC 2011; Box2D v3.0 distance_joint.c, revolute_joint.c, prismatic_joint.c, weld_joint.c,
 * wheel_joint.c, mouse_joint.c), solved by the contact solver (solver/contact-solver.ts) inside the same
 * substeps as the contacts, on the same packed solver bodies. Its stages run every row by its type's
 * row functions (each type's file; rows-2d.ts JointTypeRows2D), the point links' and pins' lean loops
 * (distance-joint.ts, revolute-joint.ts) first. A stage picks the type by a chain of tests rather than
 * a table, so that each call site sees one function, which the engine can inline; the warm start picks
 * the joint's shape (point, axis, distance), three calls that take no doubles (a call the engine does
 * not inline boxes its double arguments).
 *
 * 1. `gatherJointBodies` (while the contact solver gathers its bodies): every joint whose bodies are
 *    not both fixed (static, asleep or the world) gets a row; its moving bodies get solver indices;
 * 2. `prepareJoints`: anchors, axes and centres at the start of the step, spring and rigid softness,
 *    last step's impulses (warm start), then each type's effective masses;
 * 3. per substep: `warmStartJoints` (before the contacts'), `solveJoints(useBias = true)` (before the
 *    contacts' solve), `integrateJointRotations` (after the positions move), `solveJoints(useBias =
 *    false)` (the relax pass, before the contacts');
 * 4. `finishJoints` (after the bodies are written back): each joint's force and torque, the largest
 *    position error, impulses kept for the next step, and joints past their break threshold removed
 *    and reported in `world.joints.breaks`.
 *
 * Positions inside the step are tracked as in the contact solver: a body's centre is its centre at
 * the start of the step plus its solver displacement; its rotation since the start is integrated
 * here per substep (cos, sin and angle per solver body). Rigid parts of joints are soft constraints
 * of `world.joints.settings.hertz` (Box2D's joint softness) while `useBias`, and rigid (no bias) in
 * the relax pass; springs keep their own softness in both. A joint that carries an impulse marks its
 * bodies in the solver body's `pushed` slot, as contacts do: they were not in free flight.
 */

/** The frame of the row being worked on (layout-2d.ts F_*). */
const frame = new Float64Array(R.FRAME_SIZE);
/** What the row functions of a pass read, filled by each stage (rows-2d.ts JointPass2D). */
const pass: JointPass2D = { sb: frame, rot: frame, rows: frame, f: frame, useBias: false };

/** The pass over world's joint rows (its arrays as they are now), with `useBias`. */
function passOf(world: PhysicsWorld, useBias: boolean): JointPass2D {
  const p = pass;
  p.sb = world.collision.bodyState;
  p.rot = world.joints.rotation;
  p.rows = world.joints.rows;
  p.useBias = useBias;
  return p;
}
/** A row's reading (force, torque, error, strain; finishJoints). */
const reading = new Float64Array(4);

/** finishJoints' largest position error of the step (m) and its joint's entity id, as finishRows leaves them. */
const worst = new Float64Array(2);

/** A joint body's class (bodyClass): its BodyType (0 to 3), plus ROTATES when it turns. */
const ROTATES = 4;

/**
 * Whether the world has joints to solve (then the contact solver runs even without contacts). Called
 * by the contact solver at the start of every solve; it also clears the break events of the previous
 * step, so `world.joints.breaks` always holds the last step's.
 * @category Joints and ropes
 */
export function jointsToSolve(world: PhysicsWorld): boolean {
  const js = world.joints;
  if (js.breaksStep !== world.steps) {
    js.breaks.count = 0;
    js.breaksStep = world.steps;
  }
  return world.dimensions === 2 && js.attached.length > 0 && query(world, [world.components.Joint]).length > 0;
}

/**
 * Builds this step's joint rows and gives the moving bodies of every joint a solver index (from `count`
 * on, in `world.collision.solverBodies`, marked with the current `solverStamp`). Also
 * writes, for those bodies, the per-entity scratch the contact solver's gather reads (inverse mass and
 * inertia, body type), since bodies without colliders are not seen by the broadphase.
 * @returns the new solver body count.
 * @category Joints and ropes
 */
export function gatherJointBodies(world: PhysicsWorld, count: number): number {
  const js = world.joints;
  js.rowCount = 0;
  if (world.dimensions !== 2) return count;
  const c = world.components;
  const J = c.Joint;
  const joints = query(world, [J]);
  const n = joints.length;
  if (n === 0) return count;
  const cs = world.collision;
  const JA = J.a,
    JBd = J.b;
  const stamp = ++js.stamp;
  const bs = js.bodyStamp,
    cls = js.bodyClass;
  for (let i = 0; i < n; i++) {
    const j = joints[i]!;
    const a = JA[j]!,
      b = JBd[j]!;
    if (a !== 0) {
      bs[a] = stamp;
      cls[a] = BodyType.Dynamic;
    }
    bs[b] = stamp;
    cls[b] = BodyType.Dynamic;
  }
  // The joint bodies' classes (BodyType) by collision/body-class.ts's ranking.
  const ranked = rankedLists(world, []);
  for (let k = 0; k < ranked.length; k++) {
    const list = ranked[k]!,
      t = rankedListType(k);
    for (let i = 0; i < list.length; i++) {
      const e = list[i]!;
      if (bs[e] === stamp) cls[e] = t;
    }
  }
  const rot = query(world, [c.Inertia, c.AngularVelocity]);
  for (let i = 0; i < rot.length; i++) {
    const e = rot[i]!;
    if (bs[e] === stamp) cls[e] = cls[e]! | ROTATES;
  }

  ensureRows(js, n);
  const ri = js.rowInts;
  // Room for both bodies of every joint, grown before the loop (a branch that runs only in a
  // world's first step is compiled as a deoptimisation of the whole loop).
  const list = withRoom(cs.solverBodies, count + 2 * n);
  const mark = cs.solverMark,
    index = cs.solverIndex,
    sstamp = cs.solverStamp;
  const invMass = cs.invMass,
    invInertia = cs.invInertia,
    type = cs.bodyType;
  const mInv = c.Mass.inv,
    iInv = c.Inertia.inv;
  const T = J.type,
    F = J.flags;
  let rows = 0;
  for (let i = 0; i < n; i++) {
    const j = joints[i]!;
    const a = JA[j]!,
      b = JBd[j]!;
    const ca = a === 0 ? BodyType.Static : cls[a]! & 3,
      cb = cls[b]! & 3;
    const fixedA = ca >= BodyType.Static,
      fixedB = cb >= BodyType.Static;
    if (fixedA && fixedB) continue;
    let ia = 0,
      ib = 0;
    for (let side = 0; side < 2; side++) {
      const e = side === 0 ? a : b;
      if (side === 0 ? fixedA : fixedB) continue;
      if (mark[e] !== sstamp) {
        mark[e] = sstamp;
        index[e] = count;
        list[count++] = e;
      }
      const k = cls[e]!;
      if ((k & 3) === BodyType.Kinematic) {
        invMass[e] = 0;
        invInertia[e] = 0;
        type[e] = BodyType.Kinematic;
      } else {
        invMass[e] = mInv[e]!;
        invInertia[e] = k & ROTATES ? iInv[e]! : 0;
        type[e] = BodyType.Dynamic;
      }
      if (side === 0) ia = index[e]!;
      else ib = index[e]!;
    }
    const o = rows * ROW_INTS;
    ri[o + R.EID] = j;
    ri[o + R.IA] = ia;
    ri[o + R.IB] = ib;
    ri[o + R.TF] = T[j]! | (F[j]! << 8);
    rows++;
  }
  cs.solverBodies = list;
  js.rowCount = rows;
  return count;
}

/**
 * Resets each solver body's rotation within the step (js.rotation: cos, sin, angle) and records its
 * angle at the start of the step (js.startPose: its angle less the rotation still owed, with its cos
 * and sin), once per body rather than once per joint.
 */
function startPoses(world: PhysicsWorld): void {
  const js = world.joints,
    cs = world.collision;
  const count = cs.solverBodyCount,
    ex = cs.bodyExtra;
  js.rotation = atLeast(js.rotation, count * 3);
  const rot = js.rotation;
  for (let k = 0; k < count; k++) {
    rot[k * 3] = 1;
    rot[k * 3 + 1] = 0;
    rot[k * 3 + 2] = 0;
  }
  js.startPose = atLeast(js.startPose, count * 3);
  const pose = js.startPose,
    list = cs.solverBodies,
    angle = world.components.Angle.value;
  for (let k = 1; k < count; k++) {
    const t = angle[list[k]!]! + ex[k * BS.BX_STRIDE + BS.BX_ROT_Z]!;
    pose[k * 3] = Math.cos(t);
    pose[k * 3 + 1] = Math.sin(t);
    pose[k * 3 + 2] = t;
  }
}

/**
 * Fills every row from the joint components and the solver bodies (already gathered and filled by the
 * contact solver): start-of-step anchors (world frame, from each centre), centre difference, relative
 * angle, axis, softness, limits, motor and warm-start impulses; then its type's preparation (effective
 * masses, point links and pins). `hs` is the solver substep, s.
 * @category Joints and ropes
 */
export function prepareJoints(world: PhysicsWorld, hs: number): void {
  const js = world.joints;
  const n = js.rowCount;
  js.stats.rows = n;
  if (n === 0) return;
  startPoses(world);
  // The rigid joint softness of this step (Box2D's joint softness, its rate capped at a quarter of the substep's).
  const jointHertz = Math.min(js.settings.hertz, 0.25 / hs),
    jointZeta = js.settings.dampingRatio;
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
  js.linkCount = 0;
  js.pinCount = 0;
  frame[R.F_HS] = hs;
  prepareRows(world, hs, n, jBias, jMass, jImp);
  js.generalCount = n - js.linkCount - js.pinCount;
}

/**
 * prepareJoints' loop over rows 0 .. n - 1 with the step's rigid softness (jBias 1/s, jMass, jImp). A
 * function of its own, ending with its loop: prepareJoints runs once a step, so V8 compiles this loop on
 * the stack (OSR) before the code after it has run, and inline, that code would have no type feedback in
 * the compiled loop: its first statement would deoptimise the loop's code at every step's exit.
 */
function prepareRows(world: PhysicsWorld, hs: number, n: number, jBias: number, jMass: number, jImp: number): void {
  const js = world.joints;
  const warm = js.settings.warmStarting;
  const c = world.components;
  const J = c.Joint;
  const sb = world.collision.bodyState,
    ex = world.collision.bodyExtra,
    pose = js.startPose;
  const rows = js.rows,
    ri = js.rowInts,
    imp = js.impulses,
    f = frame;
  const { x: px, y: py } = c.Position,
    ang = c.Angle.value;
  for (let r = 0; r < n; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const j = ri[q + R.EID]!,
      ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!;
    const a = J.a[j]!,
      b = J.b[j]!;
    const oA = ia * BS.BS2_STRIDE,
      oB = ib * BS.BS2_STRIDE;
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
      cAx = ex[ia * BS.BX_STRIDE + BS.BX_BASE_X]!;
      cAy = ex[ia * BS.BX_STRIDE + BS.BX_BASE_Y]!;
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
    let cb: number, sbn: number;
    if (ib !== 0) {
      cBx = ex[ib * BS.BX_STRIDE + BS.BX_BASE_X]!;
      cBy = ex[ib * BS.BX_STRIDE + BS.BX_BASE_Y]!;
      tB = pose[ib * 3 + 2]!;
      cb = pose[ib * 3]!;
      sbn = pose[ib * 3 + 1]!;
    } else {
      tB = ang[b]!;
      cb = Math.cos(tB);
      sbn = Math.sin(tB);
    }
    let rBx = cb * lbx - sbn * lby,
      rBy = sbn * lbx + cb * lby;
    if (ib === 0) {
      rBx += px[b]!;
      rBy += py[b]!;
    }
    rows[o + R.RAX] = rAx;
    rows[o + R.RAY] = rAy;
    rows[o + R.RBX] = rBx;
    rows[o + R.RBY] = rBy;
    const dcx = cBx - cAx,
      dcy = cBy - cAy;
    rows[o + R.DCX] = dcx;
    rows[o + R.DCY] = dcy;
    rows[o + R.DANG] = unwind(tB - tA - J.referenceAngle[j]!);
    rows[o + R.AXX] = cA * J.axisX[j]! - sA * J.axisY[j]!;
    rows[o + R.AXY] = sA * J.axisX[j]! + cA * J.axisY[j]!;
    rows[o + R.JB] = jBias;
    rows[o + R.JM] = jMass;
    rows[o + R.JI] = jImp;
    soft(rows, o + R.SB, J.hertz[j]!, J.dampingRatio[j]!, hs);
    rows[o + R.LOW] = J.lower[j]!;
    rows[o + R.UP] = J.upper[j]!;
    rows[o + R.MSPD] = J.motorSpeed[j]!;
    rows[o + R.MMAX] = J.maxMotorForce[j]! * hs;
    const base = j * IMPULSES;
    for (let s = 0; s < IMPULSES; s++) rows[o + R.ILX + s] = warm ? imp[base + s]! : 0;
    f[R.F_MA] = sb[oA + BS.BS2_INV_MASS]!;
    f[R.F_IA] = sb[oA + BS.BS2_INV_INERTIA]!;
    f[R.F_MB] = sb[oB + BS.BS2_INV_MASS]!;
    f[R.F_IB] = sb[oB + BS.BS2_INV_INERTIA]!;
    f[R.F_RAX] = rAx;
    f[R.F_RAY] = rAy;
    f[R.F_RBX] = rBx;
    f[R.F_RBY] = rBy;
    f[R.F_DX] = dcx + rBx - rAx;
    f[R.F_DY] = dcy + rBy - rAy;
    const type = ri[q + R.TF]! & 255;
    // The prismatic and wheel joints share one preparation: one call site, inlined once.
    if (type === JointType.Distance) DISTANCE_ROWS_2D.prepare(js, J, j, r, f);
    else if (type === JointType.Revolute) REVOLUTE_ROWS_2D.prepare(js, J, j, r, f);
    else if (type === JointType.Prismatic || type === JointType.Wheel) PRISMATIC_ROWS_2D.prepare(js, J, j, r, f);
    else if (type === JointType.Weld) WELD_ROWS_2D.prepare(js, J, j, r, f);
    else MOUSE_ROWS_2D.prepare(js, J, j, r, f);
  }
}

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
    const o = k * BS.BS2_STRIDE;
    if (sb[o + BS.BS2_INV_INERTIA]! === 0) continue;
    const w = sb[o + BS.BS2_W]! * hs;
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
 * Applies every joint's accumulated impulses to its bodies (warm start, once per substep, before the
 * contacts'): the point links' and pins', then each general row's by its type.
 * @category Joints and ropes
 */
export function warmStartJoints(world: PhysicsWorld): void {
  const js = world.joints;
  const n = js.rowCount;
  if (n === 0) return;
  const p = passOf(world, false),
    ri = js.rowInts;
  warmStartPointLinks(world);
  warmStartPins(world);
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!,
      type = ri[q + R.TF]! & 255;
    if (type === R.POINT_LINK || type === R.PIN) continue;
    if (type === JointType.Distance) warmStartDistanceRow(p, ia, ib, o);
    else if (type === JointType.Prismatic || type === JointType.Wheel) warmStartAxis(p, ia, ib, o, type === JointType.Wheel);
    else warmStartPoint(p, ia, ib, o, type === JointType.Revolute);
  }
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
 * One pass over every joint row (see solveJoints): the point links and pins, then each general row's
 * frame filled and its type's row solve run, its bodies marked `pushed` when it pushes them.
 */
function solveJointRows(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const js = world.joints;
  const n = js.rowCount;
  const p = passOf(world, useBias),
    sb = p.sb,
    ri = js.rowInts;
  const invH = 1 / hs;
  p.f[R.F_INVH] = invH;
  solvePointLinks(world, invH, useBias);
  solvePins(world, useBias);
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!,
      tf = ri[q + R.TF]!;
    const type = tf & 255;
    if (type === R.POINT_LINK || type === R.PIN) continue;
    anchorsFrame(p, o, ia, ib);
    separationFrame(p, o, ia, ib);
    p.f[R.F_REL] = p.rows[o + R.DANG]! + p.rot[ib * 3 + 2]! - p.rot[ia * 3 + 2]!;
    // The joint pushes its bodies (the contact solver's `pushed` slot: they are not in free flight).
    const flags = tf >> 8;
    let done: number;
    if (type === JointType.Distance) done = DISTANCE_ROWS_2D.solve(p, ia, ib, o, flags);
    else if (type === JointType.Revolute) done = REVOLUTE_ROWS_2D.solve(p, ia, ib, o, flags);
    else if (type === JointType.Prismatic) done = PRISMATIC_ROWS_2D.solve(p, ia, ib, o, flags);
    else if (type === JointType.Weld) done = WELD_ROWS_2D.solve(p, ia, ib, o, flags);
    else if (type === JointType.Wheel) done = WHEEL_ROWS_2D.solve(p, ia, ib, o, flags);
    else done = MOUSE_ROWS_2D.solve(p, ia, ib, o, flags);
    if (done === R.ROW_PUSHED) {
      sb[ia * BS.BS2_STRIDE + BS.BS2_PUSHED] = 1;
      sb[ib * BS.BS2_STRIDE + BS.BS2_PUSHED] = 1;
    }
  }
  // The static world's row must stay at rest whatever a fixed body's joint wrote into it.
  sb[BS.BS2_VX] = 0;
  sb[BS.BS2_VY] = 0;
  sb[BS.BS2_W] = 0;
}

/**
 * After the bodies are written back: each joint's constraint force and torque (accumulated impulse
 * of the last substep / h_s, its type's reading), the largest position error left, the impulses kept
 * for the next step's warm start, and breaking: a joint whose force exceeds `breakForce`, torque
 * `breakTorque` or strain `breakStretch` is removed and reported in `world.joints.breaks`.
 * @category Joints and ropes
 */
export function finishJoints(world: PhysicsWorld, hs: number): void {
  const js = world.joints;
  const n = js.rowCount;
  js.stats.maxError = 0;
  js.stats.maxErrorJoint = 0;
  if (n === 0) return;
  const p = passOf(world, false);
  p.f[R.F_INVH] = 1 / hs;
  finishPointLinks(js);
  finishPins(js);
  const best = worst;
  best[0] = 0;
  best[1] = 0;
  const doomed = finishRows(world, p, n, best);
  js.stats.maxError = best[0]!;
  js.stats.maxErrorJoint = best[1]!;
  if (doomed) for (const j of doomed) removeJointUnchecked(world, j);
}

/**
 * finishJoints' loop over rows 0 .. n - 1 (pass `p`): each row's reading into its joint's force and
 * torque, its impulses kept for the next step, the largest position error (m) and its joint into
 * best[0] and best[1] (best[0] starts at 0); @returns the joints to break, or null. A function of its
 * own, ending with its loop, for the reason prepareRows is.
 */
function finishRows(world: PhysicsWorld, p: JointPass2D, n: number, best: Float64Array): number[] | null {
  const js = world.joints;
  const J = world.components.Joint;
  const rows = p.rows,
    ri = js.rowInts,
    imp = js.impulses,
    out = reading;
  let maxError = 0;
  let doomed: number[] | null = null;
  for (let r = 0; r < n; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const j = ri[q + R.EID]!,
      tf = ri[q + R.TF]!;
    const type = tf === R.POINT_LINK ? JointType.Distance : tf === R.PIN ? JointType.Revolute : tf & 255;
    const ia = ri[q + R.IA]!,
      ib = ri[q + R.IB]!;
    anchorsFrame(p, o, ia, ib);
    separationFrame(p, o, ia, ib);
    out[0] = 0;
    out[1] = 0;
    out[2] = 0;
    out[3] = 0;
    const flags = tf >> 8;
    if (type === JointType.Distance) distanceReading(p, ia, ib, o, flags, out);
    else if (type === JointType.Revolute) revoluteReading(p, ia, ib, o, flags, out);
    else if (type === JointType.Prismatic || type === JointType.Wheel) axisReading(p, ia, o, out, type === JointType.Wheel);
    else if (type === JointType.Weld) weldReading(p, ia, ib, o, flags, out);
    else mouseReading(p, ia, ib, o, flags, out);
    const force = out[0]!,
      torque = out[1]!,
      error = out[2]!,
      stretch = out[3]!;
    J.force[j] = force;
    J.torque[j] = torque;
    if (error > maxError) {
      maxError = error;
      best[0] = error;
      best[1] = j;
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
  return doomed;
}
