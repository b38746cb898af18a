// The solar-system scene against the ephemeris it starts from (astronomy-engine): the book's closing
// project, graded by the issue's goal (every planet within 1.5 times the point-mass floor after one
// year from 2012-01-01 with RK4 at 1 h).

import { createPhysicsWorld, type IntegratorName, linearMomentum, type PhysicsWorld, step } from '@bitphysics/physics';
import { SOLAR_SYSTEM_BODIES, SOLAR_SYSTEM_PLANETS, type SolarSystemHandles, solarSystem, solarSystemErrors } from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';

/**
 * The floor a point-mass model of these nine bodies reaches against astronomy-engine after one year
 * from 2012-01-01, as stated in the issue (measured independently of this code): the bar is 1.5 times it.
 * The outer planets are "below 2e-5".
 */
const ISSUE_FLOOR: Record<string, number> = {
  Mercury: 2.8e-3,
  Venus: 1.1e-4,
  Earth: 1.6e-4,
  Mars: 2.4e-4,
  Jupiter: 2e-5,
  Saturn: 2e-5,
  Uranus: 2e-5,
  Neptune: 2e-5,
};

function run(
  integrator: IntegratorName,
  stepHours: number,
  days: number,
): { world: PhysicsWorld; handles: SolarSystemHandles; errors: Float64Array } {
  const world = createPhysicsWorld(solarSystem.worldOptions({ integrator, stepHours }));
  const handles = solarSystem.build(world);
  const n = Math.round((days * 24) / stepHours);
  for (let i = 0; i < n; i++) step(world);
  return { world, handles, errors: solarSystemErrors(world, handles) };
}

describe('solar-system scene', () => {
  test('starts on the ephemeris: every planet error is rounding at t = 0', () => {
    const world = createPhysicsWorld(solarSystem.worldOptions());
    const handles = solarSystem.build(world);
    expect(handles.ids.length).toBe(SOLAR_SYSTEM_BODIES.length);
    // Same ephemeris call, same rotation: only the subtraction of the Sun rounds (1e-16 relative).
    for (const e of solarSystemErrors(world, handles)) expect(e).toBeLessThan(1e-13);
  });

  test('one year from 2012-01-01 with RK4 at 1 h: every planet within 1.5 times the point-mass floor', () => {
    const { world, handles, errors } = run('rk4', 1, 366);
    expect(world.time).toBeCloseTo(366, 9);
    const report = SOLAR_SYSTEM_PLANETS.map((p, i) => `${p} ${errors[i]!.toExponential(2)}`).join(', ');
    SOLAR_SYSTEM_PLANETS.forEach((p, i) => {
      expect(errors[i], `${p}: ${report}`).toBeLessThanOrEqual(1.5 * ISSUE_FLOOR[p]!);
    });
    // Momentum conservation: the pair sum obeys Newton's third law, so total momentum (zero at the
    // barycentric start, up to the ephemeris' own imbalance) stays where it was to rounding.
    const p = linearMomentum(world);
    const world0 = createPhysicsWorld(solarSystem.worldOptions());
    solarSystem.build(world0);
    const p0 = linearMomentum(world0);
    expect(Math.hypot(p[0]! - p0[0]!, p[1]! - p0[1]!, p[2]! - p0[2]!)).toBeLessThan(1e-15);
    expect(handles.epoch).toBe(Date.UTC(2012, 0, 1));
  });

  test('the bar can fail: semi-implicit Euler at 1 day misses it for Mercury and Venus', () => {
    // First order at 366 steps a year: Mercury's orbit (88 days) is far from converged (measured ~0.2).
    const { errors } = run('semi-implicit-euler', 24, 366);
    expect(errors[0]).toBeGreaterThan(1.5 * ISSUE_FLOOR.Mercury!);
    expect(errors[1]).toBeGreaterThan(1.5 * ISSUE_FLOOR.Venus!);
  });

  test('bad options are refused with the function and parameter named', () => {
    expect(() => solarSystem.worldOptions({ stepHours: 0 })).toThrow(/solarSystem.worldOptions: stepHours must be/);
    expect(() => solarSystem.worldOptions({ integrator: 'leapfrog' as IntegratorName })).toThrow(/integrator must be one of/);
    const world = createPhysicsWorld(solarSystem.worldOptions());
    expect(() => solarSystem.build(world, { date: 'yesterday' })).toThrow(/solarSystem.build: date must be a valid date/);
    expect(() => solarSystem.build(world, { count: 3 })).toThrow(/count must be 9/);
    expect(world.entityIndex.aliveCount).toBe(0);
    expect(() => solarSystem.build(createPhysicsWorld({ dimensions: 2 }))).toThrow(/needs a 3D world/);
  });
});
