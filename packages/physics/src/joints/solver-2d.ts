import { BodyType } from '../collision/broadphase/grid.js';
import { ensureRows } from '../world/joint-state-2d.js';
import { ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { EID, IA, IB, TF } from './layout-2d.js';

/**
 * The joint solver: Box2D v3's soft-step joints (Catto, "Solver2D", 2024, and "Soft Constraints",
 * GDC 2011; Box2D v3.0 distance_joint.c, revolute_joint.c, prismatic_joint.c, weld_joint.c,
 * wheel_joint.c, mouse_joint.c), solved by the contact solver (solver/contact-solver.ts) inside the same
 * substeps as the contacts, on the same packed solver bodies:
 *
 * 1. `gatherJointBodies` (while the contact solver gathers its bodies): every joint whose bodies are
 *    not both fixed (static, asleep or the world) gets a row; its moving bodies get solver indices;
 * 2. `prepareJoints`: anchors, axes and centres at the start of the step, effective masses, spring
 *    and rigid softness, last step's impulses (warm start);
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
 * bodies in the solver row's `pushed` slot (index 7), as contacts do: they were not in free flight.
 */

enum Class {
  Dynamic = 0,
  Kinematic = 1,
  Static = 2,
  Sleeping = 3,
}
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

/** `list` if it holds `n` entries, else a copy in an array of at least n (twice its length). */
function withRoom(list: Int32Array, n: number): Int32Array {
  if (list.length >= n) return list;
  const grown = new Int32Array(Math.max(n, 2 * list.length));
  grown.set(list);
  return grown;
}

/**
 * Builds this step's joint rows and gives the moving bodies of every joint a solver index (after the
 * contacts' bodies, in `world.collision.solverBodies`, marked with the current `solverStamp`). Also
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
      cls[a] = Class.Dynamic;
    }
    bs[b] = stamp;
    cls[b] = Class.Dynamic;
  }
  const classify = (comp: object, value: number): void => {
    const ents = query(world, [comp]);
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      if (bs[e] === stamp) cls[e] = value;
    }
  };
  classify(c.Static, Class.Static);
  classify(c.Kinematic, Class.Kinematic);
  classify(c.Sleeping, Class.Sleeping);
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
    const ca = a === 0 ? Class.Static : cls[a]! & 3,
      cb = cls[b]! & 3;
    const fixedA = ca >= Class.Static,
      fixedB = cb >= Class.Static;
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
      if ((k & 3) === Class.Kinematic) {
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
    ri[o + EID] = j;
    ri[o + IA] = ia;
    ri[o + IB] = ib;
    ri[o + TF] = T[j]! | (F[j]! << 8);
    rows++;
  }
  cs.solverBodies = list;
  js.rowCount = rows;
  return count;
}
