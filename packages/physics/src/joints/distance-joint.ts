import * as BS from '../solver/body-state-layout.js';
import { currentHandle } from '../world/handles.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, type JointStore, JointType } from '../world/joint-store-2d.js';
import { IMPULSES, LINK_FLOATS, LINK_INTS, ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, checkEnds2D, makeJoint } from './joint-2d.js';
import { assertBreakLimit, checkDistance, type JointBaseOptions } from './joint-base.js';
import * as R from './layout-2d.js';
import {
  anchorsFrame,
  applyImpulse,
  type JointPass2D,
  type JointTypeRows2D,
  limitRow,
  separationFrame,
  springLimitImpulse,
  springRow,
} from './rows-2d.js';
import { springImpulse } from './softness.js';

/**
 * The 2D distance joint (a rod, a rope or a spring between two anchors): its options, addDistanceJoint,
 * its row's preparation, warm start, solve and reading, and the point links' passes (a rod or rope
 * between two bodies that do not turn and has no spring, packed by its preparation: warm start, solve,
 * impulses back into the rows). joints/solver-2d.ts runs them.
 */

/**
 * Options of `addDistanceJoint`.
 * @category Joints and ropes
 */
export interface DistanceJointOptions extends JointBaseOptions {
  /** Anchor on A, world point, m. Default A's centre; required when A is the world. */
  anchorA?: ArrayLike<number>;
  /** Anchor on B, world point, m. Default B's centre. */
  anchorB?: ArrayLike<number>;
  /** Rest length, m, > 0. Default the anchors' distance now. */
  length?: number;
  /** Shortest allowed length, m, in [0, length]. Default `length` for a rod (hertz 0), 0 for a spring. */
  minLength?: number;
  /** Longest allowed length, m, >= length (Infinity allowed). Default `length` for a rod, Infinity for a spring. */
  maxLength?: number;
  /**
   * Spring stiffness as a natural frequency, Hz, >= 0; 0 = no spring. Default 0. A spring of fixed stiffness:
   * its stiffness k = (2 pi hertz)^2 / K_ref is fixed, K_ref = mA + mB + (iA |rA|^2 + iB |rB|^2) / 2 (the anchors' levers rA, rB from the centres), so the spring stores 1/2 k C^2 and a lever's swing does no work on it (with both anchors at the centres it is the frequency of the bodies' relative motion).
   */
  hertz?: number;
  /** Spring damping ratio, >= 0 (1 = critical). Default 0. */
  dampingRatio?: number;
  /** Strain (length - rest) / rest past which the joint breaks (tears), > 0. Default Infinity. */
  breakStretch?: number;
}

/**
 * Adds a distance joint between anchor points of A and B: a rigid rod of `length` (default), a spring
 * of `hertz` and `dampingRatio` toward it (a soft constraint: Catto, "Soft Constraints", GDC 2011),
 * and/or a range [minLength, maxLength] it may not leave: `{ minLength: 0 }` makes a rope link that only
 * pulls. Box2D v3's distance joint.
 * @returns the joint entity.
 * @throws TypeError | RangeError on a missing or removed body, a == b, a 3D world, unknown options,
 *   length <= 0, minLength > length, maxLength < length, negative hertz or damping ratio, breakForce or
 *   breakStretch <= 0, or a full world.
 * @example
 * const rod = addDistanceJoint(world, { b: bob, anchorA: [0, 5] });   // bob swings on a 5 m rod... from [0, 5]
 * @category Joints and ropes
 */
export function addDistanceJoint(world: PhysicsWorld, options: DistanceJointOptions): number {
  const where = 'addDistanceJoint';
  const keys = ['anchorA', 'anchorB', 'length', 'minLength', 'maxLength', 'hertz', 'dampingRatio', 'breakStretch'];
  const ends = checkEnds2D(where, world, options, keys);
  const d = checkDistance(where, options, ends.a, centre(world, ends.a), centre(world, ends.b));
  if (options.breakStretch !== undefined) assertBreakLimit(where, 'breakStretch', options.breakStretch);
  const j = makeJoint(world, JointType.Distance, ends, d.pa, d.pb, options);
  const J = world.components.Joint;
  J.length[j] = d.length;
  J.minLength[j] = d.minLength;
  J.maxLength[j] = d.maxLength;
  J.hertz[j] = d.hertz;
  J.dampingRatio[j] = d.zeta;
  J.flags[j] = (d.hertz > 0 ? JointFlag.Spring : 0) | (d.minLength < d.maxLength ? JointFlag.Limit : 0);
  J.breakStretch[j] = options.breakStretch ?? Infinity;
  return currentHandle(world, j);
}

/**
 * Prepares distance joint `j`'s row r (its anchors, pose and masses at the start of the step in the
 * frame `f`, layout-2d.ts): the effective mass along the anchors' line, the rest length and limits, the
 * spring of fixed stiffness (`hs` the substep, s), and, for a rod or rope between bodies that do not
 * turn and without a spring, its point link.
 */
export function prepareDistanceRow(js: JointState, J: JointStore, j: number, r: number, f: Float64Array): void {
  const rows = js.rows,
    ri = js.rowInts;
  const o = r * ROW_FLOATS,
    q = r * ROW_INTS;
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!,
    dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const flags = ri[q + R.TF]! >> 8;
  springRow(rows, o, J, j, f);
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
    const l = js.linkCount * LINK_FLOATS,
      li = js.linkCount * LINK_INTS;
    const lf = js.links,
      imp = js.impulses;
    lf[l + R.LK_DX] = dx;
    lf[l + R.LK_DY] = dy;
    lf[l + R.LK_MASS] = rows[o + R.KAX]!;
    const rope = minL < maxL;
    lf[l + R.LK_LEN] = rope ? maxL : rest;
    lf[l + R.LK_ACC] = js.settings.warmStarting
      ? rope
        ? -imp[j * IMPULSES + (R.IUP - R.ILX)]!
        : imp[j * IMPULSES + (R.ISPR - R.ILX)]!
      : 0;
    lf[l + R.LK_ROPE] = rope ? 1 : 0;
    js.linkInts[li + R.LK_OA] = ri[q + R.IA]! * BS.BS2_STRIDE;
    js.linkInts[li + R.LK_OB] = ri[q + R.IB]! * BS.BS2_STRIDE;
    js.linkInts[li + R.LK_ROW] = r;
    js.linkCount++;
    ri[q + R.TF] = R.POINT_LINK;
  }
}

/**
 * A distance joint's warm start: its spring's (or rod's) and limits' impulses along the anchors'
 * current line; nothing when the anchors meet (no direction).
 */
export function warmStartDistanceRow(p: JointPass2D, ia: number, ib: number, o: number): void {
  const { sb, rows, f } = p;
  const axial = springLimitImpulse(rows, o);
  if (axial === 0) return;
  anchorsFrame(p, o, ia, ib);
  separationFrame(p, o, ia, ib);
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!,
    dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const L = Math.sqrt(dx * dx + dy * dy);
  if (L < 1e-12) return;
  const px = (axial * dx) / L,
    py = (axial * dy) / L;
  applyImpulse(sb, ia * BS.BS2_STRIDE, ib * BS.BS2_STRIDE, px, py, rAx * py - rAy * px, rBx * py - rBy * px);
}

/**
 * One pass of a distance joint's row (Box2D v3's b2SolveDistanceJoint) on its frame: the spring, then
 * the lower and upper length limits (a rope link: only the upper), or the rigid rod, soft while the
 * pass uses bias. @returns ROW_SKIPPED when the anchors coincide (no direction), ROW_PUSHED when the
 * link holds an impulse, else ROW_MOVED (a slack rope leaves its bodies in free flight).
 */
export function solveDistanceRow(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number {
  const { sb, rows, f } = p;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const L = Math.sqrt(dx * dx + dy * dy);
  if (L < 1e-12) return R.ROW_SKIPPED;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const ux = dx / L,
    uy = dy / L;
  const crA = rAx * uy - rAy * ux,
    crB = rBx * uy - rBy * ux;
  // The inverse effective mass along u, and the anchors' relative velocity along it.
  const K =
    sb[oA + BS.BS2_INV_MASS]! +
    sb[oB + BS.BS2_INV_MASS]! +
    sb[oA + BS.BS2_INV_INERTIA]! * crA * crA +
    sb[oB + BS.BS2_INV_INERTIA]! * crB * crB;
  const wA = sb[oA + BS.BS2_W]!,
    wB = sb[oB + BS.BS2_W]!;
  let vr =
    (sb[oB + BS.BS2_VX]! - wB * rBy - sb[oA + BS.BS2_VX]! + wA * rAy) * ux +
    (sb[oB + BS.BS2_VY]! + wB * rBx - sb[oA + BS.BS2_VY]! - wA * rAx) * uy;
  const k = rows[o + R.KAX]!;
  const minL = rows[o + R.MINL]!,
    maxL = rows[o + R.MAXL]!;
  let total = 0;
  if (minL < maxL) {
    if (flags & JointFlag.Spring) {
      const impulse = springImpulse(vr, L - rows[o + R.LEN]!, K, rows[o + R.ISPR]!, rows[o + R.SB]!, rows[o + R.SM]!);
      rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
      total += impulse;
      vr += impulse * K;
    }
    if (minL > 0) {
      const impulse = limitRow(p, o, R.ILOW, L - minL, k, vr);
      total += impulse;
      vr += impulse * K;
    }
    if (maxL < Infinity) total -= limitRow(p, o, R.IUP, maxL - L, k, -vr);
  } else {
    const C = L - rows[o + R.LEN]!;
    let bias = 0,
      ms = 1,
      is = 0;
    if (p.useBias) {
      bias = rows[o + R.JB]! * C;
      ms = rows[o + R.JM]!;
      is = rows[o + R.JI]!;
    }
    const impulse = -ms * k * (vr + bias) - is * rows[o + R.ISPR]!;
    rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
    total = impulse;
  }
  const px = total * ux,
    py = total * uy;
  applyImpulse(sb, oA, oB, px, py, rAx * py - rAy * px, rBx * py - rBy * px);
  // A taut (or sprung) link pushes its bodies; a slack rope leaves them in free flight.
  return rows[o + R.ISPR] !== 0 || rows[o + R.ILOW] !== 0 || rows[o + R.IUP] !== 0 ? R.ROW_PUSHED : R.ROW_MOVED;
}

/**
 * A distance joint's reading after the step into out (rows-2d.ts JointTypeRows2D): its force along the
 * anchors' line (N), its error outside its length or limits (m) and its strain (length - rest) / rest.
 */
export function distanceReading(p: JointPass2D, _ia: number, _ib: number, o: number, _flags: number, out: Float64Array): void {
  const { rows, f } = p;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const L = Math.sqrt(dx * dx + dy * dy);
  out[0] = Math.abs(rows[o + R.ISPR]! + rows[o + R.ILOW]! - rows[o + R.IUP]!) * f[R.F_INVH]!;
  const minL = rows[o + R.MINL]!,
    maxL = rows[o + R.MAXL]!,
    rest = rows[o + R.LEN]!;
  out[2] = minL < maxL ? Math.max(0, minL - L, L - maxL) : Math.abs(L - rest);
  out[3] = rest > 0 ? (L - rest) / rest : 0;
}

/**
 * The point links' warm start (once per substep, before the contacts'): each link's accumulated impulse
 * applied again along the anchors' current line.
 */
export function warmStartPointLinks(world: PhysicsWorld): void {
  const js = world.joints;
  const sb = world.collision.bodyState;
  const lf = js.links,
    lint = js.linkInts;
  for (let l = 0, m = js.linkCount; l < m; l++) {
    const f = l * LINK_FLOATS,
      i = l * LINK_INTS;
    const acc = lf[f + R.LK_ACC]!;
    if (acc === 0) continue;
    const oA = lint[i + R.LK_OA]!,
      oB = lint[i + R.LK_OB]!;
    const dx = sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + lf[f + R.LK_DX]!,
      dy = sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + lf[f + R.LK_DY]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const s = acc / L;
    linkImpulse(sb, oA, oB, s * dx, s * dy);
  }
}

/** A point link's linear impulse P (N s): -P to the body at body-state offset oA, +P to oB's (neither turns). */
function linkImpulse(sb: Float64Array, oA: number, oB: number, px: number, py: number): void {
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    mB = sb[oB + BS.BS2_INV_MASS]!;
  sb[oA + BS.BS2_VX] = sb[oA + BS.BS2_VX]! - mA * px;
  sb[oA + BS.BS2_VY] = sb[oA + BS.BS2_VY]! - mA * py;
  sb[oB + BS.BS2_VX] = sb[oB + BS.BS2_VX]! + mB * px;
  sb[oB + BS.BS2_VY] = sb[oB + BS.BS2_VY]! + mB * py;
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
    const oA = lint[i + R.LK_OA]!,
      oB = lint[i + R.LK_OB]!;
    const dx = sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + lf[f + R.LK_DX]!,
      dy = sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + lf[f + R.LK_DY]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const ux = dx / L,
      uy = dy / L;
    const vAx = sb[oA + BS.BS2_VX]!,
      vAy = sb[oA + BS.BS2_VY]!,
      vBx = sb[oB + BS.BS2_VX]!,
      vBy = sb[oB + BS.BS2_VY]!;
    const vr = (vBx - vAx) * ux + (vBy - vAy) * uy;
    const C = L - lf[f + R.LK_LEN]!;
    const acc = lf[f + R.LK_ACC]!;
    let impulse: number;
    if (lf[f + R.LK_ROPE] === 0) {
      impulse = -jm * lf[f + R.LK_MASS]! * (vr + jb * C) - ji * acc;
      lf[f + R.LK_ACC] = acc + impulse;
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
      let next = old - ms * lf[f + R.LK_MASS]! * (-vr + bias) - is * old;
      if (next < 0) next = 0;
      lf[f + R.LK_ACC] = -next;
      impulse = old - next;
    }
    linkImpulse(sb, oA, oB, impulse * ux, impulse * uy);
    if (lf[f + R.LK_ACC] !== 0) {
      sb[oA + BS.BS2_PUSHED] = 1;
      sb[oB + BS.BS2_PUSHED] = 1;
    }
  }
}

/** The point links' accumulated impulses back into their rows (the spring slot of a rod, the upper limit's of a rope), which keep them for the next step. */
export function finishPointLinks(js: JointState): void {
  const rows = js.rows;
  const lf = js.links,
    lint = js.linkInts;
  for (let l = 0, m = js.linkCount; l < m; l++) {
    const f = l * LINK_FLOATS,
      o = lint[l * LINK_INTS + R.LK_ROW]! * ROW_FLOATS;
    if (lf[f + R.LK_ROPE] === 0) rows[o + R.ISPR] = lf[f + R.LK_ACC]!;
    else rows[o + R.IUP] = -lf[f + R.LK_ACC]!;
  }
}

/** The 2D distance joint's row functions (rows-2d.ts JointTypeRows2D). */
export const DISTANCE_ROWS_2D: JointTypeRows2D = {
  prepare: prepareDistanceRow,
  solve: solveDistanceRow,
};
