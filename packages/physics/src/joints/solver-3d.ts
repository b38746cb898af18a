import { classifyBody, lookUpBodyBits } from '../collision/body-class.js';
import { contact3DStateOf } from '../collision/manifolds-3d.js';
import { BS3_PUSHED, BS3_STRIDE } from '../solver/body-state-layout.js';
import { joinSolverBodies } from '../solver/solver-bodies.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { type JointPass3D, type JointRows3D, poseJoint3D } from './rows-3d.js';
import { soft } from './softness.js';
import { type Joint3DStore, Joint3DType, joints3DOf, removeJoint3DUnchecked } from './store-3d.js';

/**
 * The 3D joints' rows of the contact solver (joints/solver-3d.ts calls these next to the contacts', in the same
 * soft substeps, on the same packed body state): Box2D v3's joints (joint.c, revolute_joint.c,
 * weld_joint.c, distance_joint.c) carried to 3D, with the world inverse inertia tensors of
 * solver/manifold-rows-3d.ts.
 *
 * - Each body's pose during the substeps: position = base + displacement, orientation = exp(theta) q
 *   with theta the rotation owed so far (exact rotation of the component orientation).
 * - Point rows (ball, hinge, fixed): C = p_B + r_B - p_A - r_A = 0 as one 3 x 3 block, K P = sum over
 *   bodies of (P / m + (I^-1 (r x P)) x r); soft (Box2D's joint softness: 60 Hz capped at a quarter of
 *   the substep rate, damping ratio 2, i.e. 2 zeta) with bias, rigid in the relax passes.
 * - Angular lock: the error rotation E = conj(q_A) q_B conj(q_rest) as the small-angle vector 2 vec(E)
 *   (A's frame, turned to the world); fixed: three rows with K = I_A^-1 + I_B^-1; hinge: the two rows
 *   perpendicular to the axis. The hinge angle is 2 atan2(vec(E) . axis, w(E)); its limits are one-sided
 *   rows (speculative when apart), its motor a row bounded by the largest torque times h_s.
 * - Cone: the angle between A's axis and B's (phi) stays <= the half angle: a one-sided row about
 *   n = a_A x a_B / |a_A x a_B|, with d phi / dt = (w_B - w_A) . n.
 * - Slider: the fixed joint's three angular rows, the point block restricted to the plane
 *   perpendicular to A's axis u (K' = P K P + u u^T, P = 1 - u u^T), and along u, at the point of A
 *   under B's anchor, a translation limit (one-sided rows, speculative when apart) and a motor bounded
 *   by the largest force times h_s (Box2D v3 prismatic_joint.c).
 * - Distance: a row along the anchors' line, equality (rod), spring (Box2D's soft spring of `hertz`
 *   and `dampingRatio`) and one-sided limits.
 * - Warm start (every row, Box2D v3's joints): the point and angular-lock impulses (world vectors), the
 *   hinge's and slider's limit and motor impulses (signed along the axis; a limit's impulse from the
 *   other side is taken back when the near side changes), the cone's (>= 0 about the current n; reset
 *   when n is undefined, the axes parallel) and the distance joint's rod or spring impulse (`lx`) and
 *   lower and upper limit impulses (`limit`, `ly`, each >= 0, along the current anchor line; reset when
 *   the anchors meet) are applied again, unscaled, at the start of each substep. After the substeps a
 *   joint whose force (impulse / h_s) or torque passes its threshold breaks: it is removed and listed
 *   in `joint3DBreaks`.
 */

/** Joint stiffness (Box2D v3 defaults: joint hertz 60, damping ratio 2), capped at a quarter of the substep rate. */
const JOINT_HERTZ = 60,
  JOINT_DAMPING = 2;

/** Rows of a type no joint of which was made yet: none is solved. */
const NO_ROWS: JointRows3D = {
  warmStart() {},
  solve() {},
  reading(_s, _j, _hs, out) {
    out[0] = 0;
    out[1] = 0;
  },
};
// Each type's rows, handed over by useJointType3D: the solver does not import the types' files, which
// import the 3D feature's install (joint-3d.ts make), and that imports this module. A stage picks the
// type by a chain of tests rather than a table, so that each call site sees one function, which the
// engine can inline.
let ballRows = NO_ROWS,
  hingeRows = NO_ROWS,
  fixedRows = NO_ROWS,
  distanceRows = NO_ROWS,
  sliderRows = NO_ROWS;

/**
 * Hands the solver the rows of a 3D joint type (Joint3DType), called by the type's add call (whose file
 * holds them) and, for every type, by restore. The rows serve every world of the program.
 * @category Joints and ropes
 */
export function useJointType3D(type: number, rows: JointRows3D): void {
  if (type === Joint3DType.Ball) ballRows = rows;
  else if (type === Joint3DType.Hinge) hingeRows = rows;
  else if (type === Joint3DType.Fixed) fixedRows = rows;
  else if (type === Joint3DType.Distance) distanceRows = rows;
  else if (type === Joint3DType.Slider) sliderRows = rows;
}

/** Per joint of the list (scratch, filled each step): its bodies' solver indices (ka, kb) and entities (ja, jb). */
let ka = new Int32Array(16),
  kb = new Int32Array(16),
  ja = new Int32Array(16),
  jb = new Int32Array(16);
const jsoft = new Float64Array(3);

/**
 * Whether the world has 3D joints.
 * @category Joints and ropes
 */
export function joints3DToSolve(world: PhysicsWorld): boolean {
  const s = joints3DOf(world);
  return world.dimensions === 3 && s !== undefined && s.list.length > 0;
}

/**
 * Gives the joints' moving bodies solver indices (continuing the list); returns the new count.
 * @category Joints and ropes
 */
export function gatherJoint3DBodies(world: PhysicsWorld, count: number): number {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3) return count;
  if (s.breaks.length > 0 && s.breaks[0]![3] !== world.steps) s.breaks.length = 0;
  const n = s.list.length;
  if (ka.length < n) {
    ka = new Int32Array(2 * n);
    kb = new Int32Array(2 * n);
    ja = new Int32Array(2 * n);
    jb = new Int32Array(2 * n);
  }
  // Each joint's bodies in list order, classified now (the type joinSolverBodies reads).
  lookUpBodyBits(world);
  for (let i = 0; i < n; i++) {
    const j: number = s.list[i]!;
    const a = s.a[j]!,
      b = s.b[j]!;
    if (a !== 0) classifyBody(world, a);
    if (b !== 0) classifyBody(world, b);
    ja[i] = a;
    jb[i] = b;
  }
  return joinSolverBodies(world.collision, ja, jb, ka, kb, n, count);
}

/**
 * Softness for this step, and marks the joint bodies as pushed. Every row's impulse is kept (warm start).
 * @category Joints and ropes
 */
export function prepareJoints3D(world: PhysicsWorld, hs: number): void {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3 || s.list.length === 0) return;
  contact3DStateOf(world, true);
  soft(jsoft, 0, Math.min(JOINT_HERTZ, 0.25 / hs), JOINT_DAMPING, hs);
  const sb = world.collision.bodyState;
  for (let i = 0; i < s.list.length; i++) {
    if (ka[i]! > 0) sb[BS3_STRIDE * ka[i]! + BS3_PUSHED] = 1;
    if (kb[i]! > 0) sb[BS3_STRIDE * kb[i]! + BS3_PUSHED] = 1;
  }
}

/** The pass the row solves read (rows-3d.ts JointPass3D), filled by each solveJoints3D. */
const pass: JointPass3D = {
  s: undefined as unknown as Joint3DStore,
  sb: new Float64Array(0),
  T: new Float64Array(0),
  hs: 0,
  useBias: false,
  bRate: 0,
  ms: 1,
  is: 0,
};

/**
 * Warm start: last substep's impulses of every row applied again, each joint's by its type's warm start
 * (point, angular lock, limits, motors, cone, distance) on its bodies' poses.
 * @category Joints and ropes
 */
export function warmStartJoints3D(world: PhysicsWorld): void {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3) return;
  const p = pass;
  p.s = s;
  p.sb = world.collision.bodyState;
  p.T = contact3DStateOf(world, true).invInertia;
  for (let i = 0; i < s.list.length; i++) {
    const j = s.list[i]!,
      a = ka[i]!,
      b = kb[i]!;
    poseJoint3D(world, s, j, a, b);
    const type = s.type[j]!;
    if (type === Joint3DType.Ball) ballRows.warmStart(p, j, a, b);
    else if (type === Joint3DType.Hinge) hingeRows.warmStart(p, j, a, b);
    else if (type === Joint3DType.Fixed) fixedRows.warmStart(p, j, a, b);
    else if (type === Joint3DType.Distance) distanceRows.warmStart(p, j, a, b);
    else sliderRows.warmStart(p, j, a, b);
  }
}

/**
 * One pass over the joints: soft with `useBias`, else relaxing (no bias); each joint's bodies posed,
 * then its type's row solve (its file's, handed over by useJointType3D).
 * @category Joints and ropes
 */
export function solveJoints3D(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3) return;
  const sb = world.collision.bodyState,
    T = contact3DStateOf(world, true).invInertia;
  const p = pass;
  p.s = s;
  p.sb = sb;
  p.T = T;
  p.hs = hs;
  p.useBias = useBias;
  p.bRate = useBias ? jsoft[0]! : 0;
  p.ms = useBias ? jsoft[1]! : 1;
  p.is = useBias ? jsoft[2]! : 0;
  for (let i = 0; i < s.list.length; i++) {
    const j = s.list[i]!,
      a = ka[i]!,
      b = kb[i]!;
    poseJoint3D(world, s, j, a, b);
    const type = s.type[j]!,
      flags = s.flags[j]!;
    if (type === Joint3DType.Ball) ballRows.solve(p, j, a, b, flags);
    else if (type === Joint3DType.Hinge) hingeRows.solve(p, j, a, b, flags);
    else if (type === Joint3DType.Fixed) fixedRows.solve(p, j, a, b, flags);
    else if (type === Joint3DType.Distance) distanceRows.solve(p, j, a, b, flags);
    else sliderRows.solve(p, j, a, b, flags);
  }
}

/** A joint's force (N) and torque (N m) after the substeps, from its type's reading (finishJoints3D). */
const reading = new Float64Array(2);

/**
 * After the substeps: each joint's force and torque by its type's reading; joints past their breaking
 * force or torque are removed and listed.
 * @category Joints and ropes
 */
export function finishJoints3D(world: PhysicsWorld, hs: number): void {
  const s = joints3DOf(world);
  if (s === undefined || world.dimensions !== 3) return;
  const broken: number[] = [];
  const out = reading;
  for (const j of s.list) {
    const type = s.type[j]!;
    if (type === Joint3DType.Ball) ballRows.reading(s, j, hs, out);
    else if (type === Joint3DType.Hinge) hingeRows.reading(s, j, hs, out);
    else if (type === Joint3DType.Fixed) fixedRows.reading(s, j, hs, out);
    else if (type === Joint3DType.Distance) distanceRows.reading(s, j, hs, out);
    else sliderRows.reading(s, j, hs, out);
    if (out[0]! > s.breakForce[j]! || out[1]! > s.breakTorque[j]!) broken.push(j);
  }
  for (const j of broken) {
    const h = (e: number): number => (e === 0 ? 0 : currentHandle(world, e));
    s.breaks.push([h(j), h(s.a[j]!), h(s.b[j]!), world.steps]);
    removeJoint3DUnchecked(world, s, j);
  }
}
