import {
  addBody,
  addElectricField,
  addFluidRegion,
  addMagneticField,
  addSpring,
  createPhysicsWorld,
  setBuoyancy,
  setCharge,
  setElectricField,
  setFluidRegion,
  setMagneticField,
  setSpring,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Setters for field, region and spring entities change the physics at run time without writes to
 * raw stores. Each is checked against a closed form that holds exactly (to rounding) for the
 * world's default semi-implicit Euler scheme: under a constant force F over n steps of h,
 * v = F n h / m exactly, because the velocity update is v += (F / m) h.
 */
describe('field and region setters', () => {
  test('setElectricField moves the field: a charge at rest accelerates along the new E (v = q E t / m)', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 0.01 });
    const q = 2,
      m = 0.5;
    const p = addBody(world, { mass: m });
    setCharge(world, p, q);
    const field = addElectricField(world, { field: [3, 0] });
    stepMany(world, 10);
    const V = world.components.Velocity,
      s = slotOf(p);
    // 0.1 s at a = q E / m = 12 m/s^2 along x.
    expect(V.x[s]).toBeCloseTo(((q * 3) / m) * 0.1, 12);
    expect(V.y[s]).toBe(0);
    setElectricField(world, field, { field: [0, -5] });
    stepMany(world, 10);
    expect(V.x[s]).toBeCloseTo(((q * 3) / m) * 0.1, 12); // unchanged: E has no x part now
    expect(V.y[s]).toBeCloseTo(((q * -5) / m) * 0.1, 12);
  });

  test('setMagneticField flips B: the cyclotron rotation reverses, at omega = q B / m, speed unchanged', () => {
    // A charge in a uniform B_z turns its velocity at omega = -q B / m (rad/s; counter-clockwise for q B < 0).
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3 });
    const q = 1,
      m = 1,
      B = 2;
    const p = addBody(world, { mass: m, velocity: [1, 0] });
    setCharge(world, p, q);
    const field = addMagneticField(world, { field: B });
    const V = world.components.Velocity,
      s = slotOf(p);
    const angle = () => Math.atan2(V.y[s]!, V.x[s]!);
    stepMany(world, 100); // 0.1 s
    const turned = angle();
    // Exact rotation -q B t / m = -0.2 rad; the explicit Lorentz update is first order: O(omega h) = 0.2 % relative here.
    expect(turned).toBeCloseTo((-q * B * 0.1) / m, 3);
    setMagneticField(world, field, { field: -B });
    stepMany(world, 100);
    // Turned back by the same angle: the sense reversed.
    expect(angle()).toBeCloseTo(0, 3);
    // A magnetic force does no work: the speed stays 1 m/s to the scheme's first-order drift (h omega)^2 per step.
    expect(Math.hypot(V.x[s]!, V.y[s]!)).toBeCloseTo(1, 3);
  });

  test('setFluidRegion doubles the density: a neutrally buoyant ball rises at a = g (rho_f / rho_b - 1) = g', () => {
    const world = createPhysicsWorld({ gravity: [0, -10], dt: 0.01 });
    const r = 0.5,
      rhoBody = 1000;
    const ball = addBody(world, { position: [0, -5], mass: rhoBody * Math.PI * r * r }); // 2D: mass = rho pi r^2
    setBuoyancy(world, ball, { shape: 'ball', radius: r });
    const water = addFluidRegion(world, { surface: 0, density: 1000 });
    stepMany(world, 20);
    const V = world.components.Velocity,
      s = slotOf(ball);
    // Archimedes: buoyancy rho_f A g balances the weight rho_b A g exactly.
    expect(Math.abs(V.y[s]!)).toBeLessThan(1e-9);
    setFluidRegion(world, water, { density: 2000 });
    stepMany(world, 10);
    expect(V.y[s]).toBeCloseTo(10 * 0.1, 9); // still fully under: constant net force m g upward
    expect(() => setFluidRegion(world, water, { xRange: [1, 0] })).toThrow(/setFluidRegion: xRange\[1\] must be > xRange\[0\]/);
    expect(world.components.FluidRegion.minX[slotOf(water)]).toBe(-Infinity); // the refused call changed nothing
  });

  test('setSpring changes stiffness, rest length and anchor: one step gives v = -(k / m) x h', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 0.01 });
    const m = 2;
    const b = addBody(world, { position: [1, 0], mass: m });
    const spring = addSpring(world, { anchor: [0, 0], b, stiffness: 10, restLength: 0 });
    const V = world.components.Velocity,
      s = slotOf(b);
    step(world);
    expect(V.x[s]).toBeCloseTo(-(10 / m) * 1 * 0.01, 12);
    setSpring(world, spring, { stiffness: 40, anchor: [world.components.Position.x[s]!, 1] });
    const vx0 = V.x[s]!,
      vy0 = V.y[s]!;
    step(world);
    // The anchor is now 1 m straight above: the force is along +y only, k y = 40 N.
    expect(V.x[s]).toBeCloseTo(vx0, 12);
    expect(V.y[s]! - vy0).toBeCloseTo((40 / m) * 1 * 0.01, 9);
    expect(() => setSpring(world, spring, { oneSided: 'false' as never })).toThrow(/setSpring: oneSided must be a boolean, got "false"/);
    const two = addSpring(world, { a: b, b: addBody(world, { position: [3, 0] }), stiffness: 1 });
    expect(() => setSpring(world, two, { anchor: [0, 0] })).toThrow(/setSpring: anchor is only for a spring with a fixed end/);
  });
});
