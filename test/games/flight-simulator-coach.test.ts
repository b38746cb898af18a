/**
 * The flight simulator's coach (games/flight-simulator/coach.ts), flown headless: a pilot who does
 * what the tip says, a moment late (REACTIONS), holds the keys it names and lets go when it says "let
 * go", the aircraft flown by the assist as the game flies it. Every ring is flown through: the tip
 * says "let go" only when letting go takes the whole aircraft through (./course.ts clearThrough), so
 * obeying it never misses (at the tube's edge it did, three rings in a row for a stranger).
 */

import { describe, expect, it } from 'vitest';
import { BANK_KEY_RAMP, flightState, heldBank, rampKey } from '../../games/flight-simulator/assist';
import { courseTipText, markerBearing } from '../../games/flight-simulator/coach';
import { PASS_RADIUS, predictThroughRing, type Ring, ringWay } from '../../games/flight-simulator/course';
import { assistedAircraft } from './flight-simulator-flyer';

/** How long after a tip shows the pilot's keys follow it, s (a player reading and pressing): quick and slow. */
const REACTIONS = [0.2, 0.35];
const desk = { touch: false, compact: false, pilotPitch: false };

/**
 * Flies at a ring `ahead` m along +x, `side` m to the right (+z) and `up` m above the aircraft (its
 * way through along +x), the keys as the coach's tip of `reaction` s before says: returns how far from
 * the ring's centre the aircraft crossed its plane, m, and whether the tip ever said "let go".
 */
function obey(ahead: number, side: number, up: number, reaction: number): { offset: number; saidLetGo: boolean } {
  const { world, C, e, state, fly } = assistedAircraft();
  const ring: Ring = {
    x: C.Position.x[e]! + ahead,
    y: C.Position.y[e]! + up,
    z: C.Position.z[e]! + side,
    nx: 1,
    ny: 0,
    nz: 0,
    status: 'ahead',
  };
  const seen: string[] = [];
  const key = { roll: 0, pitch: 0 };
  let pathRate = 0,
    saidLetGo = false;
  for (let i = 0; i < 60 * 40; i++) {
    const s = flightState(world, e);
    const position = [C.Position.x[e]!, C.Position.y[e]!, C.Position.z[e]!];
    const velocity = [C.Velocity.x[e]!, C.Velocity.y[e]!, C.Velocity.z[e]!];
    const through = predictThroughRing(
      ring,
      { position, velocity, bank: s.bank, rollRate: s.rollRate, pathRate, held: heldBank(state) },
      true,
    );
    const way = Number.isFinite(through.offset)
      ? ringWay(markerBearing(ring, through.point))
      : { side: 0 as const, up: 0 as const, sideAmount: '', upAmount: '' };
    const tip = courseTipText(5, 10, way, desk, through.offset);
    saidLetGo ||= /Let go/.test(tip);
    seen.push(tip);
    const read = seen[Math.max(0, seen.length - 1 - Math.round(reaction / world.dt))]!;
    const letGo = /Let go|straight ahead/.test(read);
    const roll = letGo ? 0 : read.includes('→') ? 1 : read.includes('←') ? -1 : 0;
    const pitch = letGo ? 0 : read.includes('↑') ? 1 : read.includes('↓') ? -1 : 0;
    key.roll = rampKey(key.roll, roll, world.dt, BANK_KEY_RAMP);
    key.pitch = rampKey(key.pitch, pitch, world.dt);
    fly(s, key.roll, key.pitch);
    pathRate = (flightState(world, e).path - s.path) / world.dt;
    const gap = ring.x - C.Position.x[e]!;
    if (gap <= 0) {
      // Where the step crossed the plane, on the straight line between its ends.
      const f = (ring.x - position[0]!) / (C.Position.x[e]! - position[0]!);
      const py = position[1]! + f * (C.Position.y[e]! - position[1]!),
        pz = position[2]! + f * (C.Position.z[e]! - position[2]!);
      return { offset: Math.hypot(py - ring.y, pz - ring.z), saidLetGo };
    }
  }
  return { offset: Infinity, saidLetGo };
}

describe('the coach (coach.ts) flown by a pilot who does what it says', () => {
  it('rings to the side, above and below: holding what the tip names and letting go when it says so flies through each', () => {
    const offsets: string[] = [];
    for (const reaction of REACTIONS)
      for (const [ahead, side, up] of [
        [1000, 150, 0],
        [1000, -250, 0],
        [1200, 120, 60],
        [900, -80, -50],
        [1100, 300, 40],
      ] as const) {
        const { offset, saidLetGo } = obey(ahead, side, up, reaction);
        offsets.push(`${reaction} s ${ahead}/${side}/${up}: ${offset.toFixed(1)} m`);
        expect(saidLetGo, offsets.join(', ')).toBe(true);
        // Through the ring by its own pass test (PASS_RADIUS, 71 m; no promise of the marker), with 10 m
        // to spare: measured at most 49.6 m (0.2 s) and 42.3 m (0.35 s). With "let go" said wherever
        // the marker was inside PASS_RADIUS, as it was, one crossed at 69.9 m, its wing through the tube.
        expect(offset, offsets.join(', ')).toBeLessThan(PASS_RADIUS - 10);
      }
  });
});
