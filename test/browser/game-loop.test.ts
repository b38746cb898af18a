/**
 * the game kit's createGameLoop in Node with a fake frame scheduler: steps per frame from real time,
 * alpha, pause (alpha 1, no steps), single steps, the clock after a reset, fps, error handling, bad options.
 */
import { describe, expect, it } from 'vitest';
import { createGameLoop } from '../../packages/game-kit/src/loop';

/** A fake requestAnimationFrame: `tick(ms)` runs the pending callback at time `now + ms`. */
function fakeFrames() {
  let pending: ((t: number) => void) | null = null;
  let now = 1000;
  return {
    requestFrame: (cb: (t: number) => void) => {
      pending = cb;
      return 1;
    },
    cancelFrame: () => {
      pending = null;
    },
    tick(ms: number) {
      now += ms;
      const cb = pending;
      pending = null;
      cb?.(now);
    },
    get pending() {
      return pending !== null;
    },
  };
}

function setup(dt = 0.01) {
  const frames = fakeFrames();
  let steps = 0;
  const alphas: number[] = [];
  const loop = createGameLoop({
    dt,
    step: () => {
      steps++;
    },
    render: (a) => {
      alphas.push(a);
    },
    requestFrame: frames.requestFrame,
    cancelFrame: frames.cancelFrame,
  });
  return { frames, loop, alphas, steps: () => steps };
}

describe('createGameLoop', () => {
  it('runs the whole steps that fit the real time and renders once a frame with alpha', () => {
    const { frames, loop, alphas, steps } = setup(0.01);
    let first = 0;
    loop.afterFirstFrame(() => {
      first++;
    });
    loop.start();
    frames.tick(16); // first frame: no elapsed time yet
    expect(steps()).toBe(0);
    expect(first).toBe(1);
    frames.tick(25); // 25 ms: 2 steps of 10 ms, 5 ms left
    expect(steps()).toBe(2);
    expect(alphas.at(-1)).toBeCloseTo(0.5, 9);
    frames.tick(5); // 10 ms in the accumulator: one more step, alpha 0
    expect(steps()).toBe(3);
    expect(alphas.at(-1)).toBeCloseTo(0, 9);
    expect(loop.frames).toBe(3);
    expect(first).toBe(1);
  });

  it('pauses: frames are drawn with alpha 1 and no steps; stepOnce steps exactly once', () => {
    const { frames, loop, alphas, steps } = setup(0.01);
    loop.start();
    frames.tick(16);
    loop.paused = true;
    for (let i = 0; i < 5; i++) frames.tick(50);
    expect(steps()).toBe(0);
    expect(alphas.slice(-5)).toEqual([1, 1, 1, 1, 1]);
    loop.stepOnce();
    expect(steps()).toBe(1);
    loop.paused = false;
    frames.tick(10);
    expect(steps()).toBe(2); // no backlog from the pause
  });

  it('runFrames runs n frames now, each its steps of the given time and a render: none while paused; bad n or seconds throw', () => {
    const { frames, loop, alphas, steps } = setup(0.01);
    loop.start();
    frames.tick(16);
    const drawn = loop.frames;
    // 10 frames of one fixed step each (the default): 10 steps, 10 renders at alpha 0, no real frame run.
    loop.runFrames(10);
    expect(steps()).toBe(10);
    expect(loop.frames).toBe(drawn + 10);
    expect(alphas.slice(-10)).toEqual(new Array(10).fill(0));
    expect(frames.pending).toBe(true);
    // 4 frames of 25 ms: 10 of 10 ms in all (2, 3, 2, 3), each frame's alpha the time left over.
    loop.runFrames(4, 0.025);
    expect(steps()).toBe(20);
    expect(alphas.at(-1)).toBeCloseTo(0, 9);
    // Paused: drawn, alpha 1, no steps.
    loop.paused = true;
    loop.runFrames(3);
    expect(steps()).toBe(20);
    expect(alphas.slice(-3)).toEqual([1, 1, 1]);
    expect(() => loop.runFrames(1.5)).toThrow(/runFrames: n must be an integer/);
    expect(() => loop.runFrames(-1)).toThrow(RangeError);
    expect(() => loop.runFrames(1, Number.NaN)).toThrow(/runFrames: seconds must be finite/);
  });

  it('clamps long frames and caps the steps of one frame', () => {
    const { frames, loop, steps } = setup(0.01);
    loop.start();
    frames.tick(16);
    frames.tick(5000); // a stalled tab: at most maxStepsPerFrame (4) steps
    expect(steps()).toBe(4);
  });

  it('after resetClock the next frame takes no steps for the time before it, the frames after it step again', () => {
    const { frames, loop, steps } = setup(0.01);
    loop.start();
    frames.tick(16);
    frames.tick(20); // 2 steps
    expect(steps()).toBe(2);
    loop.resetClock(); // a new world, built in the 60 ms before the next frame
    frames.tick(60);
    expect(steps()).toBe(2);
    frames.tick(35); // 3 steps of the new world, 5 ms left
    expect(steps()).toBe(5);
  });

  it('measures frames per second', () => {
    const { frames, loop } = setup(0.01);
    loop.start();
    for (let i = 0; i < 61; i++) frames.tick(1000 / 60);
    expect(loop.fps).toBeGreaterThan(59);
    expect(loop.fps).toBeLessThan(61);
  });

  it('stops and reports when a step throws', () => {
    const frames = fakeFrames();
    const errors: unknown[] = [];
    const loop = createGameLoop({
      dt: 0.01,
      step: () => {
        throw new RangeError('boom');
      },
      render: () => {},
      onError: (e) => errors.push(e),
      requestFrame: frames.requestFrame,
      cancelFrame: frames.cancelFrame,
    });
    loop.start();
    frames.tick(16);
    frames.tick(20);
    expect(errors).toHaveLength(1);
    expect(loop.running).toBe(false);
    expect(frames.pending).toBe(false);
  });

  it('rejects bad options naming them', () => {
    const base = { step: () => {}, render: () => {}, requestFrame: () => 0, cancelFrame: () => {} };
    expect(() => createGameLoop({ ...base, dt: 0 })).toThrow(/dt must be > 0, got 0/);
    expect(() => createGameLoop({ ...base, dt: 0.01, maxStepsPerFrame: 0 })).toThrow(RangeError);
    expect(() => createGameLoop({ ...base, dt: 0.01, fps: 60 } as never)).toThrow(/unknown option "fps"/);
    expect(() => createGameLoop({ ...base, dt: 0.01, render: 5 } as never)).toThrow(TypeError);
    const loop = createGameLoop({ ...base, dt: 0.01 });
    expect(() => {
      (loop as { paused: unknown }).paused = 'yes';
    }).toThrow(TypeError);
  });
});
