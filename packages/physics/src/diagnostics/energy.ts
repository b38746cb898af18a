import { Not, query } from 'bitecs';
import type { PhysicsWorld } from '../world';
import { currentSeparation } from '../collision/narrowphase';

/**
 * Diagnostics, computed on demand (never inside the step, so they cost nothing unless asked for).
 * Bodies without a `Mass` component (bare particles) have no defined mass and are not counted;
 * static and kinematic bodies have infinite mass and are not counted either.
 */

function massive(world: PhysicsWorld) {
  const c = world.components;
  return query(world, [c.Position, c.Velocity, c.Mass, Not(c.Static), Not(c.Kinematic)]);
}

/**
 * Kinetic energy, J: sum of m |v|^2 / 2 (translation) and I |w|^2 / 2 (rotation, scalar inertia).
 */
export function kineticEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z, m = c.Mass.value;
  let ents = massive(world);
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum += m[e]! * (vx[e]! * vx[e]! + vy[e]! * vy[e]! + vz[e]! * vz[e]!);
  }
  ents = query(world, [c.AngularVelocity, c.Inertia, Not(c.Static), Not(c.Kinematic)]);
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z, I = c.Inertia.value;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum += I[e]! * (wx[e]! * wx[e]! + wy[e]! * wy[e]! + wz[e]! * wz[e]!);
  }
  return 0.5 * sum;
}

/**
 * Potential energy of the world's uniform gravity, J: sum of -m g . x, zero at the origin
 * (so with g = (0, -g) it is m g y).
 */
export function gravitationalPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const px = c.Position.x, py = c.Position.y, pz = c.Position.z, m = c.Mass.value;
  const g = world.gravity;
  const gx = g[0]!, gy = g[1]!, gz = g[2]!;
  const ents = massive(world);
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum -= m[e]! * (gx * px[e]! + gy * py[e]! + gz * pz[e]!);
  }
  return sum;
}

/**
 * Elastic energy stored in overlapping contacts, J. The contact solver's soft constraints are
 * implicitly integrated damped springs (Catto, "Soft Constraints", GDC 2011) of stiffness
 * k = m_eff (2 pi f)^2, with m_eff the pair's effective mass and f the contact frequency (2 f against
 * infinite mass); a contact overlapping by d holds k d^2 / 2. This is the energy a pile compressed
 * by an impact gives back as it pushes itself apart. Measured at the current positions for the
 * contacts of the last step.
 */
export function contactSpringEnergy(world: PhysicsWorld): number {
  const cs = world.collision;
  const rows = cs.cache.rows;
  const st = cs.settings;
  const hs = world.h / st.solverSubsteps;
  const f = Math.min(st.contactHertz, 0.25 / hs);
  const w = 2 * Math.PI * f;
  let sum = 0;
  for (let i = 0; i < rows.count; i++) {
    const s = currentSeparation(world, rows, i);
    if (s >= 0) continue;
    const k = rows.normalMass[i]! * w * w * (rows.rigidPartner[i] === 1 ? 4 : 1);
    sum += 0.5 * k * s * s;
  }
  return sum;
}

/** Total mechanical energy, J: kinetic plus every potential energy the world knows. */
export function totalEnergy(world: PhysicsWorld): number {
  return kineticEnergy(world) + gravitationalPotentialEnergy(world);
}

/**
 * Total linear momentum sum of m v, kg m/s, written into `out` (length 3) and returned.
 */
export function linearMomentum(world: PhysicsWorld, out: Float64Array = new Float64Array(3)): Float64Array {
  const c = world.components;
  const vx = c.Velocity.x, vy = c.Velocity.y, vz = c.Velocity.z, m = c.Mass.value;
  const ents = massive(world);
  let x = 0, y = 0, z = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const mass = m[e]!;
    x += mass * vx[e]!; y += mass * vy[e]!; z += mass * vz[e]!;
  }
  out[0] = x; out[1] = y; out[2] = z;
  return out;
}

/** Number of contacts the solver handled in the last (sub)step. */
export function contactCount(world: PhysicsWorld): number {
  return world.collision.stats.contacts;
}

/** Milliseconds each stage took in the last step, as a fresh object. */
export function stageTimings(world: PhysicsWorld): Record<string, number> {
  return { ...world.timings };
}
