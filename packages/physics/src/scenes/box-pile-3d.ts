import { addPlane } from '../bodies/rigid.js';
import type { PhysicsWorld } from '../world/options.js';
import { addCubes } from './cubes.js';
import { type JitteredBox3D, jitteredBox3D } from './jittered-grid.js';
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
export interface BoxPile3DLayout extends JitteredBox3D {
  /** Half extent of every box, m (1 x 1 x 1 m boxes). */
  half: number;
  /** Mass of a box, kg (density 1 kg/m^3). */
  mass: number;
  /** Restitution of boxes and walls, in [0, 1]. */
  restitution: number;
  /** Friction coefficient of boxes and walls (>= 0). */
  friction: number;
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
  const half = 0.5;
  return { ...jitteredBox3D('box-pile-3d', options, 200_000, 2 * half), half, mass: 1, restitution: 0.1, friction: 0.6 };
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
    const boxes = addCubes(world, layout.positions, layout.count, layout.half, layout.mass, material);
    return { boxes, layout };
  },
};
