import { round } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

const metres = (v: ExtraValue): string => (typeof v === 'number' ? v.toExponential(2) : String(v));

/**
 * Bench side of `joint-grid` (Box2D v3's joint benchmark; peers rapier2d and rapier2d-simd): `--count` is
 * the grid's side; the probe records the largest joint error (anchor separation after each step, m)
 * over the timed steps and at the last one, and the number of joints solved.
 */
export const jointGridBench: BenchScene = {
  name: 'joint-grid',
  maxCount: 400,
  defaults: { steps: 120, warmup: 10 },
  probe(world) {
    let worst = 0;
    return {
      beginTiming(): void {
        worst = 0;
      },
      afterStep(): void {
        if (world.joints.stats.maxError > worst) worst = world.joints.stats.maxError;
      },
      extras(): Record<string, ExtraValue> {
        return { maxJointError: round(worst, 6), lastJointError: round(world.joints.stats.maxError, 6), joints: world.joints.stats.rows };
      },
    };
  },
  columns: [
    { key: 'maxJointError', label: 'max joint err m', format: metres },
    { key: 'joints', label: 'joints', format: (v) => String(v) },
  ],
  notes: [
    'joint-grid: --count is the side (100: 10,000 bodies, 19,800 revolute joints; the 7 middle bodies of the top row pinned; gravity -10 m/s^2).',
    'max joint err: largest anchor separation of any joint after any timed step (m); lastJointError (JSON) after the last one.',
  ],
};
