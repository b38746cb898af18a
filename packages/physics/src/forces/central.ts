import { KERNEL } from '../threads/kernels.js';
import { runParallel } from '../threads/parallel.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import type { ForceLaw } from './law.js';

const NO_PARAMS: number[] = [];

/**
 * General central force F = k r^(n-1) r_hat about each body's centre (cx, cy, cz): written as
 * k r^(n-2) (x - c). At r = 0 the force is 0 for n > 1 and undefined otherwise (skipped).
 * Position-only. Source: Ramtal and Dobre ch. 6, "central forces".
 * @category Forces
 */
export const centralForceSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.CentralForce, c.Position, c.Force]);
  if (ents.length === 0) return;
  const C = c.CentralForce;
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z;
  const fx = c.Force.x,
    fy = c.Force.y,
    fz = c.Force.z;
  // On the world's threads when that pays (threads/kernels.ts centralForce: the same arithmetic).
  if (
    runParallel(
      world,
      'centralForceSystem',
      KERNEL.centralForce,
      [C.cx, C.cy, C.cz, C.k, C.n, px, py, pz, fx, fy, fz],
      NO_PARAMS,
      ents.length,
      ents,
    ) !== null
  )
    return;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const dx = px[e]! - C.cx[e]!,
      dy = py[e]! - C.cy[e]!,
      dz = pz[e]! - C.cz[e]!;
    const r2 = dx * dx + dy * dy + dz * dz;
    if (r2 === 0) continue;
    const n = C.n[e]!;
    const k = C.k[e]! * (n === 2 ? 1 : r2 ** (0.5 * (n - 2)));
    fx[e] = fx[e]! + k * dx;
    fy[e] = fy[e]! + k * dy;
    fz[e] = fz[e]! + k * dz;
  }
};
centralForceSystem.velocityDependent = false;
