import { boxPile3DLayout, type BoxPile3DHandles } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';
import { maxBoxOverlap3D, maxBoxWallPenetration3D } from '../quality-boxes3d.js';
import { round } from './format.js';

const percent = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(2) : String(v));

/**
 * Bench side of `box-pile-3d`: the count limit, our box ids, and the settled quality of every engine's
 * pile after the last step, from each engine's final centres and orientations: the largest box-box
 * penetration and the deepest wall penetration in % of the half extent (goal: <= 5 %), and how many
 * pairs overlap at all. Our line also counts the boxes asleep (rapier3d's adapter reports its own).
 */
export const boxPile3DBench: BenchScene = {
  name: 'box-pile-3d',
  maxCount: 200_000,
  defaults: { steps: 300, warmup: 30 },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as BoxPile3DHandles).boxes;
  },
  probe(world) {
    return { extras: () => ({ sleeping: world.collision.stats.sleeping }) };
  },
  extras(snapshot, options) {
    const layout = boxPile3DLayout({ count: options.count, seed: options.seed });
    const overlap = maxBoxOverlap3D(snapshot.positions, snapshot.orientations, layout.half);
    const wall = maxBoxWallPenetration3D(snapshot.positions, snapshot.orientations, layout.half, layout.min, layout.max);
    return {
      maxOverlapPercent: round(overlap.maxOverlapPercent, 4),
      maxOverlapM: round(overlap.maxOverlap, 6),
      overlappingPairs: overlap.overlappingPairs,
      maxWallPenetrationPercent: round((100 * wall) / layout.half, 4),
    };
  },
  columns: [
    { key: 'maxOverlapPercent', label: 'max overlap %h', format: percent },
    { key: 'maxWallPenetrationPercent', label: 'wall pen. %h', format: percent },
    { key: 'overlappingPairs', label: 'overlapping pairs', format: (v) => String(v) },
    { key: 'sleeping', label: 'asleep', format: (v) => String(v) },
  ],
  notes: [
    'box-pile-3d: 1 m cubes (1 kg, friction 0.6, restitution 0.1) from a jittered 1.5 m grid about eight layers deep into a closed box, gravity -10 m/s^2; 300 timed steps after 30 of warm-up by default (the top layer lands after ~1.5 s).',
    'max overlap: largest penetration depth between two boxes after the last step (separating-axis test of the 15 axes), in % of the half extent (goal <= 5 %); wall pen.: deepest box corner past a wall, same unit.',
  ],
};
