/**
 * The hull on the seabed (games/submarine/seabed.ts), headless with the helm on a calm sea: a dive
 * into the bed at speed costs one hit, resting on it (Dive still held, or let go) costs nothing
 * more, a slow landing costs nothing, and the hull neither sinks into the bed nor is thrown off it.
 */

import { createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, type SubmarineHandles, seabedHeight, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { createHelmState, HELM, type HelmInput, type HelmState, NO_INPUT, steer } from '../../games/submarine/helm';
import { SEABED, type SeabedState, seabedInput, touchSeabed } from '../../games/submarine/seabed';

interface Boat {
  world: PhysicsWorld;
  h: SubmarineHandles;
  helm: HelmState;
  bed: SeabedState;
  hits: number;
  /** Deepest the keel has been under the bed, m. */
  sunk: number;
  /** Whether the hull has touched the bed (touchSeabed found a contact). */
  touched: boolean;
}

/** The boat hovering (neutral tanks) with its keel `clearance` m over the seabed at `x` (m). */
function boat(clearance: number, x = 0): Boat {
  const world = createPhysicsWorld(submarine.worldOptions());
  const probe = submarine.build(createPhysicsWorld(submarine.worldOptions()), { seed: 1, count: 0 });
  const y = seabedHeight(probe.seabed, x) + SUBMARINE.height / 2 + clearance;
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [x, y] });
  world.components.FluidRegion.surface.fill(0);
  return {
    world,
    h,
    helm: createHelmState(SUBMARINE_NEUTRAL_FILL),
    bed: { touching: false, spared: 0, diveStopped: false },
    hits: 0,
    sunk: 0,
    touched: false,
  };
}

/** Holds `input` for `seconds`: the helm steers, the world steps, the seabed contact is resolved. */
function run(b: Boat, input: Partial<HelmInput>, seconds: number): void {
  const n = Math.round(seconds / b.world.dt);
  const c = b.world.components;
  for (let i = 0; i < n; i++) {
    const held = seabedInput(b.bed, { ...NO_INPUT, ...input });
    steer(b.world, b.h, held, b.helm);
    step(b.world);
    const contact = touchSeabed(b.world, b.h, b.bed, b.world.time, held.dive);
    // As games/submarine/main.ts does: on a contact the helm brakes and holds where the boat stops.
    if (contact !== '') b.helm.holdY = Number.NaN;
    if (contact !== '') b.touched = true;
    if (contact === 'hit') b.hits++;
    const x = c.Position.x[b.h.hull]!,
      keel = c.Position.y[b.h.hull]! - SUBMARINE.height / 2;
    b.sunk = Math.max(b.sunk, seabedHeight(b.h.seabed, x) - keel);
  }
}

describe('submarine on the seabed', () => {
  it('a full-speed dive into the bed costs one hit; resting there 12 s, Dive held or let go, costs none more', () => {
    const b = boat(12);
    let fastest = 0;
    // Dive from 12 m above the bed: at the dive speed's 7 m/s well past SEABED.hitSpeed when it lands.
    for (let t = 0; t < 4 && !b.bed.touching; t += b.world.dt) {
      fastest = Math.max(fastest, -b.world.components.Velocity.y[b.h.hull]!);
      run(b, { dive: true }, b.world.dt);
    }
    expect(b.bed.touching).toBe(true);
    expect(fastest).toBeGreaterThan(2 * SEABED.hitSpeed);
    expect(b.hits).toBe(1);
    run(b, { dive: true }, 8); // pressed against the bed by tanks and thrusters
    run(b, {}, 4); // let go: the helm holds where the boat came to rest
    expect(b.hits).toBe(1);
    // Resting, not sinking in: the push-out keeps the keel within 0.3 m of the bed's line (the hull
    // is 3 m tall; 0.3 m is where a player would see it buried).
    expect(b.sunk).toBeLessThan(0.3);
  });

  it('Dive held onto the steepest slope of the bed for 12 s: one hit, then the helm holds there', () => {
    // The steepest 10 m of the seeded bed within 300 m of the start (the boat's own course).
    const probe = submarine.build(createPhysicsWorld(submarine.worldOptions()), { seed: 1, count: 0 });
    let steepest = 0,
      at = 0;
    for (let x = -300; x <= 300; x += 2) {
      const slope = Math.abs(seabedHeight(probe.seabed, x + 5) - seabedHeight(probe.seabed, x - 5)) / 10;
      if (slope > steepest) [steepest, at] = [slope, x];
    }
    expect(steepest).toBeGreaterThan(0.4); // a slope of over 22 degrees
    const b = boat(12, at);
    run(b, { dive: true }, 12);
    expect(b.hits).toBe(1);
    // The bed stops the dive (the helm holds where the boat comes to rest until Dive is pressed
    // again), so the hull is not driven on down the slope: it ends off the bed or resting on it.
    expect(Math.abs(b.world.components.Velocity.y[b.h.hull]!)).toBeLessThan(0.3);
    expect(b.helm.mode).toBe('holding');
    // Pressed again after the 2 s spare: the boat, within a metre or two of the bed, dives back onto it.
    run(b, {}, 0.1);
    const hits = b.hits;
    run(b, { dive: true }, 3);
    expect(b.hits - hits).toBeLessThanOrEqual(1);
  });

  it('a slow landing (1.4 m/s, a light press on Dive) costs no hit', () => {
    const b = boat(6);
    run(b, { dive: true, heave: 1.4 / HELM.diveSpeed }, 8);
    expect(b.touched).toBe(true); // it reached the bed
    expect(b.hits).toBe(0);
  });

  it('bounces at the restitution times the approach speed, not more', () => {
    const b = boat(12);
    const c = b.world.components;
    let before = 0;
    while (!b.bed.touching) {
      before = c.Velocity.y[b.h.hull]!;
      run(b, { dive: true }, b.world.dt);
    }
    // Normal restitution: out at 0.3 times in (the bed is nearly level at x = 0; 35 % allows its
    // slope and the step's gravity and thrust).
    const after = c.Velocity.y[b.h.hull]!;
    expect(after).toBeGreaterThan(0);
    expect(after).toBeLessThan(-before * SEABED.restitution * 1.35);
  });
});
