/**
 * Three stars from the solar system's second mission want a centred launch (games/solar-system/
 * aim-depth.ts skillStars, aimRings), and the line before the launch names the stars an arrival
 * earns (./meeting-words.ts forecastWords): at Venus's launch window every speed from 2.3 to 2.9
 * km/s arrives, and the speed alone gave each three stars, so any launch won.
 */

import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { solarSystem } from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';
import { burnPressSize } from '../../games/solar-system/advice';
import { aimRings, STAR_RINGS, skillStars } from '../../games/solar-system/aim-depth';
import { forecastLaunch } from '../../games/solar-system/forecast';
import { forecastWords } from '../../games/solar-system/meeting-words';
import { BURN_STEP, heliocentricState, MISSIONS, missionTimeStep, starsFor } from '../../games/solar-system/missions';
import { nextLaunchWindow } from '../../games/solar-system/wait-pace';

describe('skill stars', () => {
  test('the rule: the lesson keeps the speed’s stars; from mission 2 three want a centred aim and no burn', () => {
    const venus = MISSIONS[1]!;
    expect(skillStars(0, MISSIONS[0]!, MISSIONS[0]!.stars3, 0.9, 2)).toBe(3);
    expect(skillStars(1, venus, venus.stars3, STAR_RINGS, 0)).toBe(3);
    expect(skillStars(1, venus, venus.stars3, STAR_RINGS + 0.01, 0)).toBe(2);
    expect(skillStars(1, venus, venus.stars3 - 0.2, 0.1, 1)).toBe(2);
    expect(skillStars(1, venus, venus.stars2 + 0.1, 0.1, 0)).toBe(1);
    expect(() => skillStars(1, venus, 2, Number.NaN, 0)).toThrow(/rings/);
  });

  test('Venus at its launch window, speeds 2.3 to 3.1 km/s: every arrival reads ✓ with the stars it earns, three only where centred', () => {
    const options = { stepHours: 1, integrator: 'rk4' as const, date: '2012-01-01T00:00:00Z' };
    const world = createPhysicsWorld(solarSystem.worldOptions(options));
    const handles = solarSystem.build(world, options);
    const m = MISSIONS[1]!;
    const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
    const earth = [...heliocentricState(world, handles, handles.bodies.Earth)];
    const venus = [...heliocentricState(world, handles, handles.bodies.Venus)];
    const win = nextLaunchWindow(earth, venus, mu, { next: 0, period: 0 });
    const dt = missionTimeStep(m, 1 / 24);
    for (let k = Math.round(win.next / dt); k > 0; k--) step(world);
    const target = [...heliocentricState(world, handles, handles.bodies.Venus)];
    let arrived = 0,
      oldThree = 0,
      three = 0;
    for (let tenths = 23; tenths <= 31; tenths++) {
      const aim = { angle: 180, speed: tenths / 10 };
      const f = forecastLaunch(world, handles, m, aim, 1 / 24);
      const rings = aimRings(world, handles, m, aim);
      const s = skillStars(1, m, aim.speed, rings, 0);
      const stars = '★'.repeat(s);
      const [words] = forecastWords('Venus', f, m.zone, target, stars);
      const what = `${aim.speed} km/s: ${words}, ${f.outcome}, aim ${rings.toFixed(2)} rings`;
      // The ✓ is the forecast's arrival (the flight's rule), and it names the stars the launch earns.
      expect(words.startsWith('✓'), what).toBe(f.outcome === 'arrived');
      if (f.outcome !== 'arrived') continue;
      expect(words, what).toBe(`✓ Venus will be there · ${stars}`);
      arrived++;
      if (starsFor(m, aim.speed) === 3) oldThree++;
      if (s === 3) three++;
    }
    // A cheap arrival earns three stars only when centred: fewer than the speed alone would give.
    expect(arrived).toBeGreaterThan(2);
    expect(three).toBeLessThan(oldThree);
  });

  test('a press of the advised burn’s key makes the whole burn the hint worked out; other presses one step', () => {
    const advice = { kind: 'burn' as const, direction: 'faster' as const, presses: 17 };
    // Mercury's "Press ↑ 17 times now": one press, 0.85 km/s (before: 17 presses of 0.05 km/s).
    expect(burnPressSize(advice, 'faster', true)).toBeCloseTo(17 * BURN_STEP, 12);
    expect(burnPressSize(advice, 'slower', true)).toBe(BURN_STEP);
    expect(burnPressSize(advice, 'faster', false)).toBe(BURN_STEP);
    expect(burnPressSize({ ...advice, kind: 'coast' }, 'faster', true)).toBe(BURN_STEP);
  });
});
