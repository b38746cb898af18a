/**
 * What a let-go of Dive holds (games/submarine/release.ts): the depth order at the moment the key
 * was let go, timed by the events' timestamps, whatever the frame rate; and the boat, headless on a
 * calm sea, stops where a boat let go at that moment (steps run one by one) stops. Also the on-screen
 * stick's small dead zone (games/submarine/stick.ts).
 */

import { createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE_NEUTRAL_FILL, type SubmarineHandles, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { createHelmState, type HelmState, keyHeaveShare, NO_INPUT, steer } from '../../games/submarine/helm';
import { createHeaveTiming, MAX_RELEASE_TAIL, releasedOrder } from '../../games/submarine/release';
import { STICK_DEAD, stickDirection, stickShare } from '../../games/submarine/stick';

/** A boat hovering 40 m down on a calm sea, and its helm. */
function hover(): { world: PhysicsWorld; h: SubmarineHandles; helm: HelmState } {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -40] });
  world.components.FluidRegion.surface.fill(0);
  const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
  for (let i = 0; i < 120; i++) {
    steer(world, h, NO_INPUT, helm);
    step(world);
  }
  return { world, h, helm };
}

/**
 * Runs `steps` steps as the page does (main.ts stepWorld): the timing says which way to steer, a
 * press ended in the past takes the order back to its let-go's moment.
 */
function runTimed(b: ReturnType<typeof hover>, timing: ReturnType<typeof createHeaveTiming>, steps: number): void {
  for (let i = 0; i < steps; i++) {
    const now = b.world.time;
    const t = timing.step(now);
    if (!Number.isNaN(t.letGoAt) && b.helm.mode === 'diving')
      b.helm.holdY = releasedOrder(b.helm.holdY, timing.orderAt(t.letGoAt), b.helm.mode);
    steer(b.world, b.h, { ...NO_INPUT, dive: t.dir < 0, rise: t.dir > 0, heave: keyHeaveShare(0, 0) }, b.helm);
    if (b.helm.mode === 'diving') timing.note(now, b.helm.holdY);
    step(b.world);
  }
}

describe('submarine let-go', () => {
  it('holds the order of the let-go when the order ran past it, never runs the order on', () => {
    expect(releasedOrder(-45, -42, 'diving')).toBe(-42);
    expect(releasedOrder(-40, -42, 'diving')).toBe(-40);
    expect(releasedOrder(-35, -38, 'rising')).toBe(-38);
    expect(releasedOrder(-40, -38, 'rising')).toBe(-40);
    expect(releasedOrder(-45, Number.NaN, 'diving')).toBe(-45);
    expect(() => releasedOrder(-45, -42, 'holding')).toThrow(/releasedOrder: mode/);
  });

  it('times a press by its events: runs it on to its length, takes back steps run past it, caps the tail', () => {
    const t = createHeaveTiming();
    expect(() => t.event(2, 0)).toThrow(/HeaveTiming.event: dir/);
    expect(() => t.event(1, Number.NaN)).toThrow(/HeaveTiming.event: stamp/);
    t.event(-1, 1000); // Dive pressed at 1000 ms
    expect(t.step(5)).toEqual({ dir: -1, letGoAt: Number.NaN }); // first seen at game time 5 s
    t.note(5, -41);
    t.note(5.5, -44);
    t.note(6, -47);
    t.event(-1, 1200); // a key repeat: nothing
    t.event(0, 1600); // let go 0.6 s after the press: the order of game time 5.6 s
    expect(t.step(6.5)).toEqual({ dir: 0, letGoAt: 5.6 });
    expect(t.orderAt(5.6)).toBe(-44);
    expect(t.step(6.6)).toEqual({ dir: 0, letGoAt: Number.NaN });
    // A let-go before the steps have caught up: the dive runs on to its length, then stops.
    t.event(1, 2000);
    t.step(10);
    t.event(0, 2500);
    expect(t.step(10.2).dir).toBe(1);
    expect(t.step(10.5)).toEqual({ dir: 0, letGoAt: Number.NaN });
    // A tap between two steps runs for its own length from the next step.
    t.event(-1, 3000);
    t.event(0, 3100);
    expect(t.step(20).dir).toBe(-1);
    expect(t.step(20.09).dir).toBe(-1);
    expect(t.step(20.1).dir).toBe(0);
    // The tail is at most MAX_RELEASE_TAIL past the step that sees the let-go.
    t.event(-1, 4000);
    t.step(25);
    t.event(0, 9000); // held 5 s while the steps stalled at game time 25 s; they run on at 26 s
    expect(t.step(26).dir).toBe(-1);
    expect(t.step(26 + MAX_RELEASE_TAIL - 0.01).dir).toBe(-1);
    expect(t.step(26 + MAX_RELEASE_TAIL)).toEqual({ dir: 0, letGoAt: Number.NaN });
  });

  it('a Dive held 1.5 s and let go mid-frame at 1 frame a second stops within 0.3 m of where one let go at that moment does', () => {
    // The reference: steps run one by one, the key let go after exactly 90 steps (1.5 s).
    const ref = hover();
    for (let i = 0; i < 90; i++) {
      steer(ref.world, ref.h, { ...NO_INPUT, dive: true, heave: keyHeaveShare(0, 0) }, ref.helm);
      step(ref.world);
    }
    for (let i = 0; i < 600; i++) {
      steer(ref.world, ref.h, NO_INPUT, ref.helm);
      step(ref.world);
    }
    const refY = ref.world.components.Position.y[ref.h.hull]!;
    expect(refY).toBeLessThan(-45); // it dived: 6 m/s for 1.5 s, less the start
    // The page at 1 frame a second: the press seen at the first step of a frame, let go 1.5 s later
    // by the clock; the next frame runs 60 steps, the one after sees the let-go 0.5 s late.
    const b = hover(),
      timing = createHeaveTiming();
    timing.event(-1, 10_000);
    runTimed(b, timing, 120); // two frames: 2 s of steps, the key still held as far as the steps know
    const ranOn = b.helm.holdY;
    timing.event(0, 11_500);
    runTimed(b, timing, 600);
    const y = b.world.components.Position.y[b.h.hull]!;
    expect(ranOn).toBeLessThan(refY - 2); // the order had run on metres past the let-go
    expect(Math.abs(y - refY)).toBeLessThan(0.3);
  });
});

describe('submarine stick', () => {
  it('a drag of 3 px of a phone stick`s 56 px reach moves the boat; a wobble across a push does not', () => {
    const px = 3 / 56;
    expect(px).toBeGreaterThan(STICK_DEAD);
    expect(stickDirection(-px, 0)).toBe(-1);
    expect(stickDirection(px, 0.01)).toBe(1);
    expect(stickDirection(0.02, 0)).toBe(0); // a resting thumb's tremble
    expect(stickDirection(0.15, 0.8)).toBe(0); // pushed up, wobbling sideways
    expect(stickDirection(0.6, 0.6)).toBe(1); // the diagonal asks for both
    expect(stickShare(px, false)).toBe(0.2);
    expect(stickShare(0.5, false)).toBe(0.5);
    expect(stickShare(0.1, true)).toBe(1);
    expect(() => stickDirection(1.5, 0)).toThrow(/stickDirection: v/);
  });
});
