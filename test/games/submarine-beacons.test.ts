/**
 * The submarine's beacon pointer (games/submarine/beacons.ts), headless: it holds one target beacon
 * until it is collected instead of flipping between beacons as the boat passes them, and a boat that follows it (ahead at 10 m/s,
 * down or up at 5 m/s, as the game's boat) sees the distance fall until it collects each beacon.
 */

import { createPhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, seabedHeight, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import {
  BACK_REACH,
  BEACON_CATCH,
  BEACON_PASSED,
  beaconLabel,
  beaconName,
  catchesBeacon,
  chooseBeacon,
  courseSpeed,
  LABEL_LINE_MAX,
  LEG_MAX,
  LEG_MIN_SHARE,
  lastBeacon,
  layCourse,
  MINE_WARNING,
  missWarning,
  missWarningText,
  passedBeacon,
  RIDGE_CLEAR_BELOW,
  RIDGE_WARNING,
  ridgeInWay,
  seabedBetween,
  TURNED_BACK,
} from '../../games/submarine/beacons';
import { createHelmState, NO_INPUT, steer } from '../../games/submarine/helm';

describe('submarine beacon pointer', () => {
  it('holds its target until it is collected, however near another passes, then takes the nearest left', () => {
    // Closer than BEACON_PASSED apart, so that neither counts as passed by the boat between them.
    const beacons = [100, -50, 125, -50],
      taken = [false, false];
    let current = -1,
      switches = 0,
      nearestSwitches = 0,
      nearest = -1;
    // The boat drifts to and fro across the line halfway between them, as a boat turning there does.
    for (let i = 0; i < 40; i++) {
      const x = 112.5 + (i % 2 === 0 ? 3 : -3);
      const next = chooseBeacon(beacons, taken, x, -40, current);
      if (current >= 0 && next !== current) switches++;
      current = next;
      const n = chooseBeacon(beacons, taken, x, -40, -1); // the old rule: the nearest, every frame
      if (nearest >= 0 && n !== nearest) nearestSwitches++;
      nearest = n;
    }
    expect(nearestSwitches).toBe(39);
    expect(switches).toBe(0);
    // Held with the boat right on the other beacon (a stranger saw the target flip as they passed beacons).
    expect(chooseBeacon(beacons, taken, 125, -50, 0)).toBe(0);
    // With none held, the nearest; the collected one hands over to the nearest left; none left: -1.
    expect(chooseBeacon(beacons, taken, 120, -50, -1)).toBe(1);
    expect(chooseBeacon(beacons, [true, false], 100, -50, 0)).toBe(1);
    expect(chooseBeacon([100, -50, 200, -50, 300, -50], [true, false, false], 290, -50, 0)).toBe(2);
    expect(chooseBeacon(beacons, [true, true], 100, -50, 1)).toBe(-1);
  });

  it('a beacon collected moves the target to the next uncollected one along the course, past the ones passed by; then back to those', () => {
    // Course A (0) near the start, then B, C, D along x (laid out of index order on purpose).
    const beacons = [50, -20, 300, -40, 180, -30, 420, -50];
    const taken = [false, false, false, false];
    // A stranger passed A (the target) and collected B (x 180, index 2): the target is C (x 300), not A behind.
    taken[2] = true;
    expect(chooseBeacon(beacons, taken, 185, -30, 0, 2)).toBe(1);
    // Held from then on, even with the boat back by A.
    expect(chooseBeacon(beacons, taken, 50, -20, 1)).toBe(1);
    // C and D collected: none left ahead, so back to A.
    taken[1] = true;
    expect(chooseBeacon(beacons, taken, 300, -40, 1, 1)).toBe(3);
    taken[3] = true;
    expect(chooseBeacon(beacons, taken, 420, -50, 3, 3)).toBe(0);
    taken[0] = true;
    expect(chooseBeacon(beacons, taken, 50, -20, 0, 0)).toBe(-1);
    // The target itself collected: the next along the course, whatever is nearer.
    expect(chooseBeacon(beacons, [true, false, false, false], 60, -20, 0, 0)).toBe(2);
  });

  it('missWarning: a target left behind warns, moving away, how far on it counts as passed; not near it, backing or at the finish', () => {
    const beacons = [40, -20, 160, -40, 280, -30];
    // Past the ring and half a hull (8 + 6 m) and moving on: BEACON_PASSED less the way gone.
    expect(missWarning(beacons, 1, 160 + 20, 3)).toBe(BEACON_PASSED - 20);
    expect(missWarning(beacons, 1, 160 + BEACON_PASSED + 5, 3)).toBe(0);
    expect(missWarning(beacons, 1, 160 + 10, 3)).toBeNaN(); // still at the ring
    expect(missWarning(beacons, 1, 160 + 20, -2)).toBeNaN(); // backing to it
    expect(missWarning(beacons, 1, 160 + 20, 0.2)).toBeNaN(); // stopped
    expect(missWarning(beacons, 2, 280 + 20, 3)).toBeNaN(); // the finish
    // Warned before it is passed: every x at which it counts as passed was warned of just before.
    for (let x = 160; x < 260; x += 0.5)
      if (passedBeacon(beacons, 1, x + 0.5)) expect(missWarning(beacons, 1, x, 2)).toBeGreaterThanOrEqual(0);
    expect(() => missWarning(beacons, 3, 0, 0)).toThrow(/missWarning: i/);
    expect(() => missWarning(beacons, 1, Number.NaN, 0)).toThrow(/missWarning: x/);
  });

  it('missWarningText: the going-away warning fits a phone: every line at most LABEL_LINE_MAX characters (one of 49 ran off 390 px)', () => {
    for (const left of [0, 0.2, 9.5, BEACON_PASSED, 999]) {
      const text = missWarningText(left);
      expect(text).toContain('Astern');
      expect(text).toContain(`skipped in ${Math.ceil(left)} m`);
      for (const line of text.split('\n')) expect(line.length, line).toBeLessThanOrEqual(LABEL_LINE_MAX);
    }
    // The other warning lines the label can carry fit the same width.
    for (const line of [RIDGE_WARNING, MINE_WARNING.over, MINE_WARNING.under])
      expect(line.length, line).toBeLessThanOrEqual(LABEL_LINE_MAX);
    for (const line of beaconLabel(485, -120, true, '', 'F').split('\n')) expect(line.length, line).toBeLessThanOrEqual(LABEL_LINE_MAX);
    expect(() => missWarningText(-1)).toThrow(RangeError);
    expect(() => missWarningText(Number.NaN)).toThrow(RangeError);
  });

  it('a target overshot by more than BEACON_PASSED along x is passed: the target moves on ahead, never to one far behind; the finish is never passed', () => {
    // A (0) by the start, B, C, D, E, F along x; F (x 620) is the finish.
    const beacons = [40, -20, 160, -40, 280, -30, 400, -50, 510, -35, 620, -45];
    expect(lastBeacon(beacons)).toBe(5);
    const taken = [true, false, false, false, false, false];
    // B overshot: held up to BEACON_PASSED behind (backing that far is about 10 s at 4 m/s) ...
    expect(passedBeacon(beacons, 1, 160 + BEACON_PASSED - 0.5)).toBe(false);
    expect(chooseBeacon(beacons, taken, 160 + BEACON_PASSED - 0.5, -40, 1)).toBe(1);
    // ... and just past it B is passed and the target is C, ahead.
    expect(passedBeacon(beacons, 1, 160 + BEACON_PASSED + 0.5)).toBe(true);
    expect(chooseBeacon(beacons, taken, 160 + BEACON_PASSED + 0.5, -40, 1)).toBe(2);
    // A stranger's run: A, B overshot, then D, E collected: the target stays ahead (F), never "B: 412 m behind".
    const run = [true, false, false, true, true, false];
    expect(chooseBeacon(beacons, run, 512, -35, 4, 4)).toBe(5);
    for (let x = 400; x <= 700; x += 5) {
      const i = chooseBeacon(beacons, run, x, -40, 5);
      expect(beacons[2 * i]! - x).toBeGreaterThan(-Math.max(BEACON_PASSED, x - 620) - 1e-9);
    }
    // The finish overshot by 80 m is still the target (collecting it ends the run).
    expect(passedBeacon(beacons, 5, 700)).toBe(false);
    expect(chooseBeacon(beacons, run, 700, -40, 5)).toBe(5);
    // A passed beacon can still be fetched: with the boat back by it, it is open again.
    expect(passedBeacon(beacons, 1, 170)).toBe(false);
    expect(() => passedBeacon(beacons, 6, 0)).toThrow(/passedBeacon: i/);
    expect(() => passedBeacon(beacons, 0, Number.NaN)).toThrow(/passedBeacon/);
  });

  it('reversing: a beacon is never skipped while the boat backs towards it or has stopped, and the target is the beacon it backs to', () => {
    // Issue 34: backing to fetch a skipped A the stranger collected B and the target moved on to C,
    // ahead; C was marked skipped though the player had reversed on the warning.
    const beacons = [40, -20, 160, -40, 280, -30, 400, -50, 510, -35, 620, -45];
    // C overshot by more than BEACON_PASSED: passed moving on ahead, not backing, nor stopped.
    expect(passedBeacon(beacons, 2, 280 + BEACON_PASSED + 5, 3)).toBe(true);
    expect(passedBeacon(beacons, 2, 280 + BEACON_PASSED + 5, -2)).toBe(false);
    expect(passedBeacon(beacons, 2, 280 + BEACON_PASSED + 5, 0)).toBe(false);
    expect(() => passedBeacon(beacons, 2, 0, Number.NaN)).toThrow(/passedBeacon: vx/);
    const taken = [true, false, false, false, false, false];
    expect(chooseBeacon(beacons, taken, 280 + BEACON_PASSED + 5, -40, 2, -1, -2)).toBe(2);
    expect(chooseBeacon(beacons, taken, 280 + BEACON_PASSED + 5, -40, 2, -1, 3)).toBe(3);
    // B skipped (the target is D, ahead); backing from 330 m towards B the target stays D until C,
    // the nearest beacon behind, is within BACK_REACH (issue 34: braking with Astern swung the label
    // round to a beacon skipped 50 m behind); then it is C; C collected on the way, the target is B, not D ahead.
    expect(chooseBeacon(beacons, taken, 330, -40, 3, -1, -3)).toBe(3);
    expect(chooseBeacon(beacons, taken, 280 + BACK_REACH + 1, -40, 3, -1, -3)).toBe(3);
    expect(chooseBeacon(beacons, taken, 280 + BACK_REACH - 1, -40, 3, -1, -3)).toBe(2);
    expect(chooseBeacon(beacons, [true, false, true, false, false, false], 275, -30, 2, 2, -3)).toBe(1);
    // Going on ahead again, the skipped beacon far behind hands over to the first ahead.
    expect(chooseBeacon(beacons, [true, false, true, false, false, false], 260, -30, 1, -1, 3)).toBe(3);
    // Backing a little after braking short of the target (within TURNED_BACK of it): it stays.
    expect(chooseBeacon(beacons, taken, 400 - 20, -50, 3, -1, -2)).toBe(3);
    // Backing on further, C 87 m behind is beyond BACK_REACH: the target is still D.
    expect(chooseBeacon(beacons, taken, 400 - TURNED_BACK - 5, -50, 3, -1, -2)).toBe(3);
  });

  it('a current carrying the boat back does not turn the target round to a beacon skipped behind it (issue 34)', () => {
    const beacons = [40, -20, 160, -40, 280, -30, 400, -50];
    const taken = [true, false, false, false];
    // B (160) skipped, C (280) the target 20 m ahead; the boat drifts back at 1.2 m/s with no Astern
    // asked: it counts as stopped (0), and the target stays C however near B comes.
    expect(courseSpeed(-1.2, false)).toBe(0);
    expect(chooseBeacon(beacons, taken, 180, -40, 2, -1, courseSpeed(-1.2, false))).toBe(2);
    // Astern asked: backing counts, ahead does not (the brake slowing a boat still going ahead).
    expect(courseSpeed(-3, true)).toBe(-3);
    expect(courseSpeed(4, true)).toBe(0);
    expect(courseSpeed(4, false)).toBe(4);
    expect(() => courseSpeed(Number.NaN, false)).toThrow(/courseSpeed: vx/);
  });

  it('reversing on the "skipped in 1 m" warning at full ahead keeps the target, and the boat backs onto it', () => {
    // The helm and the sea stepped in full: the boat runs at full ahead past its target C, and on
    // the warning's last metre Astern is held (the page counts a boat going astern as not moving on:
    // main.ts goingX). C must never count as passed, and backing takes the hull into its ring (on the
    // way out the hull runs through it from the start: only the way back is counted).
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -30] });
    world.components.FluidRegion.surface.fill(0);
    h.seabed.y.fill(-1000);
    const helm = createHelmState(SUBMARINE_NEUTRAL_FILL),
      c = world.components,
      e = h.hull;
    const course = [-200, -30, -100, -30, 0, -30, 400, -30];
    const going = () => (!Number.isNaN(warned) || helm.throttle < 0 ? Math.min(c.Velocity.x[e]!, 0) : c.Velocity.x[e]!);
    let warned = Number.NaN,
      passed = false,
      caught = false,
      furthest = 0;
    for (let i = 0; i < 60 * 40 && !caught; i++) {
      const x = c.Position.x[e]!;
      const left = missWarning(course, 2, x, going());
      if (Number.isNaN(warned) && left <= 1) warned = x;
      steer(world, h, { ...NO_INPUT, ahead: Number.isNaN(warned), astern: !Number.isNaN(warned) }, helm);
      step(world);
      passed ||= passedBeacon(course, 2, c.Position.x[e]!, going());
      furthest = Math.max(furthest, c.Position.x[e]!);
      caught = !Number.isNaN(warned) && catchesBeacon(c.Position.x[e]!, c.Position.y[e]!, c.Angle.value[e]!, 0, -30);
    }
    expect(warned).toBeGreaterThan(BEACON_PASSED - 1.5);
    expect(passed).toBe(false);
    expect(caught).toBe(true);
    console.log(`warned at ${warned.toFixed(1)} m past C, Astern: furthest ${furthest.toFixed(1)} m past, back in its ring`);
  });

  it('an overshoot of 60 m past the first beacon (a key held seconds too long) is recovered: following the pointer collects 6/6 before the finish', () => {
    // Issue 34: holding Ahead and Dive 5 s from the start ran a stranger far past A; A was lost for
    // good ("0/6 (1 missed)") and 6/6 was out of reach. The boat backs at 4 m/s and goes ahead at 8.
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { seed: 1, count: 6 });
    layCourse(h.beacons, h.seabed, 1);
    const taken = new Array<boolean>(6).fill(false);
    const finish = lastBeacon(h.beacons);
    let x = h.beacons[0]! + 60,
      y = h.beacons[1]!,
      current = 0,
      order: number[] = [];
    const dt = 1 / 20;
    for (let t = 0; t < 900 && !taken[finish]; t += dt) {
      current = chooseBeacon(h.beacons, taken, x, y, current);
      const dx = h.beacons[2 * current]! - x,
        dy = h.beacons[2 * current + 1]! - y;
      x += Math.sign(dx) * Math.min((dx > 0 ? 8 : 4) * dt, Math.abs(dx));
      y += Math.sign(dy) * Math.min(5 * dt, Math.abs(dy));
      for (let i = 0; i < 6; i++)
        if (!taken[i] && catchesBeacon(x, y, 0, h.beacons[2 * i]!, h.beacons[2 * i + 1]!)) {
          taken[i] = true;
          order = [...order, i];
          current = chooseBeacon(h.beacons, taken, x, y, current, i);
        }
    }
    expect(order[0]).toBe(0); // backed up to A first
    expect(order.at(-1)).toBe(finish);
    expect(taken.every(Boolean)).toBe(true);
    // Further than BEACON_PASSED past it, the target moves on, and A is still collectable going back.
    expect(
      chooseBeacon(h.beacons, [false, false, false, false, false, false], h.beacons[0]! + BEACON_PASSED + 1, h.beacons[1]!, 0),
    ).not.toBe(0);
    expect(passedBeacon(h.beacons, 0, h.beacons[0]!)).toBe(false);
  });

  it('following the pointer from the surface, the distance shown falls until each beacon is taken', () => {
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { seed: 1, count: 6 });
    const taken = new Array<boolean>(6).fill(false);
    let x = 0,
      y = -1,
      current = -1,
      last = Infinity,
      rises = 0;
    const dt = 1 / 60;
    for (let t = 0; t < 600 && taken.includes(false); t += dt) {
      const i = chooseBeacon(h.beacons, taken, x, y, current);
      const dx = h.beacons[2 * i]! - x,
        dy = h.beacons[2 * i + 1]! - y;
      const d = Math.hypot(dx, dy);
      if (i === current && d > last + 1e-9) rises++;
      current = i;
      last = d;
      if (d < 7) {
        taken[i] = true; // collected (the game's 7 m radius)
        last = Infinity;
        continue;
      }
      x += Math.sign(dx) * Math.min(10 * dt, Math.abs(dx));
      y += Math.sign(dy) * Math.min(5 * dt, Math.abs(dy));
    }
    expect(taken.every(Boolean)).toBe(true);
    expect(rises).toBe(0);
  });

  it('the label says ahead or behind and how far down or up, each from 3 m', () => {
    // Ahead or behind along the heading, and how far down or up (the label once gave the distance only).
    expect(beaconLabel(83.3, -43.6)).toBe('beacon 83 m ahead, 44 m down');
    expect(beaconLabel(-45, 30)).toBe('beacon 45 m behind, 30 m up');
    expect(beaconLabel(20, -2)).toBe('beacon 20 m ahead');
    expect(beaconLabel(1, -2)).toBe('beacon here');
    // A mine on the way adds which side to pass it; a ridge, the more urgent, takes the line instead.
    expect(beaconLabel(20, -2, false, 'over')).toBe(`beacon 20 m ahead\n${MINE_WARNING.over}`);
    expect(beaconLabel(20, -2, true, 'under')).toBe(`beacon 20 m ahead\n${RIDGE_WARNING}`);
    // Named, so that a switch to another beacon is seen ("52 m ahead" then "157 m ahead" was not).
    expect(beaconLabel(52, 9, false, '', beaconName(2))).toBe('target C: 52 m ahead, 9 m up');
    expect([0, 1, 25, 26, 27].map(beaconName)).toEqual(['A', 'B', 'Z', 'A2', 'B2']);
    expect(() => beaconName(-1)).toThrow(/beaconName: index must be an integer >= 0, got -1/);
    expect(() => beaconName(1.5)).toThrow(/beaconName: index/);
  });

  it('warns of a ridge when the straight way to the beacon runs under the seabed', () => {
    // A bed 60 m down with a ridge up to 25 m down from x = 20 to 40 m; the hull and the beacon 59 m
    // apart at 40 m down: the line between them is level and 15 m under the ridge's top.
    const bed = (x: number) => (x >= 20 && x <= 40 ? -25 : -60);
    expect(seabedBetween(0, -40, 59, -40, bed)).toBe(true);
    expect(beaconLabel(59, 0, seabedBetween(0, -40, 59, -40, bed))).toBe(`beacon 59 m ahead\n${RIDGE_WARNING}`);
    // At 20 m down the line clears the ridge by 5 m: no warning.
    expect(seabedBetween(0, -20, 59, -20, bed)).toBe(false);
    expect(beaconLabel(59, 0, seabedBetween(0, -20, 59, -20, bed))).toBe('beacon 59 m ahead');
    // A ridge 1 m wide is not stepped over by the sampling (every metre or less).
    const thin = (x: number) => (x >= 30.2 && x <= 31.1 ? -25 : -60);
    expect(seabedBetween(0, -40, 59, -40, thin)).toBe(true);
    // The seeded course: the hull 15 m over the bed at x = 0 looking at a point 15 m over the bed at
    // x = 300 m. The warning holds exactly where a point of the line is under the bed (checked every 0.1 m).
    const h = submarine.build(createPhysicsWorld(submarine.worldOptions()), { seed: 1, count: 2 });
    const at = (x: number) => seabedHeight(h.seabed, x);
    for (const [x0, x1] of [
      [0, 300],
      [100, 400],
      [500, 200],
    ] as const) {
      const y0 = at(x0) + 15,
        y1 = at(x1) + 15;
      let under = false;
      for (let x = Math.min(x0, x1); x <= Math.max(x0, x1); x += 0.1) under ||= y0 + ((x - x0) / (x1 - x0)) * (y1 - y0) < at(x) - 0.05;
      if (under) expect(seabedBetween(x0, y0, x1, y1, at)).toBe(true);
    }
    expect(() => seabedBetween(Number.NaN, 0, 1, 0, bed)).toThrow(/seabedBetween: x0/);
  });

  it('clears the ridge warning once the ridge is far under the keel or behind the boat going away (issue 34)', () => {
    // The bed of the test above: a ridge up to 25 m down from x = 20 to 40 m, 60 m down round it.
    const bed = (x: number) => (x >= 20 && x <= 40 ? -25 : -60);
    const keel = (y: number) => y - SUBMARINE.height / 2;
    // Reported: the boat at 16 m, its beacon deep past the ridge (55 m down at x = 59): the straight
    // way dips under the ridge's flank (29 m down at x = 20), so the old check (seabedBetween) warned
    // "climb over it" though the crest lies 9 m under the boat.
    expect(seabedBetween(0, -16, 59, -55, bed)).toBe(true);
    expect(ridgeInWay(0, -16, 59, -55, bed, keel(-16), 3)).toBe(false);
    // The boat at 30 m, under the crest: the climb is needed, the warning stays.
    expect(ridgeInWay(0, -30, 59, -55, bed, keel(-30), 3)).toBe(true);
    // The crest just inside RIDGE_CLEAR_BELOW under the keel still warns; just past it, clear.
    const y = -25 + SUBMARINE.height / 2;
    expect(ridgeInWay(0, y + RIDGE_CLEAR_BELOW - 0.1, 59, -55, bed, keel(y + RIDGE_CLEAR_BELOW - 0.1), 3)).toBe(true);
    expect(ridgeInWay(0, y + RIDGE_CLEAR_BELOW + 0.1, 59, -55, bed, keel(y + RIDGE_CLEAR_BELOW + 0.1), 3)).toBe(false);
    // The ridge behind: the boat at 40 m at x = 70 with its beacon back at x = 0 past the ridge.
    // Going away ahead at 3 m/s: clear; stopped or backing toward it: the warning holds.
    expect(seabedBetween(70, -40, 0, -40, bed)).toBe(true);
    expect(ridgeInWay(70, -40, 0, -40, bed, keel(-40), 3)).toBe(false);
    expect(ridgeInWay(70, -40, 0, -40, bed, keel(-40), 0)).toBe(true);
    expect(ridgeInWay(70, -40, 0, -40, bed, keel(-40), -2)).toBe(true);
    // No ridge under the way: no warning whatever the keel.
    expect(ridgeInWay(0, -20, 59, -20, bed, -100, 3)).toBe(false);
    expect(() => ridgeInWay(0, -20, 59, -20, bed, Number.NaN, 3)).toThrow(/ridgeInWay: keel/);
  });
});

describe('submarine beacon ring', () => {
  it('any part of the hull inside the drawn ring (BEACON_CATCH round the beacon) collects; just outside does not', () => {
    const L = SUBMARINE.length / 2,
      H = SUBMARINE.height / 2,
      R = BEACON_CATCH;
    // Level hull at (0, -30): the beacon ahead of the bow, above the deck, and at a corner.
    expect(catchesBeacon(0, -30, 0, L + R - 0.1, -30)).toBe(true);
    expect(catchesBeacon(0, -30, 0, L + R + 0.1, -30)).toBe(false);
    expect(catchesBeacon(0, -30, 0, -(L + R - 0.1), -30)).toBe(true); // behind the stern
    expect(catchesBeacon(0, -30, 0, 0, -30 + H + R - 0.1)).toBe(true);
    expect(catchesBeacon(0, -30, 0, 0, -30 + H + R + 0.1)).toBe(false);
    const d = (R - 0.1) / Math.SQRT2;
    expect(catchesBeacon(0, -30, 0, L + d, -30 - H - d)).toBe(true);
    expect(catchesBeacon(0, -30, 0, L + R / Math.SQRT2, -30 - H - R / Math.SQRT2 - 0.2)).toBe(false);
    // Bow up (90 degrees): the bow is at (0, -30 + L).
    expect(catchesBeacon(0, -30, Math.PI / 2, 0, -30 + L + R - 0.1)).toBe(true);
    expect(catchesBeacon(0, -30, Math.PI / 2, H + R + 0.1, -30)).toBe(false);
    // The hull's centre 13.9 m from the lamp, its bow inside the ring: collected (the old rule, the
    // centre within 8 m, did not).
    expect(Math.hypot(L + R - 0.1, 0)).toBeGreaterThan(8);
    expect(() => catchesBeacon(0, Number.NaN, 0, 1, 1)).toThrow(/catchesBeacon: y0/);
    expect(() => catchesBeacon(0, 0, Number.POSITIVE_INFINITY, 1, 1)).toThrow(/catchesBeacon: angle/);
  });
});

describe('submarine course', () => {
  it('after each beacon the next target is near (a leg of at most LEG_MAX m along x) and open (no ridge on the straight way)', () => {
    let legs = 0,
      ridges = 0,
      longest = 0;
    for (let seed = 1; seed <= 20; seed++)
      for (const count of [2, 6, 10, 20]) {
        const world = createPhysicsWorld(submarine.worldOptions());
        const h = submarine.build(world, { seed, count });
        const first = [h.beacons[0]!, h.beacons[1]!];
        layCourse(h.beacons, h.seabed, seed);
        expect([h.beacons[0], h.beacons[1]]).toEqual(first);
        const bed = (x: number) => seabedHeight(h.seabed, x);
        const leg = Math.min(LEG_MAX, (1000 - first[0]!) / (count - 1));
        const taken = new Array<boolean>(count).fill(false);
        for (let i = 0; i < count; i++) {
          const x = h.beacons[2 * i]!,
            y = h.beacons[2 * i + 1]!;
          // Between 8 m over the seabed and 10 m under the surface, inside the scene's seabed.
          expect(y).toBeLessThanOrEqual(-10);
          expect(y).toBeGreaterThanOrEqual(bed(x) + 8 - 1e-9);
          expect(x).toBeLessThanOrEqual(1000 + 1e-9);
          if (i === 0) continue;
          const dx = x - h.beacons[2 * i - 2]!;
          expect(dx).toBeGreaterThanOrEqual(LEG_MIN_SHARE * leg - 1e-9);
          expect(dx).toBeLessThanOrEqual(leg + 1e-9);
        }
        // Collected in turn, at each beacon the pointer's next target (the nearest left) is near and open.
        for (let i = 0; i < count - 1; i++) {
          taken[i] = true;
          const x = h.beacons[2 * i]!,
            y = h.beacons[2 * i + 1]!;
          const next = chooseBeacon(h.beacons, taken, x, y, -1);
          expect(next).toBeGreaterThan(i);
          const nx = h.beacons[2 * next]!,
            ny = h.beacons[2 * next + 1]!;
          longest = Math.max(longest, Math.hypot(nx - x, ny - y));
          legs++;
          if (seabedBetween(x, y, nx, ny, bed)) ridges++;
        }
      }
    // The scene's own layout: legs of up to 308 m, 12 of 420 behind a ridge (seeds 1 to 30, 6 and 10 beacons).
    expect(longest).toBeLessThan(160);
    expect(ridges).toBeLessThanOrEqual(Math.floor(0.02 * legs));
    expect(() => layCourse(new Float64Array(4), { x0: 0, dx: 1, y: new Float64Array(2) }, Number.NaN)).toThrow(/layCourse: seed/);
  });
});
