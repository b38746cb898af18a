// The submarine scene and the ballast law against Archimedes' balance, the terminal speed of
// quadratic drag (F = k v^2) and the hydrostatic trim balance; its vertical thrusters against the
// same speed law and the righting moment.

import { addBody, createPhysicsWorld, type PhysicsWorld, setBallast, setBallastTarget, setBodyThrust, step } from '@bitphysics/physics';
import {
  SUBMARINE,
  SUBMARINE_NEUTRAL_FILL,
  SUBMARINE_WATER_DENSITY,
  seabedHeight,
  setSubmarineThrusters,
  submarine,
} from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';

/** A submerged hull 40 m down with both tanks at `fill`. */
function submerged(fill: number): { world: PhysicsWorld; hull: number } {
  const world = createPhysicsWorld(submarine.worldOptions());
  const { hull } = submarine.build(world, { fill, position: [0, -40], count: 0 });
  return { world, hull };
}

function run(world: PhysicsWorld, seconds: number): void {
  for (let i = 0, n = Math.round(seconds / world.dt); i < n; i++) step(world);
}

describe('ballast and buoyancy (Archimedes)', () => {
  test('the neutral fill is where the hull weighs what it displaces', () => {
    // dryMass + 2 capacity f = rho L H: the analytic balance (0.7675 for this hull).
    const S = SUBMARINE;
    expect(S.dryMass + 2 * S.tankCapacity * SUBMARINE_NEUTRAL_FILL).toBeCloseTo(SUBMARINE_WATER_DENSITY * S.length * S.height, 6);
    const { world, hull } = submerged(SUBMARINE_NEUTRAL_FILL);
    const y0 = world.components.Position.y[hull]!;
    run(world, 30);
    // Neutral: no net force, so it stays where it was (to rounding of the balance, ~1e-9 m).
    expect(Math.abs(world.components.Position.y[hull]! - y0)).toBeLessThan(1e-6);
  });

  test('heavier than neutral it sinks, lighter it rises: v(t) = v_t tanh(a0 t / v_t), v_t = sqrt(dm g / k)', () => {
    // Extra water dm = +-0.05 * 2 * 20,000 kg = 2,000 kg: net weight dm g (mass m constant, tanks at
    // their target) against the drag k v^2 of the submerged hull. m dv/dt = dm g - k v^2 has the exact
    // solution v_t tanh(a0 t / v_t) with a0 = dm g / m. Semi-implicit Euler at 1/60 s: 1e-3 relative.
    for (const sign of [1, -1]) {
      const { world, hull } = submerged(SUBMARINE_NEUTRAL_FILL + sign * 0.05);
      world.components.Position.y[hull] = -400; // deep water: no surface or seabed in 30 s
      const m = world.components.Mass.value[hull]!,
        dW = 0.05 * 2 * SUBMARINE.tankCapacity * 9.81;
      run(world, 30);
      const vt = Math.sqrt(dW / SUBMARINE.dragCoefficient),
        a0 = dW / m;
      const expected = vt * Math.tanh((a0 * world.time) / vt);
      expect(Math.abs(-sign * world.components.Velocity.y[hull]! - expected) / expected).toBeLessThan(1e-3);
    }
  });

  test('the tanks fill at their rate and the mass follows', () => {
    const { world, hull } = submerged(0);
    setBallastTarget(world, hull, 1);
    run(world, 0.5); // fillRate (1 / s) for 0.5 s: half full
    const fill = SUBMARINE.fillRate * 0.5;
    expect(world.components.Ballast.fore[hull]).toBeCloseTo(fill, 9);
    expect(world.components.Mass.value[hull]).toBeCloseTo(SUBMARINE.dryMass + 2 * SUBMARINE.tankCapacity * fill, 6);
    expect(world.components.Mass.inv[hull]).toBeCloseTo(1 / world.components.Mass.value[hull]!, 15);
  });

  test('a held dive takes the surfaced boat 2 m under within 6 s', () => {
    // The game's Dive key raises the tanks' target by 0.5 a second; the tanks follow at fillRate. From
    // floating empty on a calm sea (the scene's start), the boat must be 2 m lower within 6 s: a player
    // sees it respond.
    const world = createPhysicsWorld(submarine.worldOptions());
    const { hull } = submarine.build(world, { seed: 1, count: 0 });
    world.components.FluidRegion.surface.fill(0);
    run(world, 2);
    const y0 = world.components.Position.y[hull]!;
    let target = 0,
      under = Infinity;
    for (let i = 1; i <= 6 * 60 && under === Infinity; i++) {
      target = Math.min(1, target + 0.5 / 60);
      setBallastTarget(world, hull, target, target);
      step(world);
      if (world.components.Position.y[hull]! < y0 - 2) under = i / 60;
    }
    expect(under).toBeLessThan(6);
  });

  test('vents open on the surface: 2 m under within 2.2 s, the tanks flooding at 1 a second', () => {
    // Both tanks' target set to full at once (vents open) on the boat floating empty on a calm sea.
    const world = createPhysicsWorld(submarine.worldOptions());
    const { hull } = submarine.build(world, { seed: 1, count: 0 });
    world.components.FluidRegion.surface.fill(0);
    run(world, 2);
    const y0 = world.components.Position.y[hull]!;
    setBallastTarget(world, hull, 1);
    let under = Infinity;
    for (let i = 1; i <= 6 * 60 && under === Infinity; i++) {
      step(world);
      if (world.components.Position.y[hull]! < y0 - 2) under = i / 60;
    }
    expect(under).toBeLessThan(2.2);
  });

  test('equal vertical thrusters heave the hull: v(t) = v_t tanh(a0 t / v_t), v_t = sqrt(2 T / k)', () => {
    // Neutral tanks 400 m down, both thrusters at +50 kN: m dv/dt = 2 T - k v^2 (no torque: the
    // pushes are equal and opposite about the centre), the same exact solution as the screw's.
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { fill: SUBMARINE_NEUTRAL_FILL, position: [0, -400], count: 0 });
    const T = SUBMARINE.thrusterForce;
    setSubmarineThrusters(h, T, T);
    run(world, 10);
    const m = world.components.Mass.value[h.hull]!;
    const vt = Math.sqrt((2 * T) / SUBMARINE.dragCoefficient),
      a0 = (2 * T) / m;
    const expected = vt * Math.tanh((a0 * world.time) / vt);
    expect(Math.abs(world.components.Velocity.y[h.hull]! - expected) / expected).toBeLessThan(1e-3);
    expect(Math.abs(world.components.Angle.value[h.hull]!)).toBeLessThan(1e-9);
    expect(Math.abs(world.components.Velocity.x[h.hull]!)).toBeLessThan(1e-9);
  });

  test('opposite vertical thrusters pitch the hull to sin(theta) = arm (F_fore - F_aft) / (M g GM)', () => {
    // Fore up 25 kN, aft down 25 kN: no net force, torque arm (F_fore - F_aft) = 4.5 m x 50 kN, nose
    // up, balanced by the righting moment M g GM sin(theta) (forces/ballast.ts): 7.9 degrees.
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { fill: SUBMARINE_NEUTRAL_FILL, position: [0, -400], count: 0 });
    const F = SUBMARINE.thrusterForce / 2;
    setSubmarineThrusters(h, F, -F);
    run(world, 40);
    const M = world.components.Mass.value[h.hull]!;
    const expected = Math.asin((SUBMARINE.thrusterArm * 2 * F) / (M * 9.81 * SUBMARINE.metacentricHeight));
    expect(world.components.Angle.value[h.hull]).toBeCloseTo(expected, 4);
    expect(Math.abs(world.components.Velocity.y[h.hull]!)).toBeLessThan(1e-6);
  });

  test('thrust along the hull: v(t) = v_t tanh(a0 t / v_t) towards v_t = sqrt(F / k)', () => {
    const { world, hull } = submerged(SUBMARINE_NEUTRAL_FILL);
    setBodyThrust(world, hull, [SUBMARINE.maxThrust, 0]);
    run(world, 40);
    // F = 400 kN, k = 2400 kg/m: v_t = 12.9 m/s; m dv/dt = F - k v^2 with m constant (neutral tanks).
    const m = world.components.Mass.value[hull]!;
    const vt = Math.sqrt(SUBMARINE.maxThrust / SUBMARINE.dragCoefficient),
      a0 = SUBMARINE.maxThrust / m;
    const expected = vt * Math.tanh((a0 * world.time) / vt);
    expect(Math.abs(world.components.Velocity.x[hull]! - expected) / expected).toBeLessThan(1e-3);
    expect(expected).toBeGreaterThan(0.95 * vt); // close to terminal by then
    expect(Math.abs(world.components.Velocity.y[hull]!)).toBeLessThan(1e-6);
  });

  test('unequal tanks trim the hull to tan(theta) = arm dm / (M GM)', () => {
    // Same total water as neutral, moved forward: fore 0.9, aft 2 * 0.7675 - 0.9 = 0.635. The fore
    // tank's extra weight (arm 4 m) balances the righting moment M g GM sin(theta) at cos(theta):
    // tan(theta) = 4 * 20,000 * (0.9 - 0.635) / (110,700 * 1.5) -> theta = -7.3 degrees (nose down).
    const aft = 2 * SUBMARINE_NEUTRAL_FILL - 0.9;
    const { world, hull } = submerged(SUBMARINE_NEUTRAL_FILL);
    setBallast(world, hull, {
      dryMass: SUBMARINE.dryMass,
      capacity: SUBMARINE.tankCapacity,
      fill: [0.9, aft],
      arm: SUBMARINE.tankArm,
      metacentricHeight: SUBMARINE.metacentricHeight,
    });
    run(world, 60);
    const M = world.components.Mass.value[hull]!;
    const expected = -Math.atan((SUBMARINE.tankArm * SUBMARINE.tankCapacity * (0.9 - aft)) / (M * SUBMARINE.metacentricHeight));
    expect(world.components.Angle.value[hull]).toBeCloseTo(expected, 4);
  });

  test('floats at the surface with the draft rho L d = m', () => {
    const world = createPhysicsWorld(submarine.worldOptions());
    const { hull } = submarine.build(world);
    run(world, 30);
    const draft = SUBMARINE.dryMass / (SUBMARINE_WATER_DENSITY * SUBMARINE.length);
    expect(world.components.Position.y[hull]).toBeCloseTo(SUBMARINE.height / 2 - draft, 3);
  });

  test('lays the first beacon close and shallow, the others over the course between the seabed and the surface', () => {
    for (const seed of [1, 2, 3, 4, 5, 6]) {
      const h = submarine.build(createPhysicsWorld(submarine.worldOptions()), { seed, count: 8 });
      const b = h.beacons;
      expect(b[0]!).toBeGreaterThanOrEqual(55);
      expect(b[0]!).toBeLessThanOrEqual(75);
      expect(b[1]!).toBeGreaterThanOrEqual(-28);
      expect(b[1]!).toBeLessThanOrEqual(-15);
      for (let i = 1; i < 8; i++) {
        const x = b[2 * i]!,
          y = b[2 * i + 1]!;
        expect(x).toBeGreaterThanOrEqual(100);
        expect(x).toBeLessThanOrEqual(1000);
        expect(x).toBeGreaterThan(b[2 * i - 2]!); // in order along the course
        expect(y).toBeLessThanOrEqual(-10);
        expect(y).toBeGreaterThanOrEqual(seabedHeight(h.seabed, x) + 8);
      }
    }
  });

  test('bad input is refused and leaves the body as it was', () => {
    const world = createPhysicsWorld({ gravity: [0, -9.81] });
    const b = addBody(world, { mass: 3 });
    expect(() => setBallast(world, b, { dryMass: 0, capacity: 1 })).toThrow(/setBallast: dryMass must be/);
    expect(() => setBallast(world, b, { dryMass: 1, capacity: 1, fill: 2 })).toThrow(/setBallast: fill must be/);
    expect(() => setBallastTarget(world, b, 0.5)).toThrow(/setBallastTarget: entity \d+ has no ballast/);
    expect(() => setBodyThrust(world, b, [1, Number.NaN])).toThrow(/setBodyThrust: force/);
    const sea = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(sea, { count: 0 });
    expect(() => setSubmarineThrusters(h, 1.01 * SUBMARINE.thrusterForce, 0)).toThrow(/setSubmarineThrusters: fore and aft must be within/);
    expect(() => setSubmarineThrusters(h, 0, Number.NaN)).toThrow(/setSubmarineThrusters: aft/);
    expect([...h.thrusters]).toEqual([0, 0]);
    expect(world.components.Mass.value[b]).toBe(3);
  });
});
