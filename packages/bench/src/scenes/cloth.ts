import type { BenchScene, ExtraValue } from './types.js';
import { round } from './format.js';

/**
 * Bench side of `cloth` (ours only): `--count` is the cloth's side; the probe records the largest link
 * strain (length / rest - 1) over the timed steps and the number of links.
 */
export const clothBench: BenchScene = {
  name: 'cloth',
  maxCount: 512,
  defaults: { steps: 300, warmup: 30 },
  probe(world) {
    let worst = 0;
    return {
      beginTiming(): void { worst = 0; },
      afterStep(): void { if (world.cloth.maxStretch > worst) worst = world.cloth.maxStretch; },
      extras(): Record<string, ExtraValue> {
        return { maxStretch: round(worst, 6), links: world.cloth.count, substeps: world.cloth.substeps };
      },
    };
  },
  columns: [
    { key: 'maxStretch', label: 'max stretch', format: (v) => (typeof v === 'number' ? `${(100 * v).toFixed(2)}%` : String(v)) },
    { key: 'links', label: 'links', format: (v) => String(v) },
  ],
  notes: [
    'cloth: --count is the side (64: 4,096 points, 23,938 links: structural, shear, bending), pinned along the top edge, 4 m/s wind with 1 m/s turbulence.',
    'max stretch: largest link strain (length / rest - 1) after any timed step; 11 XPBD substeps a step (the default).',
  ],
};
