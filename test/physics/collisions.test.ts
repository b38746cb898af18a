import { addBody, addSegment, kineticEnergy, linearMomentum, stepMany } from '@bitphysics/physics';
import fc from 'fast-check';
import { describe, expect, test } from 'vitest';
import { zeroGravityWorld } from './helpers';

/**
 * Two-body collisions against the textbook results (Ramtal and Dobre ch. 11; any mechanics text):
 * momentum is conserved; a perfectly elastic collision conserves kinetic energy; the normal relative
 * velocity is reversed and scaled by the restitution; the tangential velocities are untouched when
 * the surfaces are frictionless. Tolerance 1e-12 relative: the solver computes these impulses in
 * closed form for an isolated pair, so only rounding separates it from the exact answer.
 */
describe('two-body collisions', () => {
  const rel = (a: number, b: number) => Math.abs(a - b) / Math.max(1, Math.abs(b));

  test('1D elastic collision conserves momentum and kinetic energy and matches the exact velocities', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: 1, max: 20, noNaN: true }),
        fc.double({ min: -20, max: -1, noNaN: true }),
        (m1, m2, u1, u2) => {
          const world = zeroGravityWorld();
          const a = addBody(world, { position: [0, 0], velocity: [u1, 0], mass: m1, radius: 0.5, restitution: 1, friction: 0 });
          const b = addBody(world, { position: [1.5, 0], velocity: [u2, 0], mass: m2, radius: 0.5, restitution: 1, friction: 0 });
          const p0 = linearMomentum(world)[0]!,
            k0 = kineticEnergy(world);
          stepMany(world, 20);
          const V = world.components.Velocity;
          expect(rel(linearMomentum(world)[0]!, p0)).toBeLessThan(1e-12);
          expect(rel(kineticEnergy(world), k0)).toBeLessThan(1e-12);
          // v1' = ((m1 - m2) u1 + 2 m2 u2) / (m1 + m2), v2' = ((m2 - m1) u2 + 2 m1 u1) / (m1 + m2)
          expect(rel(V.x[a]!, ((m1 - m2) * u1 + 2 * m2 * u2) / (m1 + m2))).toBeLessThan(1e-12);
          expect(rel(V.x[b]!, ((m2 - m1) * u2 + 2 * m1 * u1) / (m1 + m2))).toBeLessThan(1e-12);
        },
      ),
      { numRuns: 50, seed: 7 },
    );
  });

  test('2D elastic oblique collision conserves momentum and kinetic energy', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: -0.9, max: 0.9, noNaN: true }),
        fc.double({ min: 1, max: 20, noNaN: true }),
        (m1, m2, offset, speed) => {
          const world = zeroGravityWorld();
          addBody(world, { position: [-2, offset], velocity: [speed, 0], mass: m1, radius: 0.5, restitution: 1, friction: 0 });
          addBody(world, { position: [0, 0], velocity: [0, 0], mass: m2, radius: 0.5, restitution: 1, friction: 0 });
          const p0 = linearMomentum(world),
            k0 = kineticEnergy(world);
          const px = p0[0]!,
            py = p0[1]!;
          stepMany(world, 60);
          const p1 = linearMomentum(world);
          expect(Math.abs(p1[0]! - px) / (m1 * speed)).toBeLessThan(1e-12);
          expect(Math.abs(p1[1]! - py) / (m1 * speed)).toBeLessThan(1e-12);
          expect(rel(kineticEnergy(world), k0)).toBeLessThan(1e-12);
        },
      ),
      { numRuns: 50, seed: 11 },
    );
  });

  test('inelastic collision scales the normal relative velocity by the restitution', () => {
    for (const e of [0, 0.25, 0.5, 0.9]) {
      const world = zeroGravityWorld();
      // Oblique: centres offset by 0.6 m across the line of motion.
      const a = addBody(world, { position: [-2, 0.6], velocity: [6, 0], mass: 2, radius: 0.5, restitution: e, friction: 0 });
      const b = addBody(world, { position: [0, 0], velocity: [-1, 0], mass: 3, radius: 0.5, restitution: e, friction: 0 });
      const P = world.components.Position,
        V = world.components.Velocity;
      // The normal at impact: where the centres are when they first touch (straight-line motion before).
      // Relative motion along x at 7 m/s with vertical offset 0.6: touching when dx = -sqrt(1 - 0.36) = -0.8.
      const nx = 0.8,
        ny = -0.6; // from a to b
      const vn0 = (V.x[b]! - V.x[a]!) * nx + (V.y[b]! - V.y[a]!) * ny;
      const vt0 = (V.x[b]! - V.x[a]!) * -ny + (V.y[b]! - V.y[a]!) * nx;
      stepMany(world, 40);
      const vn1 = (V.x[b]! - V.x[a]!) * nx + (V.y[b]! - V.y[a]!) * ny;
      const vt1 = (V.x[b]! - V.x[a]!) * -ny + (V.y[b]! - V.y[a]!) * nx;
      expect(vn0).toBeLessThan(0);
      expect(Math.abs(vn1 - -e * vn0)).toBeLessThan(1e-12 * Math.abs(vn0));
      expect(Math.abs(vt1 - vt0)).toBeLessThan(1e-12 * Math.abs(vn0));
      void P;
    }
  });

  test('equal-mass oblique elastic collision with a ball at rest leaves perpendicular velocities', () => {
    for (const offset of [0.2, 0.5, 0.8]) {
      const world = zeroGravityWorld();
      const a = addBody(world, { position: [-3, offset], velocity: [5, 0], mass: 1, radius: 0.5, restitution: 1, friction: 0 });
      const b = addBody(world, { position: [0, 0], mass: 1, radius: 0.5, restitution: 1, friction: 0 });
      stepMany(world, 60);
      const V = world.components.Velocity;
      const dot = V.x[a]! * V.x[b]! + V.y[a]! * V.y[b]!;
      expect(Math.abs(dot) / 25).toBeLessThan(1e-12);
      expect(Math.hypot(V.x[b]!, V.y[b]!)).toBeGreaterThan(0.1);
    }
  });

  test('3D sphere collisions conserve momentum and kinetic energy; the normal velocity scales by restitution', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: 0.1, max: 10, noNaN: true }),
        fc.double({ min: -0.6, max: 0.6, noNaN: true }),
        fc.double({ min: -0.6, max: 0.6, noNaN: true }),
        fc.constantFrom(0.3, 1),
        (m1, m2, oy, oz, e) => {
          const world = zeroGravityWorld(3);
          const a = addBody(world, { position: [-3, oy, oz], velocity: [8, 0, 0], mass: m1, radius: 0.5, restitution: e, friction: 0 });
          const b = addBody(world, { position: [0, 0, 0], velocity: [-1, 0, 0], mass: m2, radius: 0.5, restitution: e, friction: 0 });
          const p0 = Array.from(linearMomentum(world)),
            k0 = kineticEnergy(world);
          // Normal at first touch: relative motion along x, offset (oy, oz).
          const d = Math.sqrt(1 - oy * oy - oz * oz);
          const n = [d, -oy, -oz];
          const V = world.components.Velocity;
          const vrel = () => [V.x[b]! - V.x[a]!, V.y[b]! - V.y[a]!, V.z[b]! - V.z[a]!];
          const dot = (u: number[], v: number[]) => u[0]! * v[0]! + u[1]! * v[1]! + u[2]! * v[2]!;
          const vn0 = dot(vrel(), n);
          stepMany(world, 40);
          const p1 = linearMomentum(world);
          for (let i = 0; i < 3; i++) expect(Math.abs(p1[i]! - p0[i]!) / (8 * m1)).toBeLessThan(1e-12);
          expect(Math.abs(dot(vrel(), n) + e * vn0)).toBeLessThan(1e-10 * Math.abs(vn0));
          if (e === 1) expect(rel(kineticEnergy(world), k0)).toBeLessThan(1e-12);
        },
      ),
      { numRuns: 40, seed: 3 },
    );
  });

  test('a ball hitting the end point of a segment bounces off the point, along the line through it', () => {
    // Segment ends at (0, 0); the ball comes from the right heading left, 0.3 m below the segment's
    // line: it meets the end point itself, whose normal points from (0,0) to the ball's centre.
    const world = zeroGravityWorld();
    addSegment(world, { a: [-5, 0], b: [0, 0], restitution: 1, friction: 0 });
    const ball = addBody(world, { position: [3, -0.3], velocity: [-6, 0], radius: 0.5, restitution: 1, friction: 0 });
    stepMany(world, 60);
    const V = world.components.Velocity;
    // At contact the centre is at (sqrt(0.25 - 0.09), -0.3) = (0.4, -0.3): n = (0.8, -0.6).
    // Reflection of (-6, 0) about n: v - 2 (v . n) n = (-6, 0) + 9.6 (0.8, -0.6) = (1.68, -5.76).
    expect(V.x[ball]!).toBeCloseTo(1.68, 10);
    expect(V.y[ball]!).toBeCloseTo(-5.76, 10);
  });
});
