/** Contact and sensor events: appending a begin/end touch event with the entities' current handles. */

import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import type { EventList } from './manifolds-2d.js';

function handle(world: PhysicsWorld, e: number): number {
  return e > 0 ? currentHandle(world, e) : e;
}

/**
 * Appends an event (entities as slots; stored as the handles of the lives they are in now, see
 * `currentHandle`; 0 and a boundary face's negative id stay as they are); returns its row.
 * @category Events
 */
export function pushEvent(world: PhysicsWorld, list: EventList, shapeA: number, shapeB: number, bodyA: number, bodyB: number): number {
  const i = list.count;
  if (i >= list.shapeA.length) {
    const rec = list as unknown as Record<string, Float64Array>;
    for (const k of ['shapeA', 'shapeB', 'bodyA', 'bodyB', 'px', 'py', 'nx', 'ny', 'approachSpeed']) {
      const old = rec[k]!;
      const next = new (old.constructor as new (m: number) => typeof old)(old.length * 2);
      next.set(old);
      rec[k] = next;
    }
  }
  list.shapeA[i] = handle(world, shapeA);
  list.shapeB[i] = handle(world, shapeB);
  list.bodyA[i] = handle(world, bodyA);
  list.bodyB[i] = handle(world, bodyB);
  list.px[i] = 0;
  list.py[i] = 0;
  list.nx[i] = 0;
  list.ny[i] = 0;
  list.approachSpeed[i] = 0;
  list.count = i + 1;
  return i;
}
