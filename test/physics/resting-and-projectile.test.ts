import { addBody, addSegment, createPhysicsWorld, setBoundary, step, stepMany } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

describe('projectile under constant gravity', () => {
  /**
   * Free flight follows the exact parabola y(t) = y0 + v0 t - g t^2 / 2, x(t) = x0 + u0 t, under every
   * scheme and step: the world's constant gravity is integrated exactly (x += v h + g h^2 / 2, v += g h),
   * not with the scheme's O(h) or O(h^2) error. Tolerance 1e-9 m: rounding over up to 240 steps.
   */
  test('matches x(t), y(t) exactly under every scheme and step', () => {
    const g = 9.81;
    for (const integrator of [
      'semi-implicit-euler',
      'explicit-euler',
      'implicit-euler',
      'rk2',
      'rk4',
      'position-verlet',
      'velocity-verlet',
    ] as const) {
      for (const dt of [1 / 30, 1 / 60, 1 / 120]) {
        const world = createPhysicsWorld({ gravity: [0, -g], dt, integrator });
        const ball = addBody(world, { position: [1, 2], velocity: [3, 12] });
        const T = 2;
        const n = Math.round(T / dt);
        stepMany(world, n);
        const t = n * dt;
        const P = world.components.Position,
          V = world.components.Velocity;
        expect(Math.abs(P.x[ball]! - (1 + 3 * t))).toBeLessThan(1e-9);
        expect(Math.abs(V.y[ball]! - (12 - g * t))).toBeLessThan(1e-9);
        expect(Math.abs(P.y[ball]! - (2 + 12 * t - 0.5 * g * t * t))).toBeLessThan(1e-9);
      }
    }
  });
});

describe('resting contact', () => {
  /**
   * A ball set down on the floor must stay put: less than 1 mm of drift over 10 s, and no jitter (its
   * speed stays below 1 mm/s). The soft contact holds it where the spring force balances its weight:
   * m g / k of overlap, k = m_eff (2 pi f)^2 with f = 2 x 60 Hz against the static floor, about 0.02 mm.
   */
  for (const dimensions of [2, 3] as const) {
    test(`a ${dimensions}D ball on the boundary floor neither sinks nor jitters over 10 s`, () => {
      // Sleep off: this checks the contact solver itself (asleep, the ball could not move at all).
      const world = createPhysicsWorld({ dimensions, gravity: dimensions === 2 ? [0, -9.81] : [0, -9.81, 0], sleep: false });
      setBoundary(world, dimensions === 2 ? { min: [-5, 0], max: [5, 10] } : { min: [-5, 0, -5], max: [5, 10, 5] });
      const ball = addBody(world, { position: dimensions === 2 ? [0, 0.5] : [0, 0.5, 0], radius: 0.5, restitution: 0.5, friction: 0.3 });
      const P = world.components.Position,
        V = world.components.Velocity;
      let maxDrift = 0,
        maxSpeed = 0;
      for (let i = 0; i < 600; i++) {
        step(world);
        maxDrift = Math.max(maxDrift, Math.abs(P.y[ball]! - 0.5), Math.abs(P.x[ball]!), Math.abs(P.z[ball]!));
        if (i > 10) maxSpeed = Math.max(maxSpeed, Math.hypot(V.x[ball]!, V.y[ball]!, V.z[ball]!));
      }
      expect(maxDrift).toBeLessThan(1e-3);
      expect(maxSpeed).toBeLessThan(1e-3);
    });
  }

  test('a ball resting on an inclined segment with static friction above tan(theta) stays put', () => {
    // Slope of 20 degrees; mu = 0.6 > tan(20 deg) = 0.364, so static friction holds the ball if it
    // cannot roll: rotation off, the ball then behaves as a block on an incline.
    const world = createPhysicsWorld({ gravity: [0, -9.81], sleep: false });
    const theta = (20 * Math.PI) / 180;
    addSegment(world, {
      a: [-10 * Math.cos(theta), -10 * Math.sin(theta)],
      b: [10 * Math.cos(theta), 10 * Math.sin(theta)],
      friction: 0.6,
    });
    const nx = -Math.sin(theta),
      ny = Math.cos(theta);
    const ball = addBody(world, { position: [0.5 * nx, 0.5 * ny], radius: 0.5, friction: 0.6, rotates: false });
    const P = world.components.Position;
    stepMany(world, 600);
    expect(Math.hypot(P.x[ball]! - 0.5 * nx, P.y[ball]! - 0.5 * ny)).toBeLessThan(1e-3);
  });

  test('a block-like ball slides down a frictionless-enough incline with a = g (sin theta - mu_k cos theta)', () => {
    // 30 degrees, mu = 0.2 < tan(30) = 0.577: slides. Rotation off, so the contact behaves as a block.
    const g = 9.81,
      theta = Math.PI / 6,
      mu = 0.2;
    const world = createPhysicsWorld({ gravity: [0, -g], dt: 1 / 240 });
    addSegment(world, {
      a: [-100 * Math.cos(theta), 100 * Math.sin(theta)],
      b: [100 * Math.cos(theta), -100 * Math.sin(theta)],
      friction: mu,
    });
    const nx = Math.sin(theta),
      ny = Math.cos(theta);
    const ball = addBody(world, { position: [0.5 * nx, 0.5 * ny], radius: 0.5, friction: mu, rotates: false });
    const V = world.components.Velocity;
    stepMany(world, 480); // 2 s
    const speed = Math.hypot(V.x[ball]!, V.y[ball]!);
    const expected = g * (Math.sin(theta) - mu * Math.cos(theta)) * 2;
    // First-order time stepping and the solver's soft start: 1% of the 6.4 m/s reached.
    expect(Math.abs(speed - expected) / expected).toBeLessThan(0.01);
  });
});
