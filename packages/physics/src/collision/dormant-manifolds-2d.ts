import { hasComponent } from 'bitecs';
import type { PhysicsWorld } from '../world/options.js';
import { MAX_MANIFOLDS } from './manifold-limits-2d.js';
import { growManifoldBuffer, type ManifoldBuffer, pairHash, type ShapeCollisionState } from './manifolds-2d.js';

/**
 * The warm start of sleeping 2D shape contacts. A pair of sleeping bodies (or a sleeping body and
 * static geometry) is not collided, so its manifold drops out of the previous step's rows, which are
 * the only warm start the solver reads (solver/manifold-prepare-2d.ts). Without these rows a woken
 * resting pile would start its contacts from zero impulse: every body falls a step's worth of gravity
 * before its contacts catch it, which can lift a tall stack over the sleep threshold. Box2D v3 keeps a sleeping island's contact constraints, impulses
 * included, in its sleeping solver set and restores them when the island wakes; here the touching
 * rows of the bodies that fall asleep are copied to `ShapeCollisionState.dormant`, where the first
 * step after their wake finds them (`findDormant`), and are dropped once their bodies are awake
 * (`pruneDormant`).
 */

/** Whether body `e` holds still as its sleeping contacts' partner: the static world (0), a static body or a sleeping one. */
function still(world: PhysicsWorld, e: number): boolean {
  const c = world.components;
  return e === 0 || hasComponent(world, e, c.Static) || hasComponent(world, e, c.Sleeping);
}

/**
 * The row of `st.dormant` for the shape pair (a, b), or -1.
 * @category Collision
 */
export function findDormant(st: ShapeCollisionState, a: number, b: number): number {
  const slots = st.dormantSlots;
  if (slots.length === 0) return -1;
  const mask = slots.length - 1;
  const d = st.dormant;
  let s = pairHash(a, b) & mask;
  for (;;) {
    const r = slots[s]!;
    if (r === 0) return -1;
    if (d.shapeA[r - 1] === a && d.shapeB[r - 1] === b) return r - 1;
    s = (s + 1) & mask;
  }
}

/** Hashes the rows of `st.dormant` into `st.dormantSlots` (at least twice as many slots as rows). */
function rehash(st: ShapeCollisionState): void {
  const d = st.dormant,
    n = d.count;
  let size = 16;
  while (size < 2 * n) size *= 2;
  const slots = st.dormantSlots.length === size ? st.dormantSlots.fill(0) : new Int32Array(size);
  const mask = size - 1;
  for (let i = 0; i < n; i++) {
    let s = pairHash(d.shapeA[i]!, d.shapeB[i]!) & mask;
    while (slots[s] !== 0) s = (s + 1) & mask;
    slots[s] = i + 1;
  }
  st.dormantSlots = slots;
}

/** Copies the warm start of row i of `from` (pair, bodies, spawn stamps, points' ids and impulses) to row k of `to`. */
function copyWarmStart(from: ManifoldBuffer, i: number, to: ManifoldBuffer, k: number): void {
  to.shapeA[k] = from.shapeA[i]!;
  to.shapeB[k] = from.shapeB[i]!;
  to.bodyA[k] = from.bodyA[i]!;
  to.bodyB[k] = from.bodyB[i]!;
  to.stampA[k] = from.stampA[i]!;
  to.stampB[k] = from.stampB[i]!;
  to.pointCount[k] = from.pointCount[i]!;
  to.rollingImpulse[k] = from.rollingImpulse[i]!;
  for (let p = 0; p < 2; p++) {
    to.id[2 * k + p] = from.id[2 * i + p]!;
    to.normalImpulse[2 * k + p] = from.normalImpulse[2 * i + p]!;
    to.tangentImpulse[2 * k + p] = from.tangentImpulse[2 * i + p]!;
  }
}

/**
 * After bodies fell asleep this step (islands/sleep.ts): keeps the touching rows of this step whose
 * bodies both hold still now (asleep, static or the static world) in `st.dormant`, replacing the
 * pair's row there if it had one.
 * @category Collision
 */
export function keepSleepingManifolds(world: PhysicsWorld): void {
  const st = world.collision.shapes;
  if (!st.active) return;
  const m = st.previous, // this step's rows (finishManifolds made them the cache)
    d = st.dormant;
  const before = d.count;
  // Room for every row kept first (a pyramid falling asleep keeps a thousand at once), rather than
  // doubling the dormant buffer row by row.
  let kept = 0;
  for (let i = 0, n = m.count; i < n; i++) if (m.touching[i] === 1 && still(world, m.bodyA[i]!) && still(world, m.bodyB[i]!)) kept++;
  if (kept > 0) growManifoldBuffer(d, Math.min(d.count + kept, MAX_MANIFOLDS));
  for (let i = 0, n = m.count; i < n; i++) {
    if (m.touching[i] !== 1 || !still(world, m.bodyA[i]!) || !still(world, m.bodyB[i]!)) continue;
    // A pair is in a step's rows once: the rows appended here need no hash until the loop ends.
    let k = findDormant(st, m.shapeA[i]!, m.shapeB[i]!);
    if (k < 0) {
      growManifoldBuffer(d, d.count + 1);
      k = d.count++;
    }
    copyWarmStart(m, i, d, k);
  }
  if (d.count > before) rehash(st);
  st.dormantWakes = world.collision.sleep.wakes;
}

/**
 * After a step's rows took their warm start (solver/manifold-prepare-2d.ts), if any body woke since
 * the last look: drops the rows of `st.dormant` whose bodies do not both hold still any more (woken,
 * so their pairs were collided this step and found their rows, or removed).
 * @category Collision
 */
export function pruneDormant(world: PhysicsWorld): void {
  const st = world.collision.shapes,
    d = st.dormant;
  const wakes = world.collision.sleep.wakes;
  if (d.count === 0 || st.dormantWakes === wakes) return;
  st.dormantWakes = wakes;
  const stamp = world.spawnStamp;
  let k = 0;
  for (let i = 0, n = d.count; i < n; i++) {
    const a = d.bodyA[i]!,
      b = d.bodyB[i]!;
    // A removed shape's slot has a new spawn stamp once it is used again.
    const alive = (d.shapeA[i]! <= 0 || stamp[d.shapeA[i]!] === d.stampA[i]) && stamp[d.shapeB[i]!] === d.stampB[i];
    if (!alive || !still(world, a) || !still(world, b)) continue;
    if (k !== i) copyWarmStart(d, i, d, k);
    k++;
  }
  if (k === d.count) return;
  d.count = k;
  rehash(st);
}
