import { query } from 'bitecs';
import { assertInteger } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import { worldTreeFields } from './barnes-hut/tree.js';

/**
 * Accuracy diagnostics of mutual gravity: the direct-sum field at a sample of bodies, the relative
 * error of the tree field against it, and the rate at which the summation method changes total
 * momentum. Computed on demand, never inside the step; they allocate their results.
 */

/**
 * Direct-sum gravitational field, m/s^2, at the bodies `targets` (indices into the arrays) of n bodies
 * with positions (x, y, z), m, and masses m, kg: g_i = sum over j != i of G m_j d / (d^2 + eps^2)^(3/2),
 * d = x_j - x_i, the same Plummer-softened pair law as the direct and tree methods (pairs with
 * d^2 + eps^2 = 0, coincident bodies without softening, are skipped as they are there). O(n) per target.
 * @returns out, with the field at targets[k] in out[3k..3k+2] (allocated when not given).
 * @category Forces
 */
export function directField(
  n: number,
  x: ArrayLike<number>,
  y: ArrayLike<number>,
  z: ArrayLike<number>,
  m: ArrayLike<number>,
  G: number,
  eps2: number,
  targets: ArrayLike<number>,
  out: Float64Array = new Float64Array(3 * targets.length),
): Float64Array {
  for (let k = 0; k < targets.length; k++) {
    const i = targets[k]!;
    const xi = x[i]!,
      yi = y[i]!,
      zi = z[i]!;
    let ax = 0,
      ay = 0,
      az = 0;
    for (let j = 0; j < n; j++) {
      if (j === i) continue;
      const dx = x[j]! - xi,
        dy = y[j]! - yi,
        dz = z[j]! - zi;
      const r2 = dx * dx + dy * dy + dz * dz + eps2;
      if (r2 === 0) continue;
      const w = m[j]! / (r2 * Math.sqrt(r2));
      ax += w * dx;
      ay += w * dy;
      az += w * dz;
    }
    out[3 * k] = G * ax;
    out[3 * k + 1] = G * ay;
    out[3 * k + 2] = G * az;
  }
  return out;
}

/**
 * `count` indices spread evenly over 0..n-1 (floor(k n / count)); all of them if count >= n.
 * @category Forces
 */
export function sampleIndices(n: number, count: number): Int32Array {
  const c = Math.min(n, Math.max(0, Math.floor(count)));
  const out = new Int32Array(c);
  for (let k = 0; k < c; k++) out[k] = Math.floor((k * n) / c);
  return out;
}

/**
 * Summary of relative errors |a - a_exact| / |a_exact| over a sample (fractions, not percent).
 * @category Forces
 */
export interface FieldErrorStats {
  /** Bodies compared. */
  sample: number;
  median: number;
  /** 99th percentile (the value below which 99% of the sample lies). */
  p99: number;
  max: number;
  mean: number;
}

/**
 * Relative errors of `approx` against `exact` (both 3 numbers a body, as from directField): for each
 * body |a - e| / |e|, or 0 when both are zero and Infinity when only e is. Summary of them.
 * @category Forces
 */
export function fieldErrorStats(approx: ArrayLike<number>, exact: ArrayLike<number>): FieldErrorStats {
  const k = Math.floor(exact.length / 3);
  const errs = new Float64Array(k);
  let sum = 0;
  for (let i = 0; i < k; i++) {
    const ex = exact[3 * i]!,
      ey = exact[3 * i + 1]!,
      ez = exact[3 * i + 2]!;
    const d = Math.hypot(approx[3 * i]! - ex, approx[3 * i + 1]! - ey, approx[3 * i + 2]! - ez);
    const e = Math.hypot(ex, ey, ez);
    errs[i] = e > 0 ? d / e : d > 0 ? Infinity : 0;
    sum += errs[i]!;
  }
  errs.sort();
  const at = (q: number) => (k === 0 ? 0 : errs[Math.min(k - 1, Math.floor(q * k))]!);
  return { sample: k, median: at(0.5), p99: at(0.99), max: k === 0 ? 0 : errs[k - 1]!, mean: k === 0 ? 0 : sum / k };
}

function mutualBodies(world: PhysicsWorld) {
  const c = world.components;
  return query(world, [c.MutualGravity, c.Position, c.Mass, c.Force]);
}

/**
 * Relative error of the tree field (the Barnes-Hut method with the world's G, softening and opening
 * angle, whatever method the world steps with) against the direct sum, over `sample` bodies spread
 * evenly over the world's mutual-gravity bodies (default 1,000; all if fewer). Costs one tree
 * evaluation plus sample x N pair terms.
 * @throws RangeError if sample is not an integer >= 1.
 * @category Forces
 */
export function gravityFieldError(world: PhysicsWorld, sample = 1000): FieldErrorStats {
  assertInteger('gravityFieldError', 'sample', sample, 1, Number.MAX_SAFE_INTEGER);
  const ents = mutualBodies(world);
  const n = ents.length;
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position,
    pm = c.Mass.value;
  const x = new Float64Array(n),
    y = new Float64Array(n),
    z = new Float64Array(n),
    m = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const e = ents[i]!;
    x[i] = px[e]!;
    y[i] = py[e]!;
    z[i] = pz[e]!;
    m[i] = pm[e]!;
  }
  const targets = sampleIndices(n, sample);
  const L = world.laws;
  const exact = directField(n, x, y, z, m, L.gravitationalConstant, L.gravitySoftening ** 2, targets);
  const t = worldTreeFields(world, ents);
  const approx = new Float64Array(exact.length);
  for (let k = 0; k < targets.length; k++) {
    const s = t.slot[targets[k]!]!;
    approx[3 * k] = t.ax[s]!;
    approx[3 * k + 1] = t.ay[s]!;
    approx[3 * k + 2] = t.az[s]!;
  }
  return fieldErrorStats(approx, exact);
}

/**
 * Median relative error of the tree field against the direct sum over `sample` bodies (see gravityFieldError).
 * @category Forces
 */
export function forceErrorMedian(world: PhysicsWorld, sample = 1000): number {
  return gravityFieldError(world, sample).median;
}

/**
 * Momentum bookkeeping of mutual gravity at the current positions.
 * @category Forces
 */
export interface GravityMomentumRate {
  /** Net mutual-gravity force sum_i F_i, N (= kg m/s^2): the rate at which it changes total momentum. */
  rate: Float64Array;
  /** |rate|, N. */
  magnitude: number;
  /** sum_i |F_i|, N: the scale to compare `magnitude` with. */
  total: number;
  /** magnitude / total (0 when total is 0). Exact pairwise-opposite forces give rounding only, ~1e-16 to 1e-13. */
  relative: number;
}

/**
 * The net force of mutual gravity on the world's mutual-gravity bodies, computed by the world's own
 * method ('barnes-hut': the tree; 'direct': the pair sum), i.e. the drift rate of total momentum
 * that mutual gravity causes (Newton's third law makes it zero; any remainder is the method's
 * momentum drift). 'direct' costs O(N^2).
 * @category Forces
 */
export function gravityMomentumRate(world: PhysicsWorld): GravityMomentumRate {
  const ents = mutualBodies(world);
  const n = ents.length;
  const c = world.components;
  const rate = new Float64Array(3);
  let total = 0;
  if (n >= 2) {
    const pm = c.Mass.value;
    const fx = new Float64Array(n),
      fy = new Float64Array(n),
      fz = new Float64Array(n);
    if (world.laws.gravityMethod === 'barnes-hut') {
      const t = worldTreeFields(world, ents);
      for (let s = 0; s < n; s++) {
        const w = t.m[s]!,
          i = t.perm[s]!;
        fx[i] = w * t.ax[s]!;
        fy[i] = w * t.ay[s]!;
        fz[i] = w * t.az[s]!;
      }
    } else {
      const { x: px, y: py, z: pz } = c.Position;
      const L = world.laws;
      const G = L.gravitationalConstant,
        eps2 = L.gravitySoftening ** 2;
      for (let i = 0; i < n; i++) {
        const a = ents[i]!;
        for (let j = i + 1; j < n; j++) {
          const b = ents[j]!;
          const dx = px[b]! - px[a]!,
            dy = py[b]! - py[a]!,
            dz = pz[b]! - pz[a]!;
          const r2 = dx * dx + dy * dy + dz * dz + eps2;
          if (r2 === 0) continue;
          const k = (G * pm[a]! * pm[b]!) / (r2 * Math.sqrt(r2));
          fx[i] += k * dx;
          fy[i] += k * dy;
          fz[i] += k * dz;
          fx[j] -= k * dx;
          fy[j] -= k * dy;
          fz[j] -= k * dz;
        }
      }
    }
    for (let i = 0; i < n; i++) {
      rate[0] += fx[i]!;
      rate[1] += fy[i]!;
      rate[2] += fz[i]!;
      total += Math.hypot(fx[i]!, fy[i]!, fz[i]!);
    }
  }
  const magnitude = Math.hypot(rate[0]!, rate[1]!, rate[2]!);
  return { rate, magnitude, total, relative: total > 0 ? magnitude / total : 0 };
}
