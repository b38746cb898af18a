import { BS2_DX, BS2_DY, BS2_INV_MASS, BS2_PUSHED, BS2_VX, BS2_VY } from '../solver/body-state-layout.js';
import { assertKnownKeys, assertNonNegative, assertPositive, describe } from '../validation/validate.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import { LINK_FLOATS, LINK_INTS, ROW_FLOATS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertBreakLimit, BASE_KEYS, centre, checkEnds, handle, type JointBaseOptions, makeJoint, optionalPoint } from './joint-2d.js';
import * as R from './layout-2d.js';
import { limitRow, springImpulse } from './rows-2d.js';

/**
 * The 2D distance joint (a rod, a rope or a spring between two anchors): its options, addDistanceJoint,
 * its row solve, and the point links' passes (a rod or rope between two bodies that do not turn and
 * has no spring, packed by joints/prepare-2d.ts: warm start, solve, impulses back into the rows). Its
 * general rows are prepared and finished with the other 2D joints' (joints/prepare-2d.ts, finish-2d.ts)
 * and solved in their loop (joints/solve-2d.ts).
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
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchorA', 'anchorB', 'length', 'minLength', 'maxLength', 'hertz', 'dampingRatio', 'breakStretch'],
    ['a'],
  );
  if (ends.a === 0 && options.anchorA === undefined)
    throw new RangeError(`${where}: anchorA (a world point) is required when a is the world`);
  const pa = optionalPoint(where, 'anchorA', options.anchorA, ends.a === 0 ? [0, 0] : centre(world, ends.a));
  const pb = optionalPoint(where, 'anchorB', options.anchorB, centre(world, ends.b));
  const length = options.length ?? Math.hypot(pb[0] - pa[0], pb[1] - pa[1]);
  assertPositive(where, 'length', length);
  const hertz = options.hertz ?? 0;
  assertNonNegative(where, 'hertz', hertz);
  const zeta = options.dampingRatio ?? 0;
  assertNonNegative(where, 'dampingRatio', zeta);
  const minL = options.minLength ?? (hertz > 0 ? 0 : length);
  const maxL = options.maxLength ?? (hertz > 0 ? Infinity : length);
  assertNonNegative(where, 'minLength', minL);
  if (!(minL <= length)) throw new RangeError(`${where}: minLength must be <= length (${length}), got ${describe(minL)}`);
  if (typeof maxL !== 'number' || Number.isNaN(maxL) || !(maxL >= length))
    throw new RangeError(`${where}: maxLength must be >= length (${length}), got ${describe(maxL)}`);
  if (options.breakStretch !== undefined) assertBreakLimit(where, 'breakStretch', options.breakStretch);
  const j = makeJoint(world, JointType.Distance, ends, pa, pb, options);
  const J = world.components.Joint;
  J.length[j] = length;
  J.minLength[j] = minL;
  J.maxLength[j] = maxL;
  J.hertz[j] = hertz;
  J.dampingRatio[j] = zeta;
  J.flags[j] = (hertz > 0 ? JointFlag.Spring : 0) | (minL < maxL ? JointFlag.Limit : 0);
  J.breakStretch[j] = options.breakStretch ?? Infinity;
  return handle(world, j);
}

/**
 * One pass of a distance joint's row (Box2D v3's b2SolveDistanceJoint) on the frame `f` of
 * layout-2d.ts: the spring, then the lower and upper length limits (a rope link: only the upper), or
 * the rigid rod. @returns ROW_SKIPPED when the anchors coincide (no direction), ROW_PUSHED when the
 * link holds an impulse, else ROW_MOVED (a slack rope leaves its bodies in free flight).
 */
export function solveDistanceRow(rows: Float64Array, o: number, flags: number, useBias: boolean, f: Float64Array): number {
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const L = Math.sqrt(dx * dx + dy * dy);
  if (L < 1e-12) return R.ROW_SKIPPED;
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const vAx = f[R.F_VAX]!,
    vAy = f[R.F_VAY]!,
    wA = f[R.F_WA]!,
    vBx = f[R.F_VBX]!,
    vBy = f[R.F_VBY]!,
    wB = f[R.F_WB]!;
  const invH = f[R.F_INVH]!;
  const ux = dx / L,
    uy = dy / L;
  const crA = rAx * uy - rAy * ux,
    crB = rBx * uy - rBy * ux;
  const k = rows[o + R.KAX]!;
  const minL = rows[o + R.MINL]!,
    maxL = rows[o + R.MAXL]!;
  let total = 0;
  // Relative velocity of the anchors along u.
  let vr = (vBx - wB * rBy - vAx + wA * rAy) * ux + (vBy + wB * rBx - vAy - wA * rAx) * uy;
  if (minL < maxL) {
    if (flags & JointFlag.Spring) {
      const C = L - rows[o + R.LEN]!;
      const impulse = springImpulse(vr, C, mA + mB + iA * crA * crA + iB * crB * crB, rows[o + R.ISPR]!, rows[o + R.SB]!, rows[o + R.SM]!);
      rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
      total += impulse;
      vr += impulse * (mA + mB + iA * crA * crA + iB * crB * crB);
    }
    if (minL > 0) {
      const impulse = limitRow(rows, o, R.ILOW, L - minL, k, vr, invH, useBias);
      total += impulse;
      vr += impulse * (mA + mB + iA * crA * crA + iB * crB * crB);
    }
    if (maxL < Infinity) {
      total -= limitRow(rows, o, R.IUP, maxL - L, k, -vr, invH, useBias);
    }
  } else {
    const C = L - rows[o + R.LEN]!;
    let bias = 0,
      ms = 1,
      is = 0;
    if (useBias) {
      bias = rows[o + R.JB]! * C;
      ms = rows[o + R.JM]!;
      is = rows[o + R.JI]!;
    }
    const impulse = -ms * k * (vr + bias) - is * rows[o + R.ISPR]!;
    rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
    total = impulse;
  }
  const Px = total * ux,
    Py = total * uy;
  f[R.F_VAX] = vAx - mA * Px;
  f[R.F_VAY] = vAy - mA * Py;
  f[R.F_WA] = wA - iA * (rAx * Py - rAy * Px);
  f[R.F_VBX] = vBx + mB * Px;
  f[R.F_VBY] = vBy + mB * Py;
  f[R.F_WB] = wB + iB * (rBx * Py - rBy * Px);
  // A taut (or sprung) link pushes its bodies; a slack rope leaves them in free flight.
  return rows[o + R.ISPR] !== 0 || rows[o + R.ILOW] !== 0 || rows[o + R.IUP] !== 0 ? R.ROW_PUSHED : R.ROW_MOVED;
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
    const acc = lf[f + 4]!;
    if (acc === 0) continue;
    const oA = lint[i]!,
      oB = lint[i + 1]!;
    const dx = sb[oB + BS2_DX]! - sb[oA + BS2_DX]! + lf[f]!,
      dy = sb[oB + BS2_DY]! - sb[oA + BS2_DY]! + lf[f + 1]!;
    const L = Math.sqrt(dx * dx + dy * dy);
    if (L < 1e-12) continue;
    const s = acc / L,
      Px = s * dx,
      Py = s * dy,
      mA = sb[oA + BS2_INV_MASS]!,
      mB = sb[oB + BS2_INV_MASS]!;
    sb[oA + BS2_VX] = sb[oA + BS2_VX]! - mA * Px;
    sb[oA + BS2_VY] = sb[oA + BS2_VY]! - mA * Py;
    sb[oB + BS2_VX] = sb[oB + BS2_VX]! + mB * Px;
    sb[oB + BS2_VY] = sb[oB + BS2_VY]! + mB * Py;
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

/** The point links' accumulated impulses back into their rows (the spring slot of a rod, the upper limit's of a rope), which keep them for the next step. */
export function finishPointLinks(js: JointState): void {
  const rows = js.rows;
  const lf = js.links,
    lint = js.linkInts;
  for (let l = 0, m = js.linkCount; l < m; l++) {
    const f = l * LINK_FLOATS,
      o = lint[l * LINK_INTS + 2]! * ROW_FLOATS;
    if (lf[f + 5] === 0) rows[o + R.ISPR] = lf[f + 4]!;
    else rows[o + R.IUP] = -lf[f + 4]!;
  }
}
