/**
 * Removing 3D joints: unlisting a joint, its removal hook for removed bodies, shared by the 3D joint
 * API (joints/api-3d.ts) and the 3D joint solver's breaks (joints/solver-3d.ts).
 */
import { entityExists, removeEntity } from 'bitecs';
import { wakeIsland } from '../islands/sleep.js';
import { removeNoCollide } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';
import { type Joint3DStore, joints3DOf } from './store-3d.js';

/**
 * Internal: unlists and removes joint slot j, and wakes its bodies (what held them is gone).
 * @category Joints and ropes
 */
export function removeJoint3DUnchecked(world: PhysicsWorld, s: Joint3DStore, j: number): void {
  unlistJoint3D(world, s, j);
  if (entityExists(world, j)) removeEntity(world, j);
}

/**
 * Takes joint slot j out of the list and the no-collide pairs, and wakes the islands of its bodies
 * that still exist: a sleeping body the joint held up (a bob at rest on its string) must fall.
 * @category Joints and ropes
 */
export function unlistJoint3D(world: PhysicsWorld, s: Joint3DStore, j: number): void {
  const i = s.list.indexOf(j);
  if (i >= 0) s.list.splice(i, 1);
  const a = s.a[j]!,
    b = s.b[j]!;
  removeNoCollide(world.joints, j, a, b);
  s.a[j] = 0;
  s.b[j] = 0;
  if (a !== 0 && entityExists(world, a)) wakeIsland(world, a);
  if (b !== 0 && entityExists(world, b)) wakeIsland(world, b);
}

/**
 * Removal hook: removing a body removes its 3D joints (and removing a joint entity unlists it).
 * @category Joints and ropes
 */
export function removeJoints3DOf(world: PhysicsWorld, eid: number): void {
  const s = joints3DOf(world);
  if (s === undefined || s.list.length === 0) return;
  if (s.list.includes(eid)) {
    unlistJoint3D(world, s, eid);
    return;
  }
  for (const j of s.list.filter((k) => s.a[k] === eid || s.b[k] === eid)) removeJoint3DUnchecked(world, s, j);
}
