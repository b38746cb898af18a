import type { PhysicsWorld } from '../world/options.js';
import { addBallsInBox } from './cubes.js';
import { type JitteredBox3D, jitteredBox3D } from './jittered-grid.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `spheres-in-box` scene.
 * @category Scenes
 */
export interface SpheresInBoxOptions {
  /** Number of spheres, integer in [1, 2_000_000]. Default 5000. */
  count?: number;
  /** Seed of the jitter. Default 1. */
  seed?: number;
}

/**
 * The resolved layout of `spheres-in-box`, for peer engines.
 * @category Scenes
 */
export interface SpheresInBoxLayout extends JitteredBox3D {
  /** Sphere radius, m. */
  radius: number;
  /** Mass of a sphere, kg. */
  mass: number;
  /** Restitution of spheres and walls, in [0, 1]. */
  restitution: number;
  /** Friction coefficient of spheres and walls (>= 0). */
  friction: number;
}

/**
 * The `spheres-in-box` layout: spheres of radius 0.5 m (1 kg, restitution 0.5, friction 0.1) on a
 * jittered 1.5 m grid about eight layers deep (a square footprint of ceil(sqrt(N / 8)) cells a side),
 * in a closed box one cell taller than the layers; gravity (0, -10, 0).
 * @throws TypeError | RangeError on bad options.
 * @category Scenes
 */
export function spheresInBoxLayout(options: SpheresInBoxOptions = {}): SpheresInBoxLayout {
  const radius = 0.5;
  return { ...jitteredBox3D('spheres-in-box', options, 2_000_000, 2 * radius), radius, mass: 1, restitution: 0.5, friction: 0.1 };
}

/**
 * Handles of `spheres-in-box`.
 * @category Scenes
 */
export interface SpheresInBoxHandles {
  spheres: Uint32Array;
  layout: SpheresInBoxLayout;
}

/**
 * `spheres-in-box`: the 3D benchmark scene compared against rapier3d.
 * @category Scenes
 */
export const spheresInBox: SceneDefinition<SpheresInBoxOptions, SpheresInBoxHandles> = {
  name: 'spheres-in-box',
  description: 'N spheres (r 0.5 m, e 0.5, mu 0.1) fall from a jittered grid about eight layers deep into a closed box; 3D',
  defaultCount: 5000,
  worldOptions(options = {}) {
    const count = options.count ?? 5000;
    return { dimensions: 3, capacity: count + 16, gravity: [0, -10, 0] };
  },
  build(world: PhysicsWorld, options: SpheresInBoxOptions = {}): SpheresInBoxHandles {
    if (world.dimensions !== 3) throw new RangeError(`spheres-in-box: needs a 3D world, got dimensions ${world.dimensions}`);
    const layout = spheresInBoxLayout(options);
    const spheres = addBallsInBox(world, layout, 3);
    return { spheres, layout };
  },
};
