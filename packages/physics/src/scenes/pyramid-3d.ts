import { addPlane } from '../bodies/rigid.js';
import { assertInteger, assertKnownKeys, optionOr } from '../validation/validate.js';
import { slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addCubes } from './cubes.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `pyramid-3d` scene.
 * @category Scenes
 */
export interface Pyramid3DOptions {
  /** Boxes along a side of the bottom layer, integer in [1, 60]; the pyramid has base (base + 1) (2 base + 1) / 6 boxes. Default 20 (2,870 boxes). */
  count?: number;
  /** Unused (the layout is regular); accepted so every scene takes a seed. */
  seed?: number;
}

/**
 * The layout every engine builds for `pyramid-3d` (SI units).
 * @category Scenes
 */
export interface Pyramid3DLayout {
  /** Boxes along a side of the bottom layer. */
  base: number;
  /** Boxes in all, sum of k^2 for k = 1..base. */
  count: number;
  /** Box half extent, m (1 m cubes). */
  half: number;
  /** Distance between neighbouring box centres in a layer, m. */
  pitch: number;
  /** Friction coefficient of boxes and ground (>= 0). */
  friction: number;
  /** Restitution of boxes and ground, in [0, 1]. */
  restitution: number;
  /** Mass of a box, kg (density 1 kg/m^3). */
  mass: number;
  /** Gravity, m/s^2. */
  gravity: [number, number, number];
  /** Box centres (x0, y0, z0, ...), bottom layer first, row by row; layers rest exactly on each other. */
  positions: Float64Array;
}

/**
 * The layout of `pyramid-3d`: square layers of 1 m cubes, each layer one box shorter a side than the
 * one below and centred on it (so a box rests on four), 1.05 m apart within a layer, every layer
 * resting exactly on the one below; the ground is the plane y = 0.
 * @throws RangeError if count is not an integer in [1, 60].
 * @category Scenes
 */
export function pyramid3DLayout(options: Pyramid3DOptions = {}): Pyramid3DLayout {
  assertKnownKeys('pyramid-3d', options, ['count', 'seed']);
  const base = optionOr('pyramid-3d', 'count', options.count, 20, assertInteger, 1, 60);
  const count = (base * (base + 1) * (2 * base + 1)) / 6;
  const pitch = 1.05,
    half = 0.5;
  const positions = new Float64Array(3 * count);
  let k = 0;
  for (let layer = 0; layer < base; layer++) {
    const n = base - layer;
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        positions[k++] = (i - (n - 1) / 2) * pitch;
        positions[k++] = half + layer * 2 * half;
        positions[k++] = (j - (n - 1) / 2) * pitch;
      }
    }
  }
  return { base, count, half, pitch, friction: 0.6, restitution: 0, mass: 1, gravity: [0, -10, 0], positions };
}

/**
 * What `pyramid-3d`'s build returns.
 * @category Scenes
 */
export interface Pyramid3DHandles {
  /** The boxes' body slots, in layout order (bottom layer first). */
  boxes: Uint32Array;
  /** The ground plane's slot. */
  ground: number;
  /** The layout built. */
  layout: Pyramid3DLayout;
}

/**
 * `pyramid-3d`: the 3D counterpart of `pyramid`: `count` is the side of the bottom layer (20: 2,870
 * cubes of 1 m, friction 0.6, restitution 0) on a ground plane, each layer centred on the one below.
 * World defaults otherwise (4 substeps, sleeping on).
 * @category Scenes
 */
export const pyramid3D: SceneDefinition<Pyramid3DOptions, Pyramid3DHandles> = {
  name: 'pyramid-3d',
  description: 'square pyramid of 1 m cubes (friction 0.6, 1.05 m pitch) on a ground plane; --count is the base side (20: 2,870 boxes); 3D',
  defaultCount: 20,
  worldOptions(options = {}) {
    const layout = pyramid3DLayout(options);
    return { dimensions: 3, capacity: 2 * layout.count + 16, gravity: layout.gravity };
  },
  build(world: PhysicsWorld, options: Pyramid3DOptions = {}): Pyramid3DHandles {
    if (world.dimensions !== 3) throw new RangeError(`pyramid-3d: needs a 3D world, got dimensions ${world.dimensions}`);
    const layout = pyramid3DLayout(options);
    const material = { friction: layout.friction, restitution: layout.restitution };
    const ground = slotOf(addPlane(world, { normal: [0, 1, 0], ...material }));
    const boxes = addCubes(world, layout.positions, layout.count, layout.half, layout.mass, material);
    return { boxes, ground, layout };
  },
};
