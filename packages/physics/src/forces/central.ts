import type { KernelArray } from '../threads/kernel-types.js';
import { runParallel } from '../threads/parallel.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
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
  const { x: px, y: py, z: pz } = c.Position;
  const { x: fx, y: fy, z: fz } = c.Force;
  // Kernel `centralForce`, on the world's threads when that pays.
  runParallel(
    world,
    'centralForceSystem',
    centralForce,
    [C.cx, C.cy, C.cz, C.k, C.n, px, py, pz, fx, fy, fz],
    NO_PARAMS,
    ents.length,
    ents,
  );
};
centralForceSystem.velocityDependent = false;

/**
 * Central force (forces/central.ts): F += k r^(n-2) (x - c), skipped at r = 0. A: cx, cy, cz, k, n
 * (CentralForce), px, py, pz, fx, fy, fz. P unused. Returns 0.
 */
export function centralForce(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const cx = A[0] as Float64Array,
    cy = A[1] as Float64Array,
    cz = A[2] as Float64Array,
    K = A[3] as Float64Array,
    N = A[4] as Float64Array;
  const px = A[5] as Float64Array,
    py = A[6] as Float64Array,
    pz = A[7] as Float64Array;
  const fx = A[8] as Float64Array,
    fy = A[9] as Float64Array,
    fz = A[10] as Float64Array;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const dx = px[e]! - cx[e]!,
      dy = py[e]! - cy[e]!,
      dz = pz[e]! - cz[e]!;
    const r2 = dx * dx + dy * dy + dz * dz;
    if (r2 === 0) continue;
    const n = N[e]!;
    const k = K[e]! * (n === 2 ? 1 : r2 ** (0.5 * (n - 2)));
    fx[e] = fx[e]! + k * dx;
    fy[e] = fy[e]! + k * dy;
    fz[e] = fz[e]! + k * dz;
  }
  return P.length * 0;
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(centralForceSystem, (w) => [[w.components.CentralForce, w.components.Position, w.components.Force]]);
