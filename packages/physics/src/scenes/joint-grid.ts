import { addBody } from '../bodies/api.js';
import { addRevoluteJoint } from '../joints/revolute-joint.js';
import type { PhysicsWorld } from '../world/options.js';
import { countAndSeed } from './options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `joint-grid` scene.
 * @category Scenes
 */
export interface JointGridOptions {
  /** Bodies along each side of the square grid, integer in [2, 400]. Default 100 (10,000 bodies, 19,800 joints). */
  count?: number;
  /** Unused (the scene has no randomness); accepted like every scene's. Default 1. */
  seed?: number;
}

/**
 * Handles of the `joint-grid` scene.
 * @category Scenes
 */
export interface JointGridHandles {
  /** Body handles, row-major from the top-left: (row i, column k) is bodies[i * side + k]. */
  bodies: Float64Array;
  /** Joint handles. */
  joints: Float64Array;
  /** Bodies along a side. */
  side: number;
}

/**
 * `joint-grid`, Box2D v3's joint benchmark: a side x side grid of 1 kg bodies 1 m apart (the moment of
 * inertia of a 0.4 m disc, no colliders), each joined to its left and upper neighbours by revolute
 * joints at the midpoints. The seven middle bodies of the top row are static (pinned); the rest of the
 * net falls and swings under gravity (0, -10) m/s^2. Measures the joint solver alone: ms a step and
 * the largest joint error (anchor separation, m).
 * @category Scenes
 */
export const jointGrid: SceneDefinition<JointGridOptions, JointGridHandles> = {
  name: 'joint-grid',
  description: 'side x side bodies joined by revolute joints, the top middle pinned, falling and swinging (Box2D v3 joint_grid); 2D',
  defaultCount: 100,
  worldOptions(options = {}) {
    const n = options.count ?? 100;
    return { dimensions: 2, capacity: 3 * n * n + 16, gravity: [0, -10] };
  },
  build(world: PhysicsWorld, options: JointGridOptions = {}): JointGridHandles {
    const where = 'joint-grid';
    if (world.dimensions !== 2) throw new RangeError(`${where}: needs a 2D world, got dimensions ${world.dimensions}`);
    const { count: n } = countAndSeed(where, options, ['count', 'seed'], 100, 2, 400);
    const inertia = 0.5 * 1 * 0.4 * 0.4;
    const bodies = new Float64Array(n * n);
    const joints: number[] = [];
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < n; k++) {
        const pinned = i === 0 && k >= n / 2 - 3 && k <= n / 2 + 3;
        const position = [k, -i];
        const b = pinned ? addBody(world, { position, static: true }) : addBody(world, { position, mass: 1, inertia });
        bodies[i * n + k] = b;
        if (i > 0) joints.push(addRevoluteJoint(world, { a: bodies[(i - 1) * n + k]!, b, anchor: [k, -i + 0.5] }));
        if (k > 0) joints.push(addRevoluteJoint(world, { a: bodies[i * n + k - 1]!, b, anchor: [k - 0.5, -i] }));
      }
    }
    return { bodies, joints: Float64Array.from(joints), side: n };
  },
};
