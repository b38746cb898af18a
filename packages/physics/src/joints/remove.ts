import { entityExists, hasComponent, removeEntity } from 'bitecs';
import { detachClothLink } from '../cloth/solver.js';
import { wakeIsland } from '../islands/sleep.js';
import { removeNoCollide } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';

/**
 * Removes joint entity `j` (which must be a live joint): its bodies are woken (what held them is
 * gone) and no longer count it as attached.
 * @category Joints and ropes
 */
export function removeJointUnchecked(world: PhysicsWorld, j: number): void {
  detachJoint(world, j);
  removeEntity(world, j);
}

/** The bookkeeping of removing joint `j`, without removing the entity: wake its bodies, uncount it. */
function detachJoint(world: PhysicsWorld, j: number): void {
  const J = world.components.Joint;
  const att = world.joints.attached;
  const a = J.a[j]!,
    b = J.b[j]!;
  removeNoCollide(world.joints, j, a, b);
  if (a !== 0) {
    att[a] = att[a]! - 1;
    if (entityExists(world, a)) wakeIsland(world, a);
  }
  att[b] = att[b]! - 1;
  if (entityExists(world, b)) wakeIsland(world, b);
}

/**
 * Removal hook: removes every joint attached to body `eid` (so no joint ever holds a recycled id);
 * if `eid` is itself a joint, does its bookkeeping (the caller removes the entity). Costs nothing in a
 * world without joints or for a body that no joint holds.
 * @category Joints and ropes
 */
export function removeJointsOf(world: PhysicsWorld, eid: number): void {
  const att = world.joints.attached;
  if (att.length === 0) return;
  const J = world.components.Joint,
    L = world.components.ClothLink;
  if (hasComponent(world, eid, J)) {
    detachJoint(world, eid);
    return;
  }
  if (hasComponent(world, eid, L)) {
    detachClothLink(world, eid);
    return;
  }
  if (att[eid] === 0) return;
  const joints = query(world, [J]);
  const doomed: number[] = [];
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    if (J.a[j] === eid || J.b[j] === eid) doomed.push(j);
  }
  for (const j of doomed) removeJointUnchecked(world, j);
  if (att[eid] === 0) return;
  const links = query(world, [L]);
  const cut: number[] = [];
  for (let i = 0; i < links.length; i++) {
    const l = links[i]!;
    if (L.a[l] === eid || L.b[l] === eid) cut.push(l);
  }
  for (const l of cut) {
    detachClothLink(world, l);
    removeEntity(world, l);
  }
}
