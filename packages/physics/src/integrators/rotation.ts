import { rotateInPlaceBy } from '../math/quaternion.js';
import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import { splitRigidRotations } from './euler-equations.js';
import { simpleSpinningBodies, tensorBodies, torquedBodies } from './queries.js';

/**
 * Angular velocity update of the semi-implicit Euler scheme: w += tau I^-1 h with a scalar moment of
 * inertia (2D: the z component; 3D: isotropic bodies such as balls), Newton's second law for rotation
 * (Ramtal and Dobre ch. 13); for 3D bodies with a principal inertia tensor, a torque kick and the
 * symplectic splitting of the free rigid body (`splitRigidRotations`), which also turns the orientation.
 * @category Integrators
 */
export function applyTorques(world: PhysicsWorld, h: number): void {
  const c = world.components;
  if (world.dimensions === 3) {
    // Principal inertia tensors: the free rigid-body splitting turns w and the orientation together
    // (euler-equations.ts), so advanceOrientations leaves these bodies alone.
    splitRigidRotations(world, tensorBodies(world), h);
  }
  const ents = torquedBodies(world);
  if (ents.length === 0) return;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const { x: tx, y: ty, z: tz } = c.Torque;
  const ii = c.Inertia.inv;
  if (world.dimensions === 2) {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      wz[e] = wz[e]! + tz[e]! * ii[e]! * h;
    }
  } else {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const k = ii[e]! * h;
      wx[e] = wx[e]! + tx[e]! * k;
      wy[e] = wy[e]! + ty[e]! * k;
      wz[e] = wz[e]! + tz[e]! * k;
    }
  }
}

/**
 * Advances orientations with the current angular velocity over h.
 * 2D: angle += w_z h. 3D: q <- exp(w h / 2) q, the exact rotation by |w| h about w (world frame)
 * for constant w, then renormalised so |q| stays 1 to rounding.
 * Source: Shoemake, "Animating rotation with quaternion curves" (SIGGRAPH 1985); Ramtal and Dobre ch. 15.
 * @category Integrators
 */
export function advanceOrientations(world: PhysicsWorld, h: number): void {
  const ents = simpleSpinningBodies(world);
  if (ents.length === 0) return;
  const check = world.dimensions === 2 ? advanceAngles(world, ents, h) : advanceQuaternions(world, ents, h);
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');
}

/*
 * The two loops of advanceOrientations, each a function that returns its finiteness sum and does
 * nothing after its loop: run once a step, a long loop is compiled on the stack (OSR) during its
 * first call, and an operation after it that had not run by then threw that code away at every
 * later call (70 times in 100 steps of a threaded balls-in-box at 20,000 balls).
 */

/** 2D: angle += w_z h for every body of `ents`; returns the sum of their w_z (NaN if one is not finite). */
function advanceAngles(world: PhysicsWorld, ents: ArrayLike<number>, h: number): number {
  const a = world.components.Angle.value,
    wz = world.components.AngularVelocity.z;
  let check = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const w = wz[e]!;
    a[e] = a[e]! + w * h;
    check += w;
  }
  return check;
}

/** advanceQuaternions' rotation vector w h of one body (scratch). */
const spin = new Float64Array(3);

/**
 * 3D: q <- exp(w h / 2) q for every body of `ents`; returns the sum of their w components (NaN if one
 * is not finite). The rotation is math/quaternion.ts rotateInPlaceBy, its rotation vector in an array:
 * where V8 does not inline the call, numbers would go boxed, a few heap numbers a body a step.
 */
function advanceQuaternions(world: PhysicsWorld, ents: ArrayLike<number>, h: number): number {
  const c = world.components;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const { x: qx, y: qy, z: qz } = c.Orientation,
    qw = c.Orientation.w;
  let check = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const ax = wx[e]!,
      ay = wy[e]!,
      az = wz[e]!;
    check += ax + ay + az;
    if (ax === 0 && ay === 0 && az === 0) continue;
    spin[0] = ax * h;
    spin[1] = ay * h;
    spin[2] = az * h;
    rotateInPlaceBy(qx, qy, qz, qw, e, spin);
  }
  return check;
}
