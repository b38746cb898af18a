import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';
import { inverseSquarePairs } from './pairwise.js';

/**
 * Coulomb's law between every pair of charged bodies: F on b = k q_a q_b (x_b - x_a) / (r^2 + eps^2)^(3/2)
 * (like charges repel), and the opposite on a. Softening eps from `setElectrostatics`. Position-only.
 * Source: Ramtal and Dobre ch. 10.
 * @category Forces
 */
export const coulombSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.Charge, c.Position, c.Force]);
  const n = ents.length;
  if (n < 2) return;
  // Like charges repel: the inverse-square pair sum with a negative coupling.
  inverseSquarePairs(world, ents, c.Charge.value, -world.laws.coulombConstant, world.laws.electricSoftening ** 2);
};
coulombSystem.velocityDependent = false;

const E = new Float64Array(3);
const B = new Float64Array(3);

/**
 * The total uniform electric and magnetic field at time t (sum over ElectricField and MagneticField
 * entities), written into e and b (V/m and T).
 * @category Forces
 */
export function fieldsAt(world: PhysicsWorld, t: number, e: Float64Array, b: Float64Array): void {
  const c = world.components;
  e.fill(0);
  b.fill(0);
  const sum = (ents: ArrayLike<number>, F: typeof c.ElectricField, out: Float64Array) => {
    for (let i = 0; i < ents.length; i++) {
      const f = ents[i]!;
      const k = Math.cos(F.omega[f]! * t + F.phase[f]!);
      out[0] = out[0]! + F.x[f]! + F.ampX[f]! * k;
      out[1] = out[1]! + F.y[f]! + F.ampY[f]! * k;
      out[2] = out[2]! + F.z[f]! + F.ampZ[f]! * k;
    }
  };
  sum(query(world, [c.ElectricField]), c.ElectricField, e);
  sum(query(world, [c.MagneticField]), c.MagneticField, b);
}

/**
 * Electric and magnetic fields on charges: the Lorentz force F = q (E + v x B) on every body with a
 * charge. In a 2D world B is along z (out of the screen): v x B = (v_y B_z, -v_x B_z). Velocity-
 * dependent (the magnetic part). Source: Ramtal and Dobre ch. 10; Griffiths, Introduction to
 * Electrodynamics, eq. 5.1.
 * @category Forces
 */
export const lorentzSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  if (query(world, [c.ElectricField]).length === 0 && query(world, [c.MagneticField]).length === 0) return;
  const ents = query(world, [c.Charge, c.Force, c.Velocity]);
  if (ents.length === 0) return;
  fieldsAt(world, world.time, E, B);
  const ex = E[0]!,
    ey = E[1]!,
    ez = E[2]!;
  const is2D = world.dimensions === 2;
  const bx = is2D ? 0 : B[0]!,
    by = is2D ? 0 : B[1]!,
    bz = B[2]!;
  const q = c.Charge.value,
    { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const qe = q[e]!;
    const ux = vx[e]!,
      uy = vy[e]!,
      uz = vz[e]!;
    fx[e] = fx[e]! + qe * (ex + uy * bz - uz * by);
    fy[e] = fy[e]! + qe * (ey + uz * bx - ux * bz);
    fz[e] = fz[e]! + qe * (ez + ux * by - uy * bx);
  }
};

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(coulombSystem, (w) => [[w.components.Charge, w.components.Position, w.components.Force]]);
idleWithout(lorentzSystem, (w) => [[w.components.ElectricField], [w.components.MagneticField]]);
