/**
 * `contactEvents(world)`: the contact and sensor events of the last step, 2D or 3D, in one shape of
 * list, with the normal impulse each new contact carried. A view built from the collision state's own
 * lists (collision/manifolds-2d.ts in 2D, collision/manifolds-3d.ts in 3D) and the step's manifolds.
 */

import { assertNonNegative } from '../validation/validate.js';
import { slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import type { EventList } from './manifolds-2d.js';
import { findPrevious } from './manifolds-2d.js';
import { contact3DStateOf, type EventList3D } from './manifolds-3d.js';

/**
 * Approach speed above which a begin event is also a hit event, m/s: Box2D v3's default
 * `hitEventThreshold` (1 m/s), so a box set down gently begins touching without a hit.
 * @category Events
 */
export const HIT_SPEED = 1;

/**
 * One list of contact events, structure of arrays; read rows 0..count-1. Entities are handles (as
 * the API takes them): 0 is the static world (the body of a plane, a segment or the boundary box), and
 * in 2D a boundary face is the shape -1 - face (faces 0 -x, 1 +x, 2 -y, 3 +y).
 * @category Events
 */
export interface ContactEventList {
  /** Events in the list (rows 0..count-1). */
  count: number;
  /** Shape A (the sensor, for sensor events). A ball body is its own shape. */
  shapeA: Float64Array;
  /** Shape B. */
  shapeB: Float64Array;
  /** Body of shape A (0: the static world). */
  bodyA: Float64Array;
  /** Body of shape B. */
  bodyB: Float64Array;
  /** Contact point, world frame, m (`begin` and `hit`; 0 elsewhere). `pz` is 0 in 2D. */
  px: Float64Array;
  py: Float64Array;
  pz: Float64Array;
  /** Unit normal from shape A to shape B (`begin` and `hit`; 0 elsewhere). `nz` is 0 in 2D. */
  nx: Float64Array;
  ny: Float64Array;
  nz: Float64Array;
  /** Approach speed along the normal at the start of the step, m/s, >= 0 (`begin` and `hit`). */
  approachSpeed: Float64Array;
  /**
   * Normal impulse the contact carried over the step, N s, >= 0, summed over the manifold's points
   * (`begin` and `hit`; 0 elsewhere). For a body of mass m stopped by the contact from speed v it is
   * m v (plus the weight's m g dt of the step). With the world's `substeps` above 1 it is the last
   * substep's.
   */
  impulse: Float64Array;
}

/**
 * The events of the last step (`contactEvents`). `begin`: a pair of shapes started touching; `end`: a
 * pair stopped touching (or one of its shapes or bodies was removed); `hit`: the begin events whose
 * approach speed was at least the hit speed; `sensorBegin` / `sensorEnd`: a shape started or stopped
 * overlapping a sensor (`shapeA` the sensor).
 * @category Events
 */
export interface ContactEventLists {
  begin: ContactEventList;
  end: ContactEventList;
  hit: ContactEventList;
  sensorBegin: ContactEventList;
  sensorEnd: ContactEventList;
}

const FIELDS = ['shapeA', 'shapeB', 'bodyA', 'bodyB', 'px', 'py', 'pz', 'nx', 'ny', 'nz', 'approachSpeed', 'impulse'] as const;

function createList(): ContactEventList {
  const l = { count: 0 } as Record<string, unknown>;
  for (const k of FIELDS) l[k] = new Float64Array(16);
  return l as unknown as ContactEventList;
}

/** Makes room for `n` rows (doubling; keeps nothing: the list is rewritten) and sets count to 0. */
function reset(list: ContactEventList, n: number): void {
  list.count = 0;
  let size = list.shapeA.length;
  if (size >= n) return;
  while (size < n) size *= 2;
  const rec = list as unknown as Record<string, Float64Array>;
  for (const k of FIELDS) rec[k] = new Float64Array(size);
}

/** Copies row i of a 2D or 3D list into the next row of `out`; returns that row. */
function copyRow(out: ContactEventList, src: EventList | EventList3D, i: number, three: boolean): number {
  const r = out.count++;
  out.shapeA[r] = src.shapeA[i]!;
  out.shapeB[r] = src.shapeB[i]!;
  out.bodyA[r] = src.bodyA[i]!;
  out.bodyB[r] = src.bodyB[i]!;
  out.px[r] = src.px[i]!;
  out.py[r] = src.py[i]!;
  out.nx[r] = src.nx[i]!;
  out.ny[r] = src.ny[i]!;
  out.pz[r] = three ? (src as EventList3D).pz[i]! : 0;
  out.nz[r] = three ? (src as EventList3D).nz[i]! : 0;
  out.approachSpeed[r] = src.approachSpeed[i]!;
  out.impulse[r] = 0;
  return r;
}

function copyList(out: ContactEventList, src: EventList | EventList3D, three: boolean): void {
  reset(out, src.count);
  for (let i = 0; i < src.count; i++) copyRow(out, src, i, three);
}

/** Slot of a shape or body as the solver rows hold it (handles to slots; 0 and boundary faces as they are). */
function rowId(e: number): number {
  return e > 0 ? slotOf(e) : e;
}

/** Normal impulse of the 2D pair (a, b) in the last step's manifolds, N s (0 if it has no row). */
function impulse2D(world: PhysicsWorld, a: number, b: number): number {
  const st = world.collision.shapes;
  const j = findPrevious(st, rowId(a), rowId(b));
  if (j < 0) return 0;
  const buf = st.previous;
  let sum = 0;
  for (let p = 0, m = buf.pointCount[j]!; p < m; p++) sum += buf.totalNormalImpulse[2 * j + p]!;
  return sum;
}

/** Normal impulse of the 3D pair (a, b) in the last step's manifolds, N s, summed over its rows (a mesh pair has a row per triangle). */
function impulse3D(world: PhysicsWorld, a: number, b: number): number {
  const st = contact3DStateOf(world);
  if (st === undefined) return 0;
  const buf = st.current,
    sa = rowId(a),
    sb = rowId(b);
  let sum = 0;
  for (let i = 0; i < buf.count; i++) {
    if (buf.shapeA[i] !== sa || buf.shapeB[i] !== sb) continue;
    for (let k = 0, m = buf.points[i]!; k < m; k++) sum += buf.ln[4 * i + k]!;
  }
  return sum;
}

const views = new WeakMap<PhysicsWorld, ContactEventLists>();

/**
 * The contact and sensor events of the last step, in 2D and 3D alike: `begin`, `end`, `hit` (begin
 * events at least `hitSpeed` fast), `sensorBegin`, `sensorEnd`, each with the shapes and bodies (as
 * handles), the contact point, the normal from A to B, the approach speed and the normal impulse.
 *
 * Events are per step: each `step` replaces them. Read them after every `step`, or, with
 * `createFixedStepLoop`, in its `step` callback right after `step(world)` (a frame may run several
 * steps or none). The returned lists belong to the world and are rewritten by the next call; copy
 * what you keep. Two ball bodies (bodies made with a `radius` and no shapes) touching each other give no events; a ball
 * against a shape does.
 *
 * @param world a 2D or 3D physics world.
 * @param hitSpeed approach speed at which a begin event is also a hit, m/s, >= 0 (default `HIT_SPEED`, 1 m/s).
 * @throws RangeError if `hitSpeed` is negative or not finite.
 * @category Events
 */
export function contactEvents(world: PhysicsWorld, hitSpeed: number = HIT_SPEED): ContactEventLists {
  assertNonNegative('contactEvents', 'hitSpeed', hitSpeed);
  let view = views.get(world);
  if (view === undefined) {
    view = { begin: createList(), end: createList(), hit: createList(), sensorBegin: createList(), sensorEnd: createList() };
    views.set(world, view);
  }
  const three = world.dimensions === 3;
  const src = three ? contact3DStateOf(world)?.events : world.collision.shapes.events;
  if (src === undefined) {
    for (const list of [view.begin, view.end, view.hit, view.sensorBegin, view.sensorEnd]) list.count = 0;
    return view;
  }
  copyList(view.begin, src.begin, three);
  copyList(view.end, src.end, three);
  copyList(view.sensorBegin, src.sensorBegin, three);
  copyList(view.sensorEnd, src.sensorEnd, three);
  const begin = view.begin,
    hit = view.hit;
  reset(hit, begin.count);
  for (let i = 0; i < begin.count; i++) {
    const a = begin.shapeA[i]!,
      b = begin.shapeB[i]!;
    begin.impulse[i] = three ? impulse3D(world, a, b) : impulse2D(world, a, b);
    if (begin.approachSpeed[i]! < hitSpeed) continue;
    const r = copyRow(hit, begin as unknown as EventList3D, i, true);
    hit.impulse[r] = begin.impulse[i]!;
  }
  return view;
}
