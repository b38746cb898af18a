/**
 * A finger's flick: how fast it was moving as it let go, read from the pointer events' own time
 * stamps (not from frames), so a quick flick up at the hoop throws on a slow phone (10 frames a
 * second: a frame's moves arrive together) as on a fast one. No DOM: the tests run it in Node.
 */

/**
 * The least event time the release speed is read over, ms: from the newest sample at least this long
 * before the release (the press when none is). Not less: a phone's touch sample a few ms before the
 * release, or the frame's last move handed over with it by a slow page, is where the finger lifts.
 */
export const FLICK_SPAN_MS = 30;

/** A release-speed span longer than this, ms (no sample between it and FLICK_SPAN_MS before the release), reads as no flick: a finger that stopped. */
export const FLICK_MAX_SPAN_MS = 200;

/** The slowest flick that throws, CSS px per ms (slower: a finger sliding to aim, or lifting off). */
export const FLICK_MIN_SPEED = 0.6;

/** A flick this fast, CSS px per ms, or faster throws as a full pull does (MAX_THROW_SPEED). */
export const FLICK_FULL_SPEED = 3;

/** The least a flick must point up, degrees over the horizontal (flatter: a slide sideways, not a throw). */
export const FLICK_MIN_RISE_DEG = 20;

/** One pointer sample: where (CSS px, y down) and when (the event's timeStamp, ms). */
export interface FlickSample {
  readonly x: number;
  readonly y: number;
  readonly t: number;
}

/** The samples of the current press kept for its release speed (the last FLICK_MAX_SPAN_MS of them and the one before). */
export class FlickTracker {
  private samples: FlickSample[] = [];

  /** Starts a new press at (x, y), CSS px, at event time `t`, ms. */
  press(x: number, y: number, t: number): void {
    this.samples = [{ x, y, t }];
  }

  /**
   * Adds a move of the press to (x, y), CSS px, at event time `t`, ms (each of a pointermove's
   * coalesced events in turn: a slow page hands a frame's moves over at once, each with its time).
   * A sample older than the last one kept is ignored; the ones far behind the newest are dropped.
   */
  move(x: number, y: number, t: number): void {
    const last = this.samples[this.samples.length - 1];
    if (!last || !(t >= last.t)) return;
    this.samples.push({ x, y, t });
    while (this.samples.length > 2 && this.samples[1]!.t <= t - FLICK_MAX_SPAN_MS) this.samples.shift();
  }

  /**
   * The finger's velocity as it lets go at (x, y), CSS px, at event time `t`, ms: px per ms (y down),
   * from the newest sample at least FLICK_SPAN_MS before `t` (the press when none is) to the
   * release; [0, 0] when that span is 0 or longer than FLICK_MAX_SPAN_MS, or no press was made.
   */
  release(x: number, y: number, t: number): [number, number] {
    this.move(x, y, t);
    const end = this.samples[this.samples.length - 1];
    if (!end) return [0, 0];
    let from = this.samples[0]!;
    for (const s of this.samples) if (s !== end && s.t <= end.t - FLICK_SPAN_MS) from = s;
    const dt = end.t - from.t;
    if (!(dt > 0) || dt > FLICK_MAX_SPAN_MS) return [0, 0];
    return [(end.x - from.x) / dt, (end.y - from.y) / dt];
  }
}

/**
 * The slingshot pull, CSS px (the pointer minus the ball's start, y down), that throws as a flick at
 * velocity (vx, vy), px per ms (y down), does: opposite to the flick, FLICK_FULL_SPEED giving
 * `fullPull` (a full-speed throw); null when it is no flick: slower than FLICK_MIN_SPEED or pointing
 * up less than FLICK_MIN_RISE_DEG.
 * @throws RangeError unless the velocity is finite and fullPull is finite and > 0.
 */
export function flickPull(vx: number, vy: number, fullPull: number): [number, number] | null {
  if (!(Number.isFinite(vx) && Number.isFinite(vy))) throw new RangeError(`flickPull: velocity must be finite, got (${vx}, ${vy})`);
  if (!(fullPull > 0 && Number.isFinite(fullPull))) throw new RangeError(`flickPull: fullPull must be finite and > 0 px, got ${fullPull}`);
  const speed = Math.hypot(vx, vy);
  if (speed < FLICK_MIN_SPEED || -vy < speed * Math.sin((FLICK_MIN_RISE_DEG * Math.PI) / 180)) return null;
  const length = fullPull * Math.min(1, speed / FLICK_FULL_SPEED);
  return [(-vx / speed) * length, (-vy / speed) * length];
}
