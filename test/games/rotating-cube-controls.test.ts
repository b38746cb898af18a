/**
 * rotating-cube's controls legend and a finger's press in the room (games/rotating-cube/controls.ts):
 * the legend says what Q E do in each mode in plain words, and a plain tap picks the floor cell under
 * it (on the cube too) while a drag from the cube flicks it.
 */
import { describe, expect, it } from 'vitest';
import { cubeControls, ROLL_QUEUE_MAX, RollQueue, TAP_SLOP, touchPress } from '../../games/rotating-cube/controls';

const line = (mode: 'room' | 'cube' | 'flip', touch: boolean, keys: string) =>
  cubeControls(mode, touch).find((c) => c.keys === keys)!.action;

describe('rotating cube legend', () => {
  it('room: Q E turn the cube flat on the floor (a turn about the vertical), W A S D roll it; no pivot jargon', () => {
    expect(line('room', false, 'Q E')).toMatch(/quarter turn flat on the floor/);
    expect(line('room', false, 'W A S D')).toMatch(/^roll the cube over an edge/);
    for (const c of cubeControls('room', false)) expect(c.action).not.toMatch(/pivot:|pitch|yaw|\broll\)/);
  });

  it("flip: Q E spin it like a wheel facing the player, W S tip it, A D turn it; free spin: the keys push the arrow's tip on screen", () => {
    expect(line('flip', false, 'Q E')).toMatch(/like a wheel facing you/);
    expect(line('flip', false, 'W S, A D')).toMatch(/tip it .* \(W S\), turn it left or right \(A D\)/);
    expect(line('cube', false, 'W S, A D')).toMatch(/tip up or down \(W S\), left or right \(A D\) on screen/);
    expect(line('cube', false, 'Q E')).toMatch(/toward you or away/);
    for (const mode of ['cube', 'flip'] as const) expect(cubeControls(mode, false).some((c) => c.keys === 'Space')).toBe(false);
  });

  it('room: the legend says a quarter turn counts as a move and a jump is free', () => {
    expect(line('room', false, 'Q E')).toMatch(/\(counts as a move\)$/);
    expect(line('room', true, 'Q E')).toMatch(/counts as a move/);
    expect(line('room', false, 'Space')).toMatch(/^jump \(free: not a move\)$/);
  });

  it('on a touch screen the room legend says a drag across the cube flicks it', () => {
    expect(line('room', true, 'Tap')).toMatch(/drag across the cube: flick it/);
    expect(line('room', false, 'Click')).toMatch(/^a floor cell: slide the cube onto it/);
    expect(line('room', false, 'Click')).not.toMatch(/flick/);
  });
});

describe('rotating cube: a finger in the room', () => {
  it('a tap on the cube pushes to the cell under it; a drag from it flicks; a tap on the floor pushes; a drag from the floor turns the camera', () => {
    expect(touchPress(true, 0)).toBe('push');
    expect(touchPress(true, TAP_SLOP)).toBe('push');
    expect(touchPress(true, TAP_SLOP + 0.5)).toBe('flick');
    expect(touchPress(true, 80)).toBe('flick');
    expect(touchPress(false, 3)).toBe('push');
    expect(touchPress(false, TAP_SLOP + 0.5)).toBe('none');
    expect(() => touchPress(true, -1)).toThrow(/touchPress: movedPx/);
    expect(() => touchPress(false, Number.NaN)).toThrow(/touchPress: movedPx/);
  });
});

describe('rotating cube roll queue', () => {
  it('a roll tap while the cube is busy waits and acts once it rests: two ▼ taps, two rolls', () => {
    // A phone player tapped ▼ twice 2 s apart and got one roll: the second tap came while the first
    // roll still turned. Frames as the page reads them: busy while a roll turns or the cube settles.
    const q = new RollQueue();
    const frames: { tap?: string; busy: boolean }[] = [
      { tap: 's', busy: false },
      { busy: true },
      { tap: 's', busy: true },
      { busy: true },
      { busy: false },
      { busy: false },
    ];
    const rolls: string[] = [];
    for (const f of frames) {
      if (f.tap && q.press(f.tap, f.busy)) rolls.push(f.tap);
      const next = q.take(f.busy);
      if (next) rolls.push(next);
    }
    expect(rolls).toEqual(['s', 's']);
    expect(q.pending).toEqual([]);
  });
  it('up to ROLL_QUEUE_MAX presses wait, in order; one more replaces the last; a press while free with some waiting goes after them; clear forgets them', () => {
    const q = new RollQueue();
    expect(ROLL_QUEUE_MAX).toBe(2);
    expect([q.press('w', true), q.press('a', true), [...q.pending]]).toEqual([false, false, ['w', 'a']]);
    expect([q.press('d', true), [...q.pending]]).toEqual([false, ['w', 'd']]);
    expect(q.take(true)).toBe('');
    expect(q.take(false)).toBe('w');
    // Free with one still waiting: the new press waits behind it.
    expect([q.press('s', false), [...q.pending]]).toEqual([false, ['d', 's']]);
    expect([q.take(false), q.take(false), q.take(false)]).toEqual(['d', 's', '']);
    expect(q.press('s', false)).toBe(true);
    q.press('d', true);
    q.clear();
    expect(q.take(false)).toBe('');
  });

  it('quick presses during a roll all roll, in order; a held key rolls again each time the cube rests, and stops when let go', () => {
    // The page's frames as queueRolls reads them (main.ts): a roll keeps the cube busy ROLL frames
    // after the press that starts it (a roll in the room takes about 40 frames of 1/60 s to rest).
    // A stranger's quick run, D A D with 8 frames between presses, all came while one roll turned:
    // with a queue of one the A was replaced and the cube went D D.
    const ROLL = 40;
    const play = (presses: Record<number, string>, heldFrames: Record<string, [number, number]>, frames: number) => {
      const q = new RollQueue();
      const rolls: string[] = [];
      let busyUntil = -1;
      for (let f = 0; f < frames; f++) {
        const busy = f < busyUntil;
        const held = Object.keys(heldFrames).filter((k) => f >= heldFrames[k]![0] && f < heldFrames[k]![1]);
        const key = presses[f];
        let next = key && q.press(key, busy) ? key : '';
        if (!key || !next) next ||= q.take(busy, held);
        if (next) {
          rolls.push(`${next}@${f}`);
          busyUntil = f + ROLL;
        }
      }
      return rolls;
    };
    expect(play({ 0: 'd', 8: 'a', 16: 'd' }, {}, 200)).toEqual(['d@0', 'a@40', 'd@80']);
    // Held 100 frames (1.7 s): a roll at once and one each time it rests while the key is down.
    expect(play({ 0: 'd' }, { d: [0, 100] }, 300)).toEqual(['d@0', 'd@40', 'd@80']);
    // Held just past one roll's rest: two rolls; a tap: one.
    expect(play({ 0: 'w' }, { w: [0, 41] }, 300)).toEqual(['w@0', 'w@40']);
    expect(play({ 0: 'w' }, { w: [0, 3] }, 300)).toEqual(['w@0']);
    // A press waiting goes before the held key's repeat.
    expect(play({ 0: 'd', 10: 'w' }, { d: [0, 100] }, 300)).toEqual(['d@0', 'w@40', 'd@80']);
  });
});
