/**
 * The solar system's reading of a launch before its first try (games/solar-system/orbit-crossing.ts):
 * the radius of a Kepler orbit in a direction against the conic's own formula, and where a launch's
 * forecast meets the target's orbit: not at all for the first mission's short start, on the orbit
 * line for a faster launch, sooner for a faster one; and the score's part for few launches.
 */

import { createPhysicsWorld, slotOf } from '@bitphysics/physics';
import { solarSystem } from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';
import { tutorialAim } from '../../games/solar-system/advice';
import { forecastLaunch } from '../../games/solar-system/forecast';
import { keplerState } from '../../games/solar-system/kepler';
import { heliocentricState, MISSIONS, missionScore, SCORE_FIRST_TRY } from '../../games/solar-system/missions';
import { meetingPoint, orbitCrossings, orbitRadiusToward, orbitReach, pathDay, targetLag } from '../../games/solar-system/orbit-crossing';

describe('orbitRadiusToward', () => {
  test('a circle is its radius every way; an ellipse (e = 0.6) is a(1 - e) at perihelion, a(1 + e) at aphelion, p at 90 degrees', () => {
    const mu = 2.959e-4;
    const v = Math.sqrt(mu / 1.5);
    const circle = [1.5, 0, 0, 0, 0, v];
    for (const deg of [0, 37, 90, 181, 300]) {
      const a = (deg * Math.PI) / 180;
      expect(orbitRadiusToward(circle, mu, Math.cos(a), 0, Math.sin(a))).toBeCloseTo(1.5, 12);
    }
    // At perihelion q = a(1 - e) the speed is sqrt(mu (1 + e) / q) (vis-viva).
    const a = 2,
      e = 0.6,
      q = a * (1 - e);
    const ellipse = [q, 0, 0, 0, 0, Math.sqrt((mu * (1 + e)) / q)];
    expect(orbitRadiusToward(ellipse, mu, 1, 0, 0)).toBeCloseTo(q, 12);
    expect(orbitRadiusToward(ellipse, mu, -3, 0, 0)).toBeCloseTo(a * (1 + e), 12);
    expect(orbitRadiusToward(ellipse, mu, 0, 0, 1)).toBeCloseTo(a * (1 - e * e), 12);
    // A direction a little off the plane reads as its projection.
    expect(orbitRadiusToward(ellipse, mu, 0, 0.05, 1)).toBeCloseTo(a * (1 - e * e), 12);
    expect(() => orbitRadiusToward(ellipse, 0, 1, 0, 0)).toThrow(/orbitRadiusToward: mu must be positive and finite, got 0/);
    expect(() => orbitRadiusToward(ellipse, mu, 0, 0, 0)).toThrow(/orbitRadiusToward: the direction must be finite and not zero/);
  });
});

describe('orbitCrossings and meetingPoint', () => {
  const options = { stepHours: 1, integrator: 'rk4' as const, date: '2012-01-01T00:00:00Z' };
  const world = createPhysicsWorld(solarSystem.worldOptions(options));
  const handles = solarSystem.build(world, options);
  const m = MISSIONS[0]!;
  const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
  const mars = heliocentricState(world, handles, handles.bodies.Mars);
  const lesson = tutorialAim(world, handles, m, 1 / 24)!;

  test('the first mission’s short start never reaches Mars’s orbit; faster launches cross it, on the line, sooner the faster', () => {
    const short = forecastLaunch(world, handles, m, lesson.start, 1 / 24);
    expect(orbitCrossings(short, mars, mu)).toEqual([]);
    expect(meetingPoint(short, mars, mu)).toBe(-1);
    let lastDay = Infinity;
    for (const extra of [1.5, 2.5, 4]) {
      const f = forecastLaunch(world, handles, m, { angle: lesson.hit.angle, speed: lesson.hit.speed + extra }, 1 / 24);
      const i = orbitCrossings(f, mars, mu)[0]!;
      expect(i, `+${extra} km/s`).toBeGreaterThan(0);
      // The point is past the orbit's line, the one before it short of it.
      const r = (k: number) => Math.hypot(f.path[3 * k]!, f.path[3 * k + 1]!, f.path[3 * k + 2]!);
      const line = (k: number) => orbitRadiusToward(mars, mu, f.path[3 * k]!, f.path[3 * k + 1]!, f.path[3 * k + 2]!);
      expect(r(i)).toBeGreaterThanOrEqual(line(i));
      expect(r(i - 1)).toBeLessThan(line(i - 1));
      const day = pathDay(f, i);
      // Faster than the Hohmann transfer (259 days to 1.52 AU), and sooner for a faster launch.
      expect(day).toBeLessThan(259);
      expect(day).toBeLessThan(lastDay);
      lastDay = day;
    }
    const f = short;
    expect(pathDay(f, f.points - 1)).toBe(f.end);
    expect(() => pathDay(f, f.points)).toThrow(/pathDay: index must be a whole number in \[0, \d+\], got \d+/);
  });

  test('the meeting point: for the first mission’s arriving launch the probe is within the ring of Mars’s own place that day; for a miss it is not', () => {
    // Mars's place on a day, from its Kepler orbit now (two-body; the planets bend it by far less than the ring).
    const gap = (f: ReturnType<typeof forecastLaunch>, i: number): number => {
      const at = keplerState(mars, mars.subarray(3), mu, pathDay(f, i));
      return Math.hypot(f.path[3 * i]! - at[0]!, f.path[3 * i + 1]! - at[1]!, f.path[3 * i + 2]! - at[2]!);
    };
    const hit = forecastLaunch(world, handles, m, lesson.hit, 1 / 24);
    expect(hit.outcome).toBe('arrived');
    const i = meetingPoint(hit, mars, mu);
    expect(i).toBeGreaterThan(0);
    // This launch crosses Mars's orbit going out (day 195, Mars far off) and meets it coming back:
    // the meeting point is the later one, within the ring (0.14 AU) to 0.01 AU.
    expect(orbitCrossings(hit, mars, mu).length).toBeGreaterThan(0);
    expect(gap(hit, i)).toBeLessThan(m.zone + 0.01);
    for (const k of orbitCrossings(hit, mars, mu)) expect(gap(hit, k)).toBeGreaterThanOrEqual(gap(hit, i));
    // Turned 30 degrees inwards it misses: nowhere on its crossings is Mars within the ring.
    const miss = forecastLaunch(world, handles, m, { angle: lesson.hit.angle - 30, speed: lesson.hit.speed }, 1 / 24);
    expect(miss.outcome).toBe('missed');
    const j = meetingPoint(miss, mars, mu);
    expect(j).toBeGreaterThan(0);
    expect(gap(miss, j)).toBeGreaterThan(m.zone - 0.01);
  });

  test('targetLag: the days until Mars reaches the meeting point, the verdict the line gives at every speed (a stranger read "Will Mars be there?" and no answer)', () => {
    // Brute force: the day, within half of Mars's 687-day period of the probe's, when Mars's Kepler
    // place comes nearest the point (a scan a tenth of a day apart). targetLag agrees within 0.2 day.
    const scan = (f: ReturnType<typeof forecastLaunch>, i: number): number => {
      const day = pathDay(f, i);
      let best = 0,
        nearest = Infinity;
      for (let d = -343; d <= 343; d += 0.1) {
        const at = keplerState(mars, mars.subarray(3), mu, day + d);
        const g = Math.hypot(f.path[3 * i]! - at[0]!, f.path[3 * i + 1]! - at[1]!, f.path[3 * i + 2]! - at[2]!);
        if (g < nearest) [best, nearest] = [d, g];
      }
      return best;
    };
    const lags: number[] = [];
    // The lesson's arriving speed, and from it slower and faster by up to 1.5 km/s (launches that miss).
    for (const extra of [0, -0.4, 0.4, 1, 1.5]) {
      const f = forecastLaunch(world, handles, m, { angle: lesson.hit.angle, speed: lesson.hit.speed + extra }, 1 / 24);
      const i = meetingPoint(f, mars, mu);
      if (i < 0) continue;
      const lag = targetLag(f, i, mars, mu);
      expect(Math.abs(lag - scan(f, i)), `+${extra} km/s`).toBeLessThan(0.2);
      // An arrival: Mars is there within the days its ring takes to pass (0.14 AU at 24 km/s, 0.0139 AU a day: 10 days).
      if (f.outcome === 'arrived') expect(Math.abs(lag), `+${extra} km/s`).toBeLessThan(m.zone / 0.0139 + 1);
      lags.push(lag);
    }
    // A miss is told by a lag of days, both ways: some launches find Mars still to come, some after it passed.
    expect(lags.length).toBeGreaterThanOrEqual(4);
    expect(lags.some((l) => l > 5) && lags.some((l) => l < -5)).toBe(true);
    expect(() => targetLag(forecastLaunch(world, handles, m, lesson.start, 1 / 24), 10_000, mars, mu)).toThrow(/pathDay: index/);
  });
});

describe('missionScore', () => {
  test('the tries part: SCORE_FIRST_TRY for the first launch, half for the second, a third for the third; in the total', () => {
    const m = MISSIONS[0]!;
    const first = missionScore(m, 3, 250);
    expect(first.tries).toBe(SCORE_FIRST_TRY);
    expect(missionScore(m, 3, 250, 2).tries).toBe(SCORE_FIRST_TRY / 2);
    expect(missionScore(m, 3, 250, 3).tries).toBe(Math.round(SCORE_FIRST_TRY / 3));
    expect(first.total).toBe(first.budget + first.time + first.tries);
    expect(() => missionScore(m, 3, 250, 0)).toThrow(/missionScore: launches must be a whole number >= 1, got 0/);
    expect(() => missionScore(m, 3, 250, 1.5)).toThrow(/missionScore: launches must be a whole number >= 1, got 1.5/);
  });
});

describe('orbitReach', () => {
  const mu = 2.959e-4;
  // A path straight out along +x from 1 AU to `far` AU, 50 points.
  const out = (far: number) => Float64Array.from({ length: 150 }, (_, k) => (k % 3 === 0 ? 1 + ((far - 1) * (k / 3)) / 49 : 0));
  test('a circle of 1.5 AU: a path out to 1.45 AU is short of it by 0.05 AU (reached within a zone of 0.06, not 0.04); out to 1.6 AU it got past', () => {
    const circle = [1.5, 0, 0, 0, 0, Math.sqrt(mu / 1.5)];
    const short = orbitReach(out(1.45), 50, circle, mu, 0.04, true);
    expect(short.reached).toBe(false);
    expect(short.r).toBeCloseTo(1.45, 12);
    expect(short.orbit).toBeCloseTo(1.5, 12);
    expect(orbitReach(out(1.45), 50, circle, mu, 0.06, true).reached).toBe(true);
    const past = orbitReach(out(1.6), 50, circle, mu, 0, true);
    expect([past.reached, past.r]).toEqual([true, expect.closeTo(1.6, 12)]);
    // Inwards, towards a circle of 0.8 AU, the same path (1 AU at its nearest) falls short by 0.2 AU.
    const inner = [0.8, 0, 0, 0, 0, Math.sqrt(mu / 0.8)];
    const fell = orbitReach(out(1.6), 50, inner, mu, 0.1, false);
    expect([fell.reached, fell.r, fell.orbit]).toEqual([false, expect.closeTo(1, 12), expect.closeTo(0.8, 12)]);
    expect(orbitReach(out(1.6), 0, inner, mu, 0.1, false)).toEqual({ reached: false, r: Number.NaN, orbit: Number.NaN });
  });

  test('an ellipse is read where the path goes, not at the target’s distance now: from aphelion (1.66 AU) a path out to 1.45 AU towards perihelion (1.38 AU) got past it', () => {
    // a (1 - e) = 1.38, a (1 + e) = 1.66: at aphelion, on -x, the speed sqrt(mu (1 - e) / Q) (vis-viva).
    const a = 1.52,
      e = 0.14 / 1.52,
      Q = a * (1 + e);
    const ellipse = [-Q, 0, 0, 0, -Math.sqrt((mu * (1 - e)) / Q), 0];
    const r = orbitReach(out(1.45), 50, ellipse, mu, 0, true);
    expect(r.reached).toBe(true);
    expect(r.orbit).toBeCloseTo(a * (1 - e), 9);
    expect(Math.hypot(ellipse[0]!, ellipse[1]!)).toBeGreaterThan(1.45);
  });

  test('rejects bad input, naming the function and the value', () => {
    const circle = [1.5, 0, 0, 0, 0, 0.01];
    expect(() => orbitReach(out(1.2), 51, circle, mu, 0, true)).toThrow(/orbitReach: points must be an integer in \[0, 50\], got 51/);
    expect(() => orbitReach(out(1.2), 1.5, circle, mu, 0, true)).toThrow(/orbitReach: points .* got 1.5/);
    expect(() => orbitReach(out(1.2), 50, circle, mu, -1, true)).toThrow(/orbitReach: zone must be finite and >= 0, got -1/);
  });
});
