import { type BoxPile3DHandles, boxPile3DLayout } from '@bitphysics/physics';
import { maxBoxOverlap3D, maxBoxWallPenetration3D } from '../quality-boxes3d.js';
import { round } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

/**
 * Tracks when a pile of `count` bodies first had half and all of them asleep: `record(asleep, step)`
 * after every timed step with the bodies asleep after it and the step's number counted from the
 * start (warm-up included, 1 for the first step); `fields()` gives `halfAsleepStep` and
 * `allAsleepStep`, each that step number or null if it never happened in the timed steps. Used by
 * our probe and by the rapier3d adapter, so both engines are counted the same way.
 */
export function asleepSteps(count: number): {
  record(asleep: number, step: number): void;
  fields(): { halfAsleepStep: number | null; allAsleepStep: number | null };
} {
  let half: number | null = null,
    all: number | null = null;
  return {
    record(asleep, step) {
      if (half === null && 2 * asleep >= count) half = step;
      if (all === null && asleep >= count) all = step;
    },
    fields: () => ({ halfAsleepStep: half, allAsleepStep: all }),
  };
}

const percent = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(2) : String(v));

/**
 * Bench side of `box-pile-3d`: the count limit, our box ids, and the settled quality of every engine's
 * pile after the last step, from each engine's final centres and orientations: the largest box-box
 * penetration and the deepest wall penetration in % of the half extent (goal: <= 5 %), and how many
 * pairs overlap at all. Our line also counts the boxes asleep (rapier3d's adapter reports its own),
 * and when half and all of them first slept (`asleepSteps`).
 */
export const boxPile3DBench: BenchScene = {
  name: 'box-pile-3d',
  maxCount: 200_000,
  defaults: { steps: 300, warmup: 30 },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as BoxPile3DHandles).boxes;
  },
  probe(world, _handles, options) {
    const sleep = asleepSteps(options.count);
    return {
      afterStep: () => sleep.record(world.collision.stats.sleeping, Math.round(world.time / world.dt)),
      extras: () => ({ sleeping: world.collision.stats.sleeping, ...sleep.fields() }),
    };
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
    { key: 'halfAsleepStep', label: 'half asleep', format: (v) => (v === null ? '-' : String(v)) },
    { key: 'allAsleepStep', label: 'all asleep', format: (v) => (v === null ? '-' : String(v)) },
  ],
  notes: [
    "box-pile-3d: 1 m cubes (1 kg, friction 0.6, restitution 0.1) from a jittered 1.5 m grid about eight layers deep into a closed box, gravity -10 m/s^2; 300 timed steps after 30 of warm-up by default (the top layer lands after ~1.5 s, the pile sleeps by step ~300): the warm-up holds the first JIT compilation and the bottom layer's landing (~0.2 s); --warmup 0 --steps 330 times everything from the drop.",
    'half asleep / all asleep: the first step (counted from the drop, warm-up included) after which half / all of the boxes were asleep, within the timed steps (-: not within them).',
    'mean ms covers every timed step, landing and settling included (the median of a pile that ends asleep is mostly sleeping steps): the whole-run measure.',
    'max overlap: largest penetration depth between two boxes after the last step (separating-axis test of the 15 axes), in % of the half extent (goal <= 5 %); wall pen.: deepest box corner past a wall, same unit.',
  ],
};
