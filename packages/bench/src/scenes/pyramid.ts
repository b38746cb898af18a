import { pyramidLayout, type PyramidHandles } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';
import { round } from './format.js';

const metres = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(4) : String(v));

/**
 * Bench side of `pyramid`: the base limit, our box ids, and how well every engine's pyramid stood
 * after the timed steps, from each engine's final box centres against the layout: `topDrop` (m the
 * top box sank, positive down), `maxDrift` (largest horizontal move of any box, m) and `fallen`
 * (boxes more than 0.5 m below where they started). 600 timed steps and no warm-up by default, so the
 * figures cover the pyramid's first 10 s from its exact start.
 */
export const pyramidBench: BenchScene = {
  name: 'pyramid',
  maxCount: 1000,
  defaults: { steps: 600, warmup: 0 },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as PyramidHandles).boxes;
  },
  extras(snapshot, options) {
    const layout = pyramidLayout({ count: options.count });
    const p = snapshot.positions, p0 = layout.positions;
    let maxDrift = 0, fallen = 0;
    for (let i = 0; i < layout.count; i++) {
      const dx = Math.abs(p[2 * i]! - p0[2 * i]!);
      if (dx > maxDrift) maxDrift = dx;
      if (p[2 * i + 1]! < p0[2 * i + 1]! - 0.5) fallen++;
    }
    const top = layout.count - 1;
    return {
      topDrop: round(p0[2 * top + 1]! - p[2 * top + 1]!, 6),
      maxDrift: round(maxDrift, 6),
      fallen,
    };
  },
  columns: [
    { key: 'topDrop', label: 'top drop m', format: metres },
    { key: 'maxDrift', label: 'max drift m', format: metres },
    { key: 'fallen', label: 'fallen', format: (v) => String(v) },
  ],
  notes: [
    'pyramid: --count is the base (40: 820 boxes of 1 x 1 m, friction 0.6, restitution 0, density 1 kg/m^2, 1.05 m pitch, gravity -10 m/s^2).',
    'top drop: how far the top box sank (m, positive down); max drift: largest horizontal move of any box (m); fallen: boxes > 0.5 m below their start.',
  ],
};
