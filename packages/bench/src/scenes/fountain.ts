import { CHURN_COLUMNS, CHURN_NOTES, churnProbe } from './churn-probe.js';
import type { BenchScene } from './types.js';

/**
 * Bench side of `fountain` (churn at scale: count live bare drops, count / 50 born and as many expiring
 * every step): the step times against `plain-loop` (the same births, deaths and gravity over bare
 * arrays with a free list), and `churnProbe`'s measurements of our world (live, spawned and expired
 * per step, heap growth, allocation per step).
 *
 * Steady state: drops live 2/3 to 1 s, so the live count reaches `count` after 60 steps and stays
 * there (within a few hundred). Hence 90 warm-up steps and 120 timed steps by default (2 s of steady
 * churn: two lifetimes).
 */
export const fountainBench: BenchScene = {
  name: 'fountain',
  maxCount: 16_000_000,
  defaults: { steps: 120, warmup: 90 },
  probe(world, handles) {
    return churnProbe(world, [(handles as { emitter: number }).emitter]);
  },
  columns: CHURN_COLUMNS,
  notes: CHURN_NOTES,
};
