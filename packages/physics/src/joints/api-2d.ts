import { entityExists, hasComponent, removeEntity } from 'bitecs';
import { detachClothLink } from '../cloth/solver.js';
import { wakeIsland } from '../islands/sleep.js';
import { assertFinite, assertNonNegative, assertPositive } from '../validation/validate.js';
import { currentHandle, resolveEntity, SLOT_RANGE } from '../world/handles.js';
import { removeNoCollide } from '../world/joint-no-collide.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import { IMPULSES } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { checkLimits, requireJoint, wakeJoint } from './joint-2d.js';
import { ILOW, ILX, IMOT, ISPR, IUP } from './layout-2d.js';

/**
 * Calls on the 2D joints of every type: isJoint, removeJoint, setJointMotor, setJointLimits, setJointSpring
 * and the readings jointLength, jointAngle and jointAnchors; the removal of a joint and the removal hook
 * of a body. Each joint type's options and add call are in a file of its own (distance-joint.ts,
 * revolute-joint.ts, prismatic-joint.ts, weld-joint.ts, wheel-joint.ts, mouse-joint.ts), on the shared
 * checks of joint-2d.ts.
 */

/**
 * Whether `id` is the handle of a live joint (or cloth link) of this world.
 * @category Joints and ropes
 */
export function isJoint(world: PhysicsWorld, id: number): boolean {
  if (world.dimensions !== 2 || typeof id !== 'number' || !Number.isInteger(id) || id < 1) return false;
  const slot = id % SLOT_RANGE;
  if (slot < 1 || slot > world.capacity || !entityExists(world, slot) || currentHandle(world, slot) !== id) return false;
  return hasComponent(world, slot, world.components.Joint) || hasComponent(world, slot, world.components.ClothLink);
}

/**
 * Removes a joint or a cloth link (the bodies of a joint wake).
 * @throws RangeError if `joint` is not the handle of a live joint or cloth link.
 * @category Joints and ropes
 */
export function removeJoint(world: PhysicsWorld, joint: number): void {
  const slot = resolveEntity(world, joint, 'removeJoint', 'joint');
  if (world.dimensions === 2 && hasComponent(world, slot, world.components.ClothLink)) {
    detachClothLink(world, slot);
    removeEntity(world, slot);
    return;
  }
  removeJointUnchecked(world, requireJoint('removeJoint', world, joint));
}

/**
 * Sets a joint's motor: target `speed` (rad/s for revolute and wheel, m/s for prismatic) and largest
 * torque (N m) or force (N) `maxForce`, >= 0; 0 turns the motor off.
 * @throws RangeError if `joint` is not a live revolute, prismatic or wheel joint, or on bad values.
 * @category Joints and ropes
 */
export function setJointMotor(world: PhysicsWorld, joint: number, speed: number, maxForce: number): void {
  const where = 'setJointMotor';
  const j = requireJoint(where, world, joint, [JointType.Revolute, JointType.Prismatic, JointType.Wheel]);
  assertFinite(where, 'speed', speed);
  assertNonNegative(where, 'maxForce', maxForce);
  const J = world.components.Joint;
  J.motorSpeed[j] = speed;
  J.maxMotorForce[j] = maxForce;
  J.flags[j] = maxForce > 0 ? J.flags[j]! | JointFlag.Motor : J.flags[j]! & ~JointFlag.Motor;
  if (maxForce === 0) world.joints.impulses[j * IMPULSES + (IMOT - ILX)] = 0;
  wakeJoint(world, j);
}

/**
 * Sets (or with `lower` null, removes) a joint's limits: revolute angles, rad in [-pi, pi]; prismatic
 * and wheel translations, m; lower <= upper.
 * @throws RangeError if `joint` is not a live revolute, prismatic or wheel joint, or on bad limits.
 * @category Joints and ropes
 */
export function setJointLimits(world: PhysicsWorld, joint: number, lower: number | null, upper?: number): void {
  const where = 'setJointLimits';
  const j = requireJoint(where, world, joint, [JointType.Revolute, JointType.Prismatic, JointType.Wheel]);
  const J = world.components.Joint;
  const base = j * IMPULSES;
  world.joints.impulses[base + (ILOW - ILX)] = 0;
  world.joints.impulses[base + (IUP - ILX)] = 0;
  if (lower === null) {
    J.flags[j] = J.flags[j]! & ~JointFlag.Limit;
    wakeJoint(world, j);
    return;
  }
  checkLimits(where, lower, upper, 'lower', 'upper', J.type[j] === JointType.Revolute ? Math.PI : Infinity);
  J.lower[j] = lower;
  J.upper[j] = upper!;
  J.flags[j] = J.flags[j]! | JointFlag.Limit;
  wakeJoint(world, j);
}

/**
 * Sets a joint's spring: natural frequency `hertz` (Hz, >= 0; 0 removes the spring, or makes a weld's
 * linear part or a distance joint rigid) and `dampingRatio` (>= 0). Mouse joints need hertz > 0.
 * @throws RangeError if `joint` is not a live joint, or on bad values.
 * @category Joints and ropes
 */
export function setJointSpring(world: PhysicsWorld, joint: number, hertz: number, dampingRatio: number): void {
  const where = 'setJointSpring';
  const j = requireJoint(where, world, joint);
  const J = world.components.Joint;
  if (J.type[j] === JointType.Mouse) assertPositive(where, 'hertz', hertz);
  else assertNonNegative(where, 'hertz', hertz);
  assertNonNegative(where, 'dampingRatio', dampingRatio);
  J.hertz[j] = hertz;
  J.dampingRatio[j] = dampingRatio;
  if (J.type[j] !== JointType.Weld && J.type[j] !== JointType.Mouse) {
    J.flags[j] = hertz > 0 ? J.flags[j]! | JointFlag.Spring : J.flags[j]! & ~JointFlag.Spring;
  }
  world.joints.impulses[j * IMPULSES + (ISPR - ILX)] = 0;
  wakeJoint(world, j);
}

/**
 * The current length of a distance joint (distance between its anchors), m.
 * @throws RangeError if `joint` is not a live distance joint.
 * @category Joints and ropes
 */
export function jointLength(world: PhysicsWorld, joint: number): number {
  const j = requireJoint('jointLength', world, joint, [JointType.Distance]);
  const [ax, ay, bx, by] = anchorsOf(world, j);
  return Math.hypot(bx - ax, by - ay);
}

/**
 * The relative angle of a revolute or weld joint: angle of B minus angle of A minus the angle between
 * them when the joint was made, rad, wrapped into [-pi, pi].
 * @throws RangeError if `joint` is not a live revolute or weld joint.
 * @category Joints and ropes
 */
export function jointAngle(world: PhysicsWorld, joint: number): number {
  const j = requireJoint('jointAngle', world, joint, [JointType.Revolute, JointType.Weld]);
  const J = world.components.Joint,
    ang = world.components.Angle.value;
  let x = (J.b[j] === 0 ? 0 : ang[J.b[j]!]!) - (J.a[j] === 0 ? 0 : ang[J.a[j]!]!) - J.referenceAngle[j]!;
  x -= 2 * Math.PI * Math.round(x / (2 * Math.PI));
  return x;
}

/**
 * The world positions of a joint's two anchors, m: [ax, ay, bx, by] (A's is the fixed point or the
 * mouse target when A is the world). @throws RangeError if `joint` is not a live joint.
 * @category Joints and ropes
 */
export function jointAnchors(world: PhysicsWorld, joint: number): [number, number, number, number] {
  return anchorsOf(world, requireJoint('jointAnchors', world, joint));
}

function anchorsOf(world: PhysicsWorld, j: number): [number, number, number, number] {
  const J = world.components.Joint,
    P = world.components.Position,
    ang = world.components.Angle.value;
  const point = (e: number, lx: number, ly: number): [number, number] => {
    if (e === 0) return [lx, ly];
    const co = Math.cos(ang[e]!),
      si = Math.sin(ang[e]!);
    return [P.x[e]! + co * lx - si * ly, P.y[e]! + si * lx + co * ly];
  };
  const a = point(J.a[j]!, J.localAx[j]!, J.localAy[j]!),
    b = point(J.b[j]!, J.localBx[j]!, J.localBy[j]!);
  return [a[0], a[1], b[0], b[1]];
}

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
