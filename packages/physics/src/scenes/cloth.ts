import { type Cloth, createCloth } from '../cloth/create.js';
import { setWind } from '../forces/configure.js';
import type { PhysicsWorld } from '../world/options.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `cloth` scene.
 * @category Scenes
 */
export interface ClothSceneOptions {
  /** Points along each side, integer in [2, 512]. Default 64 (4,096 points, 23,938 links). */
  count?: number;
  /** Seed of the wind's turbulence. Default 1. */
  seed?: number;
}

/**
 * `cloth`: a 6.4 m square cloth of side x side points (1 kg in all) pinned along its top edge, with
 * structural, shear and bending links (createCloth's defaults), in a 4 m/s wind along +x with
 * turbulence of 1 m/s RMS over 2 m and 1 s (8 Fourier modes), under gravity (0, -9.81) m/s^2. Measures the cloth solver:
 * ms a step and the largest link stretch.
 * @category Scenes
 */
export const clothScene: SceneDefinition<ClothSceneOptions, Cloth> = {
  name: 'cloth',
  description: 'side x side cloth pinned at its top edge in a turbulent wind (XPBD links: structural, shear, bending); 2D',
  defaultCount: 64,
  worldOptions(options = {}) {
    const n = options.count ?? 64;
    return { dimensions: 2, capacity: 7 * n * n + 16, gravity: [0, -9.81] };
  },
  build(world: PhysicsWorld, options: ClothSceneOptions = {}): Cloth {
    const where = 'cloth';
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const { count: n, seed } = countAndSeed(where, options, ['count', 'seed'], 64, 2, 512);
    setWind(world, { velocity: [4, 0], turbulence: { intensity: 1, lengthScale: 2, timeScale: 1, seed, modes: 8 } });
    return createCloth(world, { columns: n, rows: n, width: 6.4, height: 6.4, origin: [0, 6.4], mass: 1, drag: 0.05 / n });
  },
};
