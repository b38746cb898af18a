import { entityExists, removeEntity } from 'bitecs';
import { addIslandEdge, EdgeFlag, type IslandEdges } from '../islands/edges.js';
import { wakeIsland } from '../islands/sleep.js';
import { registerFeatureState } from '../world/external-state.js';
import { removeNoCollide } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Kinds of 3D joints.
 * @category Joints and ropes
 */
export const Joint3DType = Object.freeze({ Ball: 0, Hinge: 1, Fixed: 2, Distance: 3, Slider: 4 } as const);

/**
 * Flags of a 3D joint.
 * @category Joints and ropes
 */
export const Joint3DFlag = Object.freeze({ Limit: 1, Motor: 2, Spring: 4, Cone: 8 } as const);

/**
 * The 3D joints of a world, indexed by joint entity (slot), structure of arrays; kept outside the world
 * object (registered for snapshots). Anchors and axes are in the bodies' frames (about their centres
 * of mass); body A 0 is the fixed world, whose frame is the world's.
 * @category Joints and ropes
 */
export interface Joint3DStore {
  /** Joint slots in the order made (removed ones are taken out). */
  list: number[];
  type: Uint8Array;
  flags: Uint8Array;
  a: Int32Array;
  b: Int32Array;
  /** Anchors in A's and B's frames, m. */
  ax: Float64Array;
  ay: Float64Array;
  az: Float64Array;
  bx: Float64Array;
  by: Float64Array;
  bz: Float64Array;
  /** Hinge, slider or cone axis in A's and B's frames (unit). */
  uax: Float64Array;
  uay: Float64Array;
  uaz: Float64Array;
  ubx: Float64Array;
  uby: Float64Array;
  ubz: Float64Array;
  /** B's orientation relative to A's when made, conj(q_A) q_B (x, y, z, w). */
  rx: Float64Array;
  ry: Float64Array;
  rz: Float64Array;
  rw: Float64Array;
  /** Hinge angle limits, rad; cone half angle, rad; distance and slider translation limits, m. */
  lower: Float64Array;
  upper: Float64Array;
  /** Motor speed (hinge: rad/s; slider: m/s) and its largest torque (hinge: N m) or force (slider: N). */
  motorSpeed: Float64Array;
  maxMotorTorque: Float64Array;
  /** Distance: rest length, m; spring frequency, Hz (0 rigid), and damping ratio. */
  length: Float64Array;
  hertz: Float64Array;
  dampingRatio: Float64Array;
  /** Breaking force, N, and torque, N m (Infinity: never). */
  breakForce: Float64Array;
  breakTorque: Float64Array;
  /**
   * Accumulated impulses (warm start, all kept between steps): linear (3), angular (3), limit, motor
   * (hinge and slider: signed along the axis; ball: the cone's, >= 0). Distance: lx the rod or spring,
   * limit the lower limit (>= 0, pushing apart), ly the upper limit (>= 0, pulling together), along the
   * anchor line. N s and N m s.
   */
  lx: Float64Array;
  ly: Float64Array;
  lz: Float64Array;
  wx: Float64Array;
  wy: Float64Array;
  wz: Float64Array;
  limit: Float64Array;
  motor: Float64Array;
  /** Joints broken in the last step: [joint, a, b, step] (handles, then the step count). */
  breaks: number[][];
}

function create(capacity: number): Joint3DStore {
  const n = capacity + 1,
    f = (): Float64Array => new Float64Array(n);
  return {
    list: [],
    type: new Uint8Array(n),
    flags: new Uint8Array(n),
    a: new Int32Array(n),
    b: new Int32Array(n),
    ax: f(),
    ay: f(),
    az: f(),
    bx: f(),
    by: f(),
    bz: f(),
    uax: f(),
    uay: f(),
    uaz: f(),
    ubx: f(),
    uby: f(),
    ubz: f(),
    rx: f(),
    ry: f(),
    rz: f(),
    rw: f(),
    lower: f(),
    upper: f(),
    motorSpeed: f(),
    maxMotorTorque: f(),
    length: f(),
    hertz: f(),
    dampingRatio: f(),
    breakForce: f(),
    breakTorque: f(),
    lx: f(),
    ly: f(),
    lz: f(),
    wx: f(),
    wy: f(),
    wz: f(),
    limit: f(),
    motor: f(),
    breaks: [],
  };
}

/**
 * The world's 3D joint store (made when `create` is true).
 * @category Joints and ropes
 */
export function joints3DOf(world: PhysicsWorld, create_: true): Joint3DStore;
export function joints3DOf(world: PhysicsWorld, create_?: boolean): Joint3DStore | undefined;
export function joints3DOf(world: PhysicsWorld, create_ = false): Joint3DStore | undefined {
  return joints3D(world, create_);
}

/** The world's 3D joint store, registered for snapshots under `joints3d`. */
const joints3D = registerFeatureState('joints3d', (world) => create(world.capacity));

/**
 * Adds the 3D joints' edges to the step's island graph `e` (islands/edges.ts): every joint ties its
 * bodies' islands, and one that carried an impulse (any of its rows' accumulated impulses not 0)
 * supports its bodies: a bob at rest on its string may sleep.
 * @category Joints and ropes
 */
export function addJointEdges3D(world: PhysicsWorld, e: IslandEdges): void {
  if (world.dimensions !== 3) return;
  const s = joints3DOf(world);
  if (s === undefined) return;
  const list = s.list;
  for (let i = 0; i < list.length; i++) {
    const j: number = list[i]!;
    const load =
      Math.abs(s.lx[j]!) +
      Math.abs(s.ly[j]!) +
      Math.abs(s.lz[j]!) +
      Math.abs(s.wx[j]!) +
      Math.abs(s.wy[j]!) +
      Math.abs(s.wz[j]!) +
      Math.abs(s.limit[j]!) +
      Math.abs(s.motor[j]!);
    addIslandEdge(e, s.a[j]!, s.b[j]!, load > 0 ? EdgeFlag.JOINT | EdgeFlag.SUPPORTS : EdgeFlag.JOINT);
  }
}

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
