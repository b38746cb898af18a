import { type BallsInBoxHandles, ballsInBoxLayout } from '@bitphysics/physics';
import { maxBallOverlap, maxWallPenetration } from '../quality.js';
import type { BenchScene, ExtraValue } from './types.js';

const percent = (v: ExtraValue): string => (typeof v === 'number' ? `${v.toFixed(2)}` : String(v));

/**
 * Bench side of `balls-in-box`: the count limit of `ballsInBoxLayout`, `--restitution` (of balls and
 * walls, default 0.5; every engine builds the layout with it), and for every engine:
 * - the settled quality of the pile (largest ball-ball overlap and deepest wall penetration, as a
 *   percentage of the ball radius), from the final positions with the same grid search;
 * - `energyDrift`: (E_end - E_0) / E_0 of the mechanical energy E = sum (m v^2 / 2 + m g y) of the
 *   balls, from the layout (at rest) to the final snapshot (after warm-up and timed steps). With
 *   `--restitution 1` only friction (0.1) should take energy out; a value near 0 is a pile that keeps
 *   the energy its impacts should keep, a large negative one an engine that loses it in its contacts.
 */
export const ballsInBoxBench: BenchScene = {
  name: 'balls-in-box',
  maxCount: 10_000_000,
  params: {
    restitution: {
      default: 0.5,
      min: 0,
      max: 1,
      description: 'balls-in-box: restitution of balls and walls (1: perfectly elastic, for energyDrift)',
    },
  },
  sceneOptions(options) {
    return { restitution: options.params?.restitution ?? 0.5 };
  },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as BallsInBoxHandles).balls;
  },
  extras(snapshot, options) {
    const radius = snapshot.radius ?? 0.5;
    const overlap = maxBallOverlap(snapshot.positions, radius, snapshot.dimensions);
    const layout = ballsInBoxLayout({ count: options.count, seed: options.seed });
    const r = typeof radius === 'number' ? radius : layout.radius;
    const wall = maxWallPenetration(snapshot.positions, radius, snapshot.dimensions, layout.min, layout.max);
    const g = -layout.gravity[1],
      m = layout.mass;
    let e0 = 0,
      e1 = 0;
    for (let i = 0; i < layout.count; i++) e0 += m * g * layout.positions[2 * i + 1]!;
    const v = snapshot.velocities;
    for (let i = 0; i < snapshot.count; i++) {
      e1 += m * g * snapshot.positions[2 * i + 1]!;
      if (v) e1 += 0.5 * m * (v[2 * i]! * v[2 * i]! + v[2 * i + 1]! * v[2 * i + 1]!);
    }
    return {
      energyDrift: v ? round((e1 - e0) / e0, 6) : null,
      restitution: options.params?.restitution ?? 0.5,
      maxOverlapPercent: round(overlap.maxOverlapPercent, 4),
      maxOverlapM: round(overlap.maxOverlap, 6),
      overlappingPairs: overlap.overlappingPairs,
      maxWallPenetrationPercent: round((100 * wall) / r, 4),
    };
  },
  columns: [
    { key: 'maxOverlapPercent', label: 'max overlap %r', format: percent },
    { key: 'maxWallPenetrationPercent', label: 'wall pen. %r', format: percent },
    { key: 'energyDrift', label: 'energy drift', format: (v) => (typeof v === 'number' ? `${(100 * v).toFixed(2)}%` : String(v)) },
  ],
  notes: [
    'max overlap: largest r_i + r_j - |x_i - x_j| between any two balls after the last step, in % of the radius (uniform-grid search).',
  ],
};

function round(value: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(value * f) / f;
}
