import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, ends, type Joint3DBaseOptions, make, point } from './joint-3d.js';
import { Joint3DType } from './store-3d.js';

/**
 * The 3D fixed joint (glues two bodies: no relative motion): its options and addFixedJoint3D. Its rows are
 * solved with the other 3D joints' (joints/solver-3d.ts).
 */

/**
 * Options of `addFixedJoint3D`.
 * @category Joints and ropes
 */
export interface FixedJoint3DOptions extends Joint3DBaseOptions {
  /** The point the bodies are welded at (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
}

/**
 * Fixed (weld): B keeps its position and orientation relative to A. @returns the joint's handle. @throws as addBallJoint3D.
 * @category Joints and ropes
 */
export function addFixedJoint3D(world: PhysicsWorld, options: FixedJoint3DOptions): number {
  const where = 'addFixedJoint3D';
  const e = ends(where, world, options, ['anchor']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  return currentHandle(world, make(world, where, Joint3DType.Fixed, e, options, p, p, [0, 1, 0]));
}
