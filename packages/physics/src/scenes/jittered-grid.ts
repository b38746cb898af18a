import { Rng } from '../math/rng.js';

/**
 * Bodies on a jittered cubic grid, from `jitteredGrid3D`.
 * @category Scenes
 */
export interface JitteredGrid3D {
  /** Centres, m: x0, y0, z0, x1, ... */
  positions: Float64Array;
  /** Cells along x and along z (the square footprint). */
  side: number;
  /** Layers along y. */
  layers: number;
}

/**
 * `count` centres on a grid of pitch `spacing` (m) about eight layers deep: a square footprint of
 * ceil(sqrt(count / 8)) cells a side, filled x first, then z, then y (up), each centre jittered by up
 * to +-0.4 (spacing - size) along each axis with the seeded generator, so bodies of extent `size` (m)
 * start at least 0.2 (spacing - size) apart. Shared by the spheres-in-box and box-pile-3d scenes.
 * @category Scenes
 */
export function jitteredGrid3D(count: number, seed: number, spacing: number, size: number): JitteredGrid3D {
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
  return { positions, side, layers };
}
