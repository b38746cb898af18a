import type { KernelArray } from '../threads/kernel-types.js';
import { runParallel } from '../threads/parallel.js';
import { isShared, sharedFloat64 } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';
import { inverseSquarePairs } from './pairwise.js';

/**
 * The world's packed attractor list (6 slots a source), grown by doubling; on shared memory once the
 * world has a thread pool, so the pool's workers can read it.
 */
function attractorSources(world: PhysicsWorld, n: number): Float64Array {
  let S = world.scratch.attractorSources;
  const shared = world.threadPool !== null;
  if (S === undefined || S.length < 6 * n || (shared && !isShared(S))) {
    const length = 6 * Math.max(n, 2 * (S ? S.length / 6 : 4));
    S = shared ? sharedFloat64(length) : new Float64Array(length);
    world.scratch.attractorSources = S;
  }
  return S;
}

/**
 * Per-body gravity scale: adds (s - 1) m g, so that with the world's g (which every integrator
 * applies as an acceleration) the body feels s m g. Position-only. One kernel (`gravityScale`), split
 * over the world's threads when that pays.
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
    { x: fx, y: fy, z: fz } = c.Force;
  runParallel(world, 'gravityScaleSystem', gravityScale, [s, m, fx, fy, fz], [gx, gy, gz], ents.length, ents);
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

/** The terms of the bodies attractors pull, built once per world (`world.scratch.pulledTerms`). */
function pulledTerms(world: PhysicsWorld): object[] {
  let t = world.scratch.pulledTerms;
  if (t === undefined) {
    const c = world.components;
    t = [c.Position, c.Force, c.Mass, Not(c.Static), Not(c.Kinematic)];
    world.scratch.pulledTerms = t;
  }
  return t;
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
  const bodies = query(world, pulledTerms(world));
  const G = world.laws.gravitationalConstant;
  const { x: px, y: py, z: pz } = c.Position,
    m = c.Mass.value;
  const { x: fx, y: fy, z: fz } = c.Force;
  const M = c.Attractor.mass,
    soft = c.Attractor.softening;
  // Each body sums its sources in their order (kernel `attractors`), on the world's threads when that pays.
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
  runParallel(world, 'attractorSystem', attractors, [S, px, py, pz, m, fx, fy, fz], [sources.length], bodies.length, bodies);
};
attractorSystem.velocityDependent = false;

/**
 * Per-body gravity scale (forces/gravity.ts): F += (s - 1) m g. A: s, m, fx, fy, fz. P: gx, gy, gz. Returns 0.
 */
export function gravityScale(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const s = A[0] as Float64Array,
    m = A[1] as Float64Array;
  const fx = A[2] as Float64Array,
    fy = A[3] as Float64Array,
    fz = A[4] as Float64Array;
  const gx = P[0]!,
    gy = P[1]!,
    gz = P[2]!;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const k = (s[e]! - 1) * m[e]!;
    fx[e] = fx[e]! + k * gx;
    fy[e] = fy[e]! + k * gy;
    fz[e] = fz[e]! + k * gz;
  }
  return 0;
}

/**
 * Attractors (forces/gravity.ts): each body gets -G M m (x - x_a) / (r^2 + eps^2)^(3/2) from every
 * source a in the sources' order (itself excepted). A: sources (Float64, 6 slots a source: entity
 * id, x, y, z (m), G M (m^3 s^-2), eps^2 (m^2)), px, py, pz, m, fx, fy, fz. P: 0 source count.
 * Returns 0.
 */
export function attractors(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const S = A[0] as Float64Array;
  const px = A[1] as Float64Array,
    py = A[2] as Float64Array,
    pz = A[3] as Float64Array,
    m = A[4] as Float64Array;
  const fx = A[5] as Float64Array,
    fy = A[6] as Float64Array,
    fz = A[7] as Float64Array;
  const ns = P[0]!;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const b = list[i]!;
    for (let s = 0; s < ns; s++) {
      const o = s * 6;
      if (b === S[o]) continue;
      const dx = px[b]! - S[o + 1]!,
        dy = py[b]! - S[o + 2]!,
        dz = pz[b]! - S[o + 3]!;
      const r2 = dx * dx + dy * dy + dz * dz + S[o + 5]!;
      if (r2 === 0) continue;
      const k = (-S[o + 4]! * m[b]!) / (r2 * Math.sqrt(r2));
      fx[b] = fx[b]! + k * dx;
      fy[b] = fy[b]! + k * dy;
      fz[b] = fz[b]! + k * dz;
    }
  }
  return 0;
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(gravityScaleSystem, (w) => [[w.components.GravityScale, w.components.Force, w.components.Mass]]);
idleWithout(mutualGravitySystem, (w) => [[w.components.MutualGravity, w.components.Position, w.components.Mass, w.components.Force]]);
idleWithout(attractorSystem, (w) => [[w.components.Attractor, w.components.Position]]);
