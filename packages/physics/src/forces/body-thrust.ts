import { hasComponent } from 'bitecs';
import { assertVector } from '../validation/validate.js';
import { resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Sets the body-frame force of a body (`BodyThrust`), N: `force` has `world.dimensions` components
 * (along the body's own axes: x forward). It turns with the body; zero switches it off.
 * @throws TypeError | RangeError on a non-finite vector of the wrong length, or a missing, static or
 *   kinematic body.
 * @category Forces
 */
export function setBodyThrust(world: PhysicsWorld, body: number, force: ArrayLike<number>): void {
  const where = 'setBodyThrust';
  const c = world.components;
  const eid = resolveKind(world, body, 'body', where);
  if (hasComponent(world, eid, c.Static) || hasComponent(world, eid, c.Kinematic))
    throw new RangeError(`${where}: entity ${body} is static or kinematic`);
  assertVector(where, 'force', force, world.dimensions);
  addComponentIfMissing(world, eid, c.BodyThrust);
  addComponentIfMissing(world, eid, c.Force);
  c.BodyThrust.x[eid] = force[0]!;
  c.BodyThrust.y[eid] = force[1]!;
  c.BodyThrust.z[eid] = world.dimensions === 3 ? force[2]! : 0;
}

/**
 * Body-frame forces: F_world = R F_body with R the body's rotation (3D: the unit quaternion q, F
 * rotated as q F q*, Shoemake 1985; 2D: the rotation by `Angle`, (x cos - y sin, x sin + y cos));
 * bodies without a rotation component take F as world-frame. Applied at the centre of mass (no
 * torque). Position-only (reads orientation, not velocity).
 * @category Forces
 */
export const bodyThrustSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.BodyThrust, c.Force]);
  if (ents.length === 0) return;
  const T = c.BodyThrust,
    { x: fx, y: fy, z: fz } = c.Force;
  if (world.dimensions === 2) {
    const angle = c.Angle.value;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const a = hasComponent(world, e, c.Angle) ? angle[e]! : 0;
      const co = Math.cos(a),
        s = Math.sin(a),
        x = T.x[e]!,
        y = T.y[e]!;
      fx[e] = fx[e]! + x * co - y * s;
      fy[e] = fy[e]! + x * s + y * co;
    }
    return;
  }
  const O = c.Orientation;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const vx = T.x[e]!,
      vy = T.y[e]!,
      vz = T.z[e]!;
    if (!hasComponent(world, e, O)) {
      fx[e] = fx[e]! + vx;
      fy[e] = fy[e]! + vy;
      fz[e] = fz[e]! + vz;
      continue;
    }
    const qx = O.x[e]!,
      qy = O.y[e]!,
      qz = O.z[e]!,
      qw = O.w[e]!;
    // v' = v + 2 w (u x v) + 2 u x (u x v), u = (qx, qy, qz).
    const tx = 2 * (qy * vz - qz * vy),
      ty = 2 * (qz * vx - qx * vz),
      tz = 2 * (qx * vy - qy * vx);
    fx[e] = fx[e]! + vx + qw * tx + (qy * tz - qz * ty);
    fy[e] = fy[e]! + vy + qw * ty + (qz * tx - qx * tz);
    fz[e] = fz[e]! + vz + qw * tz + (qx * ty - qy * tx);
  }
};
bodyThrustSystem.velocityDependent = false;

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(bodyThrustSystem, (w) => [[w.components.BodyThrust, w.components.Force]]);
