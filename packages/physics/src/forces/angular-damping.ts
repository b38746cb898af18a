import { hasComponent } from 'bitecs';
import { rotateInPlace, rotateVector, rotateVectorInverse } from '../math/quaternion.js';
import { runParallel } from '../threads/parallel.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import { dissipationState, linearDecay, STIFF_RATE } from './dissipation.js';
import { velocityDamping } from './drag.js';
import type { ForceLaw } from './law.js';

/**
 * The largest inverse moment of inertia of body e, 1/(kg m^2), that sets its damping rate k h / I:
 * in 2D the scalar `Inertia.inv`; in 3D the largest of `Inertia.inv` and the inverse principal moments
 * of `InertiaTensor` (a body has one or the other; the other reads 0, or what an earlier entity of the
 * slot left, which can only make the rate look larger: the stiff update is exact for the damping
 * alone, so that costs at most accuracy in the coupling, never stability). The torque law and the
 * stiff update use this same rate, so they always agree on the regime.
 */
function largestInverseInertia(world: PhysicsWorld, e: number, is2D: boolean): number {
  const c = world.components;
  const ii = c.Inertia.inv[e]!;
  if (is2D) return ii;
  const T = c.InertiaTensor;
  return Math.max(ii, T.invX[e]!, T.invY[e]!, T.invZ[e]!);
}

/**
 * Angular damping: torque tau = -k w on every body with `AngularDamping` (k in N m s, >= 0); without
 * other torques w(t) = w0 e^(-k t / I). Velocity-dependent. Source: Ramtal and Dobre ch. 13 (rotational
 * analogue of linear drag).
 *
 * A torque while k h / I < STIFF_RATE (I the smallest principal moment); at or above it this law adds
 * nothing and `stiffAngularDampingSystem` applies the exact decay w <- w exp(-k h / I) after the
 * integrator, so the damping never reverses or amplifies the spin at any step size (see
 * forces/dissipation.ts).
 * @category Forces
 */
export const angularDampingSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.AngularDamping, c.AngularVelocity, c.Torque]);
  if (ents.length === 0) return;
  const k = c.AngularDamping.k,
    { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const { x: tx, y: ty, z: tz } = c.Torque;
  const h = world.h;
  const is2D = world.dimensions === 2;
  const ii = c.Inertia.inv;
  // 2D (a scalar moment of inertia): the linear drag kernel with inertia for mass (forces/drag.ts
  // `velocityDamping`: stiff when k I^-1 h >= STIFF_RATE), on the world's threads when that pays.
  let stiff = 0;
  if (is2D) {
    stiff = runParallel(
      world,
      'angularDampingSystem',
      velocityDamping,
      [k, ii, wx, wy, wz, tx, ty, tz],
      [STIFF_RATE, 0, h],
      ents.length,
      ents,
    );
  } else {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const d = k[e]!;
      if (d * largestInverseInertia(world, e, false) * h >= STIFF_RATE) {
        stiff++;
        continue;
      }
      tx[e] = tx[e]! - d * wx[e]!;
      ty[e] = ty[e]! - d * wy[e]!;
      tz[e] = tz[e]! - d * wz[e]!;
    }
  }
  if (stiff > 0) {
    const s = dissipationState(world);
    s.angularSeen = s.epoch;
  }
};

const wb = new Float64Array(3),
  back = new Float64Array(3);

/**
 * Integrate stage, after the integrator: the stiff regime of angular damping (see
 * forces/dissipation.ts). For each turning body whose damping added no torque this (sub)step:
 * w <- w exp(-k h / I) with a scalar moment of inertia; with a principal inertia tensor, each
 * body-frame component w_i <- w_i exp(-k h / I_i) (the exact solution of I_i w_i' = -k w_i; a locked
 * axis, 1/I_i = 0, keeps its spin). The orientation is then turned by h times the change of w, so the
 * body turns over the step with its damped angular velocity.
 * @category Forces
 */
export const stiffAngularDampingSystem = (world: PhysicsWorld): void => {
  const st = dissipationState(world);
  if (st.angularSeen !== st.epoch) return;
  const c = world.components;
  const is2D = world.dimensions === 2;
  const ents = query(world, [
    c.AngularDamping,
    c.AngularVelocity,
    c.Torque,
    is2D ? c.Angle : c.Orientation,
    Not(c.Static),
    Not(c.Kinematic),
    Not(c.Sleeping),
  ]);
  const h = world.h,
    k = c.AngularDamping.k;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const angle = c.Angle.value,
    q = c.Orientation,
    T = c.InertiaTensor;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const d = k[e]!;
    if (d * largestInverseInertia(world, e, is2D) * h < STIFF_RATE) continue;
    const ox = wx[e]!,
      oy = wy[e]!,
      oz = wz[e]!;
    if (is2D) {
      const nz = oz * linearDecay(d * c.Inertia.inv[e]! * h);
      wz[e] = nz;
      angle[e] = angle[e]! + h * (nz - oz);
      continue;
    }
    const qx = q.x[e]!,
      qy = q.y[e]!,
      qz = q.z[e]!,
      qw = q.w[e]!;
    if (hasComponent(world, e, T)) {
      rotateVectorInverse(qx, qy, qz, qw, ox, oy, oz, wb);
      rotateVector(
        qx,
        qy,
        qz,
        qw,
        wb[0]! * linearDecay(d * T.invX[e]! * h),
        wb[1]! * linearDecay(d * T.invY[e]! * h),
        wb[2]! * linearDecay(d * T.invZ[e]! * h),
        back,
      );
      wx[e] = back[0]!;
      wy[e] = back[1]!;
      wz[e] = back[2]!;
    } else {
      const f = linearDecay(d * c.Inertia.inv[e]! * h);
      wx[e] = ox * f;
      wy[e] = oy * f;
      wz[e] = oz * f;
    }
    rotateInPlace(q.x, q.y, q.z, q.w, e, h * (wx[e]! - ox), h * (wy[e]! - oy), h * (wz[e]! - oz));
  }
};

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(angularDampingSystem, (w) => [[w.components.AngularDamping, w.components.AngularVelocity, w.components.Torque]]);
