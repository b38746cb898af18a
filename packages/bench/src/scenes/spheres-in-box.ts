import { type SpheresInBoxHandles, spheresInBoxLayout } from '@bitphysics/physics';
import { maxBallOverlap, maxWallPenetration } from '../quality.js';
import { round } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

const percent = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(2) : String(v));

/**
 * Bench side of `spheres-in-box` (3D): the count limit of `spheresInBoxLayout`, our sphere ids, and
 * the settled quality of every engine's pile after the last step, computed from each engine's final
 * positions with the same uniform-grid search: the largest sphere-sphere overlap and the deepest wall
 * penetration in % of the radius, and how many pairs overlap at all. Our line also counts the
 * spheres asleep (rapier3d's adapter reports its own).
 */
export const spheresInBoxBench: BenchScene = {
  name: 'spheres-in-box',
  maxCount: 2_000_000,
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as SpheresInBoxHandles).spheres;
  },
  probe(world) {
    return { extras: () => ({ sleeping: world.collision.stats.sleeping }) };
  },
  extras(snapshot, options) {
    const layout = spheresInBoxLayout({ count: options.count, seed: options.seed });
    const radius = snapshot.radius ?? layout.radius;
    const overlap = maxBallOverlap(snapshot.positions, radius, snapshot.dimensions);
    const wall = maxWallPenetration(snapshot.positions, radius, snapshot.dimensions, layout.min, layout.max);
    return {
      maxOverlapPercent: round(overlap.maxOverlapPercent, 4),
      maxOverlapM: round(overlap.maxOverlap, 6),
      overlappingPairs: overlap.overlappingPairs,
      maxWallPenetrationPercent: round((100 * wall) / layout.radius, 4),
    };
  },
  columns: [
    { key: 'maxOverlapPercent', label: 'max overlap %r', format: percent },
    { key: 'maxWallPenetrationPercent', label: 'wall pen. %r', format: percent },
    { key: 'overlappingPairs', label: 'overlapping pairs', format: (v) => String(v) },
    { key: 'sleeping', label: 'asleep', format: (v) => String(v) },
  ],
  notes: [
    'max overlap: largest r_i + r_j - |x_i - x_j| between any two spheres after the last step, in % of the radius (uniform-grid search); ' +
      'wall pen.: deepest sphere into the box, same unit. Run enough steps for the pile to settle (the top layer falls ~12 m, ~1.5 s).',
  ],
};
