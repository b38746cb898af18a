import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, type Joint3DBaseOptions, make } from './joint-3d.js';
import { checkEnds, optionalPoint } from './joint-base.js';
import * as R3 from './rows-3d.js';
import { Joint3DType } from './store-3d.js';

/**
 * The 3D fixed joint (glues two bodies: no relative motion): its options, addFixedJoint3D, and its rows
 * (FIXED_ROWS_3D), which joints/solver-3d.ts runs with the other 3D joints'.
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
  const e = checkEnds(where, world, options, 3, ['anchor']);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, e.b));
  const j = make(world, where, Joint3DType.Fixed, FIXED_ROWS_3D, e, options, p, p, [0, 1, 0]);
  return currentHandle(world, j);
}

/** A fixed joint: the three angular rows, then the point block. */
export function solveFixedRow3D(p: R3.JointPass3D, j: number, a: number, b: number, _flags: number): void {
  R3.errorRotation(p, j);
  R3.solveAngularLock(p, j, a, b, false);
  R3.preparePointBlock(p, a, b);
  R3.solvePointRows(p, j, a, b);
}

/** The 3D fixed joint's rows (rows-3d.ts JointRows3D). */
export const FIXED_ROWS_3D: R3.JointRows3D = { warmStart: R3.warmStartPointAndLock, solve: solveFixedRow3D, reading: R3.pointJointReading };
