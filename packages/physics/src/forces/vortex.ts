import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Vortex: a tangential force about an axis, F = k r^(n-1) (axis x r_hat), r the distance from the
 * axis line through (cx, cy, cz). n = 1 gives a constant swirl, n = 2 a solid-body-like one, n = 0 a
 * free-vortex-like 1/r fall-off (skipped at r = 0). Position-only.
 * @category Forces
 */
export const vortexSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.Vortex, c.Position, c.Force]);
  if (ents.length === 0) return;
  const V = c.Vortex;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const ax = V.axisX[e]!,
      ay = V.axisY[e]!,
      az = V.axisZ[e]!;
    let dx = px[e]! - V.cx[e]!,
      dy = py[e]! - V.cy[e]!,
      dz = pz[e]! - V.cz[e]!;
    const along = dx * ax + dy * ay + dz * az;
    dx -= along * ax;
    dy -= along * ay;
    dz -= along * az;
    const r = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (r === 0) continue;
    // axis x r_hat, scaled by k r^(n-1).
    const k = (V.k[e]! * r ** (V.n[e]! - 1)) / r;
    fx[e] = fx[e]! + k * (ay * dz - az * dy);
    fy[e] = fy[e]! + k * (az * dx - ax * dz);
    fz[e] = fz[e]! + k * (ax * dy - ay * dx);
  }
};
vortexSystem.velocityDependent = false;

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(vortexSystem, (w) => [[w.components.Vortex, w.components.Position, w.components.Force]]);
