/**
 * `contactEvents(world)`: the contact and sensor events of the last step, 2D or 3D, of every kind of
 * contact, from the world's one event store (collision/events.ts).
 */

import { assertNonNegative } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import { type ContactEventLists, EVENT_FIELDS, reserveEvent } from './event-lists.js';

export type { ContactEventList, ContactEventLists } from './event-lists.js';

/**
 * Approach speed above which a begin event is also a hit event, m/s: Box2D v3's default
 * `hitEventThreshold` (1 m/s), so a box set down gently begins touching without a hit.
 * @category Events
 */
export const HIT_SPEED = 1;

/**
 * The contact and sensor events of the last step, in 2D and 3D alike, from every kind of contact:
 * balls against balls, segments, planes and the boundary box, and shapes against each other: `begin`,
 * `end`, `hit` (begin events at least `hitSpeed` fast), `sensorBegin`, `sensorEnd`, each with the
 * shapes and bodies (as handles; a ball body is its own shape), the contact point, the normal from A to
 * B, the approach speed and the normal impulse.
 *
 * Events are per step: each `step` replaces them. Read them after every `step`, or, with
 * `createFixedStepLoop`, in its `step` callback right after `step(world)` (a frame may run several
 * steps or none). The returned lists are the world's own (`world.collision.events`), rewritten by the
 * next step; `hit` is rewritten by the next call too. Copy what you keep.
 *
 * @param world a 2D or 3D physics world.
 * @param hitSpeed approach speed at which a begin event is also a hit, m/s, >= 0 (default `HIT_SPEED`, 1 m/s).
 * @throws RangeError if `hitSpeed` is negative or not finite.
 * @category Events
 */
export function contactEvents(world: PhysicsWorld, hitSpeed: number = HIT_SPEED): ContactEventLists {
  assertNonNegative('contactEvents', 'hitSpeed', hitSpeed);
  const events = world.collision.events;
  const begin = events.begin,
    hit = events.hit;
  hit.count = 0;
  for (let i = 0; i < begin.count; i++) {
    if (begin.approachSpeed[i]! < hitSpeed) continue;
    reserveEvent(hit);
    const r = hit.count++;
    for (const k of EVENT_FIELDS) hit[k][r] = begin[k][i]!;
  }
  return events;
}

/**
 * The same lists as `contactEvents(world)` (kept for programs written when 3D events had their own call).
 * @deprecated use `contactEvents`, which serves 2D and 3D.
 * @category Events
 */
export function contactEvents3D(world: PhysicsWorld): ContactEventLists {
  return contactEvents(world);
}
