/**
 * The relative motion of a contact row's two bodies as the impact stage (solver/impacts.ts) sweeps it:
 * body B's motion seen from body A, on the packed solver state (CollisionState.bodyState) and the
 * impact rows (CollisionState.bodyImpact, solver/body-state-layout.ts).
 */

import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import { BodyType } from '../collision/state.js';
import type { PhysicsWorld } from '../world/options.js';
import { BI_CORR_X, BI_CORR_Y, BI_CORR_Z, BI_TIME, BS2_STRIDE, BS2_VX, BS2_VY, BS3_VZ, IMPACT_STRIDE } from './body-state-layout.js';
import { sweepIO } from './impact-state.js';

/**
 * The factor of gravity in body B's acceleration relative to body A's (dimensionless: -1, 0 or 1):
 * 1 for each of the bodies that gravity moves (dynamic; entity `a` 0 is the static world), B counted
 * plus and A minus. `type` is CollisionState.bodyType, by entity.
 */
export function gravitySign(type: Uint8Array, a: number, b: number): number {
  return (type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0);
}

/**
 * (v_B - v_A) . n, m/s: the normal relative velocity of the bodies whose packed rows start at `oa` and
 * `ob` in `sb` (stride S: BS2_STRIDE, or BS3_STRIDE with the z component), n = (nx, ny, nz) from A to B
 * (nz unused in 2D). Negative while they approach.
 */
export function normalVelocity(sb: Float64Array, oa: number, ob: number, nx: number, ny: number, nz: number, S: number): number {
  let vn = (sb[ob + BS2_VX]! - sb[oa + BS2_VX]!) * nx + (sb[ob + BS2_VY]! - sb[oa + BS2_VY]!) * ny;
  if (S !== BS2_STRIDE) vn += (sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!) * nz;
  return vn;
}

/**
 * The later of two bodies' latest impacts this step, s (>= 0; 0, the start of the step, if neither
 * had one): their impact rows start at `qa` and `qb` in `imp` (a row's BI_TIME is -1 when the body is
 * left to the substeps).
 */
export function latestImpactTime(imp: Float64Array, qa: number, qb: number): number {
  const ta = imp[qa + BI_TIME]!,
    tb = imp[qb + BI_TIME]!;
  return ta > tb ? (ta > 0 ? ta : 0) : tb > 0 ? tb : 0;
}

/**
 * Scratch of `ballMotion` and `faceMotion`: body B's acceleration of gravity relative to A's (x, y, z, m/s^2),
 * or a face contact's gap, normal speed and normal acceleration at t0. Not world state.
 */
export const motionIO = new Float64Array(3);

/** The sum of the two radii of ball contact i (Ball or StaticBall, whose A is a feature ball), m. */
export function contactRadius(world: PhysicsWorld, buf: ContactBuffer, i: number): number {
  const radius = world.components.Ball.radius;
  return radius[buf.kind[i] === ContactKind.Ball ? buf.a[i]! : buf.feature[i]!]! + radius[buf.b[i]!]!;
}

/**
 * Ball B of ball contact i seen from A at time t0 of the step (s), at the current solver velocities
 * (rows of stride S: BS2_STRIDE or BS3_STRIDE) and with the bodies' end-position corrections: writes the
 * relative position r = r0 + c_B - c_A + w t0 + a t0^2 / 2 to sweepIO 0-2, the relative velocity w + a t0
 * to 3-5 and the sum of the radii to 6 (`sweep`'s slots), and the relative acceleration a to motionIO.
 */
export function ballMotion(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number, t0: number): void {
  const c = world.components,
    cs = world.collision;
  const sb = cs.bodyState,
    imp = cs.bodyImpact;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S,
    qa = ia * IMPACT_STRIDE,
    qb = ib * IMPACT_STRIDE;
  const a = buf.a[i]!,
    b = buf.b[i]!;
  const is2D = S === BS2_STRIDE;
  const P = c.PreviousPosition;
  const f = buf.kind[i] === ContactKind.Ball ? a : buf.feature[i]!;
  const pa = buf.kind[i] === ContactKind.Ball ? P : c.Position;
  const g = world.gravity;
  const gr = gravitySign(cs.bodyType, a, b);
  const ax = gr * g[0]!,
    ay = gr * g[1]!,
    az = is2D ? 0 : gr * g[2]!;
  const wx = sb[ob + BS2_VX]! - sb[oa + BS2_VX]!,
    wy = sb[ob + BS2_VY]! - sb[oa + BS2_VY]!,
    wz = is2D ? 0 : sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!;
  const io = sweepIO;
  io[0] = P.x[b]! + imp[qb + BI_CORR_X]! - pa.x[f]! - imp[qa + BI_CORR_X]! + wx * t0 + 0.5 * ax * t0 * t0;
  io[1] = P.y[b]! + imp[qb + BI_CORR_Y]! - pa.y[f]! - imp[qa + BI_CORR_Y]! + wy * t0 + 0.5 * ay * t0 * t0;
  io[2] = is2D ? 0 : P.z[b]! + imp[qb + BI_CORR_Z]! - pa.z[f]! - imp[qa + BI_CORR_Z]! + wz * t0 + 0.5 * az * t0 * t0;
  io[3] = wx + ax * t0;
  io[4] = wy + ay * t0;
  io[5] = wz + az * t0;
  io[6] = contactRadius(world, buf, i);
  motionIO[0] = ax;
  motionIO[1] = ay;
  motionIO[2] = az;
}

/**
 * Contact i's normal relative velocity v_n (m/s, negative while approaching) at the current solver
 * velocities (rows of stride S: BS2_STRIDE or BS3_STRIDE) and the normal component a_n of gravity's
 * relative acceleration (m/s^2), along its normal n: written to motionIO 1 and 2.
 */
export function normalMotion(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): void {
  const cs = world.collision,
    g = world.gravity;
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = buf.nz[i]!;
  motionIO[1] = normalVelocity(cs.bodyState, buf.ia[i]! * S, buf.ib[i]! * S, nx, ny, nz, S);
  motionIO[2] = gravitySign(cs.bodyType, buf.a[i]!, buf.b[i]!) * (g[0]! * nx + g[1]! * ny + g[2]! * nz);
}

/**
 * Fixed-normal contact i (boundary face, plane, segment) at time t0 of the step (s), at the current solver
 * velocities (rows of stride S) and with the bodies' end-position corrections, along its normal n: writes
 * the gap s(t0) = s0 + (c_B - c_A) . n + v_n t0 + a_n t0^2 / 2 (m), the normal speed v_n + a_n t0 and the
 * normal acceleration a_n of gravity (normalMotion) to motionIO 0-2.
 */
export function faceMotion(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number, t0: number): void {
  normalMotion(world, buf, i, S);
  const vn = motionIO[1]!,
    an = motionIO[2]!;
  const imp = world.collision.bodyImpact;
  const qa = buf.ia[i]! * IMPACT_STRIDE,
    qb = buf.ib[i]! * IMPACT_STRIDE;
  motionIO[0] =
    buf.separation[i]! +
    (imp[qb + BI_CORR_X]! - imp[qa + BI_CORR_X]!) * buf.nx[i]! +
    (imp[qb + BI_CORR_Y]! - imp[qa + BI_CORR_Y]!) * buf.ny[i]! +
    (imp[qb + BI_CORR_Z]! - imp[qa + BI_CORR_Z]!) * buf.nz[i]! +
    vn * t0 +
    0.5 * an * t0 * t0;
  motionIO[1] = vn + an * t0;
}
