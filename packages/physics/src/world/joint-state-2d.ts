/**
 * What the joint solver keeps between and within steps, apart from the `Joint` components: the
 * packed solver rows of this step, the accumulated impulses that warm-start the next step, each
 * solver body's rotation within the step, and the break events of the last step.
 */

import { widenToDoubles } from './double-fields.js';
import { IMPULSES, LINK_FLOATS, LINK_INTS, PIN_FLOATS, PIN_INTS, ROW_FLOATS, ROW_INTS } from './joint-strides-2d.js';
import { markWritable } from './writable-fields.js';

/**
 * Joints broken in the last step, in the order they broke (rows 0..count-1). Read after `step`.
 * @category Joints and ropes
 */
export interface JointBreakEvents {
  /** Events in use. */
  count: number;
  /** Handle of the joint or cloth link that broke (it no longer exists). */
  joint: Float64Array;
  /** Handles of its bodies A (0 = the world) and B. */
  a: Float64Array;
  b: Float64Array;
  /** Its constraint force, N, and torque, N m, in the step it broke. */
  force: Float64Array;
  torque: Float64Array;
  /** Its strain (length - rest) / rest when it broke (distance joints; 0 for others). */
  stretch: Float64Array;
}

/**
 * Joint solver tuning; may be changed between steps.
 * @category Joints and ropes
 */
export interface JointSettings {
  /**
   * Stiffness of the rigid joint constraints' softness, Hz, > 0, capped at a quarter of the solver
   * substep rate (Box2D v3: joints are soft constraints of twice its 30 Hz contact stiffness, 60 Hz).
   * Stiffer than the cap lets Gauss-Seidel over a long chain overshoot (with the cap at half the rate,
   * 120 Hz at 4 substeps of 1/60 s threw a 10-link chain with a 10 kg load apart, even with two iterations). A soft joint under a load T stretches by about
   * T / (m omega^2) (m the effective mass of its two bodies, omega = 2 pi hertz): more substeps (a
   * higher cap) and a higher `hertz` hold a heavily loaded net tighter. Default 60 Hz.
   */
  hertz: number;
  /**
   * Passes over the joints in each substep's solve (the contacts make `solverIterations`), integer
   * >= 1; the relax pass is one. Two keep a heavily loaded net from overshooting where one does not:
   * the 100 x 100 joint grid's largest error over 2 s is 0.55 m with two, 2.5 m with one (a local
   * overshoot under the pins); the second pass costs less than the pins' lean loop saved (see `pins`).
   * Default 2.
   */
  iterations: number;
  /** Damping ratio of that softness, dimensionless, >= 0 (Box2D v3's jointDampingRatio). Default 2. */
  dampingRatio: number;
  /** Whether last step's impulses start this step's solve (warm starting). Default true. */
  warmStarting: boolean;
}

/**
 * The joint solver's state (world.joints).
 * @category Joints and ropes
 */
export interface JointState {
  readonly settings: JointSettings;
  /** Rows built this (sub)step. */
  rowCount: number;
  /** Packed rows: ROW_FLOATS floats and ROW_INTS integers each, grown by doubling. */
  rows: Float64Array;
  rowInts: Int32Array;
  /**
   * Point links of this step: distance joints between two bodies that do not rotate (cloth, rope of
   * particles), solved by a lean loop. Floats per link (LINK_FLOATS): centre-and-anchor offset (x, y)
   * at the start of the step, effective mass, rest or longest length, accumulated impulse, mode
   * (0 rod, 1 rope: pulls only). Integers per link: body row offsets of A and B, the general row.
   */
  linkCount: number;
  /** The rigid joint softness of this step: bias rate (1/s), mass scale, impulse scale (see JointSettings). */
  readonly softness: Float64Array;
  links: Float64Array;
  linkInts: Int32Array;
  /**
   * Pins of this step: revolute joints without spring, motor or limit (a chain, a net), solved by a lean
   * loop over 8 numbers a joint instead of the general row's 35. Floats per pin (PIN_FLOATS): anchors
   * from A's and B's centres at the start of the step (x, y each), centre difference (x, y),
   * accumulated impulse (x, y). Integers: solver indices of A and B, the general row.
   */
  pinCount: number;
  /** Rows of this step that are neither point links nor pins (the general loops run only if > 0). */
  generalCount: number;
  pins: Float64Array;
  pinInts: Int32Array;
  /** Per joint entity, IMPULSES accumulated impulses of the last solve (N s, N m s); allocated with the first joint. */
  impulses: Float64Array;
  /** Per entity: how many joints hold it (so removing a body without joints costs nothing). */
  attached: Int32Array;
  /** Per body: how many of its joints keep their two bodies from colliding (`collideConnected` false). */
  noCollide: Int32Array;
  /** Per joint entity: 1 if it is counted in `noCollide` and `noCollidePairs`. */
  noCollideJoint: Uint8Array;
  /** Body pair key (min * (capacity + 1) + max) -> how many joints without `collideConnected` join the pair. */
  readonly noCollidePairs: Map<number, number>;
  /** Per solver body: cos, sin and angle (rad) of its orientation at the start of the step. */
  startPose: Float64Array;
  /** Per solver body: cos, sin and angle (rad) of its rotation since the start of the step. */
  rotation: Float64Array;
  /** Per entity scratch: stamp of the classification below, and the body's class (0 dynamic, 1 kinematic, 2 static, 3 sleeping). */
  bodyStamp: Uint32Array;
  bodyClass: Uint8Array;
  stamp: number;
  /** Joints broken in the last step. */
  readonly breaks: JointBreakEvents;
  /** `world.steps` when `breaks` was last cleared. */
  breaksStep: number;
  /** Statistics of the last solve: rows solved, largest position error left (m: anchor separation or length error), its joint. */
  readonly stats: { rows: number; maxError: number; maxErrorJoint: number };
}

/**
 * Creates an empty joint state (arrays sized when the first joint appears).
 * @category Joints and ropes
 */
export function createJointState(): JointState {
  const js: JointState = {
    settings: { hertz: 60, iterations: 2, dampingRatio: 2, warmStarting: true },
    rowCount: 0,
    rows: new Float64Array(0),
    rowInts: new Int32Array(0),
    linkCount: 0,
    softness: new Float64Array(3),
    links: new Float64Array(0),
    linkInts: new Int32Array(0),
    pinCount: 0,
    generalCount: 0,
    pins: new Float64Array(0),
    pinInts: new Int32Array(0),
    impulses: new Float64Array(0),
    attached: new Int32Array(0),
    noCollide: new Int32Array(0),
    noCollideJoint: new Uint8Array(0),
    noCollidePairs: new Map(),
    rotation: new Float64Array(0),
    startPose: new Float64Array(0),
    bodyStamp: new Uint32Array(0),
    bodyClass: new Uint8Array(0),
    stamp: 0,
    breaks: {
      count: 0,
      joint: new Float64Array(16),
      a: new Float64Array(16),
      b: new Float64Array(16),
      force: new Float64Array(16),
      torque: new Float64Array(16),
      stretch: new Float64Array(16),
    },
    breaksStep: -1,
    stats: new JointSolveStats(),
  };
  // Written by every step from the first on, joints or none (world/writable-fields.ts).
  markWritable(js, ['rowCount', 'breaksStep']);
  return js;
}

/**
 * The joint solver's statistics (JointState.stats), a class so that every world's object has one map:
 * a literal made again in a later world can get another map, which makes V8 drop the optimised code
 * that reads the field.
 */
class JointSolveStats {
  rows = 0;
  maxError = 0;
  maxErrorJoint = 0;
  constructor() {
    // A fraction from the first step on (world/double-fields.ts).
    widenToDoubles(this, ['maxError']);
    markWritable(this, ['rows', 'maxErrorJoint']);
  }
}

/**
 * Allocates the per-entity arrays of `state` for a world of `capacity` entities (on the first joint).
 * @category Joints and ropes
 */
export function ensureJointArrays(state: JointState, capacity: number): void {
  if (state.impulses.length >= IMPULSES * (capacity + 1)) return;
  state.impulses = new Float64Array(IMPULSES * (capacity + 1));
  state.attached = new Int32Array(capacity + 1);
  state.noCollide = new Int32Array(capacity + 1);
  state.noCollideJoint = new Uint8Array(capacity + 1);
  state.noCollidePairs.clear();
  state.bodyStamp = new Uint32Array(capacity + 1);
  state.bodyClass = new Uint8Array(capacity + 1);
}

/**
 * Grows the rows to hold `n`.
 * @category Joints and ropes
 */
export function ensureRows(state: JointState, n: number): void {
  if (state.rows.length >= n * ROW_FLOATS) return;
  let cap = Math.max(16, state.rows.length / ROW_FLOATS);
  while (cap < n) cap *= 2;
  state.rows = new Float64Array(cap * ROW_FLOATS);
  state.rowInts = new Int32Array(cap * ROW_INTS);
  state.links = new Float64Array(cap * LINK_FLOATS);
  state.linkInts = new Int32Array(cap * LINK_INTS);
  state.pins = new Float64Array(cap * PIN_FLOATS);
  state.pinInts = new Int32Array(cap * PIN_INTS);
}

/**
 * Appends a break event, growing the buffer by doubling.
 * @category Joints and ropes
 */
export function pushBreak(ev: JointBreakEvents, joint: number, a: number, b: number, force: number, torque: number, stretch: number): void {
  if (ev.count >= ev.joint.length) {
    const n = ev.joint.length * 2;
    const gf = (o: Float64Array) => {
      const x = new Float64Array(n);
      x.set(o);
      return x;
    };
    ev.joint = gf(ev.joint);
    ev.a = gf(ev.a);
    ev.b = gf(ev.b);
    ev.force = gf(ev.force);
    ev.torque = gf(ev.torque);
    ev.stretch = gf(ev.stretch);
  }
  const i = ev.count++;
  ev.joint[i] = joint;
  ev.a[i] = a;
  ev.b[i] = b;
  ev.force[i] = force;
  ev.torque[i] = torque;
  ev.stretch[i] = stretch;
}
