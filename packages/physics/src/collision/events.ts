/**
 * Writing the contact and sensor events of a step into the world's event lists (collision/event-lists.ts),
 * with the entities as the handles of the lives they are in now (`currentHandle`).
 */

import { hasComponent } from 'bitecs';
import { currentHandle, isAlive, slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { type ContactEventList, reserveEvent, sleepingPairKey } from './event-lists.js';

function handle(world: PhysicsWorld, e: number): number {
  return e > 0 ? currentHandle(world, e) : e;
}

/**
 * Appends an event: the shapes and bodies given as entity slots (stored as the handles of the lives
 * they are in now, see `currentHandle`; 0 and a boundary face's negative id stay as they are), the
 * point, normal, approach speed and impulse 0 (the caller fills those of a begin event). Returns its row.
 * @category Events
 */
export function pushEvent(
  world: PhysicsWorld,
  list: ContactEventList,
  shapeA: number,
  shapeB: number,
  bodyA: number,
  bodyB: number,
): number {
  reserveEvent(list);
  const i = list.count;
  list.shapeA[i] = handle(world, shapeA);
  list.shapeB[i] = handle(world, shapeB);
  list.bodyA[i] = handle(world, bodyA);
  list.bodyB[i] = handle(world, bodyB);
  list.px[i] = 0;
  list.py[i] = 0;
  list.pz[i] = 0;
  list.nx[i] = 0;
  list.ny[i] = 0;
  list.nz[i] = 0;
  list.approachSpeed[i] = 0;
  list.impulse[i] = 0;
  list.count = i + 1;
  return i;
}

/** A body of a pair as the sleeping contacts see it: 0 awake (dynamic or kinematic), 1 static (or the static world), 2 asleep. */
function restState(world: PhysicsWorld, body: number): number {
  if (body <= 0) return 1;
  const c = world.components;
  if (hasComponent(world, body, c.Sleeping)) return 2;
  return hasComponent(world, body, c.Static) ? 1 : 0;
}

/**
 * For a touching pair (entity slots; shape A may be a boundary face's negative id, body 0 the static
 * world) whose rows are gone this step: if every body of it is asleep or static, and one is asleep, it
 * is kept as touching while it sleeps (`world.collision.sleepingContacts`) and true is returned: the
 * caller writes no end event. Else false.
 * @category Events
 */
export function keepWhileAsleep(world: PhysicsWorld, shapeA: number, shapeB: number, bodyA: number, bodyB: number): boolean {
  const a = restState(world, bodyA),
    b = restState(world, bodyB);
  if (a === 0 || b === 0 || (a !== 2 && b !== 2)) return false;
  world.collision.sleepingContacts.pairs.set(sleepingPairKey(shapeA, shapeB), [
    handle(world, shapeA),
    handle(world, shapeB),
    handle(world, bodyA),
    handle(world, bodyB),
  ]);
  return true;
}

/**
 * For a pair (entity slots) found touching this step that did not touch in the last: true if it was
 * kept touching while its bodies slept (it resumes; the caller writes no begin event), else false.
 * A kept pair whose shapes are no longer the same lives (a slot reused) ends here, with its old handles.
 * @category Events
 */
export function resumeAfterSleep(world: PhysicsWorld, shapeA: number, shapeB: number): boolean {
  const pairs = world.collision.sleepingContacts.pairs;
  if (pairs.size === 0) return false;
  const key = sleepingPairKey(shapeA, shapeB);
  const kept = pairs.get(key);
  if (kept === undefined) return false;
  pairs.delete(key);
  if (kept[0] === handle(world, shapeA) && kept[1] === handle(world, shapeB)) return true;
  endKept(world, kept);
  return false;
}

/**
 * Ends the pairs kept while asleep whose bodies woke without the pair touching again this step, or
 * whose shapes or bodies were removed: called once the step's contact events are written, and only
 * looks when a body woke since the last look (`sleep.wakes`).
 * @category Events
 */
export function endWokenContacts(world: PhysicsWorld): void {
  const cs = world.collision,
    kept = cs.sleepingContacts;
  if (kept.pairs.size === 0 || kept.checkedWakes === cs.sleep.wakes) return;
  kept.checkedWakes = cs.sleep.wakes;
  for (const [key, pair] of kept.pairs) {
    let alive = true;
    for (const h of pair) if (h > 0 && !isAlive(world, h)) alive = false;
    if (alive) {
      const a = restState(world, pair[2]! > 0 ? slotOf(pair[2]!) : 0),
        b = restState(world, pair[3]! > 0 ? slotOf(pair[3]!) : 0);
      if (a !== 0 && b !== 0) continue;
    }
    kept.pairs.delete(key);
    endKept(world, pair);
  }
}

/** Writes the end event of a kept pair (its handles as kept). */
function endKept(world: PhysicsWorld, pair: number[]): void {
  const list = world.collision.events.end;
  reserveEvent(list);
  const i = pushEvent(world, list, 0, 0, 0, 0);
  list.shapeA[i] = pair[0]!;
  list.shapeB[i] = pair[1]!;
  list.bodyA[i] = pair[2]!;
  list.bodyB[i] = pair[3]!;
}
