/**
 * The solar system's coarse words before a launch from the second mission on
 * (games/solar-system/meeting-words.ts forecastWords): they follow the real flight's closest approach
 * (the forecast flies the flight's own physics, ./forecast.ts), so "close" is a hit or a near miss
 * and "behind" / "ahead" the target's side when the probe comes nearest. Read from the target's lag
 * where the probe crossed its orbit, "close" once hit and once missed Venus by 0.28 AU, and "a
 * little ahead" missed it by 1.25 AU.
 */

import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { solarSystem } from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';
import { aimRings } from '../../games/solar-system/aim-depth';
import { forecastLaunch } from '../../games/solar-system/forecast';
import { CLOSE_RINGS, FAR_RINGS, forecastWords } from '../../games/solar-system/meeting-words';
import { heliocentricState, MISSIONS, missionTimeStep } from '../../games/solar-system/missions';
import { targetLag } from '../../games/solar-system/orbit-crossing';

describe('forecastWords', () => {
  test('Venus, for launches over 600 days at many speeds and angles (170° to 190°): the band is the real closest approach’s, the side the target’s then', () => {
    const options = { stepHours: 1, integrator: 'rk4' as const, date: '2012-01-01T00:00:00Z' };
    const world = createPhysicsWorld(solarSystem.worldOptions(options));
    const handles = solarSystem.build(world, options);
    const m = MISSIONS[1]!;
    const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
    const dt = missionTimeStep(m, 1 / 24);
    const bands = { close: 0, little: 0, far: 0 };
    let checked = 0;
    for (let day = 0; day < 600; day += 100) {
      const target = [...heliocentricState(world, handles, handles.bodies.Venus)];
      for (const angle of [170, 180, -170])
        for (const speed of [2.4, 2.8, 3.3]) {
          const f = forecastLaunch(world, handles, m, { angle, speed }, 1 / 24);
          if (f.outcome === 'sun') continue;
          const depth = aimRings(world, handles, m, { angle, speed });
          const [words, cls] = forecastWords('Venus', f, m.zone, target, depth);
          const rings = f.outcome === 'arrived' ? depth : f.closest / m.zone;
          const what = `day ${day}, ${angle}°, ${speed} km/s: ${words}, closest ${rings.toFixed(2)} rings`;
          expect(cls).toBe('edge');
          // The band is the closest approach's (an arrival's: the aim's centredness, its forecast
          // stopping at the ring's edge): exact thresholds, no tolerance (both read the same numbers).
          const band = rings <= CLOSE_RINGS ? 'close' : rings <= FAR_RINGS ? 'little' : 'far';
          bands[band]++;
          expect(words, what).toBe(
            band === 'close'
              ? 'Venus will be close'
              : `Venus will be ${band === 'far' ? 'far' : 'a little'} ${/behind/.test(words) ? 'behind' : 'ahead'}`,
          );
          // "Close" is an arrival: a launch on it reaches the ring.
          if (band === 'close') expect(f.outcome, what).toBe('arrived');
          // The side agrees with the days Venus (on its Kepler orbit) reaches the probe's place at the
          // closest approach, when that is over a day either way (a nearer call is on the edge).
          if (band !== 'close' && !f.closestAtLaunch) {
            const lag = targetLag(f, f.pointsToClosest - 1, target, mu);
            if (Math.abs(lag) > 1) expect(words, `${what}, lag ${lag.toFixed(1)} d`).toContain(lag > 0 ? 'behind' : 'ahead');
          }
          checked++;
        }
      for (let k = Math.round(100 / dt); k > 0; k--) step(world);
    }
    // The aims span every band ("close", a centred arrival, is the rarest: 2 of 54 on this grid).
    expect(checked).toBeGreaterThan(40);
    for (const n of Object.values(bands)) expect(n).toBeGreaterThan(1);
  });
});
