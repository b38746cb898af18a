import { addComponent, hasComponent, removeComponent } from 'bitecs';
import { keepSleepingManifolds } from '../collision/dormant-manifolds-2d.js';
import { contact3DStateOf } from '../collision/manifolds-3d.js';
import type { SleepState } from '../collision/state.js';
import { shapes3DOf } from '../shapes/store-3d.js';
import { ecsOf } from '../world/ecs-internals.js';
import { resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import type { SleepTerms } from '../world/scratch.js';
import {
  addIslandEdges,
  emptyIslandEdges,
  findRoot,
  joinContactEdges,
  joinJointEdges,
  markSupport,
  pushedSleepers2D,
  resetJoinedParents,
} from './edges.js';

/**
 * Sleeping islands (after Box2D v3's island sleep; Catto, "Solver2D", 2024): a resting pile stops
 * costing anything. A dynamic collider whose speed stays below `linearSpeed` and spin below
 * `angularSpeed` accumulates rest time; islands are the bodies joined by contacts that carried an
 * impulse this step (union-find); when every body of an island has rested `timeToSleep`, the island
 * sleeps: velocities zeroed, the `Sleeping` tag added, and integration and the contact solver skip it;
 * in 2D its shape contacts' impulses are kept for the step it wakes in (collision/dormant-manifolds-2d.ts).
 * Only a supported body rests: one that carried a contact impulse this step. A body in free flight
 * (a balloon creeping to its equilibrium height, a projectile at its apex) never sleeps, however slow.
 *
 * A sleeping body wakes when a moving (kinematic, or dynamic and not resting) body comes into
 * contact range (the broadphase wakes it for that step), in 2D when a resting body leans on it (their
 * shape contact pushed: woken for the next step, so the two rest as one island; a resting neighbour
 * that does not push leaves it asleep, and in 3D a resting body never wakes it), when its velocity is written (`setVelocity`, `applyImpulse`, or a direct
 * write to the store, noticed at the next step), when `wakeBody` is called, when gravity changes, or
 * when a body it touched is removed. Bodies driven by time-varying forces (driving or random forces,
 * thrust) or held by springs never sleep: their forces would be ignored while asleep.
 */

/**
 * Removes the Sleeping tag and resets the rest time (the body takes part again from the next system on).
 * @category Collision
 */
export function wakeTag(world: PhysicsWorld, eid: number): void {
  const c = world.components;
  if (hasComponent(world, eid, c.Sleeping)) {
    removeComponent(world, eid, c.Sleeping);
    world.collision.sleep.wakes++;
  }
  world.collision.sleep.restTime[eid] = 0;
}

/**
 * Wakes the whole island a sleeping body sleeps in (an awake body: just itself).
 * @category Collision
 */
export function wakeIsland(world: PhysicsWorld, eid: number): void {
  const c = world.components;
  if (!hasComponent(world, eid, c.Sleeping)) {
    world.collision.sleep.restTime[eid] = 0;
    return;
  }
  const id = world.collision.sleep.island[eid]!;
  const asleep = Array.from(query(world, [c.Sleeping]));
  const island = world.collision.sleep.island;
  for (const e of asleep) if (island[e] === id) wakeTag(world, e);
}

/**
 * Whether a body is asleep. @param body a body's handle.
 * @throws RangeError on a removed entity or one that is not a body.
 * @category Collision
 */
export function isSleeping(world: PhysicsWorld, body: number): boolean {
  return hasComponent(world, resolveKind(world, body, 'body', 'isSleeping'), world.components.Sleeping);
}

/**
 * Wakes a body and the island it sleeps in (no-op if it is awake). Use it after changing a sleeping
 * body's forces or position by writing components directly. @param body a body's handle.
 * @throws RangeError on a removed entity or one that is not a body.
 * @category Collision
 */
export function wakeBody(world: PhysicsWorld, body: number): void {
  wakeIsland(world, resolveKind(world, body, 'body', 'wakeBody'));
}

/**
 * Wakes every sleeping body.
 * @category Collision
 */
export function wakeAll(world: PhysicsWorld): void {
  const asleep = query(world, [world.components.Sleeping]);
  const ids = Array.from(asleep);
  for (const e of ids) wakeTag(world, e);
}

/**
 * Stage 1 (first): wakes sleeping bodies whose velocity has been written since they fell asleep, and
 * everything if gravity changed.
 * @category Collision
 */
export function wakeSystem(world: PhysicsWorld): void {
  const sl = world.collision.sleep;
  const g = world.gravity,
    last = sl.lastGravity;
  const gravityChanged = g[0] !== last[0] || g[1] !== last[1] || g[2] !== last[2];
  last[0] = g[0]!;
  last[1] = g[1]!;
  last[2] = g[2]!;
  if (!sl.anyAsleep) return;
  if (gravityChanged) {
    wakeAll(world);
    return;
  }
  const c = world.components;
  const asleep = query(world, [c.Sleeping, c.Velocity]);
  if (asleep.length === 0) {
    sl.anyAsleep = false;
    return;
  }
  // The loop is a function of its own (see sleepSystem): the wake that first follows it comes long
  // after its code was compiled.
  wakeIslandsOf(world, movedSleepers(world, asleep));
}

/** The bodies of `asleep` whose velocity is not zero, or null when there is none. */
function movedSleepers(world: PhysicsWorld, asleep: ArrayLike<number>): number[] | null {
  const V = world.components.Velocity;
  const vx = V.x,
    vy = V.y,
    vz = V.z;
  let woken: number[] | null = null;
  for (let i = 0; i < asleep.length; i++) {
    const e = asleep[i]!;
    if (vx[e] !== 0 || vy[e] !== 0 || vz[e] !== 0) (woken ??= []).push(e);
  }
  return woken;
}

/** Wakes the island of every body in `list` (none when null). */
function wakeIslandsOf(world: PhysicsWorld, list: number[] | null): void {
  if (list !== null) for (const e of list) wakeIsland(world, e);
}

/** The query terms of the sleep stage, built once per world (`world.scratch.sleepTerms`): it runs every step. */
function sleepTerms(world: PhysicsWorld): SleepTerms {
  let t = world.scratch.sleepTerms;
  if (t === undefined) {
    const c = world.components;
    t = {
      balls: [c.Position, c.Velocity, c.Ball, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      shaped: [c.Position, c.Velocity, c.Shape, c.Force, Not(c.Ball), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      shaped3D: [c.Position, c.Velocity, c.Force, Not(c.Ball), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      awake: [[c.DrivingForce], [c.RandomForce], [c.Thrust]],
      spring: [c.Spring],
      sleeping: [c.Sleeping],
    };
    world.scratch.sleepTerms = t;
  }
  return t;
}

/**
 * Makes the sleep stage's queries of `world` (see sleepTerms) while it has no entity, so that its first
 * step does not fill them (integrators/queries.ts makeIntegratorQueries). createPhysicsWorld calls it.
 * @category Collision
 */
export function makeSleepQueries(world: PhysicsWorld): void {
  const t = sleepTerms(world);
  query(world, t.balls);
  query(world, t.shaped);
  if (world.dimensions === 3) query(world, t.shaped3D);
  for (const terms of t.awake) query(world, terms);
  query(world, t.spring);
  query(world, t.sleeping);
}

/**
 * Stage 7: updates rest times and puts resting islands to sleep. Islands come from this step's
 * contacts between two dynamic bodies that carried a normal impulse; contacts with static geometry do
 * not join islands (a floor does not tie every pile together).
 *
 * Every loop over the bodies or edges is a function of its own that ends with its loop, and this one
 * has none: V8 compiles a long loop on the stack (OSR) while its function still runs interpreted, enters
 * that code at the loop in every later call, and throws it away at the first operation past the loop
 * that it has no type feedback for (here, the first island to fall asleep); the function then ran
 * interpreted, step after step.
 * @category Collision
 */
export function sleepSystem(world: PhysicsWorld): void {
  const cs = world.collision;
  const sl = cs.sleep;
  if (!sl.enabled) {
    cs.stats.sleeping = 0;
    return;
  }
  const terms = sleepTerms(world);
  const bodies = sleepCandidates(world, terms);
  const rest = sl.restTime,
    parent = sl.parent;
  // Sleepers a resting body leaned on: woken for the next step (islands/edges.ts pushedSleepers2D).
  if (world.dimensions === 2) wakeIslandsOf(world, pushedSleepers2D(world));
  // The island graph of this step: every contact and joint, from every store (islands/edges.ts).
  const edges = emptyIslandEdges();
  addIslandEdges(world, edges);
  // Support: a body rests only while some contact or joint pushed it this step.
  const stamp = ++sl.stamp;
  markSupport(edges, sl.supported, stamp);
  updateRestTimes(world, bodies, stamp);
  // Bodies that must stay awake: time-varying forces, springs.
  for (let k = 0; k < terms.awake.length; k++) zeroRestTimes(rest, query(world, terms.awake[k]!));
  zeroSpringRestTimes(world, query(world, terms.spring));
  // Islands over contacts between dynamic awake bodies that pushed, and over joints (`supported` is
  // read no more this step, and marks the candidates). Found at every step, also while no body has
  // rested timeToSleep yet (a pile still settling): a branch first taken when the first body has
  // rested that long would run uncompiled code for the rest of the settling, every step.
  joinContactEdges(world, edges, parent);
  wakeIslandsOf(world, joinJointEdges(world, edges, bodies, rest, parent, sl.supported, ++sl.stamp));
  // An island sleeps when every body in it has rested timeToSleep: its least rest time.
  fillAt(sl.islandRest, bodies, Infinity);
  leastRestAtRoots(sl, bodies);
  // Each body's island (its root) kept for fallAsleep, which runs after the parents are reset.
  if (roots.length < bodies.length) roots = new Int32Array(Math.max(bodies.length, 2 * roots.length));
  const sleepers = islandRoots(sl, bodies, roots);
  // Every body its own island again between steps: a snapshot stores such parents in a few bytes.
  resetParents(parent, bodies);
  resetJoinedParents(edges, parent);
  const asleep = query(world, terms.sleeping).length;
  cs.stats.sleeping = sl.anyAsleep ? asleep : 0;
  if (sleepers > 0) cs.stats.sleeping = fallAsleep(world, bodies, roots, terms);
}

/** sleepSystem's scratch: the root of each candidate's island this step, in candidate order. */
let roots = new Int32Array(0);

/**
 * Updates the rest time of each of `bodies`: it grows by dt while the body moves slower than
 * `linearSpeed`, spins slower than `angularSpeed` and was supported this step (`supported` is `stamp`),
 * else is 0; and makes each its own union-find root (parent[e] = e).
 */
function updateRestTimes(world: PhysicsWorld, bodies: Uint32Array, stamp: number): void {
  const sl = world.collision.sleep;
  const c = world.components;
  const rest = sl.restTime,
    parent = sl.parent,
    supported = sl.supported;
  const vx = c.Velocity.x,
    vy = c.Velocity.y,
    vz = c.Velocity.z;
  const wx = c.AngularVelocity.x,
    wy = c.AngularVelocity.y,
    wz = c.AngularVelocity.z;
  const lin2 = sl.linearSpeed * sl.linearSpeed,
    ang2 = sl.angularSpeed * sl.angularSpeed;
  const dt = world.dt;
  // Whether a body has AngularVelocity, from bitecs' component masks (what hasComponent reads, without
  // its lookups per body): no entry, no body has it.
  const ecs = ecsOf(world);
  const spin = ecs.componentMap.get(c.AngularVelocity);
  const spinMasks = spin === undefined ? null : ecs.entityMasks[spin.generationId]!,
    spinBit = spin === undefined ? 0 : spin.bitflag;
  for (let i = 0; i < bodies.length; i++) {
    const e = bodies[i]!;
    const v2 = vx[e]! * vx[e]! + vy[e]! * vy[e]! + vz[e]! * vz[e]!;
    const w2 = spinMasks !== null && ((spinMasks[e] ?? 0) & spinBit) === spinBit ? wx[e]! * wx[e]! + wy[e]! * wy[e]! + wz[e]! * wz[e]! : 0;
    rest[e] = v2 < lin2 && w2 < ang2 && supported[e] === stamp ? rest[e]! + dt : 0;
    parent[e] = e;
  }
}

/** Sets the rest time of every entity of `ents` to 0. */
function zeroRestTimes(rest: Float64Array, ents: ArrayLike<number>): void {
  for (let i = 0; i < ents.length; i++) rest[ents[i]!] = 0;
}

/** Sets the rest time of both bodies of every spring of `springs` to 0. */
function zeroSpringRestTimes(world: PhysicsWorld, springs: ArrayLike<number>): void {
  const rest = world.collision.sleep.restTime;
  const S = world.components.Spring;
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    rest[S.a[s]!] = 0;
    rest[S.b[s]!] = 0;
  }
}

/** Sets `values[e]` to `x` for each body e of `bodies`. */
function fillAt(values: Float64Array, bodies: Uint32Array, x: number): void {
  for (let i = 0; i < bodies.length; i++) values[bodies[i]!] = x;
}

/**
 * Lowers `islandRest` of each island's root (in `parent`) to the least rest time of the island's
 * bodies among `bodies` (the roots' entries start at Infinity).
 */
function leastRestAtRoots(sl: SleepState, bodies: Uint32Array): void {
  const rest = sl.restTime,
    parent = sl.parent,
    islandRest = sl.islandRest;
  for (let i = 0; i < bodies.length; i++) {
    const e = bodies[i]!;
    const r = findRoot(parent, e);
    if (rest[e]! < islandRest[r]!) islandRest[r] = rest[e]!;
  }
}

/**
 * Writes the root of body i's island (of `bodies`) to `out[i]`; returns how many bodies are in an
 * island that has rested timeToSleep (`islandRest` of its root).
 */
function islandRoots(sl: SleepState, bodies: Uint32Array, out: Int32Array): number {
  const parent = sl.parent,
    islandRest = sl.islandRest,
    T = sl.timeToSleep;
  let sleepers = 0;
  for (let i = 0; i < bodies.length; i++) {
    const r = findRoot(parent, bodies[i]!);
    out[i] = r;
    sleepers += islandRest[r]! >= T ? 1 : 0;
  }
  return sleepers;
}

/** Makes each of `bodies` its own union-find root (parent[e] = e). */
function resetParents(parent: Int32Array, bodies: Uint32Array): void {
  for (let i = 0; i < bodies.length; i++) parent[bodies[i]!] = bodies[i]!;
}

/**
 * Puts to sleep every body of `bodies` whose island (`roots`, body i's at i: its root in this step's
 * union-find) has rested timeToSleep (`sleep.islandRest` of its root), then the 2D shape contacts'
 * impulses are kept for the step they wake in (collision/dormant-manifolds-2d.ts). Returns how many
 * bodies sleep now (the `terms.sleeping` query). A function of its own: it first runs when a pile
 * falls asleep, long after sleepSystem's code was compiled.
 */
function fallAsleep(world: PhysicsWorld, bodies: Uint32Array, roots: Int32Array, terms: SleepTerms): number {
  putToSleep(world, bodies, roots);
  world.collision.sleep.anyAsleep = true;
  if (world.dimensions === 2) keepSleepingManifolds(world);
  return query(world, terms.sleeping).length;
}

/**
 * fallAsleep's loop: each body of `bodies` whose island (root `roots[i]`) has rested timeToSleep gets
 * velocities zeroed, its previous position set to its position, the `Sleeping` tag, and its island
 * recorded for waking.
 */
function putToSleep(world: PhysicsWorld, bodies: Uint32Array, roots: Int32Array): void {
  const sl = world.collision.sleep;
  const c = world.components;
  const islandRest = sl.islandRest,
    island = sl.island,
    T = sl.timeToSleep;
  const V = c.Velocity,
    W = c.AngularVelocity,
    O = c.PreviousPosition,
    P = c.Position;
  for (let i = 0; i < bodies.length; i++) {
    const e = bodies[i]!;
    const root = roots[i]!;
    if (islandRest[root]! < T) continue;
    island[e] = root;
    V.x[e] = 0;
    V.y[e] = 0;
    V.z[e] = 0;
    if (hasComponent(world, e, c.AngularVelocity)) {
      W.x[e] = 0;
      W.y[e] = 0;
      W.z[e] = 0;
    }
    O.x[e] = P.x[e]!;
    O.y[e] = P.y[e]!;
    O.z[e] = P.z[e]!;
    addComponent(world, e, c.Sleeping);
  }
}

/** sleepCandidates' reused list. Scratch, not world state. */
const candidates = { list: new Uint32Array(0) };
const NONE: readonly number[] = [];

/**
 * The bodies that may fall asleep this step, every collider alike: the awake dynamic balls, then the
 * awake dynamic bodies carrying a 2D shape and no ball, then (in 3D) those carrying a 3D shape and no
 * ball. Returns a view of a reused array (valid until the next call), a Uint32Array in every world:
 * were it the balls' query itself in a world without shapes, sleepSystem compiled against one kind
 * of list (a warm-up scene's shapes) would be thrown away at its first step in a world of the other.
 */
function sleepCandidates(world: PhysicsWorld, terms: SleepTerms): Uint32Array {
  const balls = query(world, terms.balls);
  const flat = world.collision.shapes.active;
  const s = world.dimensions === 3 ? shapes3DOf(world) : undefined;
  const solid = s?.active === true;
  const shaped: ArrayLike<number> = flat ? query(world, terms.shaped) : NONE,
    shaped3D: ArrayLike<number> = solid ? query(world, terms.shaped3D) : NONE;
  const n = balls.length + shaped.length + shaped3D.length;
  if (candidates.list.length < n) candidates.list = new Uint32Array(Math.max(n, 2 * candidates.list.length));
  const out = candidates.list;
  out.set(balls);
  out.set(shaped, balls.length);
  let k = balls.length + shaped.length;
  const first = s?.first;
  for (let i = 0; i < shaped3D.length; i++) if (first![shaped3D[i]!] !== 0) out[k++] = shaped3D[i]!;
  return out.subarray(0, k);
}

/**
 * Removal hook: a body removed from a sleeping pile wakes its island; an awake one wakes the islands of
 * the sleeping bodies it touched in the last step, through any contact store (ball rows, 2D and 3D
 * manifolds) alike.
 * @category Collision
 */
export function wakeTouching(world: PhysicsWorld, eid: number): void {
  const cs = world.collision;
  if (!cs.sleep.anyAsleep) return;
  const c = world.components;
  if (hasComponent(world, eid, c.Sleeping)) {
    wakeIsland(world, eid);
    return;
  }
  const rows = cs.cache.rows;
  for (let i = 0; i < rows.count; i++) {
    const a = rows.a[i]!,
      b = rows.b[i]!,
      f = rows.feature[i]!;
    const touches = a === eid || b === eid || (rows.kind[i] !== 0 && rows.kind[i] !== 1 && f === eid);
    if (!touches) continue;
    for (const other of [a, b]) {
      if (other !== 0 && other !== eid && hasComponent(world, other, c.Sleeping)) wakeIsland(world, other);
    }
  }
  // The manifolds' rows of the last step: in 2D finishManifolds made them `previous`.
  const flat = cs.shapes.previous;
  if (cs.shapes.active) wakePartners(world, flat.bodyA, flat.bodyB, flat.count, eid);
  const m = world.dimensions === 3 ? contact3DStateOf(world)?.current : undefined;
  if (m !== undefined) wakePartners(world, m.bodyA, m.bodyB, m.count, eid);
}

/** Wakes the island of each sleeping partner of body `eid` among the first `n` body pairs (A[i], B[i]) of a manifold store. */
function wakePartners(world: PhysicsWorld, A: Int32Array, B: Int32Array, n: number, eid: number): void {
  const sleeping = world.components.Sleeping;
  for (let i = 0; i < n; i++) {
    const a = A[i]!,
      b = B[i]!;
    if (a !== eid && b !== eid) continue;
    const other = a === eid ? b : a;
    if (other !== 0 && hasComponent(world, other, sleeping)) wakeIsland(world, other);
  }
}
