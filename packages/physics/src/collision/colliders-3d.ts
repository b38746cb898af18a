import { shapeEdits } from '../shapes/edits-3d.js';
import { Shape3DKind, type Shape3DStore } from '../shapes/store-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { type Collider3D, ColliderKind3D, createManifold3D, type Manifold3D } from './narrowphase/manifold-3d.js';
import { BodyType } from './state.js';

/**
 * The colliders of a 3D shape pass (collision/shapes-3d.ts): each shape and ball of a moving or
 * touchable body with its start-of-step pose, fattened box and speed, in reused scratch arrays, and the
 * sleeping bodies the pass met (woken with their islands after it).
 */

/** Sleeping bodies met this pass by a moving or kinematic one (woken with their islands after the pass). */
export const wakes = { list: new Int32Array(16), count: 0 };

/** Queues sleeping body `e` to be woken with its island after the pass. */
export function queueWake(e: number): void {
  if (wakes.count >= wakes.list.length) {
    const l = new Int32Array(2 * wakes.list.length);
    l.set(wakes.list);
    wakes.list = l;
  }
  wakes.list[wakes.count++] = e;
}

/** Whether a pair of body types is collided: one is dynamic, or a kinematic body meets a sleeping one (to wake it). */
export function meets(ta: number, tb: number): boolean {
  return (
    ta === BodyType.Dynamic ||
    tb === BodyType.Dynamic ||
    (ta === BodyType.Kinematic && tb === BodyType.Sleeping) ||
    (ta === BodyType.Sleeping && tb === BodyType.Kinematic)
  );
}

/** The layout of a collider's entry in `scratch.material` (collider n at STRIDE n). */
export enum ColliderMaterial {
  /** Friction coefficient, >= 0. */
  FRICTION = 0,
  /** Restitution, [0, 1]. */
  RESTITUTION = 1,
  /**
   * 1 when the shape's filter lets it meet every shape that does not filter it out on its own side
   * (group 0, mask 0xffffffff, category not 0: the defaults), else 0 (and 0 for a shapeless ball, whose
   * material is the Material component's). A pair of two such shapes is never filtered.
   */
  PERMISSIVE = 2,
  /**
   * The body's position at the start of the step, x, m: Position for a static body, else
   * PreviousPosition (where the narrowphase measures, and a manifold's anchors are taken from).
   */
  X = 3,
  /** y, m. */
  Y = 4,
  /** z, m. */
  Z = 5,
  /** Numbers a collider's entry (two unused: one entry a 64-byte line). */
  STRIDE = 8,
}

/** Per-step collider scratch (module-level, reused; the step rebuilds it). */
interface Scratch {
  n: number;
  shape: Int32Array;
  body: Int32Array;
  minX: Float64Array;
  maxX: Float64Array;
  minY: Float64Array;
  maxY: Float64Array;
  minZ: Float64Array;
  maxZ: Float64Array;
  px: Float64Array;
  py: Float64Array;
  pz: Float64Array;
  R: Float64Array;
  speed: Float64Array;
  /** A box collider that is no sensor: its smallest half extent, m (the manifold reuse's scale); else -1. */
  boxHalf: Float64Array;
  /**
   * A collider's material, filter and body start position side by side (ColliderMaterial), so a box pair
   * reads one run of memory per collider instead of a column each of the shape store and the position
   * components. The material and filter are written for every collider every pass (also a sleeping
   * one's: its material may be edited), the position when the collider is posed (a kept pose's body
   * starts where it did).
   */
  material: Float64Array;
  order: Int32Array;
  ball: Uint8Array;
  /** Per shape slot (a ball's body slot): its collider index this pass, valid where colliderStamp holds colliderPass. */
  colliderOf: Int32Array;
  colliderStamp: Int32Array;
  colliderPass: number;
  /** This pass's speculative distance of the 3D shapes, m (SHAPE_SPECULATIVE_DISTANCE capped by the world's). */
  spec: number;
  /** Whether a sensor shape took part in this pass (resting colliders then search every step: sensor events need it). */
  anySensor: boolean;
  /** Rows written minus the previous step's row of the last box pair found (the guess for the next pair's row). */
  rowShift: number;
  /**
   * Per collider index: the shape slot whose sleeping pose the index holds from the last pass (0: none),
   * with the body pose it was made from in `poseKey` (POSE_KEY numbers: start position x, y, z, then the
   * orientation x, y, z, w); valid while `poseOf` is the shape store of the pass and `poseEdits` and
   * `poseSpec` match (keptPose).
   */
  posed: Int32Array;
  poseKey: Float64Array;
  /**
   * The shape store whose pass last wrote the scratch (null before any), the shape edit count then, and
   * its speculative distance, m (NaN before any pass: a number that is not a whole one, so that V8 keeps
   * the field a double from the start; a 0 there would be a small-integer field that the first pass's
   * distance turns into a double, giving the scratch a new hidden class and throwing the compiled
   * collider code that reads it back to the interpreter, "wrong map").
   */
  poseOf: Shape3DStore | null;
  poseEdits: number;
  poseSpec: number;
}
export const scratch: Scratch = {
  n: 0,
  shape: new Int32Array(0),
  body: new Int32Array(0),
  minX: new Float64Array(0),
  maxX: new Float64Array(0),
  minY: new Float64Array(0),
  maxY: new Float64Array(0),
  minZ: new Float64Array(0),
  maxZ: new Float64Array(0),
  px: new Float64Array(0),
  py: new Float64Array(0),
  pz: new Float64Array(0),
  R: new Float64Array(0),
  speed: new Float64Array(0),
  boxHalf: new Float64Array(0),
  material: new Float64Array(0),
  order: new Int32Array(0),
  ball: new Uint8Array(0),
  colliderOf: new Int32Array(0),
  colliderStamp: new Int32Array(0),
  colliderPass: 0,
  spec: 0.02,
  anySensor: false,
  rowShift: 0,
  posed: new Int32Array(0),
  poseKey: new Float64Array(0),
  poseOf: null,
  poseEdits: -1,
  poseSpec: Number.NaN,
};

/** Numbers of a collider's entry in `scratch.poseKey`. */
const POSE_KEY = 7;

export function ensure(n: number): void {
  if (scratch.shape.length >= n) return;
  let m = Math.max(64, scratch.shape.length);
  while (m < n) m *= 2;
  // Grown arrays keep what the pass wrote so far (gather grows them while it fills them).
  const grow = <T extends Float64Array | Int32Array | Uint8Array>(a: T, k: number): T => {
    const b = new (a.constructor as new (k: number) => T)(k);
    b.set(a as never);
    return b;
  };
  const sc = scratch;
  sc.shape = grow(sc.shape, m);
  sc.body = grow(sc.body, m);
  sc.order = grow(sc.order, m);
  sc.ball = grow(sc.ball, m);
  sc.posed = grow(sc.posed, m);
  sc.poseKey = grow(sc.poseKey, POSE_KEY * m);
  for (const k of ['minX', 'maxX', 'minY', 'maxY', 'minZ', 'maxZ', 'px', 'py', 'pz', 'speed', 'boxHalf'] as const) sc[k] = grow(sc[k], m);
  sc.R = grow(sc.R, 9 * m);
  sc.material = grow(sc.material, ColliderMaterial.STRIDE * m);
}

/**
 * Whether the sleeping collider of shape `e` at index `n` keeps the pose, rotation and fattened box the
 * index got in the last pass (never for `e` = -1, an awake collider's): the scratch is still `s`'s (no other world's pass wrote it since, no
 * shape was placed or resized, the same speculative distance `spec`), the index then held `e` asleep,
 * and its body starts the step where it did: at (P.x[b], P.y[b], P.z[b]) turned by the unit quaternion
 * (Q.x[b], Q.y[b], Q.z[b], Q.w[b]). The stores and the index, not the numbers, cross the call: a call V8
 * does not inline boxes each double argument (16 bytes a collider, a step).
 * A sleeping body moves only if something sets its pose, so a settled pile is posed once.
 */
export function keptPose(
  s: Shape3DStore,
  spec: number,
  n: number,
  e: number,
  P: { x: Float64Array; y: Float64Array; z: Float64Array },
  Q: { x: Float64Array; y: Float64Array; z: Float64Array; w: Float64Array },
  b: number,
): boolean {
  const sc = scratch,
    K = sc.poseKey,
    o = POSE_KEY * n;
  // Every comparison made (bitwise &, no early return): gather asks for every collider, awake ones
  // included, so the compiled code has seen all of this before the first body of a pile falls asleep.
  const same =
    +(sc.posed[n] === e) &
    +(sc.poseOf === s) &
    +(sc.poseEdits === shapeEdits.count) &
    +(sc.poseSpec === spec) &
    +(K[o] === P.x[b]) &
    +(K[o + 1] === P.y[b]) &
    +(K[o + 2] === P.z[b]) &
    +(K[o + 3] === Q.x[b]) &
    +(K[o + 4] === Q.y[b]) &
    +(K[o + 5] === Q.z[b]) &
    +(K[o + 6] === Q.w[b]);
  return same === 1;
}

/**
 * Records at index `n` the pose a sleeping collider of shape `e` was posed from (keptPose), or with `e` =
 * 0 that the index holds none: the start position (p[po], p[po + 1], p[po + 2]) and the unit quaternion
 * (q[0], q[1], q[2], q[3]), read from the arrays (no double crosses the call).
 */
export function notePose(n: number, e: number, p: Float64Array, po: number, q: Float64Array): void {
  const sc = scratch,
    K = sc.poseKey,
    o = POSE_KEY * n;
  sc.posed[n] = e;
  K[o] = p[po]!;
  K[o + 1] = p[po + 1]!;
  K[o + 2] = p[po + 2]!;
  K[o + 3] = q[0]!;
  K[o + 4] = q[1]!;
  K[o + 5] = q[2]!;
  K[o + 6] = q[3]!;
}

/** Marks the scratch as written by a pass over `s` with speculative distance `spec` (keptPose's validity). */
export function ownPoses(s: Shape3DStore, spec: number): void {
  scratch.poseOf = s;
  scratch.poseEdits = shapeEdits.count;
  scratch.poseSpec = spec;
}

/**
 * Speculative distance of the 3D shapes, m: Box2D v3's (b2_speculativeDistance, 4 linear slops of 5 mm),
 * at most the world's `speculativeDistance` (0.1 m by default, which the ball contacts keep). A pair's
 * margin is this plus what the two bodies' speeds close in the step (speculative contacts), so boxes
 * standing 5 cm apart (a pyramid's side neighbours) are no contacts: with 0.1 m they were manifolds that
 * never pushed, a third of a pyramid's. As a fraction of the shape's size (2D's rule) it was too small
 * for thin capsules: a ragdoll's joints stretched 2.6 cm in its landing, against 1.2 cm.
 */
export const SHAPE_SPECULATIVE_DISTANCE = 0.02;

/** A collider with every field zero (kind 0, no hull), to be filled by `collider`. */
function emptyCollider(): Collider3D {
  return { kind: 0, px: 0, py: 0, pz: 0, R: new Float64Array(9), radius: 0, hy: 0, hull: null, box: 0, hx: 0, hz: 0 };
}

export const colA: Collider3D = emptyCollider();
export const colB: Collider3D = emptyCollider();
export const manifold: Manifold3D = createManifold3D();

export function collider(world: PhysicsWorld, s: Shape3DStore, i: number, out: Collider3D): void {
  const sc = scratch,
    e = sc.shape[i]!;
  out.px = sc.px[i]!;
  out.py = sc.py[i]!;
  out.pz = sc.pz[i]!;
  for (let k = 0; k < 9; k++) out.R[k] = sc.R[9 * i + k]!;
  out.box = 0;
  if (sc.ball[i]) {
    out.kind = ColliderKind3D.Sphere;
    out.radius = world.components.Ball.radius[e]!;
    out.hy = 0;
    out.hull = null;
    return;
  }
  const kind = s.kind[e]!;
  out.radius = s.radius[e]!;
  out.hy = s.hy[e]!;
  if (kind === Shape3DKind.Box) {
    out.box = 1;
    out.hx = s.hx[e]!;
    out.hz = s.hz[e]!;
  }
  if (kind === Shape3DKind.Sphere) {
    out.kind = ColliderKind3D.Sphere;
    out.hull = null;
  } else if (kind === Shape3DKind.Capsule) {
    out.kind = ColliderKind3D.Capsule;
    out.hull = null;
  } else {
    out.kind = ColliderKind3D.Polyhedron;
    out.hull = s.hulls[s.hull[e]!]!;
    out.radius = 0;
  }
}
