import { query } from '../query.js';
import type { PhysicsWorld } from '../world.js';
import type { ForceLaw } from './law.js';

/** Angular damping: torque -k w on every body with AngularDamping. Velocity-dependent. */
export const angularDampingSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.AngularDamping, c.AngularVelocity, c.Torque]);
  if (ents.length === 0) return;
  const k = c.AngularDamping.k, wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const tx = c.Torque.x, ty = c.Torque.y, tz = c.Torque.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const d = k[e]!;
    tx[e] = tx[e]! - d * wx[e]!; ty[e] = ty[e]! - d * wy[e]!; tz[e] = tz[e]! - d * wz[e]!;
  }
};
