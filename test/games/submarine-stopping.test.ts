/**
 * The submarine's speed control (games/submarine/helm.ts), headless on a calm sea: how far the boat
 * runs on from full ahead (steady at HELM.topSpeed) when Ahead is let go and when Astern is held,
 * against the distance a boat slowed by the water's drag k u^2 alone would glide (an independent
 * bound: the integral of m / (k u) du, infinite, so over a fixed 10 s it is m / k ln(1 + k u0 t / m)).
 * A stranger passed beacons because the boat ran on: let go it must stop within a hull's length,
 * and Astern (the brake) within a fifth of one.
 */

import { createPhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { coastDistance, createHelmState, HELM, type HelmInput, NO_INPUT, steer } from '../../games/submarine/helm';

/** A neutrally trimmed boat hovering 30 m down on a calm sea over open water (no seabed within reach), and its helm. */
function calmBoat() {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -30] });
  world.components.FluidRegion.surface.fill(0);
  h.seabed.y.fill(-1000);
  return { world, h, helm: createHelmState(SUBMARINE_NEUTRAL_FILL) };
}

/** A boat hovering 30 m down on a calm sea over open water, run at full ahead until steady; its stop under `input`. */
function stopFromFullAhead(input: Partial<HelmInput>): { distance: number; time: number; mass: number } {
  const { world, h, helm } = calmBoat();
  const c = world.components,
    e = h.hull;
  const run = (inp: Partial<HelmInput>, seconds: number, each?: (t: number) => boolean) => {
    for (let i = 1; i <= Math.round(seconds / world.dt); i++) {
      steer(world, h, { ...NO_INPUT, ...inp }, helm);
      step(world);
      if (each?.(i * world.dt)) return;
    }
  };
  run({}, 2);
  run({ ahead: true }, 12);
  expect(c.Velocity.x[e]!).toBeGreaterThan(0.97 * HELM.topSpeed);
  const x0 = c.Position.x[e]!,
    mass = c.Mass.value[e]!;
  let time = Number.NaN;
  run(input, 10, (t) => {
    if (c.Velocity.x[e]! > 0.05) return false;
    time = t;
    return true;
  });
  return { distance: c.Position.x[e]! - x0, time, mass };
}

describe('submarine speed control', () => {
  it('from full ahead (8 m/s): let go, stopped within 6 m and 2 s; Astern held, within 2.5 m and 0.7 s (3.0 m and 0.75 s before the Astern brake)', () => {
    const free = stopFromFullAhead({});
    const astern = stopFromFullAhead({ astern: true });
    // Drag alone over 10 s from 8 m/s: m / k ln(1 + k u0 t / m), tens of metres.
    const k = SUBMARINE.dragCoefficient,
      dragOnly = (free.mass / k) * Math.log(1 + (k * HELM.topSpeed * 10) / free.mass);
    console.log(
      `stop from ${HELM.topSpeed} m/s: let go ${free.distance.toFixed(2)} m in ${free.time.toFixed(2)} s, ` +
        `Astern ${astern.distance.toFixed(2)} m in ${astern.time.toFixed(2)} s, drag alone 10 s ${dragOnly.toFixed(0)} m`,
    );
    expect(dragOnly).toBeGreaterThan(30);
    expect(free.distance).toBeLessThan(6);
    expect(free.time).toBeLessThan(2);
    expect(astern.distance).toBeLessThan(2.5);
    expect(astern.time).toBeLessThan(0.7);
    expect(astern.distance).toBeLessThan(0.7 * free.distance);
    // The brake hint's model of a let-go (coastDistance) is the same glide, within 0.5 m.
    expect(Math.abs(coastDistance(free.mass, HELM.topSpeed, 1) - free.distance)).toBeLessThan(0.5);
  });

  it('a beacon overshot by 15 m is backed onto (the hull 8 m off it, the ring) in under 2.6 s from a stop at full Astern (3.0 s at the old half speed astern, 4 m/s)', () => {
    const { world, h, helm } = calmBoat();
    const c = world.components,
      e = h.hull;
    for (let i = 0; i < 2 / world.dt; i++) {
      steer(world, h, NO_INPUT, helm);
      step(world);
    }
    // The beacon 15 m astern of the hull's centre: inside the ring (BEACON_CATCH 8 m) once the
    // centre is within 8 m of it, the stern within about 2 m (half the hull, 6 m, nearer).
    const x0 = c.Position.x[e]!;
    let time = Number.NaN;
    for (let i = 1; i <= 10 / world.dt; i++) {
      steer(world, h, { ...NO_INPUT, astern: true }, helm);
      step(world);
      if (x0 - c.Position.x[e]! >= 15 - 8) {
        time = i * world.dt;
        break;
      }
    }
    console.log(`backed 7 m onto a beacon 15 m astern in ${time.toFixed(2)} s, astern at ${(-c.Velocity.x[e]!).toFixed(1)} m/s`);
    expect(time).toBeLessThan(2.6);
  });
});
