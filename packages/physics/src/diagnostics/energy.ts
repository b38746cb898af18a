import { spinAngularMomentum, spinKineticEnergy } from '../bodies/rigid.js';
import { currentSeparation } from '../collision/narrowphase/balls.js';
import { fieldsAt } from '../forces/electromagnetism.js';
import { ballContactHertz, contactLength, solverSubstepsFor } from '../solver/contact-scale.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';

const spin = new Float64Array(3);

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
 * @category Diagnostics
 */
export function kineticEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const m = c.Mass.value;
  let ents = massive(world);
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum += m[e]! * (vx[e]! * vx[e]! + vy[e]! * vy[e]! + vz[e]! * vz[e]!);
  }
  ents = query(world, [c.AngularVelocity, c.Inertia, Not(c.InertiaTensor), Not(c.Static), Not(c.Kinematic)]);
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const I = c.Inertia.value;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum += I[e]! * (wx[e]! * wx[e]! + wy[e]! * wy[e]! + wz[e]! * wz[e]!);
  }
  if (world.dimensions === 3) {
    ents = query(world, [c.AngularVelocity, c.InertiaTensor, c.Orientation, Not(c.Static), Not(c.Kinematic)]);
    for (let i = 0; i < ents.length; i++) sum += 2 * spinKineticEnergy(world, ents[i]!);
  }
  return 0.5 * sum;
}

/**
 * Potential energy of the world's uniform gravity, J: sum of -s m g . x, zero at the origin (so with
 * g = (0, -g) it is s m g y), s the body's GravityScale (1 without one).
 * @category Diagnostics
 */
export function gravitationalPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const m = c.Mass.value;
  const g = world.gravity;
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2]!;
  let ents = massive(world);
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum -= m[e]! * (gx * px[e]! + gy * py[e]! + gz * pz[e]!);
  }
  ents = query(world, [c.GravityScale, c.Position, c.Mass, Not(c.Static), Not(c.Kinematic)]);
  const scale = c.GravityScale.value;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    sum -= (scale[e]! - 1) * m[e]! * (gx * px[e]! + gy * py[e]! + gz * pz[e]!);
  }
  return sum;
}

/**
 * The softened pair potential k w_a w_b / sqrt(r^2 + eps^2), J, summed over every pair of `ents`
 * (each once, in query order); w by entity (mass, kg, or charge, C), k its constant with sign
 * (-G for gravity, the Coulomb constant for charges), eps2 the softening squared, m^2.
 */
function pairPotential(world: PhysicsWorld, ents: ArrayLike<number>, w: Float64Array, k: number, eps2: number): number {
  const P = world.components.Position;
  const { x: px, y: py, z: pz } = P;
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const a = ents[i]!;
    for (let j = i + 1; j < ents.length; j++) {
      const b = ents[j]!;
      const r2 = (px[b]! - px[a]!) ** 2 + (py[b]! - py[a]!) ** 2 + (pz[b]! - pz[a]!) ** 2 + eps2;
      if (r2 > 0) sum += (k * w[a]! * w[b]!) / Math.sqrt(r2);
    }
  }
  return sum;
}

/**
 * Newtonian potential energy, J: -G m_i m_j / sqrt(r^2 + eps^2) summed over mutual-gravity pairs
 * (the softened Plummer potential whose gradient the force law uses), plus -G M m / sqrt(r^2 + eps_a^2)
 * for every attractor and every dynamic body it pulls. Direct O(N^2) sum, whatever the force method.
 * @category Diagnostics
 */
export function newtonianPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const L = world.laws;
  const G = L.gravitationalConstant,
    eps2 = L.gravitySoftening ** 2;
  const { x: px, y: py, z: pz } = c.Position;
  const m = c.Mass.value;
  let sum = pairPotential(world, query(world, [c.MutualGravity, c.Position, c.Mass, c.Force]), m, -G, eps2);
  const sources = query(world, [c.Attractor, c.Position]);
  if (sources.length > 0) {
    const bodies = query(world, [c.Position, c.Force, c.Mass, Not(c.Static), Not(c.Kinematic)]);
    for (let s = 0; s < sources.length; s++) {
      const a = sources[s]!;
      const gm = G * c.Attractor.mass[a]!,
        e2 = c.Attractor.softening[a]! ** 2;
      for (let i = 0; i < bodies.length; i++) {
        const b = bodies[i]!;
        if (b === a) continue;
        const r2 = (px[b]! - px[a]!) ** 2 + (py[b]! - py[a]!) ** 2 + (pz[b]! - pz[a]!) ** 2 + e2;
        if (r2 > 0) sum -= (gm * m[b]!) / Math.sqrt(r2);
      }
    }
  }
  return sum;
}

/**
 * Elastic energy of the springs, J: stiffness (L - restLength)^2 / 2 each (bungees only while stretched).
 * @category Diagnostics
 */
export function springPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const S = c.Spring;
  const { x: px, y: py, z: pz } = c.Position;
  const springs = query(world, [c.Spring]);
  let sum = 0;
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!,
      b = S.b[s]!;
    const ax = a === 0 ? S.anchorX[s]! : px[a]!,
      ay = a === 0 ? S.anchorY[s]! : py[a]!,
      az = a === 0 ? S.anchorZ[s]! : pz[a]!;
    const stretch = Math.hypot(px[b]! - ax, py[b]! - ay, pz[b]! - az) - S.restLength[s]!;
    if (S.oneSided[s] === 1 && stretch <= 0) continue;
    sum += 0.5 * S.stiffness[s]! * stretch * stretch;
  }
  return sum;
}

const E = new Float64Array(3),
  B = new Float64Array(3);

/**
 * Electric potential energy, J: k q_i q_j / sqrt(r^2 + eps^2) over charged pairs, plus -q E . x in
 * the uniform electric field at the current time (conservative while the field is constant).
 * @category Diagnostics
 */
export function electricPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const K = world.laws.coulombConstant,
    eps2 = world.laws.electricSoftening ** 2;
  const { x: px, y: py, z: pz } = c.Position;
  const q = c.Charge.value;
  const ents = query(world, [c.Charge, c.Position]);
  let sum = pairPotential(world, ents, q, K, eps2);
  fieldsAt(world, world.time, E, B);
  if (E[0] !== 0 || E[1] !== 0 || E[2] !== 0) {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      sum -= q[e]! * (E[0]! * px[e]! + E[1]! * py[e]! + E[2]! * pz[e]!);
    }
  }
  return sum;
}

/**
 * Potential energy of central forces, J: U(r) = -k r^n / n (n != 0), -k ln r (n = 0), so that F = -dU/dr = k r^(n-1).
 * @category Diagnostics
 */
export function centralPotentialEnergy(world: PhysicsWorld): number {
  const c = world.components;
  const C = c.CentralForce;
  const { x: px, y: py, z: pz } = c.Position;
  const ents = query(world, [c.CentralForce, c.Position]);
  let sum = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const r = Math.hypot(px[e]! - C.cx[e]!, py[e]! - C.cy[e]!, pz[e]! - C.cz[e]!);
    const n = C.n[e]!,
      k = C.k[e]!;
    sum += n === 0 ? -k * Math.log(r) : (-k * r ** n) / n;
  }
  return sum;
}

/**
 * Every potential energy the world knows, J: uniform and Newtonian gravity, springs, electric, central.
 * @category Diagnostics
 */
export function potentialEnergy(world: PhysicsWorld): number {
  return (
    gravitationalPotentialEnergy(world) +
    newtonianPotentialEnergy(world) +
    springPotentialEnergy(world) +
    electricPotentialEnergy(world) +
    centralPotentialEnergy(world)
  );
}

/**
 * Elastic energy stored in overlapping contacts, J. The contact solver's soft constraints are
 * implicitly integrated damped springs (Catto, "Soft Constraints", GDC 2011) of stiffness
 * k = m_eff (2 pi f)^2, with m_eff the pair's effective mass and f the contact frequency (2 f against
 * infinite mass; f follows the balls' size, see `ballContactHertz`); a contact overlapping by d holds k d^2 / 2. This is the energy a pile compressed
 * by an impact gives back as it pushes itself apart. Measured at the current positions for the
 * contacts of the last step.
 * @category Diagnostics
 */
export function contactSpringEnergy(world: PhysicsWorld): number {
  const cs = world.collision;
  const rows = cs.cache.rows;
  const st = cs.settings;
  const length = contactLength(world, rows);
  const hs = world.h / solverSubstepsFor(st, length, world.h);
  const f = ballContactHertz(st, length, hs);
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

/**
 * Total mechanical energy, J: kinetic, every potential energy, and the elastic energy held in
 * overlapping contacts. Conserved by conservative systems up to the integrator's error.
 * @category Diagnostics
 */
export function totalEnergy(world: PhysicsWorld): number {
  return kineticEnergy(world) + potentialEnergy(world) + contactSpringEnergy(world);
}

/**
 * Total angular momentum about `about` (m; default the origin), kg m^2/s, into `out` (length 3):
 * sum of m (x - about) x v plus the spin I w of bodies with a scalar moment of inertia. In 2D only
 * out[2] (about z) is nonzero.
 * @category Diagnostics
 */
export function angularMomentum(
  world: PhysicsWorld,
  about: ArrayLike<number> = [0, 0, 0],
  out: Float64Array = new Float64Array(3),
): Float64Array {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const m = c.Mass.value;
  const ox = about[0] ?? 0,
    oy = about[1] ?? 0,
    oz = about[2] ?? 0;
  let lx = 0,
    ly = 0,
    lz = 0;
  let ents = massive(world);
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const rx = px[e]! - ox,
      ry = py[e]! - oy,
      rz = pz[e]! - oz,
      k = m[e]!;
    lx += k * (ry * vz[e]! - rz * vy[e]!);
    ly += k * (rz * vx[e]! - rx * vz[e]!);
    lz += k * (rx * vy[e]! - ry * vx[e]!);
  }
  ents = query(world, [c.AngularVelocity, c.Inertia, Not(c.InertiaTensor), Not(c.Static), Not(c.Kinematic)]);
  const I = c.Inertia.value,
    { x: wx, y: wy, z: wz } = c.AngularVelocity;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    lx += I[e]! * wx[e]!;
    ly += I[e]! * wy[e]!;
    lz += I[e]! * wz[e]!;
  }
  if (world.dimensions === 3) {
    ents = query(world, [c.AngularVelocity, c.InertiaTensor, c.Orientation, Not(c.Static), Not(c.Kinematic)]);
    for (let i = 0; i < ents.length; i++) {
      spinAngularMomentum(world, ents[i]!, spin);
      lx += spin[0]!;
      ly += spin[1]!;
      lz += spin[2]!;
    }
  }
  out[0] = world.dimensions === 2 ? 0 : lx;
  out[1] = world.dimensions === 2 ? 0 : ly;
  out[2] = lz;
  return out;
}

/**
 * Total linear momentum sum of m v, kg m/s, written into `out` (length 3) and returned.
 * @category Diagnostics
 */
export function linearMomentum(world: PhysicsWorld, out: Float64Array = new Float64Array(3)): Float64Array {
  const c = world.components;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const m = c.Mass.value;
  const ents = massive(world);
  let x = 0,
    y = 0,
    z = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const mass = m[e]!;
    x += mass * vx[e]!;
    y += mass * vy[e]!;
    z += mass * vz[e]!;
  }
  out[0] = x;
  out[1] = y;
  out[2] = z;
  return out;
}

/**
 * Number of contact points the collide stage of the last step gave the solver: the ball contacts
 * (ball-ball, ball-segment, ball-plane, ball-wall: one point each) plus the points of the shape
 * manifolds (2D: up to 2 a touching pair, a ball against a shape 1; 3D: up to 4). Sleeping pairs are
 * not counted. 0 before the first step.
 * @param world - The world.
 * @returns the count, an integer >= 0.
 * @category Diagnostics
 */
export function contactCount(world: PhysicsWorld): number {
  return world.collision.stats.contacts;
}

/**
 * Milliseconds each stage took in the last step, as a fresh object.
 * @category Diagnostics
 */
export function stageTimings(world: PhysicsWorld): Record<string, number> {
  return { ...world.timings };
}
