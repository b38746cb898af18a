import { query } from '../query';
import type { PhysicsWorld } from '../world';
import type { ForceLaw } from './law';

/** Shape codes of `Buoyancy.shape`. */
export const BuoyancyShape = Object.freeze({ Ball: 0, Box: 1 } as const);

/**
 * Submerged measure of a body whose lowest point is `depth` metres below the surface (0 = just
 * touching, 2 r or 2 halfY = fully under): volume in 3D (m^3), area in 2D (m^2).
 * Ball in 3D: spherical cap pi h^2 (3 r - h) / 3; in 2D: circular segment r^2 acos((r - h) / r) - (r - h) sqrt(2 r h - h^2);
 * box: (2 halfX) h (2 halfZ) in 3D, (2 halfX) h in 2D. Source: Ramtal and Dobre ch. 7; CRC Standard
 * Mathematical Tables for the cap and segment.
 */
export function submergedMeasure(
  dimensions: 2 | 3, shape: number, radius: number, halfX: number, halfY: number, halfZ: number, depth: number,
): { submerged: number; total: number } {
  if (shape === BuoyancyShape.Box) {
    const h = depth <= 0 ? 0 : depth >= 2 * halfY ? 2 * halfY : depth;
    const base = dimensions === 3 ? 4 * halfX * halfZ : 2 * halfX;
    return { submerged: base * h, total: base * 2 * halfY };
  }
  const r = radius;
  const h = depth <= 0 ? 0 : depth >= 2 * r ? 2 * r : depth;
  if (dimensions === 3) {
    return { submerged: (Math.PI * h * h * (3 * r - h)) / 3, total: (4 / 3) * Math.PI * r * r * r };
  }
  const a = r - h;
  const seg = r * r * Math.acos(Math.max(-1, Math.min(1, a / r))) - a * Math.sqrt(Math.max(0, 2 * r * h - h * h));
  return { submerged: seg, total: Math.PI * r * r };
}

/**
 * Buoyancy (Archimedes: F = -rho V_submerged g, opposite to gravity) and fluid drag
 * F = -f k |v| v scaled by the submerged fraction f, for every body with `Buoyancy` inside a
 * FluidRegion. Velocity-dependent (the drag).
 */
export const buoyancySystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const fluids = query(world, [c.FluidRegion]);
  if (fluids.length === 0) return;
  const ents = query(world, [c.Buoyancy, c.Position, c.Velocity, c.Force]);
  if (ents.length === 0) return;
  const Fl = c.FluidRegion, Bu = c.Buoyancy;
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z;
  const fx = c.Force.x, fy = c.Force.y, fz = c.Force.z;
  const g = world.gravity;
  const d = world.dimensions;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const shape = Bu.shape[e]!;
    const extent = shape === BuoyancyShape.Box ? Bu.halfY[e]! : Bu.radius[e]!;
    for (let j = 0; j < fluids.length; j++) {
      const f = fluids[j]!;
      const x = px[e]!, z = pz[e]!;
      if (x < Fl.minX[f]! || x > Fl.maxX[f]! || (d === 3 && (z < Fl.minZ[f]! || z > Fl.maxZ[f]!))) continue;
      const depth = Fl.surface[f]! - (py[e]! - extent);
      if (depth <= 0) continue;
      const { submerged, total } = submergedMeasure(d, shape, Bu.radius[e]!, Bu.halfX[e]!, Bu.halfY[e]!, Bu.halfZ[e]!, depth);
      const rhoV = Fl.density[f]! * submerged;
      fx[e] = fx[e]! - rhoV * g[0]!; fy[e] = fy[e]! - rhoV * g[1]!; fz[e] = fz[e]! - rhoV * g[2]!;
      const k = Bu.dragCoefficient[e]! * (submerged / total);
      if (k > 0) {
        const ux = vx[e]!, uy = vy[e]!, uz = vz[e]!;
        const s = k * Math.sqrt(ux * ux + uy * uy + uz * uz);
        fx[e] = fx[e]! - s * ux; fy[e] = fy[e]! - s * uy; fz[e] = fz[e]! - s * uz;
      }
    }
  }
};
