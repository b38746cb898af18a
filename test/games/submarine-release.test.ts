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
import { createHeaveTiming, createPressTiming, MAX_RELEASE_TAIL, MAX_UNSEEN_PRESS, releasedOrder } from '../../games/submarine/release';
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
/** The clock (ms) at which the frame that runs the step ending at game time `t` (s) comes: one frame a second, at whole seconds (game time 2 s at 10 s). */
const wallAt = (t: number): number => 8_000 + 1000 * Math.ceil(t - 1e-9);

function runTimed(b: ReturnType<typeof hover>, timing: ReturnType<typeof createHeaveTiming>, steps: number): void {
  for (let i = 0; i < steps; i++) {
    const now = b.world.time;
    const t = timing.step(now);
    if (!Number.isNaN(t.letGoAt) && b.helm.mode === 'diving')
      b.helm.holdY = releasedOrder(b.helm.holdY, timing.orderAt(t.letGoAt), b.helm.mode);
    steer(b.world, b.h, { ...NO_INPUT, dive: t.dir < 0, rise: t.dir > 0, heave: keyHeaveShare(0, 0) }, b.helm);
    if (b.helm.mode === 'diving') timing.note(now, b.helm.holdY);
    step(b.world);
    // Each step's burst drawn as one frame a second: the last step of a burst is at the frame's clock.
    timing.clock(b.world.time, wallAt(b.world.time));
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

  it('places a let-go in game time by its timestamp against the last step: runs a press on to it, takes back steps run past it', () => {
    const t = createHeaveTiming();
    expect(() => t.event(2, 0)).toThrow(/HeaveTiming.event: dir/);
    expect(() => t.event(1, Number.NaN)).toThrow(/HeaveTiming.event: stamp/);
    t.event(-1, 1000); // Dive pressed
    expect(t.step(5)).toEqual({ dir: -1, letGoAt: Number.NaN });
    t.note(5, -41);
    t.note(5.5, -44);
    t.note(6, -47);
    t.clock(6, 2000); // a frame's burst ran the steps up to game time 6 s at 2000 ms
    t.event(-1, 2100); // a key repeat: nothing
    // Let go 0.6 s after that frame: game time 6.6 s; the next frame's first step, at 6, runs on.
    t.event(0, 2600);
    expect(t.step(6.1).dir).toBe(-1);
    expect(t.step(6.6)).toEqual({ dir: 0, letGoAt: Number.NaN });
    // Steps run past the let-go before it is seen (its event waited behind a long frame): taken back.
    t.event(1, 3000);
    t.step(7);
    t.note(7, -40);
    t.note(7.2, -39);
    t.note(7.4, -38);
    t.clock(7.1, 3000);
    t.event(0, 3200); // game time 7.3 s
    expect(t.step(7.5)).toEqual({ dir: 0, letGoAt: 7.3 });
    expect(t.orderAt(7.3)).toBe(-39);
    // The clock's time since the last step counts at most MAX_RELEASE_TAIL; paused, none.
    t.event(-1, 4000);
    t.step(8);
    t.clock(8, 4000);
    t.event(0, 9000);
    expect(t.step(8 + MAX_RELEASE_TAIL - 0.01).dir).toBe(-1);
    expect(t.step(8 + MAX_RELEASE_TAIL)).toEqual({ dir: 0, letGoAt: Number.NaN });
    t.event(-1, 10_000, true);
    t.step(9);
    t.clock(9.5, 10_000);
    t.event(0, 12_000, true);
    expect(t.step(9.5)).toEqual({ dir: 0, letGoAt: Number.NaN });
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
    // The page at 1 frame a second: the press seen at the first step of a frame (game time 2 s, the
    // clock at 10 s), let go 1.5 s later by the clock, its event handled only after the next two
    // frames' bursts have run the steps to game time 4 s.
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

describe('submarine screw press timing', () => {
  /** Steps of 1/60 s from game time `from` (s) for `n` steps: the direction each step is given. */
  const steps = (t: ReturnType<typeof createPressTiming>, from: number, n: number): number[] =>
    Array.from({ length: n }, (_, i) => t.step(from + i / 60));
  const count = (dirs: number[], d: number) => dirs.filter((x) => x === d).length;

  it('a press no step saw (pressed and let go inside a stalled frame) runs for as long as it was held, from the next step', () => {
    const t = createPressTiming();
    t.clock(5, 10_000);
    t.event(1, 10_200);
    t.event(0, 11_200); // held 1 s of the clock, no step in between
    const dirs = steps(t, 5, 120);
    // 60 steps of 1/60 s are 1 s (within a step for the float sum).
    expect(Math.abs(count(dirs, 1) - 60)).toBeLessThanOrEqual(1);
    expect(dirs.slice(0, 59).every((d) => d === 1)).toBe(true);
    // Astern the same, capped at MAX_UNSEEN_PRESS.
    t.event(-1, 20_000);
    t.event(0, 25_000);
    expect(Math.abs(count(steps(t, 10, 600), -1) - 60 * MAX_UNSEEN_PRESS)).toBeLessThanOrEqual(1);
  });

  it('a press the steps saw ends at its length from its first step, no later than its let-go by the clock', () => {
    const t = createPressTiming();
    t.clock(0, 1000);
    t.event(1, 1010);
    // A frame of 0.5 s runs 30 steps with the key held; the last step's clock is at 1500 ms.
    expect(count(steps(t, 0, 30), 1)).toBe(30);
    t.clock(0.5, 1500);
    // Let go 0.3 s after that frame (held 0.79 s): 0.29 s more from game time 0.5.
    t.event(0, 1800);
    const on = count(steps(t, 0.5, 60), 1);
    expect(Math.abs(on - 0.29 * 60)).toBeLessThanOrEqual(1);
    // Held across a pause of 10 s, no frame run since: it runs on at most MAX_RELEASE_TAIL, not 10 s.
    t.event(1, 2000);
    steps(t, 1, 6);
    t.clock(1.1, 2100);
    t.event(0, 12_200);
    expect(count(steps(t, 1.1, 120), 1)).toBeLessThanOrEqual(MAX_RELEASE_TAIL * 60 + 1);
  });

  it('a let-go while paused ends the press at once; a new direction ends the one before', () => {
    const t = createPressTiming();
    t.clock(0, 0);
    t.event(1, 100);
    t.event(0, 900, true);
    expect(count(steps(t, 0, 60), 1)).toBe(0);
    t.event(1, 2000);
    t.event(-1, 2400); // Astern pressed over Ahead
    expect(steps(t, 1, 3)).toEqual([-1, -1, -1]);
    expect(() => t.event(2, 0)).toThrow(/PressTiming.event: dir/);
    expect(() => t.step(Number.NaN)).toThrow(/PressTiming.step: now/);
  });
});

describe('submarine stick', () => {
  it('a drag of 9 px of a phone stick`s 56 px reach moves the boat; a wobble across a push does not', () => {
    const px = 9 / 56;
    expect(px).toBeGreaterThan(STICK_DEAD);
    expect(stickDirection(-px, 0)).toBe(-1);
    expect(stickDirection(px, 0.01)).toBe(1);
    expect(stickDirection(0.02, 0)).toBe(0); // a resting thumb's tremble
    expect(stickDirection(0.12, 0.8)).toBe(0); // pushed up, wobbling sideways
    expect(stickDirection(0.6, 0.6)).toBe(1); // the diagonal asks for both
    expect(stickShare(px, false)).toBe(0.2);
    expect(stickShare(0.575, false)).toBeCloseTo(0.5, 12);
    expect(stickShare(0.1, true)).toBe(1);
    expect(() => stickDirection(1.5, 0)).toThrow(/stickDirection: v/);
  });
});
