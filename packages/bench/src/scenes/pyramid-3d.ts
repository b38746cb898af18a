import { type Pyramid3DHandles, pyramid3DLayout } from '@bitphysics/physics';
import { PYRAMID_COLUMNS, pyramidStanding } from './pyramid.js';
import type { BenchScene } from './types.js';

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
    return pyramidStanding(snapshot.positions, layout.positions, layout.count, 3);
  },
  columns: PYRAMID_COLUMNS,
  notes: [
    'pyramid-3d: --count is the side of the bottom layer (20: 2,870 cubes of 1 m, 1 kg, friction 0.6, restitution 0, 1.05 m pitch, gravity -10 m/s^2), each layer centred on the one below; goal: topDrop <= 0.05 m.',
    'top drop: how far the top box sank (m, positive down); max drift: largest horizontal move of any box (m); fallen: boxes > 0.5 m below their start.',
  ],
};
