import { pyramid3DLayout, type Pyramid3DHandles } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';
import { round } from './format.js';

const metres = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(4) : String(v));

/**
 * Bench side of `pyramid-3d`: the base limit, our box ids, and how well every engine's pyramid stood
 * after the timed steps, from each engine's final box centres against the layout, as `pyramid` does
 * in 2D: `topDrop` (m the top box sank, positive down), `maxDrift` (largest horizontal move of any
 * box, m, in the x-z plane) and `fallen` (boxes more than 0.5 m below where they started). 600 timed
 * steps and no warm-up by default, so the figures cover the pyramid's first 10 s from its exact start.
 */
export const pyramid3DBench: BenchScene = {
  name: 'pyramid-3d',
  maxCount: 60,
  defaults: { steps: 600, warmup: 0 },
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as Pyramid3DHandles).boxes;
  },
  extras(snapshot, options) {
    const layout = pyramid3DLayout({ count: options.count });
    const p = snapshot.positions, p0 = layout.positions;
    let maxDrift = 0, fallen = 0;
    for (let i = 0; i < layout.count; i++) {
      const d = Math.hypot(p[3 * i]! - p0[3 * i]!, p[3 * i + 2]! - p0[3 * i + 2]!);
      if (d > maxDrift) maxDrift = d;
      if (p[3 * i + 1]! < p0[3 * i + 1]! - 0.5) fallen++;
    }
    const top = layout.count - 1;
    return {
      topDrop: round(p0[3 * top + 1]! - p[3 * top + 1]!, 6),
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
    'pyramid-3d: --count is the side of the bottom layer (20: 2,870 cubes of 1 m, 1 kg, friction 0.6, restitution 0, 1.05 m pitch, gravity -10 m/s^2), each layer centred on the one below; goal: topDrop <= 0.05 m.',
    'top drop: how far the top box sank (m, positive down); max drift: largest horizontal move of any box (m); fallen: boxes > 0.5 m below their start.',
  ],
};
