/**
 * Writing the contact and sensor events of a step into the world's event lists (collision/event-lists.ts),
 * with the entities as the handles of the lives they are in now (`currentHandle`).
 */

import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { type ContactEventList, reserveEvent } from './event-lists.js';

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
