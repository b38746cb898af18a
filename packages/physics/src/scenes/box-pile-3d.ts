import { addBody } from '../bodies/api.js';
import { addPlane } from '../bodies/rigid.js';
import { addShape3D } from '../shapes/api-3d.js';
import { slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertFinite, assertInteger, assertKnownKeys } from '../world/validate.js';
import { jitteredGrid3D } from './jittered-grid.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `box-pile-3d` scene.
 * @category Scenes
 */
export interface BoxPile3DOptions {
  /** Number of boxes, integer in [1, 200_000]. Default 5000. */
  count?: number;
  /** Seed of the jitter. Default 1. */
  seed?: number;
}

/**
 * The resolved layout of `box-pile-3d`, for peer engines (SI units).
 * @category Scenes
 */
export interface BoxPile3DLayout {
  /** Number of boxes. */
  count: number;
  /** Box centres, m: x0, y0, z0, x1, ... (boxes start axis-aligned, at rest). */
  positions: Float64Array;
  /** Half extent of every box, m (1 x 1 x 1 m boxes). */
  half: number;
  /** Mass of a box, kg (density 1 kg/m^3). */
  mass: number;
  /** Restitution of boxes and walls, in [0, 1]. */
  restitution: number;
  /** Friction coefficient of boxes and walls (>= 0). */
  friction: number;
  /** Inner corner of the closed box with the smallest coordinates, m (the origin). */
  min: [number, number, number];
  /** Inner corner of the closed box with the largest coordinates, m. */
  max: [number, number, number];
  /** Gravity, m/s^2. */
  gravity: [number, number, number];
}

/**
 * The `box-pile-3d` layout, `spheres-in-box` with boxes: cubes of 1 m (1 kg, friction 0.6, restitution
 * 0.1) on a 1.5 m grid jittered by up to +-0.2 m along each axis (so neighbours start at least 0.1 m
 * apart), about eight layers deep (a square footprint of ceil(sqrt(N / 8)) cells a side), in a closed
 * box one cell taller than the layers; gravity (0, -10, 0).
 * @throws TypeError | RangeError on bad options.
 * @category Scenes
 */
export function boxPile3DLayout(options: BoxPile3DOptions = {}): BoxPile3DLayout {
  const where = 'box-pile-3d';
  assertKnownKeys(where, options, ['count', 'seed']);
  const count = options.count ?? 5000;
  assertInteger(where, 'count', count, 1, 200_000);
  const seed = options.seed ?? 1;
  assertFinite(where, 'seed', seed);
  const spacing = 1.5,
    half = 0.5;
  const { positions, side, layers } = jitteredGrid3D(count, seed, spacing, 2 * half);
  return {
    count,
    positions,
    half,
    mass: 1,
    restitution: 0.1,
    friction: 0.6,
    min: [0, 0, 0],
    max: [side * spacing, (layers + 1) * spacing, side * spacing],
    gravity: [0, -10, 0],
  };
}

/**
 * Handles of `box-pile-3d`.
 * @category Scenes
 */
export interface BoxPile3DHandles {
  /** The boxes' body slots, in layout order. */
  boxes: Uint32Array;
  /** The layout built. */
  layout: BoxPile3DLayout;
}

/**
 * `box-pile-3d`: N unit cubes dropped into a closed box (its six faces are static planes), the 3D box
 * benchmark compared against rapier3d. World defaults otherwise (4 substeps, sleeping on).
 * @category Scenes
 */
export const boxPile3D: SceneDefinition<BoxPile3DOptions, BoxPile3DHandles> = {
  name: 'box-pile-3d',
  description: 'N boxes of 1 m (mu 0.6, e 0.1) fall from a jittered grid about eight layers deep into a closed box; 3D',
  defaultCount: 5000,
  worldOptions(options = {}) {
    const count = options.count ?? 5000;
    // A box is two entities (body and shape); six planes.
    return { dimensions: 3, capacity: 2 * count + 16, gravity: [0, -10, 0] };
  },
  build(world: PhysicsWorld, options: BoxPile3DOptions = {}): BoxPile3DHandles {
    if (world.dimensions !== 3) throw new RangeError(`box-pile-3d: needs a 3D world, got dimensions ${world.dimensions}`);
    const layout = boxPile3DLayout(options);
    const [x0, y0, z0] = layout.min,
      [x1, y1, z1] = layout.max;
    const material = { friction: layout.friction, restitution: layout.restitution };
    const walls: Array<[number[], number[]]> = [
      [
        [0, 1, 0],
        [0, y0, 0],
      ],
      [
        [0, -1, 0],
        [0, y1, 0],
      ],
      [
        [1, 0, 0],
        [x0, 0, 0],
      ],
      [
        [-1, 0, 0],
        [x1, 0, 0],
      ],
      [
        [0, 0, 1],
        [0, 0, z0],
      ],
      [
        [0, 0, -1],
        [0, 0, z1],
      ],
    ];
    for (const [normal, point] of walls) addPlane(world, { normal, point, ...material });
    const boxes = new Uint32Array(layout.count);
    const p = layout.positions,
      h = layout.half,
      extents = [h, h, h];
    const density = layout.mass / (8 * h * h * h);
    for (let i = 0; i < layout.count; i++) {
      const b = addBody(world, { position: [p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!] });
      addShape3D(world, b, { type: 'box', halfExtents: extents, density, ...material });
      boxes[i] = slotOf(b);
    }
    return { boxes, layout };
  },
};
