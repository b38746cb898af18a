import { query } from 'bitecs';
import type { PhysicsWorld } from '../world';

/**
 * Linear drag F = -k v on every body with `LinearDrag` (and `Velocity`).
 * Source: Ramtal and Dobre, ch. 7, "Drag"; Stokes' law.
 */
export function linearDragSystem(world: PhysicsWorld): void {
  const { LinearDrag, Velocity, Force } = world.components;
  const ents = query(world, [LinearDrag, Velocity, Force]);
  const k = LinearDrag.k, vx = Velocity.x, vy = Velocity.y, vz = Velocity.z;
  const fx = Force.x, fy = Force.y, fz = Force.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const c = k[e];
    fx[e] -= c * vx[e];
    fy[e] -= c * vy[e];
    fz[e] -= c * vz[e];
  }
}

/**
 * Quadratic drag F = -k |v| v on every body with `QuadraticDrag`.
 * Source: Ramtal and Dobre, ch. 7, "Drag"; the drag equation F = rho C_d A v^2 / 2.
 */
export function quadraticDragSystem(world: PhysicsWorld): void {
  const { QuadraticDrag, Velocity, Force } = world.components;
  const ents = query(world, [QuadraticDrag, Velocity, Force]);
  const k = QuadraticDrag.k, vx = Velocity.x, vy = Velocity.y, vz = Velocity.z;
  const fx = Force.x, fy = Force.y, fz = Force.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const x = vx[e], y = vy[e], z = vz[e];
    const c = k[e] * Math.sqrt(x * x + y * y + z * z);
    fx[e] -= c * x;
    fy[e] -= c * y;
    fz[e] -= c * z;
  }
}
