/**
 * What a let-go of Dive or Rise holds: the depth order at the moment the key (or the stick) was let
 * go, read from the input events' timestamps (`Event.timeStamp`, ms), not from the frames. The
 * helm's order (./helm.ts `HelmState.holdY`) runs on with every step the control is held, and the
 * page runs its steps in a burst at each drawn frame: on a loaded machine at 1 to 2 frames a second a
 * let-go reaches the game up to a second of steps late or early. Placed in game time by its own
 * timestamp (the way ../black-hole/press-timing.ts reads a press's length from its events), against
 * the clock of the last step run: a let-go the steps have not caught up with runs on to it (at most
 * `MAX_RELEASE_TAIL` s), and one the steps ran past takes back the order they ran on to. Headless,
 * tested in node.
 */

/**
 * The most game time a let-go press runs on after the step that sees it let go, s: the pacer's
 * longest frame (main.ts `maxFrameTime`), the most the steps lag the wall clock by. A longer wait
 * (a stall the pacer does not make up) is not dived after the fact.
 */
export const MAX_RELEASE_TAIL = 1;

/**
 * The order a let-go holds, as the hull's y, m (negative under water): `atLetGo` (the order at the
 * moment of the let-go) when the helm's `holdY` has run past it the way the boat was ordered (`mode`
 * 'diving': down, 'rising': up), else `holdY` (it never runs the order on; NaN `atLetGo` leaves `holdY`).
 * @throws RangeError when `holdY` is not a number or `mode` is not 'diving' or 'rising'.
 */
export function releasedOrder(holdY: number, atLetGo: number, mode: string): number {
  if (typeof holdY !== 'number') throw new RangeError(`releasedOrder: holdY must be a number, got ${holdY}`);
  if (mode !== 'diving' && mode !== 'rising') throw new RangeError(`releasedOrder: mode must be 'diving' or 'rising', got ${mode}`);
  if (Number.isNaN(atLetGo) || Number.isNaN(holdY)) return holdY;
  return mode === 'diving' ? Math.max(holdY, atLetGo) : Math.min(holdY, atLetGo);
}

/** What `HeaveTiming.step` tells the game to steer by this step. */
export interface HeaveStep {
  /** The direction to steer: -1 dive, 1 rise, 0 neither (held, or a let-go press still running on). */
  dir: -1 | 0 | 1;
  /**
   * Set on the step a press ends: the game time of its let-go, s, when that lies before this step
   * (the order the steps ran on to past it is taken back: `HeaveTiming.orderAt`); NaN otherwise.
   */
  letGoAt: number;
}

/** A Dive or Rise press timed by its events (see the header). */
export interface HeaveTiming {
  /**
   * Notes the step just run: the game time after it (`game`, s) and the clock then (`wallMs`, ms, the
   * clock of `Event.timeStamp`: performance.now()). The last step of a frame's burst maps the clock
   * to the game's time for the let-go events that come before the next frame.
   */
  clock(game: number, wallMs: number): void;
  /**
   * An input event at `stamp` (its `timeStamp`, ms) left Dive / Rise asked as `dir` (-1 dive, 1
   * rise, 0 neither), with the game `paused` or running. Call it after every key or stick event; a
   * `dir` unchanged does nothing. A let-go happens at the game time the clock gives it: the last
   * step's (`clock`) plus the clock's time since (negative for an event older than it), at most
   * `MAX_RELEASE_TAIL` s either way (none while paused).
   * @throws RangeError when `dir` is not -1, 0 or 1, or `stamp` is not finite.
   */
  event(dir: number, stamp: number, paused?: boolean): void;
  /**
   * The step at game time `now` (s): which way to steer, and whether a press ended with its let-go
   * in the past. A press runs from the first step that sees it to its let-go's game time.
   * @throws RangeError when `now` is not finite.
   */
  step(now: number): HeaveStep;
  /** Notes the depth order `order` (m) after the step at game time `now` (s) of a press, for `orderAt`. */
  note(now: number, order: number): void;
  /** The order noted by the last step of the press at or before game time `time` (s); NaN before any. */
  orderAt(time: number): number;
  /** Forgets the presses so far (a new run); a control still held counts from the next step. */
  reset(): void;
}

/** A new `HeaveTiming` with nothing pressed. */
export function createHeaveTiming(): HeaveTiming {
  let dir: -1 | 0 | 1 = 0,
    game = 0,
    wall = Number.NaN;
  /** The let-go press running on: its direction and the game time of its let-go, s. */
  let tail: { dir: -1 | 1; end: number } | null = null;
  const times: number[] = [],
    orders: number[] = [];
  return {
    clock(g, wallMs) {
      game = g;
      wall = wallMs;
    },
    event(d, stamp, paused = false) {
      if (d !== -1 && d !== 0 && d !== 1) throw new RangeError(`HeaveTiming.event: dir must be -1, 0 or 1, got ${d}`);
      if (!Number.isFinite(stamp)) throw new RangeError(`HeaveTiming.event: stamp must be finite ms, got ${stamp}`);
      if (d === dir) return;
      if (dir !== 0) {
        // Before the last step's clock (an event handled after a long frame's burst) it lies back in
        // that burst's game time; after it, ahead of it.
        const since = paused || Number.isNaN(wall) ? 0 : Math.min(MAX_RELEASE_TAIL, Math.max(-MAX_RELEASE_TAIL, (stamp - wall) / 1000));
        tail = { dir, end: game + since };
      }
      dir = d as -1 | 0 | 1;
      if (dir !== 0) {
        // A new press: the one before has ended.
        tail = null;
        times.length = orders.length = 0;
      }
    },
    step(now) {
      if (!Number.isFinite(now)) throw new RangeError(`HeaveTiming.step: now must be finite s, got ${now}`);
      if (dir !== 0) return { dir, letGoAt: Number.NaN };
      if (!tail) return { dir: 0, letGoAt: Number.NaN };
      if (now < tail.end) return { dir: tail.dir, letGoAt: Number.NaN };
      const end = tail.end;
      tail = null;
      return { dir: 0, letGoAt: end < now ? end : Number.NaN };
    },
    note(now, order) {
      times.push(now);
      orders.push(order);
    },
    orderAt(time) {
      let found = Number.NaN;
      for (let i = 0; i < times.length && times[i]! <= time; i++) found = orders[i]!;
      return found;
    },
    reset() {
      tail = null;
      times.length = orders.length = 0;
    },
  };
}

/**
 * The most game time a press that no step saw (pressed and let go between two of the page's bursts
 * of steps, inside a stalled frame) runs for, s: what such a press was held on the clock, up to this.
 */
export const MAX_UNSEEN_PRESS = 2;

/**
 * A held control with two opposed directions (the screw's Ahead / Astern) timed by its events'
 * timestamps, so a press acts on the steps for as long as it was held on the clock. The page runs
 * its steps in a burst at each drawn frame and reads the controls once a burst; on a loaded machine
 * the browser draws no frame for a second or two now and then, and a key pressed and let go inside
 * such a stall was never seen by any step: the boat did not answer it at all. Here a press runs from
 * the first step that sees it (`step`) for the time it was held (its let-go's timestamp minus its
 * press's, at most `MAX_UNSEEN_PRESS` s when no step saw it), and no further than its let-go's own
 * game time by the clock of the last step (`clock`; at most `MAX_RELEASE_TAIL` s ahead), so a press
 * held across a pause does not run on for the paused time. A let-go while paused ends the press at
 * once (no game time passes while paused); a press let go while the game ran and paused before its
 * steps caught up runs on after the pause, so that it still gets the time it was held.
 */
export interface PressTiming {
  /** Notes the step just run: the game time after it (`game`, s) and the clock then (`wallMs`, ms, performance.now()). */
  clock(game: number, wallMs: number): void;
  /**
   * An input event at `stamp` (its `timeStamp`, ms) left the control asked as `dir` (-1, 1, or 0
   * for neither), with the game `paused` or running. Call it after every event that can change it;
   * a `dir` unchanged does nothing. A new direction ends the press before it at once.
   * @throws RangeError when `dir` is not -1, 0 or 1, or `stamp` is not finite.
   */
  event(dir: number, stamp: number, paused?: boolean): void;
  /**
   * The direction the control counts as held in for the step at game time `now` (s): the held
   * one, or a let-go press's while it runs on.
   * @throws RangeError when `now` is not finite.
   */
  step(now: number): -1 | 0 | 1;
  /** Forgets the presses so far (a new run); a control still held counts from the next step. */
  reset(): void;
}

/** A new `PressTiming` with nothing pressed. */
export function createPressTiming(): PressTiming {
  let dir: -1 | 0 | 1 = 0,
    game = 0,
    wall = Number.NaN;
  /** The press held now: its timestamp (ms) and the game time of the first step that saw it (NaN: none yet). */
  let since = 0,
    start = Number.NaN;
  /** The let-go press running on: its direction, and its end (game s), or its length (s) from its first step when no step saw it held. */
  let tail: { dir: -1 | 1; length: number; end: number } | null = null;
  return {
    clock(g, wallMs) {
      game = g;
      wall = wallMs;
    },
    event(d, stamp, paused = false) {
      if (d !== -1 && d !== 0 && d !== 1) throw new RangeError(`PressTiming.event: dir must be -1, 0 or 1, got ${d}`);
      if (!Number.isFinite(stamp)) throw new RangeError(`PressTiming.event: stamp must be finite ms, got ${stamp}`);
      if (d === dir) return;
      tail = null;
      if (dir !== 0 && d === 0 && !paused) {
        const held = Math.max(0, (stamp - since) / 1000);
        if (Number.isNaN(start)) tail = { dir, length: Math.min(held, MAX_UNSEEN_PRESS), end: Number.NaN };
        else {
          // The let-go's game time by the last step's clock (see HeaveTiming.event).
          const after = Number.isNaN(wall) ? 0 : Math.min(MAX_RELEASE_TAIL, Math.max(-MAX_RELEASE_TAIL, (stamp - wall) / 1000));
          tail = { dir, length: held, end: Math.min(start + held, game + after) };
        }
      }
      dir = d as -1 | 0 | 1;
      since = stamp;
      start = Number.NaN;
    },
    step(now) {
      if (!Number.isFinite(now)) throw new RangeError(`PressTiming.step: now must be finite s, got ${now}`);
      if (dir !== 0) {
        if (Number.isNaN(start)) start = now;
        return dir;
      }
      if (!tail) return 0;
      if (Number.isNaN(tail.end)) tail.end = now + tail.length;
      if (now < tail.end) return tail.dir;
      tail = null;
      return 0;
    },
    reset() {
      tail = null;
      start = Number.NaN;
    },
  };
}
