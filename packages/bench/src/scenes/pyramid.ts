import { type PyramidHandles, pyramidLayout } from '@bitphysics/physics';
import { round } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

const metres = (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(4) : String(v));

/**
 * How a pyramid of `count` boxes stood, from final centres `p` against start centres `p0` (m, `dims`
 * numbers a box: x, y in 2D, x, y, z in 3D; y up; the top box last): `topDrop` (m the top box sank,
 * positive down), `maxDrift` (largest horizontal move of any box, m: along x in 2D, in the x-z plane
 * in 3D) and `fallen` (boxes more than 0.5 m below their start). Shared by `pyramid` and `pyramid-3d`.
 */
export function pyramidStanding(p: ArrayLike<number>, p0: ArrayLike<number>, count: number, dims: 2 | 3): Record<string, number> {
  let maxDrift = 0,
    fallen = 0;
  for (let i = 0; i < count; i++) {
    const o = dims * i;
    const dx = p[o]! - p0[o]!,
      dz = dims === 3 ? p[o + 2]! - p0[o + 2]! : 0;
    const d = dims === 3 ? Math.hypot(dx, dz) : Math.abs(dx);
    if (d > maxDrift) maxDrift = d;
    if (p[o + 1]! < p0[o + 1]! - 0.5) fallen++;
  }
  const top = dims * (count - 1) + 1;
  return { topDrop: round(p0[top]! - p[top]!, 6), maxDrift: round(maxDrift, 6), fallen };
}

/** The columns of `pyramidStanding`'s fields. */
export const PYRAMID_COLUMNS: NonNullable<BenchScene['columns']> = [
  { key: 'topDrop', label: 'top drop m', format: metres },
  { key: 'maxDrift', label: 'max drift m', format: metres },
  { key: 'fallen', label: 'fallen', format: (v) => String(v) },
];

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
    return pyramidStanding(snapshot.positions, layout.positions, layout.count, 2);
  },
  columns: PYRAMID_COLUMNS,
  notes: [
    'pyramid: --count is the base (40: 820 boxes of 1 x 1 m, friction 0.6, restitution 0, density 1 kg/m^2, 1.05 m pitch, gravity -10 m/s^2).',
    'top drop: how far the top box sank (m, positive down); max drift: largest horizontal move of any box (m); fallen: boxes > 0.5 m below their start.',
  ],
};
