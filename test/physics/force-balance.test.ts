import { addBody, addFluidRegion, addSpring, createPhysicsWorld, setBuoyancy, stepMany } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

// A body whose weight another force balances exactly must stay where it is with v = 0 under every
// scheme: the exact-free-fall correction (-g h / 2 on the drift) belongs to bodies no force acts on.
// Before that rule, semi-implicit Euler moved a floating body g h^2 / 2 a step (2.45 m in 30 s).
const SCHEMES = ['semi-implicit-euler', 'explicit-euler', 'implicit-euler', 'rk2', 'rk4', 'position-verlet', 'velocity-verlet'] as const;
// Tolerance: rounding only. Buoyancy and weight cancel to within a few ulps of m g, so over 1,800
// steps the position may move by ~1e-12 m; anything systematic is g h^2 / 2 = 1.4e-3 m a step.
const TOL = 1e-9;

describe('force balance: a body at equilibrium stays exactly at rest', () => {
  for (const integrator of SCHEMES) {
    test(`a floating box (buoyancy = weight) stays put under ${integrator}`, () => {
      const g = 9.81;
      const world = createPhysicsWorld({ gravity: [0, -g], dt: 1 / 60, integrator });
      addFluidRegion(world, { surface: 0, density: 1000 });
      // Box 1 m x 0.6 m of density 500 kg/m^2: half its height under water, centre on the surface.
      const b = addBody(world, { position: [0, 0], mass: 500 * 0.6 });
      setBuoyancy(world, b, { shape: 'box', halfExtents: [0.5, 0.3], dragCoefficient: 0 });
      stepMany(world, 60 * 30);
      expect(Math.abs(world.components.Position.y[b]!)).toBeLessThan(TOL);
      expect(Math.abs(world.components.Velocity.y[b]!)).toBeLessThan(TOL);
    });

    test(`a spring hanging at its equilibrium stretch m g / k stays put under ${integrator}`, () => {
      const g = 9.81,
        m = 2,
        k = 100,
        L0 = 1;
      const world = createPhysicsWorld({ gravity: [0, -g], dt: 1 / 60, integrator });
      const y0 = -(L0 + (m * g) / k);
      const bob = addBody(world, { position: [0, y0], mass: m });
      addSpring(world, { anchor: [0, 0], b: bob, stiffness: k, restLength: L0 });
      stepMany(world, 60 * 30);
      expect(Math.abs(world.components.Position.y[bob]! - y0)).toBeLessThan(TOL);
      expect(Math.abs(world.components.Velocity.y[bob]!)).toBeLessThan(TOL);
    });
  }
});
