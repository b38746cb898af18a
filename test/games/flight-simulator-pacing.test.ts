/**
 * The flight simulator's pacing, tap latch and near-ring fade (games/flight-simulator/pacing.ts,
 * tap-latch.ts, ring-fade.ts, label-place.ts), headless: the game loop fed the flight's FRAME_CAP and STEPS_PER_FRAME keeps pace with the clock at
 * 20 frames a second and goes in slow motion (FRAME_CAP s of game time a frame) at 5; the notice
 * shows under 10 frames a second and not at the edge; a press let go before any step acts for
 * MIN_PULSE s of game time, a held key as long as it is held; a ring that spans the view is faint,
 * one far off is whole; the ring's label goes past the messages' boxes; an out-of-view ring's label
 * (ring-pointer.ts) says which way to turn.
 */

import { createGameLoop } from '@bitphysics/game-kit';
import { describe, expect, it } from 'vitest';
import { clearOfBox, labelClearOf, type ScreenBox } from '../../games/flight-simulator/label-place';
import { FLIGHT_STEP, FRAME_CAP, gameTimeOfFrame, SLOW_MOTION_FPS, STEPS_PER_FRAME, slowMotion } from '../../games/flight-simulator/pacing';
import { NEAR_FADE, nearFade } from '../../games/flight-simulator/ring-fade';
import { offScreenLabel, TURN_BEARING } from '../../games/flight-simulator/ring-pointer';
import { clearPulse, createPulse, MIN_PULSE, pressPulse, pulseOn, releasePulse } from '../../games/flight-simulator/tap-latch';

/** Runs the game loop with the flight's pacing for `frames` frames `frameMs` ms apart; returns the steps run. */
function stepsAt(frameMs: number, frames: number): number {
  let steps = 0;
  const pending: ((t: number) => void)[] = [];
  const loop = createGameLoop({
    dt: FLIGHT_STEP,
    step: () => {
      steps++;
    },
    render: () => {},
    maxFrameTime: FRAME_CAP,
    maxStepsPerFrame: STEPS_PER_FRAME,
    requestFrame: (cb) => pending.push(cb),
    cancelFrame: () => {},
  });
  loop.start();
  for (let k = 0; k <= frames; k++) pending.shift()!(k * frameMs);
  loop.stop();
  return steps;
}

describe('flight pacing', () => {
  it('keeps pace with the clock at 20 frames a second; at 5 a frame advances FRAME_CAP s of game time (slow motion), not 0.2 s', () => {
    // 10 s of clock at 20 fps: 10 s of game time (600 steps of 1/60 s), to one step.
    expect(Math.abs(stepsAt(50, 200) * FLIGHT_STEP - 10)).toBeLessThanOrEqual(FLIGHT_STEP + 1e-9);
    // 10 s of clock at 5 fps: 50 frames of 0.1 s each = 5 s of game time, to one step; catching up would be 10 s.
    const game = stepsAt(200, 50) * FLIGHT_STEP;
    expect(Math.abs(game - 50 * 0.1)).toBeLessThanOrEqual(FLIGHT_STEP + 1e-9);
    expect(FRAME_CAP).toBe(0.1);
    expect(gameTimeOfFrame(0.2)).toBe(0.1);
    expect(gameTimeOfFrame(0.04)).toBe(0.04);
    expect(() => gameTimeOfFrame(-1)).toThrow(/gameTimeOfFrame: frameSeconds/);
  });

  it('says "slow motion" under 10 frames a second, not at 12, and does not flicker between', () => {
    expect(slowMotion(false, 0)).toBe(false);
    expect(slowMotion(false, 5)).toBe(true);
    expect(slowMotion(false, 12.5)).toBe(false);
    // Between the two edges it keeps what it showed.
    const mid = (SLOW_MOTION_FPS.on + SLOW_MOTION_FPS.off) / 2;
    expect(mid).toBeGreaterThan(9);
    expect(mid).toBeLessThan(12);
    expect(slowMotion(true, mid)).toBe(true);
    expect(slowMotion(false, mid)).toBe(false);
    expect(() => slowMotion(false, Number.NaN)).toThrow(/slowMotion: fps/);
  });
});

describe('tap latch', () => {
  /** The steps of 1/60 s at which `p` acts, counting from game time `t0`, over `n` steps; `during(k)` runs before step k. */
  function acting(p: ReturnType<typeof createPulse>, n: number, during: (k: number) => void = () => {}): number {
    let count = 0;
    for (let k = 0; k < n; k++) {
      during(k);
      if (pulseOn(p, 3 + k / 60)) count++;
    }
    return count;
  }

  it('a press and release before any step acts for MIN_PULSE s of game time (9 steps of 1/60 s), then stops', () => {
    const p = createPulse();
    pressPulse(p);
    releasePulse(p);
    // 0.15 s at 1/60 s a step: 9 steps exactly.
    expect(MIN_PULSE).toBe(0.15);
    expect(acting(p, 60)).toBe(9);
  });

  it('a key held 1 s acts for the whole second and stops at its release; a second tap acts again', () => {
    const p = createPulse();
    pressPulse(p);
    const n = acting(p, 120, (k) => {
      if (k === 60) releasePulse(p);
    });
    expect(n).toBe(60);
    pressPulse(p);
    releasePulse(p);
    expect(acting(p, 60)).toBe(9);
  });

  it('a repeat of a held key does not start a new pulse; a cleared one does not act; bad time refused', () => {
    const p = createPulse();
    pressPulse(p);
    expect(pulseOn(p, 0)).toBe(true);
    pressPulse(p); // auto-repeat while held
    releasePulse(p);
    // First seen at 0: acts until 0.15 s, not from the repeat on.
    expect(pulseOn(p, 0.1)).toBe(true);
    expect(pulseOn(p, 0.16)).toBe(false);
    pressPulse(p);
    clearPulse(p);
    expect(pulseOn(p, 1)).toBe(false);
    expect(() => pulseOn(p, Number.NaN)).toThrow(/pulseOn: time/);
  });
});

describe('near-ring fade', () => {
  it("a ring spanning the phone's view at the pass is faint; 520 m off it is whole; in between it fades smoothly", () => {
    // The phone's chase view: 64 degrees high, 390 x 587 px (the narrower side across), the camera
    // 110 m behind the aircraft as it passes through a ring of outer radius 84 m (halo included).
    const tanHalf = Math.tan((32 * Math.PI) / 180) * (390 / 587);
    // The ring's edge is outside the view when its angle from the axis, atan(R / d), passes the
    // view's half angle, atan(tanHalf): there the ring covers the screen's width.
    expect(Math.atan(84 / 110)).toBeGreaterThan(Math.atan(tanHalf));
    expect(nearFade(84, 110, tanHalf)).toBeCloseTo(NEAR_FADE.least, 12);
    expect(nearFade(84, 0, tanHalf)).toBe(NEAR_FADE.least);
    // 520 m off (ring 1 at the start) it spans under half the view: whole.
    expect(84 / (520 * tanHalf)).toBeLessThan(NEAR_FADE.from);
    expect(nearFade(84, 520, tanHalf)).toBe(1);
    // Nearer and nearer, never brighter (to 1e-12), between the two ends.
    let last = 1;
    for (let d = 520; d >= 100; d -= 5) {
      const f = nearFade(84, d, tanHalf);
      expect(f).toBeLessThanOrEqual(last + 1e-12);
      expect(f).toBeGreaterThanOrEqual(NEAR_FADE.least);
      last = f;
    }
    expect(() => nearFade(0, 10, 1)).toThrow(/nearFade: radius and tanHalf/);
    expect(() => nearFade(1, -1, 1)).toThrow(/nearFade: distance/);
  });
});

describe('the ring label keeps clear of the messages (label-place.ts)', () => {
  // A phone's scene, 390 x 650 px; a label 100 x 24 px (half 50 x 12), gap 10 px.
  const tip: ScreenBox = [15, 8, 360, 60];
  const banner: ScreenBox = [40, 74, 310, 50];
  it('goes below a tip at the top that it would sit behind, by the gap', () => {
    // Centre at 30 px: the label spans 18..42, inside the tip (8..68): pushed to 68 + 10 + 12 = 90.
    expect(labelClearOf(195, 30, 50, 12, [tip], 650, 10)).toBe(90);
  });
  it('goes below the whole stacked column, taken from the top down', () => {
    // Past the tip to 90 (spans 78..102), which is inside the banner (74..124): 124 + 10 + 12 = 146.
    expect(labelClearOf(195, 30, 50, 12, [banner, tip], 650, 10)).toBe(146);
  });
  it('goes above a box in the lower half', () => {
    expect(labelClearOf(195, 560, 50, 12, [[20, 550, 350, 40]], 650, 10)).toBe(550 - 10 - 12);
  });
  it('stays where it is beside a box or clear of it', () => {
    // Left of a box at 200..300: the label's right edge (110) plus the gap stays short of it.
    expect(labelClearOf(60, 30, 50, 12, [[200, 8, 100, 60]], 650, 10)).toBe(30);
    expect(labelClearOf(195, 300, 50, 12, [tip, banner], 650, 10)).toBe(300);
  });
  it('throws on a negative half size or box', () => {
    expect(() => labelClearOf(0, 0, -1, 12, [], 650, 10)).toThrow(/labelClearOf: halfW/);
    expect(() => labelClearOf(0, 0, 1, 12, [[0, 0, -5, 4]], 650, 10)).toThrow(/labelClearOf: a box/);
  });
});

describe('the ring label keeps clear of the flight-path marker drawn over it (label-place.ts clearOfBox)', () => {
  // A phone's scene, 390 x 650 px (above nothing), 10 px from each edge. The label for a ring off to
  // the left, as a stranger saw it on a 390 x 844 phone: "◀ ring 1 · 130 m · turn left" at the left
  // edge, 252 x 30 px (half 126 x 15) centred at (136, 468), under the marker drawn at (197, 460):
  // its box 46 x 27 px and 7 px of outline and shadow round it, 60 x 41 px. Gap 6 px (LABEL_GAP).
  const scene = { w: 390, h: 650, margin: 10 };
  const marker: ScreenBox = [197 - 30, 460 - 20.5, 60, 41];
  const overlap = ([x, y]: [number, number], hw: number, hh: number, b: ScreenBox) =>
    Math.max(0, Math.min(x + hw, b[0] + b[2]) - Math.max(x - hw, b[0])) *
    Math.max(0, Math.min(y + hh, b[1] + b[3]) - Math.max(y - hh, b[1]));
  it('moves a label under the marker the least way clear of it, by the gap, inside the scene', () => {
    // Where it was placed it covers 60 x 27.5 px of the marker's drawing (1 650 px²).
    expect(overlap([136, 468], 126, 15, marker)).toBe(1650);
    const moved = clearOfBox(136, 468, 126, 15, marker, 6, scene);
    // Below the marker (its foot at 480.5, + 6 + 15): 33.5 px down, the least move (up is 49.5 px;
    // left and right leave the scene).
    expect(moved).toEqual([136, 501.5]);
    expect(overlap(moved, 126 + 6, 15 + 6, marker)).toBe(0);
  });
  it('takes the next least move where the least lands on a message or leaves the scene', () => {
    // A message box under the marker: the label goes up instead.
    expect(clearOfBox(136, 468, 126, 15, marker, 6, { ...scene, avoid: [[20, 490, 350, 60]] })).toEqual([136, 460 - 20.5 - 6 - 15]);
    // The marker near the scene's foot: no room under it, so up.
    const low: ScreenBox = [167, 600, 60, 41];
    expect(clearOfBox(136, 615, 126, 15, low, 6, scene)).toEqual([136, 600 - 6 - 15]);
  });
  it('leaves a label clear of the marker where it is, and one with no open move where it was placed', () => {
    expect(clearOfBox(136, 400, 126, 15, marker, 6, scene)).toEqual([136, 400]);
    expect(clearOfBox(195, 325, 180, 300, marker, 6, scene)).toEqual([195, 325]);
  });
  it('throws on a negative size, gap or margin, or box', () => {
    expect(() => clearOfBox(0, 0, -1, 12, marker, 6, scene)).toThrow(/clearOfBox: halfW/);
    expect(() => clearOfBox(0, 0, 1, 12, marker, 6, { ...scene, margin: Number.NaN })).toThrow(/clearOfBox: margin/);
    expect(() => clearOfBox(0, 0, 1, 12, [0, 0, -5, 4], 6, scene)).toThrow(/clearOfBox: a box/);
  });
});

describe('an out-of-view ring says how to turn to it (ring-pointer.ts)', () => {
  // A desktop scene 1060 x 750 px (half 530 x 375); the ring 30 degrees right of the way flown, level.
  const DEG = Math.PI / 180;
  const at = { ring: 8, distance: '637 m', halfW: 530, halfH: 375, behind: false, touch: false, bearing: 30 * DEG, elevation: 0 };
  it('to the side: the arrow at its edge, the turn and its key; on a phone the turn alone', () => {
    expect(offScreenLabel({ ...at, dx: 600, dy: 40 })).toEqual({ text: 'ring 8 · 637 m · turn right (hold →) ▶', arrow: '▶' });
    expect(offScreenLabel({ ...at, dx: 600, dy: 40, touch: true }).text).toBe('ring 8 · 637 m · turn right ▶');
    expect(offScreenLabel({ ...at, dx: -600, dy: 40, bearing: -30 * DEG })).toEqual({
      text: '◀ ring 8 · 637 m · turn left (hold ←)',
      arrow: '◀',
    });
  });
  it('what to do follows the bearing, not the screen: a banked cockpit view shows a ring to the right below its edge', () => {
    expect(offScreenLabel({ ...at, dx: 100, dy: 500 })).toEqual({ text: '▼ ring 8 · 637 m · turn right (hold →)', arrow: '▼' });
    // Within TURN_BEARING of the way flown: climb or dive by the elevation.
    expect(offScreenLabel({ ...at, dx: 100, dy: -500, bearing: 5 * DEG, elevation: 20 * DEG })).toEqual({
      text: '▲ ring 8 · 637 m · climb (hold ↑)',
      arrow: '▲',
    });
    expect(offScreenLabel({ ...at, dx: 100, dy: 500, bearing: -TURN_BEARING / 2, elevation: -0.3, touch: true }).text).toBe(
      '▼ ring 8 · 637 m · dive',
    );
  });
  it('behind, even straight above the centre: the side it lies and a turn (the way back)', () => {
    expect(offScreenLabel({ ...at, dx: -100, dy: -500, behind: true, bearing: -170 * DEG })).toEqual({
      text: '◀ ring 8 behind · 637 m · turn left (hold ←)',
      arrow: '◀',
    });
  });
  it('refuses a ring number under 1, a scene of no size and a bearing not finite, naming the function', () => {
    expect(() => offScreenLabel({ ...at, ring: 0, dx: 1, dy: 0 })).toThrow(/offScreenLabel: ring/);
    expect(() => offScreenLabel({ ...at, halfW: 0, dx: 1, dy: 0 })).toThrow(/offScreenLabel: halfW/);
    expect(() => offScreenLabel({ ...at, bearing: Number.NaN, dx: 1, dy: 0 })).toThrow(/offScreenLabel: bearing/);
  });
});
