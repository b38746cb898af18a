import { removeEntity } from 'bitecs';
import { query } from '../query.js';
import type { PhysicsWorld } from '../world.js';
import type { ForceLaw } from './law.js';

/**
 * Hooke springs with damping (Ramtal and Dobre ch. 8): for a spring from a (or its anchor) to b with
 * length L and unit direction u from a to b, the force on b is
 * F = -(stiffness (L - restLength) + damping (v_b - v_a) . u) u, and -F on a. A one-sided spring
 * (bungee) exerts nothing while L <= restLength. Velocity-dependent (the damping).
 */
export const springSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const springs = query(world, [c.Spring]);
  if (springs.length === 0) return;
  const S = c.Spring;
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const fx = c.Force.x, fy = c.Force.y, fz = c.Force.z;
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!, b = S.b[s]!;
    const ax = a === 0 ? S.anchorX[s]! : px[a]!, ay = a === 0 ? S.anchorY[s]! : py[a]!, az = a === 0 ? S.anchorZ[s]! : pz[a]!;
    const dx = px[b]! - ax, dy = py[b]! - ay, dz = pz[b]! - az;
    const L = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (L === 0) continue;
    const stretch = L - S.restLength[s]!;
    if (S.oneSided[s] === 1 && stretch <= 0) continue;
    const ux = dx / L, uy = dy / L, uz = dz / L;
    const rv = a === 0
      ? vx[b]! * ux + vy[b]! * uy + vz[b]! * uz
      : (vx[b]! - vx[a]!) * ux + (vy[b]! - vy[a]!) * uy + (vz[b]! - vz[a]!) * uz;
    const mag = -(S.stiffness[s]! * stretch + S.damping[s]! * rv);
    const Fx = mag * ux, Fy = mag * uy, Fz = mag * uz;
    fx[b] = fx[b]! + Fx; fy[b] = fy[b]! + Fy; fz[b] = fz[b]! + Fz;
    if (a !== 0) { fx[a] = fx[a]! - Fx; fy[a] = fy[a]! - Fy; fz[a] = fz[a]! - Fz; }
  }
};

/** Removal hook: removes every spring attached to `eid` (so no spring ever pulls a recycled id). */
export function removeSpringsOf(world: PhysicsWorld, eid: number): void {
  const c = world.components;
  const springs = query(world, [c.Spring]);
  const doomed: number[] = [];
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    if (c.Spring.a[s] === eid || c.Spring.b[s] === eid) doomed.push(s);
  }
  for (const s of doomed) removeEntity(world, s);
}
