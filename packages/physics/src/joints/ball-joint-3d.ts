import { assertFinite, describe } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, type Joint3DBaseOptions, make, requireJoint3D, unit, wakeJoint3D } from './joint-3d.js';
import { checkEnds, optionalPoint } from './joint-base.js';
import * as R3 from './rows-3d.js';
import { applyAngular, ax, bx, qa, qb, relativeSpin, rot, row3D } from './rows-3d-math.js';
import { Joint3DFlag, Joint3DType, joints3DOf } from './store-3d.js';

/**
 * The 3D ball-and-socket joint (a shared point, with an optional cone limit on B's axis): its options,
 * addBallJoint3D and setBallJoint3DCone, and its rows (BALL_ROWS_3D), which joints/solver-3d.ts runs
 * with the other 3D joints'.
 */

/**
 * Options of `addBallJoint3D`.
 * @category Joints and ropes
 */
export interface BallJoint3DOptions extends Joint3DBaseOptions {
  /** The joint's point (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Cone limit: the axis (world, when made) that B's copy of it may swing away from A's by at most `coneAngle`. Default (0, 1, 0). */
  axis?: ArrayLike<number>;
  /** Cone half angle, rad, in (0, pi). Default none (free swing). */
  coneAngle?: number;
}

/**
 * Ball and socket: the anchor points of A and B coincide (three soft rows); with `coneAngle`, B's axis
 * stays within that angle of A's (a swing cone). @returns the joint's handle.
 * @throws TypeError | RangeError `addBallJoint3D: <param> must be ...` in a 2D world, on missing or bad
 *   bodies (removed, not 3D bodies, the same twice), bad vectors, a cone angle outside (0, pi), a bad
 *   break threshold, or a full world.
 * @category Joints and ropes
 */
export function addBallJoint3D(world: PhysicsWorld, options: BallJoint3DOptions): number {
  const where = 'addBallJoint3D';
  const e = checkEnds(where, world, options, 3, ['anchor', 'axis', 'coneAngle']);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, e.b));
  const axis = options.axis === undefined ? ([0, 1, 0] as [number, number, number]) : unit(where, 'axis', options.axis);
  if (options.coneAngle !== undefined) checkConeAngle(where, options.coneAngle);
  const j = make(world, where, Joint3DType.Ball, BALL_ROWS_3D, e, options, p, p, axis);
  const s = joints3DOf(world, true);
  if (options.coneAngle !== undefined) {
    s.flags[j] = Joint3DFlag.Cone;
    s.upper[j] = options.coneAngle;
  }
  return currentHandle(world, j);
}

/**
 * Sets (or with `coneAngle` null removes) a ball-and-socket joint's cone limit: B's copy of the cone
 * axis (the `axis` given to addBallJoint3D, default (0, 1, 0), as the bodies were when the joint was
 * made) may swing at most `coneAngle` away from A's. A joint made without a cone gets one about that
 * axis. The cone's warm-start impulse starts again from zero; the bodies wake. Bodies already outside
 * a narrower cone are brought back at the joints' soft rate (60 Hz, capped at a quarter of the
 * substep rate), not in one step.
 * @param coneAngle half angle, rad, in (0, pi); null removes the limit.
 * @throws RangeError `setBallJoint3DCone: joint must be ...` on a removed entity or a joint that is not
 *   a 3D ball joint; TypeError | RangeError `setBallJoint3DCone: coneAngle must be ...` naming the value.
 *   A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setBallJoint3DCone(world: PhysicsWorld, joint: number, coneAngle: number | null): void {
  const where = 'setBallJoint3DCone';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Ball]);
  if (coneAngle !== null) {
    checkConeAngle(where, coneAngle);
    s.flags[j] = s.flags[j]! | Joint3DFlag.Cone;
    s.upper[j] = coneAngle;
  } else s.flags[j] = s.flags[j]! & ~Joint3DFlag.Cone;
  s.limit[j] = 0;
  wakeJoint3D(world, s, j);
}

/** A cone half angle, rad, finite and in (0, pi). @throws TypeError | RangeError `<where>: coneAngle must be ...` naming the value. */
function checkConeAngle(where: string, coneAngle: unknown): void {
  assertFinite(where, 'coneAngle', coneAngle);
  if (!(coneAngle > 0 && coneAngle < Math.PI)) throw new RangeError(`${where}: coneAngle must be in (0, pi), got ${describe(coneAngle)}`);
}

/** The cone's swing axis n = a_A x a_B, not normalised, into n3, of ball joint j's cone axis turned with A (into ax) and with B (into bx); @returns |n|. */
function coneNormal(p: R3.JointPass3D, j: number): number {
  const s = p.s;
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, ax);
  rot(qb, s.ubx[j]!, s.uby[j]!, s.ubz[j]!, bx);
  n3[0] = ax[1]! * bx[2]! - ax[2]! * bx[1]!;
  n3[1] = ax[2]! * bx[0]! - ax[0]! * bx[2]!;
  n3[2] = ax[0]! * bx[1]! - ax[1]! * bx[0]!;
  return Math.hypot(n3[0]!, n3[1]!, n3[2]!);
}

/** coneNormal's n. */
const n3 = new Float64Array(3);

/** A ball joint's cone: the angle between A's axis and B's stays within the half angle (s.upper). */
function solveCone(p: R3.JointPass3D, j: number, a: number, b: number): void {
  const s = p.s;
  const sn = coneNormal(p, j);
  let nx = n3[0]!,
    ny = n3[1]!,
    nz = n3[2]!;
  if (sn > 1e-9) {
    nx /= sn;
    ny /= sn;
    nz /= sn;
    // The swing phi about n, d phi / dt = (wB - wA) . n; the row C = half angle - phi >= 0 acts about -n.
    const phi = Math.atan2(sn, ax[0]! * bx[0]! + ax[1]! * bx[1]! + ax[2]! * bx[2]!);
    const cdot = -relativeSpin(p.sb, a, b, nx, ny, nz);
    R3.limitSoftness(p, s.upper[j]! - phi);
    s.limit[j] = row3D(
      p.sb,
      p.T,
      a,
      b,
      false,
      -nx,
      -ny,
      -nz,
      0,
      cdot,
      R3.limitSoft[0]!,
      R3.limitSoft[1]!,
      R3.limitSoft[2]!,
      s.limit[j]!,
      0,
      Infinity,
    );
  } else s.limit[j] = 0; // axes parallel: n undefined, far inside the cone; the row starts again from zero
}

/** A ball-and-socket joint: the point block, then its cone limit if it has one. */
export function solveBallRow3D(p: R3.JointPass3D, j: number, a: number, b: number, flags: number): void {
  R3.preparePointBlock(p, a, b);
  R3.solvePointRows(p, j, a, b);
  if (flags & Joint3DFlag.Cone) solveCone(p, j, a, b);
}

/**
 * A ball joint's warm start: its point impulse (and the angular lock's, which it does not have), then its
 * cone's impulse (limit, >= 0) about -n, n = a_A x a_B / |a_A x a_B| as in the solve; none when the axes
 * are parallel (n undefined).
 */
export function warmStartBallRow3D(p: R3.JointPass3D, j: number, a: number, b: number): void {
  R3.warmStartPointAndLock(p, j, a, b);
  const { s, sb, T } = p;
  if (s.limit[j]! !== 0) {
    const sn = coneNormal(p, j),
      l = -s.limit[j]! / sn;
    if (sn > 1e-9) applyAngular(sb, T, a, b, l * n3[0]!, l * n3[1]!, l * n3[2]!);
  }
}

/** The 3D ball joint's rows (rows-3d.ts JointRows3D). */
export const BALL_ROWS_3D: R3.JointRows3D = { warmStart: warmStartBallRow3D, solve: solveBallRow3D, reading: R3.pointJointReading };
