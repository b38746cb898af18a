import { Rng } from '../math/rng.js';
import { countAndSeed } from './options.js';

/**
 * Bodies on a jittered cubic grid in a closed box, from `jitteredBox3D`.
 * @category Scenes
 */
export interface JitteredBox3D {
  /** Number of bodies. */
  count: number;
  /** Centres, m: x0, y0, z0, x1, ... */
  positions: Float64Array;
  /** Inner corner of the closed box with the smallest coordinates, m (the origin). */
  min: [number, number, number];
  /** Inner corner of the closed box with the largest coordinates, m. */
  max: [number, number, number];
  /** Gravity, m/s^2. */
  gravity: [number, number, number];
}

/**
 * The layout the spheres-in-box and box-pile-3d scenes share: `options.count` (default 5000, an
 * integer in [1, maxCount]) centres on a 1.5 m grid about eight layers deep: a square footprint of
 * ceil(sqrt(count / 8)) cells a side, filled x first, then z, then y (up), each centre jittered by up
 * to +-0.4 (1.5 - size) m along each axis with the generator seeded by `options.seed` (default 1), so
 * bodies of extent `size` (m) start at least 0.2 (1.5 - size) m apart; in a closed box from the origin,
 * one cell taller than the layers; gravity (0, -10, 0).
 * @throws TypeError | RangeError on bad options, naming the scene `where`.
 * @category Scenes
 */
export function jitteredBox3D(where: string, options: { count?: number; seed?: number }, maxCount: number, size: number): JitteredBox3D {
  const { count, seed } = countAndSeed(where, options, ['count', 'seed'], 5000, 1, maxCount);
  const spacing = 1.5;
  const side = Math.max(1, Math.ceil(Math.sqrt(count / 8)));
  const layers = Math.ceil(count / (side * side));
  const rng = new Rng(seed);
  const jitter = 0.4 * (spacing - size);
  const positions = new Float64Array(3 * count);
  for (let i = 0; i < count; i++) {
    const x = i % side,
      z = Math.floor(i / side) % side,
      y = Math.floor(i / (side * side));
    positions[3 * i] = (x + 0.5) * spacing + rng.range(-jitter, jitter);
    positions[3 * i + 1] = (y + 0.5) * spacing + rng.range(-jitter, jitter);
    positions[3 * i + 2] = (z + 0.5) * spacing + rng.range(-jitter, jitter);
  }
  return { count, positions, min: [0, 0, 0], max: [side * spacing, (layers + 1) * spacing, side * spacing], gravity: [0, -10, 0] };
}
