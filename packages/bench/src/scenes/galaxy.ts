import { performance } from 'node:perf_hooks';
import {
  createPhysicsWorld,
  directField,
  galaxy,
  gravityFieldError,
  gravityMomentumRate,
  linearMomentum,
  type PhysicsWorld,
  sampleIndices,
  step,
} from '@bitphysics/physics';
import { query } from 'bitecs';
import { median } from '../stats.js';
import { sig } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

/** Opening angle the bench uses unless `--theta` says otherwise (the physics engineer's recommendation: median force error ~0.07%). */
export const GALAXY_DEFAULT_THETA = 0.7;
/** Bodies sampled for the force error and for the direct-sum timing. */
export const GALAXY_SAMPLE = 1000;
/** Largest world the pairwise direct method is timed at for `directSpeedupPairwise` (scaled up by (N / M)^2). */
export const GALAXY_DIRECT_WORLD_MAX = 3000;

const fixed =
  (digits: number) =>
  (v: ExtraValue): string =>
    typeof v === 'number' ? v.toFixed(digits) : String(v);

/**
 * Bench side of `galaxy` (2D, mutual gravity by Barnes-Hut): `--theta` (opening angle, default 0.7,
 * passed to the scene as `openingAngle`) and, measured on our world after the timed steps:
 *
 * - `forceErrorMedian`, `forceErrorP99`, `forceErrorMax`: relative error |a_tree - a_direct| / |a_direct|
 *   of the Barnes-Hut field against the direct sum on 1,000 bodies spread evenly over the stars
 *   (`gravityFieldError`), fractions.
 * - `momentumRateRelative`, `momentumRate`: the net mutual-gravity force |sum F_i| (N, game units) and
 *   it over sum |F_i| (`gravityMomentumRate`): the rate at which the tree's missing action-reaction
 *   symmetry changes total momentum; and `momentumDriftRelative`: |P_end - P_start| / sum m|v| over
 *   the timed steps (the drift it actually caused).
 * - `directMsEstimate` and `directSpeedup`: the direct sum's field for the 1,000 sample bodies against
 *   all N (`directField`, N^2 pair terms in all, no third-law halving) timed (median of 3) and scaled
 *   by N / 1000, over the median Barnes-Hut step. A lower bound of a direct step (no integration).
 * - `directPairwiseMsEstimate` and `directSpeedupPairwise`: the physics package's own 'direct' method
 *   (N (N - 1) / 2 pairs with Newton's third law) timed as whole steps of the same scene at
 *   M = min(N, 3000) bodies (median of 5 after 1 warm-up) and scaled by (N / M)^2.
 */
export const galaxyBench: BenchScene = {
  name: 'galaxy',
  maxCount: 2_000_000,
  defaults: { steps: 30, warmup: 3 },
  params: {
    theta: {
      default: GALAXY_DEFAULT_THETA,
      min: 0,
      exclusiveMin: true,
      description: 'galaxy: Barnes-Hut opening angle (smaller: more accurate, slower)',
    },
  },
  sceneOptions(options) {
    return { openingAngle: options.params?.theta ?? GALAXY_DEFAULT_THETA };
  },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as { stars: Uint32Array }).stars;
  },
  probe(world, _handles, options) {
    const p0 = new Float64Array(3),
      p1 = new Float64Array(3);
    let drift = NaN;
    return {
      beginTiming(): void {
        linearMomentum(world, p0);
      },
      endTiming(): void {
        linearMomentum(world, p1);
        drift = Math.hypot(p1[0]! - p0[0]!, p1[1]! - p0[1]!, p1[2]! - p0[2]!) / momentumScale(world);
      },
      extras() {
        const err = gravityFieldError(world, GALAXY_SAMPLE);
        const rate = gravityMomentumRate(world);
        const direct = timeDirectField(world, GALAXY_SAMPLE);
        const pairwise = timeDirectMethod(options.count, options.seed, options.params?.theta ?? GALAXY_DEFAULT_THETA);
        return {
          theta: world.laws.openingAngle,
          forceErrorMedian: sig(err.median, 4),
          forceErrorP99: sig(err.p99, 4),
          forceErrorMax: sig(err.max, 4),
          forceErrorSample: err.sample,
          momentumRate: sig(rate.magnitude, 4),
          momentumRateRelative: sig(rate.relative, 4),
          momentumDriftRelative: sig(drift, 4),
          directMsEstimate: sig(direct, 4),
          directPairwiseMsEstimate: sig(pairwise.ms, 4),
          directPairwiseBodies: pairwise.bodies,
        };
      },
    };
  },
  derive(_engine, msPerStep, extra) {
    const direct = extra.directMsEstimate,
      pairwise = extra.directPairwiseMsEstimate;
    return {
      directSpeedup: typeof direct === 'number' ? sig(direct / msPerStep.median, 4) : null,
      directSpeedupPairwise: typeof pairwise === 'number' ? sig(pairwise / msPerStep.median, 4) : null,
    };
  },
  columns: [
    { key: 'theta', label: 'theta', format: fixed(2) },
    { key: 'forceErrorMedian', label: 'force err median %', format: (v) => (typeof v === 'number' ? (100 * v).toFixed(3) : String(v)) },
    { key: 'momentumRateRelative', label: '|sum F|/sum|F|', format: (v) => (typeof v === 'number' ? v.toExponential(2) : String(v)) },
    { key: 'directMsEstimate', label: 'direct ms (est.)', format: fixed(0) },
    { key: 'directSpeedup', label: 'x faster than direct', format: fixed(1) },
    { key: 'directSpeedupPairwise', label: 'x vs pairwise direct', format: fixed(1) },
  ],
  notes: [
    'force err: median relative error of the Barnes-Hut field against the direct sum on 1,000 stars spread evenly over the disc (gravityFieldError).',
    'direct ms (est.): directField for those 1,000 stars against all N timed (median of 3) and scaled by N / 1000 (N^2 pair terms, no third-law halving, no integration); ' +
      "x faster than direct = that / median Barnes-Hut step. x vs pairwise direct: the physics package's own direct method (N(N-1)/2 pairs) timed as whole steps of the " +
      'same scene at min(N, 3000) stars (median of 5) and scaled by (N / M)^2.',
    "|sum F|/sum|F|: net mutual-gravity force over the sum of magnitudes (gravityMomentumRate), the tree's momentum drift rate; momentumDriftRelative in --json: |P_end - P_start| / sum m|v| over the timed steps.",
  ],
};

/** Sum of m |v| over the world's massive bodies: the scale momentum drift is compared with. */
function momentumScale(world: PhysicsWorld): number {
  const c = world.components;
  const ents = query(world, [c.MutualGravity, c.Mass, c.Velocity]);
  let s = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    s += c.Mass.value[e]! * Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!);
  }
  return s;
}

/**
 * Estimated milliseconds of the direct-sum field at all N mutual-gravity bodies of `world`: the field
 * at `sample` bodies spread evenly over them against all N (`directField`) timed three times, the
 * median scaled by N / sample.
 */
export function timeDirectField(world: PhysicsWorld, sample: number): number {
  const c = world.components;
  const ents = query(world, [c.MutualGravity, c.Position, c.Mass]);
  const n = ents.length;
  const x = new Float64Array(n),
    y = new Float64Array(n),
    z = new Float64Array(n),
    m = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const e = ents[i]!;
    x[i] = c.Position.x[e]!;
    y[i] = c.Position.y[e]!;
    z[i] = c.Position.z[e]!;
    m[i] = c.Mass.value[e]!;
  }
  const targets = sampleIndices(n, sample);
  const out = new Float64Array(3 * targets.length);
  const L = world.laws;
  const times: number[] = [];
  for (let r = 0; r < 3; r++) {
    const t0 = performance.now();
    directField(n, x, y, z, m, L.gravitationalConstant, L.gravitySoftening ** 2, targets, out);
    times.push(performance.now() - t0);
  }
  return (median(times) * n) / targets.length;
}

/**
 * Estimated milliseconds of a whole step of `galaxy` with N stars by the physics package's 'direct'
 * method: the scene built at M = min(N, 3000) stars with method 'direct', one warm-up step, the
 * median of five timed steps scaled by (N / M)^2 (the nucleus counts as one more body on both sides).
 */
export function timeDirectMethod(count: number, seed: number, theta: number): { ms: number; bodies: number } {
  const m = Math.min(count, GALAXY_DIRECT_WORLD_MAX);
  const sceneOptions = { count: m, seed, openingAngle: theta, method: 'direct' as const };
  const w = createPhysicsWorld({ ...galaxy.worldOptions(sceneOptions), seed });
  galaxy.build(w, sceneOptions);
  step(w);
  const times: number[] = [];
  for (let i = 0; i < 5; i++) {
    const t0 = performance.now();
    step(w);
    times.push(performance.now() - t0);
  }
  const scale = (count + 1) / (m + 1);
  return { ms: median(times) * scale * scale, bodies: m };
}
