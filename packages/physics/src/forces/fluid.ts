import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import { allocateStiffStamps, dissipationState, moveFromStart, quadraticDecay, STIFF_RATE } from './dissipation.js';
import type { ForceLaw } from './law.js';

/**
 * Shape codes of `Buoyancy.shape`.
 * @category Forces
 */
export const BuoyancyShape = Object.freeze({ Ball: 0, Box: 1 } as const);

/**
 * Submerged measure of a body whose lowest point is `depth` metres below the surface (0 = just
 * touching, 2 r or 2 halfY = fully under): [submerged, total], volume in 3D (m^3), area in 2D (m^2),
 * written into `out` (pass one to avoid allocating).
 * Ball in 3D: spherical cap pi h^2 (3 r - h) / 3; in 2D: circular segment r^2 acos((r - h) / r) - (r - h) sqrt(2 r h - h^2);
 * box: (2 halfX) h (2 halfZ) in 3D, (2 halfX) h in 2D. Source: Ramtal and Dobre ch. 7; CRC Standard
 * Mathematical Tables for the cap and segment.
 * @category Forces
 */
export function submergedMeasure(
  dimensions: 2 | 3,
  shape: number,
  radius: number,
  halfX: number,
  halfY: number,
  halfZ: number,
  depth: number,
  out: Float64Array = new Float64Array(2),
): Float64Array {
  if (shape === BuoyancyShape.Box) {
    const h = depth <= 0 ? 0 : depth >= 2 * halfY ? 2 * halfY : depth;
    const base = dimensions === 3 ? 4 * halfX * halfZ : 2 * halfX;
    out[0] = base * h;
    out[1] = base * 2 * halfY;
    return out;
  }
  const r = radius;
  const h = depth <= 0 ? 0 : depth >= 2 * r ? 2 * r : depth;
  if (dimensions === 3) {
    out[0] = (Math.PI * h * h * (3 * r - h)) / 3;
    out[1] = (4 / 3) * Math.PI * r * r * r;
    return out;
  }
  const a = r - h;
  out[0] = r * r * Math.acos(Math.max(-1, Math.min(1, a / r))) - a * Math.sqrt(Math.max(0, 2 * r * h - h * h));
  out[1] = Math.PI * r * r;
  return out;
}

const measure = new Float64Array(2);

/**
 * Buoyancy (Archimedes: F = -rho V_submerged g, opposite to gravity) from every FluidRegion a body
 * with `Buoyancy` dips into, and fluid drag F = -f k |v| v scaled by the submerged fraction f (summed
 * over regions, at most 1). Velocity-dependent (the drag).
 *
 * The drag is a force while f k |v| h / m < STIFF_RATE at the state it is evaluated at; otherwise it
 * adds nothing there and `stiffFluidDragSystem` applies the exact quadratic-drag update
 * v <- v / (1 + f k |v| h / m) after the integrator (see forces/dissipation.ts). Buoyancy itself is
 * always a force.
 * @category Forces
 */
export const buoyancySystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const fluids = query(world, [c.FluidRegion]);
  if (fluids.length === 0) return;
  const ents = query(world, [c.Buoyancy, c.Position, c.Velocity, c.Force]);
  if (ents.length === 0) return;
  const Fl = c.FluidRegion,
    Bu = c.Buoyancy;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: fx, y: fy, z: fz } = c.Force;
  const g = world.gravity;
  const d = world.dimensions;
  const inv = c.Mass.inv;
  const st = dissipationState(world);
  allocateStiffStamps(world, st);
  const epoch = st.epoch,
    stamp = st.fluidStamp,
    stiffK = st.fluidK;
  const limit = STIFF_RATE / world.h;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const shape = Bu.shape[e]!;
    const extent = shape === BuoyancyShape.Box ? Bu.halfY[e]! : Bu.radius[e]!;
    // Buoyancy from every region the body dips into; drag once, with the submerged fraction summed
    // over regions (overlapping regions do not drag twice) and capped at 1.
    let fraction = 0;
    for (let j = 0; j < fluids.length; j++) {
      const f = fluids[j]!;
      const x = px[e]!,
        z = pz[e]!;
      if (x < Fl.minX[f]! || x > Fl.maxX[f]! || (d === 3 && (z < Fl.minZ[f]! || z > Fl.maxZ[f]!))) continue;
      const depth = Fl.surface[f]! - (py[e]! - extent);
      if (depth <= 0) continue;
      submergedMeasure(d, shape, Bu.radius[e]!, Bu.halfX[e]!, Bu.halfY[e]!, Bu.halfZ[e]!, depth, measure);
      const rhoV = Fl.density[f]! * measure[0]!;
      fx[e] = fx[e]! - rhoV * g[0]!;
      fy[e] = fy[e]! - rhoV * g[1]!;
      fz[e] = fz[e]! - rhoV * g[2]!;
      fraction += measure[0]! / measure[1]!;
    }
    const k = Bu.dragCoefficient[e]! * (fraction < 1 ? fraction : 1);
    const ux = vx[e]!,
      uy = vy[e]!,
      uz = vz[e]!;
    const s = k * Math.sqrt(ux * ux + uy * uy + uz * uz);
    if (k > 0) {
      // Stiff at this state: no force; stamped for the exact update after the integrator.
      if (s * inv[e]! >= limit) {
        stamp[e] = epoch;
        stiffK[e] = k;
        st.fluidSeen = epoch;
        continue;
      }
      fx[e] = fx[e]! - s * ux;
      fy[e] = fy[e]! - s * uy;
      fz[e] = fz[e]! - s * uz;
    }
  }
};

/**
 * Integrate stage, after the integrator: the stiff regime of buoyancy's fluid drag (see
 * forces/dissipation.ts). A body whose fluid drag added no force this (sub)step has its velocity
 * divided by 1 + k |v| h / m, k the drag coefficient times the submerged fraction where it was
 * found stiff, and moves from where the (sub)step began with that velocity: x = x_start + h v.
 * @throws NonFiniteStateError (stage 'integrate') if a position or velocity it writes is not finite.
 * @category Forces
 */
export const stiffFluidDragSystem = (world: PhysicsWorld): void => {
  const st = dissipationState(world);
  if (st.fluidSeen !== st.epoch) return;
  const c = world.components;
  const ents = query(world, [c.Buoyancy, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)]);
  const h = world.h,
    epoch = st.epoch,
    stamp = st.fluidStamp,
    stiffK = st.fluidK,
    inv = c.Mass.inv;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const is2D = world.dimensions === 2;
  let check = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    if (stamp[e] !== epoch) continue;
    const x = vx[e]!,
      y = vy[e]!,
      z = is2D ? 0 : vz[e]!;
    const f = quadraticDecay(stiffK[e]! * Math.sqrt(x * x + y * y + z * z) * inv[e]! * h);
    check += moveFromStart(world, e, h, x * f, y * f, z * f);
  }
  if (check !== 0) reportNonFinite(world, ents, 'integrate');
};

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(buoyancySystem, (w) => [[w.components.FluidRegion]]);
