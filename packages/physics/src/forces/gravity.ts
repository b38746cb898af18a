import { KERNEL } from '../threads/kernels.js';
import { MIN_PARALLEL_PER_THREAD, runParallel } from '../threads/parallel.js';
import { sharedFloat64 } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import type { ForceLaw } from './law.js';
import { inverseSquarePairs } from './pairwise.js';

const sourcesOf = new WeakMap<PhysicsWorld, Float64Array>();

/** The world's packed attractor list for the threads (6 slots a source), on shared memory, grown by doubling. */
function attractorSources(world: PhysicsWorld, n: number): Float64Array {
  let S = sourcesOf.get(world);
  if (S === undefined || S.length < 6 * n) {
    S = sharedFloat64(6 * Math.max(n, 2 * (S ? S.length / 6 : 4)));
    sourcesOf.set(world, S);
  }
  return S;
}

/**
 * Per-body gravity scale: adds (s - 1) m g, so that with the world's g (which every integrator
 * applies as an acceleration) the body feels s m g. Position-only. Split over the world's threads
 * when it has several (threads/kernels.ts; the same arithmetic per body).
 * @category Forces
 */
export const gravityScaleSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.GravityScale, c.Force, c.Mass]);
  if (ents.length === 0) return;
  const g = world.gravity;
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2]!;
  const s = c.GravityScale.value,
    m = c.Mass.value,
    fx = c.Force.x,
    fy = c.Force.y,
    fz = c.Force.z;
  if (
    world.threadPool !== null &&
    runParallel(world, 'gravityScaleSystem', KERNEL.gravityScale, [s, m, fx, fy, fz], [gx, gy, gz], ents.length, ents) !== null
  )
    return;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const k = (s[e]! - 1) * m[e]!;
    fx[e] = fx[e]! + k * gx;
    fy[e] = fy[e]! + k * gy;
    fz[e] = fz[e]! + k * gz;
  }
};
gravityScaleSystem.velocityDependent = false;

/**
 * Mutual Newtonian gravity between every pair of bodies tagged MutualGravity, with Plummer softening:
 * F_ij = G m_i m_j (x_j - x_i) / (|x_j - x_i|^2 + eps^2)^(3/2) on i, and the opposite on j (Newton's
 * third law, so momentum is conserved to rounding). 'direct' sums all N(N-1)/2 pairs; 'barnes-hut'
 * approximates far groups by their centre of mass (see forces/barnes-hut/tree.ts). Position-only.
 * Source: Ramtal and Dobre ch. 6 and 12; Aarseth, Gravitational N-Body Simulations (2003), ch. 2.
 * @category Forces
 */
export const mutualGravitySystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.MutualGravity, c.Position, c.Mass, c.Force]);
  const n = ents.length;
  if (n < 2) return;
  const L = world.laws;
  if (L.gravityMethod === 'barnes-hut') {
    if (barnesHut === null) {
      throw new Error(
        "mutualGravitySystem: world.laws.gravityMethod is 'barnes-hut' but the Barnes-Hut tree is not loaded; choose the method with setGravitation(world, { method: 'barnes-hut' })",
      );
    }
    barnesHut(world, ents);
    return;
  }
  inverseSquarePairs(world, ents, c.Mass.value, L.gravitationalConstant, L.gravitySoftening * L.gravitySoftening);
};
mutualGravitySystem.velocityDependent = false;

let barnesHut: ((world: PhysicsWorld, ents: ArrayLike<number>) => void) | null = null;

/**
 * Hands mutual gravity its Barnes-Hut sum (forces/barnes-hut/tree.ts barnesHutGravity), which
 * `setGravitation` loads when it chooses the method 'barnes-hut' (or a snapshot restore does): a
 * program that never chooses it does not bundle the tree.
 * @category Forces
 */
export function setBarnesHutGravity(sum: (world: PhysicsWorld, ents: ArrayLike<number>) => void): void {
  barnesHut = sum;
}

/**
 * Attractors (fixed or moving masses, e.g. a sun or a black hole) pull every dynamic body with a
 * force accumulator: F = -G M m r / (r^2 + eps^2)^(3/2), r from the attractor to the body, eps the
 * attractor's softening. An attractor does not pull itself; attractors that are dynamic bodies are
 * pulled by the others. Position-only. Source: Ramtal and Dobre ch. 6.
 * @category Forces
 */
export const attractorSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const sources = query(world, [c.Attractor, c.Position]);
  if (sources.length === 0) return;
  const bodies = query(world, [c.Position, c.Force, c.Mass, Not(c.Static), Not(c.Kinematic)]);
  const G = world.laws.gravitationalConstant;
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z,
    m = c.Mass.value;
  const fx = c.Force.x,
    fy = c.Force.y,
    fz = c.Force.z;
  const M = c.Attractor.mass,
    soft = c.Attractor.softening;
  // On the world's threads when that pays: each body sums its sources in the same order
  // (threads/kernels.ts attractors), so the forces are the one-thread ones to the bit.
  if (world.threadPool !== null && bodies.length >= 2 * MIN_PARALLEL_PER_THREAD) {
    const S = attractorSources(world, sources.length);
    for (let s = 0; s < sources.length; s++) {
      const a = sources[s]!,
        o = 6 * s;
      S[o] = a;
      S[o + 1] = px[a]!;
      S[o + 2] = py[a]!;
      S[o + 3] = pz[a]!;
      S[o + 4] = G * M[a]!;
      S[o + 5] = soft[a]! * soft[a]!;
    }
    if (
      runParallel(world, 'attractorSystem', KERNEL.attractors, [S, px, py, pz, m, fx, fy, fz], [sources.length], bodies.length, bodies) !==
      null
    )
      return;
  }
  for (let s = 0; s < sources.length; s++) {
    const a = sources[s]!;
    const xa = px[a]!,
      ya = py[a]!,
      za = pz[a]!,
      gm = G * M[a]!,
      eps2 = soft[a]! * soft[a]!;
    for (let i = 0; i < bodies.length; i++) {
      const b = bodies[i]!;
      if (b === a) continue;
      const dx = px[b]! - xa,
        dy = py[b]! - ya,
        dz = pz[b]! - za;
      const r2 = dx * dx + dy * dy + dz * dz + eps2;
      if (r2 === 0) continue;
      const k = (-gm * m[b]!) / (r2 * Math.sqrt(r2));
      fx[b] = fx[b]! + k * dx;
      fy[b] = fy[b]! + k * dy;
      fz[b] = fz[b]! + k * dz;
    }
  }
};
attractorSystem.velocityDependent = false;
