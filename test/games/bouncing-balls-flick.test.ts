// A finger's flick read from the pointer events' own times (games/bouncing-balls/flick.ts), so a
// quick flick up throws at any frame rate. Figures: a flick of 160 px up in 80 ms (2 px/ms, a brisk
// thumb), its samples every 8 ms as a phone's touch screen sends them; a slow page hands a frame's
// samples over together (pointermove's coalesced events, each with its time), or only the frame's
// last one.
import { describe, expect, it } from 'vitest';
import { FLICK_FULL_SPEED, FLICK_MIN_SPEED, FlickTracker, flickPull } from '../../games/bouncing-balls/flick';

/** The flick's samples: from (100, 600) at t = 1000 ms, 160 px up and 20 px right over 80 ms, every 8 ms. */
const SAMPLES = Array.from({ length: 11 }, (_, i) => ({ x: 100 + 2 * i, y: 600 - 16 * i, t: 1000 + 8 * i }));

/**
 * The release velocity a page running at `fps` reads: the samples handed over a frame at a time
 * (`coalesced`: all of each frame's, else its last one only), the release 4 ms after the last sample.
 */
function readAt(fps: number, coalesced: boolean): [number, number] {
  const f = new FlickTracker();
  const [first, ...rest] = SAMPLES;
  f.press(first!.x, first!.y, first!.t);
  const frame = 1000 / fps;
  let batch: typeof SAMPLES = [];
  const hand = () => {
    for (const s of coalesced ? batch : batch.slice(-1)) f.move(s.x, s.y, s.t);
    batch = [];
  };
  let next = first!.t + frame;
  for (const s of rest) {
    if (s.t >= next) {
      hand();
      next += frame;
    }
    batch.push(s);
  }
  hand();
  const end = SAMPLES[SAMPLES.length - 1]!;
  return f.release(end.x, end.y, end.t + 4);
}

describe('bouncing-balls flick', () => {
  it('reads the same flick speed at 60, 20 and 10 frames a second (samples by their own times), and it throws up', () => {
    // 2.0 px/ms up; the release's 4 ms standstill lowers the read a little (FLICK_SPAN_MS: 64 px in
    // 36 ms, 1.78 px/ms), the same at every rate (to 1 %: the samples' own times are read).
    const at60 = readAt(60, true);
    for (const fps of [60, 20, 10]) {
      const [vx, vy] = readAt(fps, true);
      expect(vy, `${fps} fps`).toBeLessThan(-1.7);
      expect(Math.abs(vy - at60[1]), `${fps} fps`).toBeLessThan(0.02);
      expect(vx, `${fps} fps`).toBeGreaterThan(0);
      const pull = flickPull(vx, vy, 234);
      expect(pull, `${fps} fps`).not.toBeNull();
      // A pull down and to the left: the slingshot throws up and to the right, the flick's way.
      expect(pull![1]).toBeGreaterThan(0);
      expect(pull![0]).toBeLessThan(0);
    }
  });

  it("still reads a flick when a slow page hands over only each frame's last move (10 fps)", () => {
    // At 10 fps the release comes 4 ms after the only move handed over (where the finger lifts): the span reaches back to the press.
    const [vx, vy] = readAt(10, false);
    expect(flickPull(vx, vy, 234)).not.toBeNull();
    expect(Math.hypot(vx, vy)).toBeGreaterThan(1.5);
  });

  it('reads no flick from a finger that stopped before it let go, a slow slide, a flick sideways or down', () => {
    const stopped = new FlickTracker();
    stopped.press(100, 600, 0);
    stopped.move(100, 440, 80);
    // Held still 150 ms at the top, then lifted.
    expect(stopped.release(100, 440, 230)).toEqual([0, 0]);
    const slow = new FlickTracker();
    slow.press(100, 600, 0);
    for (let t = 10; t <= 300; t += 10) slow.move(100, 600 - 0.3 * t, t);
    const [sx, sy] = slow.release(100, 510, 305);
    expect(Math.hypot(sx, sy)).toBeLessThan(FLICK_MIN_SPEED);
    expect(flickPull(sx, sy, 234)).toBeNull();
    expect(flickPull(2, -0.3, 234)).toBeNull();
    expect(flickPull(0, 2, 234)).toBeNull();
  });

  it('throws harder the quicker the flick, a full pull from FLICK_FULL_SPEED on', () => {
    expect(Math.hypot(...flickPull(0, -FLICK_FULL_SPEED, 234)!)).toBeCloseTo(234, 6);
    expect(Math.hypot(...flickPull(0, -2 * FLICK_FULL_SPEED, 234)!)).toBeCloseTo(234, 6);
    expect(Math.hypot(...flickPull(0, -FLICK_FULL_SPEED / 2, 234)!)).toBeCloseTo(117, 6);
    expect(() => flickPull(Number.NaN, 1, 234)).toThrow(RangeError);
  });
});
