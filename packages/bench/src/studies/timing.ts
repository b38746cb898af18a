import { type PhysicsWorld, step } from '@bitphysics/physics';
import { collectGarbage } from '../memory.js';
import { runInterleaved } from '../runner.js';
import { median } from '../stats.js';

/** Steps a study's timed worlds alternate in (as `--block` does for engines): short, so all see the same load. */
export const STUDY_BLOCK = 5;

/**
 * Median milliseconds of one `step(world)` of each world: `warmup` untimed steps each, a forced
 * garbage collection, then `steps` timed steps each, the worlds alternating in blocks of
 * `STUDY_BLOCK` steps with a rotating order (`runInterleaved`), so every world is timed across the
 * same stretch of machine load. Returns one median a world, in the order given.
 * @throws whatever a step throws (e.g. NonFiniteStateError, implicit Euler's RangeError).
 */
export function medianStepMs(worlds: readonly PhysicsWorld[], steps: number, warmup: number): number[] {
  const instances = worlds.map((w) => ({
    step: (): void => {
      step(w);
    },
  }));
  runInterleaved(instances, warmup, STUDY_BLOCK, null);
  collectGarbage();
  const times = worlds.map(() => new Float64Array(steps));
  runInterleaved(instances, steps, STUDY_BLOCK, times);
  return times.map((t) => median(t));
}

/** Nanoseconds per body-step from a step time in ms and a body count (>= 1). */
export function nsPerBodyStep(ms: number, bodies: number): number {
  return (ms * 1e6) / bodies;
}
