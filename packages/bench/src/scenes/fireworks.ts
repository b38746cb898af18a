import { CHURN_COLUMNS, CHURN_NOTES, churnProbe } from './churn-probe.js';
import type { BenchScene } from './types.js';

/**
 * Bench side of `fireworks` (2D steady churn: shells burst into sparks that burst into embers, spawn
 * and expiry every step): besides the step times, `churnProbe`'s measurements of our world over the
 * scene's three emitters (live particles, spawned / expired / recycled per step, heap growth and
 * allocation per step).
 *
 * Steady state takes about 5 s to reach (shells rise ~1 s, sparks live 1-2 s, embers 0.5-1 s after
 * them): at the default 50,000, the live count is ~4,800 after 100 steps, ~42,000 after 200 and
 * ~50,000 from step 300 on, where spawned and expired per step level off at ~990 each. Hence 360
 * warm-up steps (6 s, past the ramp) and 600 timed steps (10 s of steady churn, several shell
 * lifetimes) by default.
 */
export const fireworksBench: BenchScene = {
  name: 'fireworks',
  maxCount: 10_000_000,
  defaults: { steps: 600, warmup: 360 },
  probe(world, handles) {
    const h = handles as { shells: number; sparks: number; embers: number };
    return churnProbe(world, [h.shells, h.sparks, h.embers]);
  },
  columns: CHURN_COLUMNS,
  notes: CHURN_NOTES,
};
