import { BodyType } from '../collision/broadphase/grid.js';
import { currentHandle } from '../world/handles.js';
import {
  ensureRows,
  IMPULSES,
  LINK_FLOATS,
  LINK_INTS,
  PIN_FLOATS,
  PIN_INTS,
  pushBreak,
  ROW_FLOATS,
  ROW_INTS,
} from '../world/joint-state-2d.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { removeJointUnchecked } from './remove.js';
import { fixedSpring } from './spring.js';

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

// Row float offsets.
const RAX = 0,
  RAY = 1,
  RBX = 2,
  RBY = 3,
  DCX = 4,
  DCY = 5,
  DANG = 6,
  AXX = 7,
  AXY = 8,
  KAX = 9;
const SB = 10,
  SM = 11,
  SI = 12,
  JB = 13,
  JM = 14,
  JI = 15,
  AB = 16,
  AM = 17,
  AI = 18;
const LEN = 19,
  MINL = 20,
  MAXL = 21,
  LOW = 22,
  UP = 23,
  MSPD = 24,
  MMAX = 25,
  FMAX = 26;
const ILX = 27,
  ILY = 28,
  IANG = 29,
  ISPR = 30,
  IMOT = 31,
  ILOW = 32,
  IUP = 33,
  KMOT = 34;
// Row integer offsets.
const EID = 0,
  IA = 1,
  IB = 2,
  TF = 3;
/** Extra flag (above JointFlag) in a row: the weld's angular part is soft. */
const WELD_ANGULAR_SOFT = 8;
/** Row type of a distance joint moved to the point links (the general loops skip it). */
const POINT_LINK = 255;
/** Row type of a revolute joint moved to the pins (no spring, motor or limit; the general loops skip it). */
const PIN = 254;

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
  let list = cs.solverBodies;
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
        if (count >= list.length) {
          const l = new Int32Array(list.length * 2);
          l.set(list);
          list = l;
        }
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

/**
 * Writes the soft-constraint coefficients of a spring of `hertz` (Hz, >= 0) and damping ratio `zeta`
 * (>= 0) integrated implicitly over `h` (s) at rows[o..o+2]: bias rate omega / (2 zeta + h omega) (1/s),
 * mass scale a / (1 + a) and impulse scale 1 / (1 + a), a = h omega (2 zeta + h omega) (Catto, "Soft
 * Constraints", GDC 2011; Box2D v3 b2MakeSoft). hertz 0 gives the rigid 0, 1, 0. Written so every
 * coefficient stays finite and in range at any hertz: a spring so soft that a rounds to 0 (a denormal
 * hertz) gives 0, 0, 1, no impulse at all; one so stiff that a overflows gives 1 / h, 1, 0.
 */
function soft(rows: Float64Array, o: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    rows[o] = 0;
    rows[o + 1] = 1;
    rows[o + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const hw = h * omega;
  const a = hw * (2 * zeta + hw);
  if (!(a > 0)) {
    rows[o] = 0;
    rows[o + 1] = 0;
    rows[o + 2] = 1;
    return;
  }
  rows[o] = zeta === 0 ? 1 / h : 1 / (h + (2 * zeta) / omega);
  rows[o + 1] = 1 / (1 + 1 / a);
  rows[o + 2] = 1 / (1 + a);
}

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
  if (js.rotation.length < count * 3) js.rotation = new Float64Array(Math.max(count * 3, js.rotation.length * 2));
  const rot = js.rotation;
  for (let k = 0; k < count; k++) {
    rot[k * 3] = 1;
    rot[k * 3 + 1] = 0;
    rot[k * 3 + 2] = 0;
  }
  // Each solver body's angle at the start of the step (its angle less the rotation still owed), with
  // its cos and sin, once per body rather than once per joint.
  if (js.startPose.length < count * 3) js.startPose = new Float64Array(Math.max(count * 3, js.startPose.length * 2));
  const pose = js.startPose,
    list = cs.solverBodies,
    angle = c.Angle.value;
  for (let k = 1; k < count; k++) {
    const t = angle[list[k]!]! + ex[k * 6 + 5]!;
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
    const j = ri[q + EID]!,
      ia = ri[q + IA]!,
      ib = ri[q + IB]!;
    const type = ri[q + TF]! & 255;
    let flags = ri[q + TF]! >> 8;
    const a = J.a[j]!,
      b = J.b[j]!;
    const oA = ia * 8,
      oB = ib * 8;
    const mA = sb[oA + 5]!,
      iA = sb[oA + 6]!,
      mB = sb[oB + 5]!,
      iB = sb[oB + 6]!;
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
      cAx = ex[ia * 6]!;
      cAy = ex[ia * 6 + 1]!;
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
        cBx = ex[ib * 6]!;
        cBy = ex[ib * 6 + 1]!;
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
    rows[o + RAX] = rAx;
    rows[o + RAY] = rAy;
    rows[o + RBX] = rBx;
    rows[o + RBY] = rBy;
    const dcx = cBx - cAx,
      dcy = cBy - cAy;
    rows[o + DCX] = dcx;
    rows[o + DCY] = dcy;
    let dAng = tB - tA - J.referenceAngle[j]!;
    dAng = unwind(dAng);
    rows[o + DANG] = dAng;
    const axx = cA * J.axisX[j]! - sA * J.axisY[j]!,
      axy = sA * J.axisX[j]! + cA * J.axisY[j]!;
    rows[o + AXX] = axx;
    rows[o + AXY] = axy;
    rows[o + JB] = jBias;
    rows[o + JM] = jMass;
    rows[o + JI] = jImp;
    const hertz = J.hertz[j]!,
      zeta = J.dampingRatio[j]!;
    soft(rows, o + SB, hertz, zeta, hs);
    if (hertz > 0 && (type === JointType.Distance || type === JointType.Prismatic || type === JointType.Wheel)) {
      fixedSpring(rows, o + SB, hertz, zeta, hs, mA + mB + 0.5 * (iA * (lax * lax + lay * lay) + iB * (lbx * lbx + lby * lby)));
    }
    rows[o + LOW] = J.lower[j]!;
    rows[o + UP] = J.upper[j]!;
    rows[o + MSPD] = J.motorSpeed[j]!;
    rows[o + MMAX] = J.maxMotorForce[j]! * hs;
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
        rows[o + KAX] = k > 0 ? 1 / k : 0;
        const minL = J.minLength[j]!,
          maxL = J.maxLength[j]!,
          rest = J.length[j]!;
        rows[o + LEN] = rest;
        rows[o + MINL] = minL;
        rows[o + MAXL] = maxL;
        // Neither body turns and no spring: a point link (anchors are fixed offsets within the step).
        if (iA === 0 && iB === 0 && !(flags & JointFlag.Spring) && (minL === maxL || (minL === 0 && maxL < Infinity))) {
          const l = links * LINK_FLOATS,
            li = links * LINK_INTS;
          lf[l] = dx;
          lf[l + 1] = dy;
          lf[l + 2] = rows[o + KAX]!;
          const rope = minL < maxL;
          lf[l + 3] = rope ? maxL : rest;
          lf[l + 4] = warm ? (rope ? -imp[j * IMPULSES + 6]! : imp[j * IMPULSES + 3]!) : 0;
          lf[l + 5] = rope ? 1 : 0;
          lint[li] = oA;
          lint[li + 1] = oB;
          lint[li + 2] = r;
          links++;
          ri[q + TF] = POINT_LINK;
        }
        break;
      }
      case JointType.Revolute:
        rows[o + KAX] = angularMass;
        if ((flags & (JointFlag.Spring | JointFlag.Motor | JointFlag.Limit)) === 0) ri[q + TF] = PIN;
        break;
      case JointType.Prismatic:
      case JointType.Wheel: {
        const a1 = (dx + rAx) * axy - (dy + rAy) * axx,
          a2 = rBx * axy - rBy * axx;
        const k = mA + mB + iA * a1 * a1 + iB * a2 * a2;
        rows[o + KAX] = k > 0 ? 1 / k : 0;
        rows[o + KMOT] = angularMass;
        break;
      }
      case JointType.Weld: {
        rows[o + KAX] = angularMass;
        // The linear part: its own softness if softened, else the rigid joint softness.
        if (hertz > 0) {
          rows[o + JB] = rows[o + SB]!;
          rows[o + JM] = rows[o + SM]!;
          rows[o + JI] = rows[o + SI]!;
          flags |= JointFlag.Spring;
        } else flags &= ~JointFlag.Spring;
        const ah = J.angularHertz[j]!;
        if (ah > 0) {
          soft(rows, o + AB, ah, J.angularDampingRatio[j]!, hs);
          flags |= WELD_ANGULAR_SOFT;
        } else {
          rows[o + AB] = jBias;
          rows[o + AM] = jMass;
          rows[o + AI] = jImp;
        }
        ri[q + TF] = type | (flags << 8);
        break;
      }
      case JointType.Mouse:
        rows[o + KAX] = iB > 0 ? 1 / iB : 0;
        rows[o + FMAX] = J.maxForce[j]! * hs;
        soft(rows, o + AB, hertz, zeta, hs);
        break;
    }
    const base = j * IMPULSES;
    for (let s = 0; s < IMPULSES; s++) rows[o + ILX + s] = warm ? imp[base + s]! : 0;
    if (ri[q + TF] === PIN) {
      const f = pins * PIN_FLOATS,
        i = pins * PIN_INTS;
      pf[f] = rAx;
      pf[f + 1] = rAy;
      pf[f + 2] = rBx;
      pf[f + 3] = rBy;
      pf[f + 4] = dcx;
      pf[f + 5] = dcy;
      pf[f + 6] = rows[o + ILX]!;
      pf[f + 7] = rows[o + ILY]!;
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

/** Wraps an angle into [-pi, pi]. */
function unwind(x: number): number {
  if (x > Math.PI) return x - 2 * Math.PI * Math.floor((x + Math.PI) / (2 * Math.PI));
  if (x < -Math.PI) return x + 2 * Math.PI * Math.floor((Math.PI - x) / (2 * Math.PI));
  return x;
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
    const o = k * 8;
    if (sb[o + 6]! === 0) continue;
    const w = sb[o + 2]! * hs;
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
  const lf = js.links,
    lint = js.linkInts;
  for (let l = 0, m = js.linkCount; l < m; l++) {
    const f = l * LINK_FLOATS,
      i = l * LINK_INTS;
    const acc = lf[f + 4]!;
    if (acc === 0) continue;
    const oA = lint[i]!,
      oB = lint[i + 1]!;
    const dx = sb[oB + 3]! - sb[oA + 3]! + lf[f]!,
      dy = sb[oB + 4]! - sb[oA + 4]! + lf[f + 1]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const s = acc / L,
      Px = s * dx,
      Py = s * dy,
      mA = sb[oA + 5]!,
      mB = sb[oB + 5]!;
    sb[oA] = sb[oA]! - mA * Px;
    sb[oA + 1] = sb[oA + 1]! - mA * Py;
    sb[oB] = sb[oB]! + mB * Px;
    sb[oB + 1] = sb[oB + 1]! + mB * Py;
  }
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const Px = pf[f + 6]!,
      Py = pf[f + 7]!;
    if (Px === 0 && Py === 0) continue;
    const ia = pint[i]!,
      ib = pint[i + 1]!,
      oA = ia * 8,
      oB = ib * 8;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f]! - sA * pf[f + 1]!,
      rAy = sA * pf[f]! + cA * pf[f + 1]!;
    const rBx = cB * pf[f + 2]! - sB * pf[f + 3]!,
      rBy = sB * pf[f + 2]! + cB * pf[f + 3]!;
    const mA = sb[oA + 5]!,
      iA = sb[oA + 6]!,
      mB = sb[oB + 5]!,
      iB = sb[oB + 6]!;
    sb[oA] = sb[oA]! - mA * Px;
    sb[oA + 1] = sb[oA + 1]! - mA * Py;
    sb[oA + 2] = sb[oA + 2]! - iA * (rAx * Py - rAy * Px);
    sb[oB] = sb[oB]! + mB * Px;
    sb[oB + 1] = sb[oB + 1]! + mB * Py;
    sb[oB + 2] = sb[oB + 2]! + iB * (rBx * Py - rBy * Px);
  }
  for (let r = 0, end = js.generalCount === 0 ? 0 : n; r < end; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const ia = ri[q + IA]!,
      ib = ri[q + IB]!,
      type = ri[q + TF]! & 255;
    if (type === POINT_LINK || type === PIN) continue;
    const oA = ia * 8,
      oB = ib * 8;
    const mA = sb[oA + 5]!,
      iA = sb[oA + 6]!,
      mB = sb[oB + 5]!,
      iB = sb[oB + 6]!;
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
        const dx = sb[oB + 3]! - sb[oA + 3]! + rows[o + DCX]! + rBx - rAx,
          dy = sb[oB + 4]! - sb[oA + 4]! + rows[o + DCY]! + rBy - rAy;
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
        const dx = sb[oB + 3]! - sb[oA + 3]! + rows[o + DCX]! + rBx - rAx,
          dy = sb[oB + 4]! - sb[oA + 4]! + rows[o + DCY]! + rBy - rAy;
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
    sb[oA] = sb[oA]! - mA * Px;
    sb[oA + 1] = sb[oA + 1]! - mA * Py;
    sb[oA + 2] = sb[oA + 2]! - iA * LA;
    sb[oB] = sb[oB]! + mB * Px;
    sb[oB + 1] = sb[oB + 1]! + mB * Py;
    sb[oB + 2] = sb[oB + 2]! + iB * LB;
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

/**
 * The pins' pass: the revolute joint's point-to-point block (2 x 2 effective mass from the current
 * anchors), soft while `useBias` (Box2D's joint softness), exactly as the general loop solves it.
 */
function solvePins(world: PhysicsWorld, useBias: boolean): void {
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
      oA = ia * 8,
      oB = ib * 8;
    const mA = sb[oA + 5]!,
      iA = sb[oA + 6]!,
      mB = sb[oB + 5]!,
      iB = sb[oB + 6]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f]! - sA * pf[f + 1]!,
      rAy = sA * pf[f]! + cA * pf[f + 1]!;
    const rBx = cB * pf[f + 2]! - sB * pf[f + 3]!,
      rBy = sB * pf[f + 2]! + cB * pf[f + 3]!;
    let vAx = sb[oA]!,
      vAy = sb[oA + 1]!,
      wA = sb[oA + 2]!,
      vBx = sb[oB]!,
      vBy = sb[oB + 1]!,
      wB = sb[oB + 2]!;
    const cdx = vBx - wB * rBy - vAx + wA * rAy,
      cdy = vBy + wB * rBx - vAy - wA * rAx;
    let bx = 0,
      by = 0;
    if (useBias) {
      bx = jb * (sb[oB + 3]! - sb[oA + 3]! + pf[f + 4]! + rBx - rAx);
      by = jb * (sb[oB + 4]! - sb[oA + 4]! + pf[f + 5]! + rBy - rAy);
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
    sb[oA] = vAx;
    sb[oA + 1] = vAy;
    sb[oA + 2] = wA;
    sb[oA + 7] = 1;
    sb[oB] = vBx;
    sb[oB + 1] = vBy;
    sb[oB + 2] = wB;
    sb[oB + 7] = 1;
  }
}

/**
 * The point links' pass: the distance joint's rod (soft while `useBias`, Box2D's joint softness) or
 * rope (pulls only, speculative while slack), with the anchors' offset fixed within the step.
 */
function solvePointLinks(world: PhysicsWorld, invH: number, useBias: boolean): void {
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
    const dx = sb[oB + 3]! - sb[oA + 3]! + lf[f]!,
      dy = sb[oB + 4]! - sb[oA + 4]! + lf[f + 1]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const ux = dx / L,
      uy = dy / L;
    const vAx = sb[oA]!,
      vAy = sb[oA + 1]!,
      vBx = sb[oB]!,
      vBy = sb[oB + 1]!;
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
      mA = sb[oA + 5]!,
      mB = sb[oB + 5]!;
    sb[oA] = vAx - mA * Px;
    sb[oA + 1] = vAy - mA * Py;
    sb[oB] = vBx + mB * Px;
    sb[oB + 1] = vBy + mB * Py;
    if (lf[f + 4] !== 0) {
      sb[oA + 7] = 1;
      sb[oB + 7] = 1;
    }
  }
}

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
  const lf = js.links,
    lint = js.linkInts;
  for (let l = 0, m = js.linkCount; l < m; l++) {
    const f = l * LINK_FLOATS,
      o = lint[l * LINK_INTS + 2]! * ROW_FLOATS;
    if (lf[f + 5] === 0) rows[o + ISPR] = lf[f + 4]!;
    else rows[o + IUP] = -lf[f + 4]!;
  }
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      o = pint[l * PIN_INTS + 2]! * ROW_FLOATS;
    rows[o + ILX] = pf[f + 6]!;
    rows[o + ILY] = pf[f + 7]!;
  }
  for (let r = 0; r < n; r++) {
    const o = r * ROW_FLOATS,
      q = r * ROW_INTS;
    const j = ri[q + EID]!,
      ia = ri[q + IA]!,
      ib = ri[q + IB]!,
      tf = ri[q + TF]!;
    const type = tf === POINT_LINK ? JointType.Distance : tf === PIN ? JointType.Revolute : tf & 255,
      flags = tf >> 8;
    const oA = ia * 8,
      oB = ib * 8;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * rows[o + RAX]! - sA * rows[o + RAY]!,
      rAy = sA * rows[o + RAX]! + cA * rows[o + RAY]!;
    const rBx = cB * rows[o + RBX]! - sB * rows[o + RBY]!,
      rBy = sB * rows[o + RBX]! + cB * rows[o + RBY]!;
    const dx = sb[oB + 3]! - sb[oA + 3]! + rows[o + DCX]! + rBx - rAx;
    const dy = sb[oB + 4]! - sb[oA + 4]! + rows[o + DCY]! + rBy - rAy;
    let force = 0,
      torque = 0,
      error = 0,
      stretch = 0;
    switch (type) {
      case JointType.Distance: {
        const L = Math.sqrt(dx * dx + dy * dy);
        force = Math.abs(rows[o + ISPR]! + rows[o + ILOW]! - rows[o + IUP]!) * invH;
        const minL = rows[o + MINL]!,
          maxL = rows[o + MAXL]!,
          rest = rows[o + LEN]!;
        if (minL < maxL) error = Math.max(0, minL - L, L - maxL);
        else error = Math.abs(L - rest);
        stretch = rest > 0 ? (L - rest) / rest : 0;
        break;
      }
      case JointType.Revolute:
        force = Math.sqrt(rows[o + ILX]! * rows[o + ILX]! + rows[o + ILY]! * rows[o + ILY]!) * invH;
        torque = Math.abs(rows[o + ISPR]! + rows[o + IMOT]! + rows[o + ILOW]! - rows[o + IUP]!) * invH;
        error = Math.sqrt(dx * dx + dy * dy);
        break;
      case JointType.Weld:
        force = Math.sqrt(rows[o + ILX]! * rows[o + ILX]! + rows[o + ILY]! * rows[o + ILY]!) * invH;
        torque = Math.abs(rows[o + IANG]!) * invH;
        if (!(flags & JointFlag.Spring)) error = Math.sqrt(dx * dx + dy * dy);
        break;
      case JointType.Prismatic:
      case JointType.Wheel: {
        const axx = cA * rows[o + AXX]! - sA * rows[o + AXY]!,
          axy = sA * rows[o + AXX]! + cA * rows[o + AXY]!;
        const axial = rows[o + ISPR]! + rows[o + ILOW]! - rows[o + IUP]! + (type === JointType.Prismatic ? rows[o + IMOT]! : 0);
        force = Math.hypot(axial, rows[o + ILX]!) * invH;
        torque = Math.abs(type === JointType.Prismatic ? rows[o + IANG]! : rows[o + IMOT]!) * invH;
        error = Math.abs(-axy * dx + axx * dy);
        break;
      }
      case JointType.Mouse:
        force = Math.sqrt(rows[o + ILX]! * rows[o + ILX]! + rows[o + ILY]! * rows[o + ILY]!) * invH;
        torque = Math.abs(rows[o + IANG]!) * invH;
        break;
    }
    J.force[j] = force;
    J.torque[j] = torque;
    if (error > maxError) {
      maxError = error;
      maxJoint = j;
    }
    const base = j * IMPULSES;
    for (let s = 0; s < IMPULSES; s++) imp[base + s] = rows[o + ILX + s]!;
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
