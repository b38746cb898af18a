import * as BS from '../solver/body-state-layout.js';
import { assertNonNegative } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, type JointStore, JointType } from '../world/joint-store-2d.js';
import { ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, checkEnds2D, makeJoint } from './joint-2d.js';
import { type JointBaseOptions, optionalPoint } from './joint-base.js';
import * as R from './layout-2d.js';
import { angularMass, applyImpulse, type JointPass2D, type JointTypeRows2D, pointForce, solvePointRow } from './rows-2d.js';
import { soft } from './softness.js';

/**
 * The 2D weld joint (glues two bodies, rigidly or as linear and angular springs): its options,
 * addWeldJoint, and its row's preparation, solve and reading (its warm start is rows-2d.ts
 * warmStartPoint). joints/solver-2d.ts runs them.
 */

/**
 * Options of `addWeldJoint`.
 * @category Joints and ropes
 */
export interface WeldJointOptions extends JointBaseOptions {
  /** Weld point, world, m. Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Linear softness, Hz, >= 0 (0 = rigid). Default 0. */
  hertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  dampingRatio?: number;
  /** Angular softness, Hz, >= 0 (0 = rigid). Default 0. */
  angularHertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  angularDampingRatio?: number;
}

/**
 * Adds a weld joint: B is glued to A at `anchor` with their relative angle fixed; soft (a springy
 * beam) when given hertz. Box2D v3's weld joint.
 * @returns the joint entity. @throws TypeError | RangeError on bad bodies, options or values.
 * @category Joints and ropes
 */
export function addWeldJoint(world: PhysicsWorld, options: WeldJointOptions): number {
  const where = 'addWeldJoint';
  const ends = checkEnds2D(where, world, options, ['anchor', 'hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio']);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const vals = [options.hertz ?? 0, options.dampingRatio ?? 0, options.angularHertz ?? 0, options.angularDampingRatio ?? 0];
  ['hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio'].forEach((name, i) => {
    assertNonNegative(where, name, vals[i]);
  });
  const j = makeJoint(world, JointType.Weld, ends, p, p, options);
  const J = world.components.Joint;
  J.hertz[j] = vals[0]!;
  J.dampingRatio[j] = vals[1]!;
  J.angularHertz[j] = vals[2]!;
  J.angularDampingRatio[j] = vals[3]!;
  return currentHandle(world, j);
}

/**
 * Prepares weld joint `j`'s row r (its masses at the start of the step in the frame `f`): the effective
 * mass of the relative rotation; the linear part's softness, its spring's (the Spring flag) or the
 * rigid rows'; the angular part's, its spring's (WELD_ANGULAR_SOFT) or the rigid rows'.
 */
export function prepareWeldRow(js: JointState, J: JointStore, j: number, r: number, f: Float64Array): void {
  const hs = f[R.F_HS]!;
  const rows = js.rows,
    ri = js.rowInts;
  const o = r * ROW_FLOATS,
    q = r * ROW_INTS;
  let flags = ri[q + R.TF]! >> 8;
  rows[o + R.KAX] = angularMass(f[R.F_IA]!, f[R.F_IB]!);
  if (J.hertz[j]! > 0) {
    rows[o + R.JB] = rows[o + R.SB]!;
    rows[o + R.JM] = rows[o + R.SM]!;
    rows[o + R.JI] = rows[o + R.SI]!;
    flags |= JointFlag.Spring;
  } else flags &= ~JointFlag.Spring;
  const ah = J.angularHertz[j]!;
  if (ah > 0) {
    soft(rows, o + R.AB, ah, J.angularDampingRatio[j]!, hs);
    flags |= R.WELD_ANGULAR_SOFT;
  } else {
    rows[o + R.AB] = js.softness[0]!;
    rows[o + R.AM] = js.softness[1]!;
    rows[o + R.AI] = js.softness[2]!;
  }
  ri[q + R.TF] = JointType.Weld | (flags << 8);
}

/**
 * One pass of a weld joint's rows (Box2D v3's b2SolveWeldJoint) on its frame: both parts soft as one
 * 3 x 3 system (solveSoftWeld) when it can, else the angular row (soft when the weld's angular part
 * is, or while the pass uses bias) and the anchors' point-to-point block (soft when the weld has a
 * linear spring, or while the pass uses bias). @returns ROW_PUSHED.
 */
export function solveWeldRow(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number {
  const { sb, rows } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  const turns = sb[oA + BS.BS2_INV_INERTIA]! + sb[oB + BS.BS2_INV_INERTIA]! !== 0;
  if (flags & R.WELD_ANGULAR_SOFT && flags & JointFlag.Spring && turns && solveSoftWeld(p, oA, oB, o)) return R.ROW_PUSHED;
  let bias = 0,
    ms = 1,
    is = 0;
  if (p.useBias || flags & R.WELD_ANGULAR_SOFT) {
    bias = rows[o + R.AB]! * p.f[R.F_REL]!;
    ms = rows[o + R.AM]!;
    is = rows[o + R.AI]!;
  }
  const wA = sb[oA + BS.BS2_W]!,
    wB = sb[oB + BS.BS2_W]!;
  const impulse = -ms * rows[o + R.KAX]! * (wB - wA + bias) - is * rows[o + R.IANG]!;
  rows[o + R.IANG] = rows[o + R.IANG]! + impulse;
  sb[oA + BS.BS2_W] = wA - sb[oA + BS.BS2_INV_INERTIA]! * impulse;
  sb[oB + BS.BS2_W] = wB + sb[oB + BS.BS2_INV_INERTIA]! * impulse;
  solvePointRow(p, oA, oB, o, p.useBias || (flags & JointFlag.Spring) !== 0);
  return R.ROW_PUSHED;
}

/** A weld joint's reading after the step into out: its point force (N), its angular torque (N m), and a rigid weld's anchor separation (m). */
export function weldReading(p: JointPass2D, _ia: number, _ib: number, o: number, flags: number, out: Float64Array): void {
  const f = p.f;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  out[0] = pointForce(p, o);
  out[1] = Math.abs(p.rows[o + R.IANG]!) * f[R.F_INVH]!;
  if (!(flags & JointFlag.Spring)) out[2] = Math.sqrt(dx * dx + dy * dy);
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
 * the soft row's update). Reads the anchors from the frame `f`;
 * returns false (nothing done) when a part has no spring (mass scale 0) or the system is singular, for
 * the row-by-row update.
 */
function solveSoftWeld(p: JointPass2D, oA: number, oB: number, o: number): boolean {
  const { sb, rows, f } = p;
  const msL = rows[o + R.JM]!,
    msA = rows[o + R.AM]!;
  if (!(msL > 0 && msA > 0)) return false;
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!,
    relAngle = f[R.F_REL]!;
  // The linear spring's reference: half the trace of its 2 x 2 block of A, which no rotation changes,
  // so the spring has a potential (k |separation|^2 / 2 with k = omega^2 / aRef) and cannot do work
  // around a closed path; the block itself turns with the anchors. impulseScale / massScale = 1 / a.
  const aRef = mA + mB + 0.5 * (iA * (rAx * rAx + rAy * rAy) + iB * (rBx * rBx + rBy * rBy));
  const gL = (aRef * rows[o + R.JI]!) / msL,
    gA = ((iA + iB) * rows[o + R.AI]!) / msA;
  const vAx = sb[oA + BS.BS2_VX]!,
    vAy = sb[oA + BS.BS2_VY]!,
    wA = sb[oA + BS.BS2_W]!,
    vBx = sb[oB + BS.BS2_VX]!,
    vBy = sb[oB + BS.BS2_VY]!,
    wB = sb[oB + BS.BS2_W]!;
  // A = J M^-1 J^T for the rows (x, y, angle); Box2D v2's weld matrix.
  const a11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB,
    a12 = -rAy * rAx * iA - rBy * rBx * iB,
    a22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB,
    a13 = -rAy * iA - rBy * iB,
    a23 = rAx * iA + rBx * iB,
    a33 = iA + iB;
  const lx = rows[o + R.ILX]!,
    ly = rows[o + R.ILY]!,
    lt = rows[o + R.IANG]!;
  const m11 = a11 + gL,
    m12 = a12,
    m22 = a22 + gL,
    m33 = a33 + gA;
  const bL = rows[o + R.JB]!,
    bA = rows[o + R.AB]!;
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
  rows[o + R.ILX] = lx + ix;
  rows[o + R.ILY] = ly + iy;
  rows[o + R.IANG] = lt + it;
  applyImpulse(sb, oA, oB, ix, iy, rAx * iy - rAy * ix + it, rBx * iy - rBy * ix + it);
  return true;
}

/** The 2D weld joint's row functions (rows-2d.ts JointTypeRows2D). */
export const WELD_ROWS_2D: JointTypeRows2D = {
  prepare: prepareWeldRow,
  solve: solveWeldRow,
};
