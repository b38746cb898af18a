import { ballsInBoxLayout, type BallsInBoxHandles } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';
import { maxBallOverlap, maxWallPenetration } from '../quality.js';

const percent = (v: ExtraValue): string => (typeof v === 'number' ? `${v.toFixed(2)}` : String(v));

/**
 * Bench side of `balls-in-box`: the count limit of `ballsInBoxLayout`, and the settled quality of
 * every engine's pile (largest ball-ball overlap and deepest wall penetration, as a percentage of
 * the ball radius), computed from each engine's final positions with the same grid search.
 */
export const ballsInBoxBench: BenchScene = {
  name: 'balls-in-box',
  maxCount: 10_000_000,
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as BallsInBoxHandles).balls;
  },
  extras(snapshot, options) {
    const radius = snapshot.radius ?? 0.5;
    const overlap = maxBallOverlap(snapshot.positions, radius, snapshot.dimensions);
    const layout = ballsInBoxLayout({ count: options.count, seed: options.seed });
    const r = typeof radius === 'number' ? radius : layout.radius;
    const wall = maxWallPenetration(snapshot.positions, radius, snapshot.dimensions, layout.min, layout.max);
    return {
      maxOverlapPercent: round(overlap.maxOverlapPercent, 4),
      maxOverlapM: round(overlap.maxOverlap, 6),
      overlappingPairs: overlap.overlappingPairs,
      maxWallPenetrationPercent: round((100 * wall) / r, 4),
    };
  },
  columns: [
    { key: 'maxOverlapPercent', label: 'max overlap %r', format: percent },
    { key: 'maxWallPenetrationPercent', label: 'wall pen. %r', format: percent },
  ],
  notes: [
    'max overlap: largest r_i + r_j - |x_i - x_j| between any two balls after the last step, in % of the radius (uniform-grid search).',
  ],
};

function round(value: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(value * f) / f;
}
