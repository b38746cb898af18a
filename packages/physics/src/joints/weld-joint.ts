import { assertKnownKeys, assertNonNegative } from '../validation/validate.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { BASE_KEYS, centre, checkEnds, handle, type JointBaseOptions, makeJoint, optionalPoint } from './joint-2d.js';
import * as R from './layout-2d.js';
import { solvePointBlock } from './rows-2d.js';

/**
 * The 2D weld joint (glues two bodies, rigidly or as linear and angular springs): its options,
 * addWeldJoint and its row solve. Its rows are prepared and finished with the other 2D joints'
 * (joints/prepare-2d.ts, finish-2d.ts) and solved in their loop (joints/solve-2d.ts).
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
  const ends = checkEnds(where, world, options);
  assertKnownKeys(where, options, [...BASE_KEYS, 'anchor', 'hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio'], ['a']);
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
  return handle(world, j);
}

/**
 * One pass of a weld joint's rows (Box2D v3's b2SolveWeldJoint) on the frame `f` of layout-2d.ts:
 * both parts soft as one 3 x 3 system (solveSoftWeld) when it can, else the angular row (soft when the
 * weld's angular part is, or while `useBias`) and the anchors' point-to-point block (soft when the weld
 * has a linear spring, or while `useBias`). @returns ROW_PUSHED.
 */
export function solveWeldRow(rows: Float64Array, o: number, flags: number, useBias: boolean, f: Float64Array): number {
  const iA = f[R.F_IA]!,
    iB = f[R.F_IB]!;
  if (flags & R.WELD_ANGULAR_SOFT && flags & JointFlag.Spring && iA + iB !== 0 && solveSoftWeld(rows, o, f)) return R.ROW_PUSHED;
  const kax = rows[o + R.KAX]!;
  let wA = f[R.F_WA]!,
    wB = f[R.F_WB]!;
  let bias = 0,
    ms = 1,
    is = 0;
  if (useBias || flags & R.WELD_ANGULAR_SOFT) {
    bias = rows[o + R.AB]! * f[R.F_REL]!;
    ms = rows[o + R.AM]!;
    is = rows[o + R.AI]!;
  }
  const impulse = -ms * kax * (wB - wA + bias) - is * rows[o + R.IANG]!;
  rows[o + R.IANG] = rows[o + R.IANG]! + impulse;
  wA -= iA * impulse;
  wB += iB * impulse;
  f[R.F_WA] = wA;
  f[R.F_WB] = wB;
  solvePointBlock(rows, o, f, useBias || (flags & JointFlag.Spring) !== 0);
  return R.ROW_PUSHED;
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
 * the soft row's update). Reads the bodies' velocities from the frame `f` and writes them back;
 * returns false (nothing done) when a part has no spring (mass scale 0) or the system is singular, for
 * the row-by-row update.
 */
function solveSoftWeld(rows: Float64Array, o: number, f: Float64Array): boolean {
  const msL = rows[o + R.JM]!,
    msA = rows[o + R.AM]!;
  if (!(msL > 0 && msA > 0)) return false;
  const mA0 = f[R.F_MA]!,
    iA0 = f[R.F_IA]!,
    mB0 = f[R.F_MB]!,
    iB0 = f[R.F_IB]!;
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
  const aRef = mA0 + mB0 + 0.5 * (iA0 * (rAx * rAx + rAy * rAy) + iB0 * (rBx * rBx + rBy * rBy));
  const gL = (aRef * rows[o + R.JI]!) / msL,
    gA = ((iA0 + iB0) * rows[o + R.AI]!) / msA;
  const mA = mA0,
    iA = iA0,
    mB = mB0,
    iB = iB0;
  const vAx = f[R.F_VAX]!,
    vAy = f[R.F_VAY]!,
    wA = f[R.F_WA]!,
    vBx = f[R.F_VBX]!,
    vBy = f[R.F_VBY]!,
    wB = f[R.F_WB]!;
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
  f[R.F_VAX] = vAx - mA * ix;
  f[R.F_VAY] = vAy - mA * iy;
  f[R.F_WA] = wA - iA * (rAx * iy - rAy * ix + it);
  f[R.F_VBX] = vBx + mB * ix;
  f[R.F_VBY] = vBy + mB * iy;
  f[R.F_WB] = wB + iB * (rBx * iy - rBy * ix + it);
  return true;
}
