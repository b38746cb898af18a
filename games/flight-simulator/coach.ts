/**
 * The flight simulator's coaching after the lessons: from ring 5 to the last, a short tip says where
 * the next ring lies from the line flown and what to do about it (./course.ts lessonTipText teaches
 * rings 1 to 4), so the player is coached to the last ring, never left without the next step.
 * Headless (no DOM), tested in node
 * (test/games/flight-simulator-course.test.ts).
 */

import type { Ring, RingBearing, RingWay, TipReader } from './course';
import { clearThrough, ringWhere } from './course';

/** Rings taught by the lessons (./course.ts lessonTipText, rings 1 to 4); the coach speaks from the next one on. */
export const LESSON_RINGS = 4;

/**
 * The coach's tip for ring `ring` (0-based, LESSON_RINGS or later) of `total`, lying `way` from the
 * line flown (./course.ts ringWay), for `reader`; `markerOffset` is how far from its centre the
 * flight-path marker shows the aircraft passing its plane if the pilot lets go now, m (./course.ts
 * predictThroughRing; Infinity when it shows none). "Ring 6 is to the left and a little higher: hold ←
 * and ↑ until ⊕ is in it, then let go."; "let go and fly through" only when letting go takes the
 * whole aircraft through (./course.ts clearThrough: inside the ring less half the wingspan, not on
 * its tube); the last ring is named so. On a phone (`reader.compact`) the words are shorter, in the
 * same two lines as a lesson tip.
 * @throws RangeError on a `ring` that is not an integer in [LESSON_RINGS, total), or a `total` that is not a positive integer.
 */
export function courseTipText(ring: number, total: number, way: RingWay, reader: TipReader, markerOffset: number): string {
  if (!(Number.isInteger(total) && total > 0)) throw new RangeError(`courseTipText: total must be a positive integer, got ${total}`);
  if (!(Number.isInteger(ring) && ring >= LESSON_RINGS && ring < total))
    throw new RangeError(`courseTipText: ring must be an integer in [${LESSON_RINGS}, ${total}), got ${ring}`);
  const { touch, compact } = reader;
  const name = ring === total - 1 ? `Last ring (${ring + 1})` : `Ring ${ring + 1} of ${total}`;
  const input = touch ? 'the stick' : 'the keys';
  if (clearThrough(markerOffset))
    return compact ? `${name}: ⊕ is in it. Let go and fly through.` : `${name}: the marker ⊕ is in it. Let go of ${input} and fly through.`;
  if (!way.side && !way.up) return `${name} is straight ahead: fly on through it.`;
  const sideWord = way.side > 0 ? 'right' : 'left';
  const key = way.up > 0 !== reader.pilotPitch ? '↑' : '↓';
  const stickUp = key === '↑' ? 'up' : 'down';
  const does = touch
    ? `${compact ? 'stick' : 'push the stick'} ${[way.side ? sideWord : '', way.up ? stickUp : ''].filter(Boolean).join(' and ')}`
    : `hold ${[way.side ? (way.side > 0 ? '→' : '←') : '', way.up ? key : ''].filter(Boolean).join(' and ')}`;
  return compact
    ? `${name}, ${ringWhere(way, true)}: ${does} until ⊕ is in it.`
    : `${name} is ${ringWhere(way, false)}: ${does} until the marker ⊕ is in it, then let go.`;
}

/**
 * Where `ring`'s centre lies from `point` (m, world), the point of its plane the flight-path marker
 * shows the aircraft passing (./course.ts predictThroughRing): to the right (+) or left of it across
 * the ring (along n x up, n the ring's normal, the way it is flown through) and above (+) or below it,
 * m; `bearing` 0 (the ring is ahead). The coach says these ways, so its words agree with the marker on
 * the screen (the line flown now, before the turn and climb the marker allows for, could lie on the
 * other side: a tip said "higher" with the marker above the ring).
 * @throws RangeError on a point that is not 3 finite numbers, or a ring whose normal is vertical.
 */
export function markerBearing(ring: Ring, point: readonly number[]): Pick<RingBearing, 'side' | 'up' | 'bearing'> {
  if (point.length < 3 || !point.slice(0, 3).every(Number.isFinite))
    throw new RangeError(`markerBearing: point must be 3 finite numbers, got ${point.join(', ')}`);
  const level = Math.hypot(ring.nx, ring.nz);
  if (!(level > 0))
    throw new RangeError(`markerBearing: ring's normal must have a horizontal part, got ${ring.nx}, ${ring.ny}, ${ring.nz}`);
  // Right of the way through (nx, nz) is (-nz, nx): y up, +z to the right of +x.
  const side = ((ring.x - point[0]!) * -ring.nz + (ring.z - point[2]!) * ring.nx) / level;
  return { side, up: ring.y - point[1]!, bearing: 0 };
}
