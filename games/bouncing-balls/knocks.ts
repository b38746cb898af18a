/**
 * Which collisions of a step are heard: a pile of balls starts dozens of contacts a step, and a knock
 * for each made a wall of noise (one throw into the pile, 257 sounds in 2.5 s). The limiter keeps
 * the loudest few impacts of a step above a minimum impulse, lets a body sound again only after a
 * cooldown, and spends from a budget of knocks a second that refills over time, so a settling pile
 * ticks a few times while a throw's first hit is still heard. Pure: no DOM, no audio (Node tests).
 */

/** Options of `createKnockLimiter`. */
export interface KnockLimits {
  /** Quietest impulse heard, N s (> 0). */
  minImpulse: number;
  /** Most knocks a step, integer >= 1 (the loudest of the step). */
  perStep: number;
  /** A body that knocked is silent this long, s (>= 0) (0 and negative handles, the walls, are never silenced). */
  cooldown: number;
  /** Knocks a second the budget refills with, > 0; it holds at most `burst` (>= 1). */
  perSecond: number;
  burst: number;
}

/** The bouncing-balls game's limits: a knock from 0.6 N s, 2 a step, 0.12 s per body, 10 a second (bursts of 4). */
export const KNOCK_LIMITS: Readonly<KnockLimits> = Object.freeze({ minImpulse: 0.6, perStep: 2, cooldown: 0.12, perSecond: 10, burst: 4 });

/** An impact offered to the limiter: the two bodies (handles) and its impulse, N s. */
export interface Knock {
  a: number;
  b: number;
  impulse: number;
}

/** The limiter: `offer` each impact of a step, then `take` the ones to play. */
export interface KnockLimiter {
  /** An impact of the current step. Quieter than minImpulse: dropped at once. */
  offer(a: number, b: number, impulse: number): void;
  /**
   * The knocks to play for the step that ended at world time `time`, s, loudest first (at most
   * perStep, bodies out of their cooldown, within the budget); clears the step's offers.
   * @throws RangeError on a non-finite time.
   */
  take(time: number): Knock[];
}

/** A knock limiter with `limits`. @throws RangeError naming the limit that is out of range. */
export function createKnockLimiter(limits: KnockLimits = KNOCK_LIMITS): KnockLimiter {
  const { minImpulse, perStep, cooldown, perSecond, burst } = limits;
  if (!(minImpulse > 0 && Number.isFinite(minImpulse)))
    throw new RangeError(`createKnockLimiter: minImpulse must be > 0, got ${minImpulse}`);
  if (!(Number.isInteger(perStep) && perStep >= 1))
    throw new RangeError(`createKnockLimiter: perStep must be an integer >= 1, got ${perStep}`);
  if (!(cooldown >= 0 && Number.isFinite(cooldown))) throw new RangeError(`createKnockLimiter: cooldown must be >= 0 s, got ${cooldown}`);
  if (!(perSecond > 0 && Number.isFinite(perSecond))) throw new RangeError(`createKnockLimiter: perSecond must be > 0, got ${perSecond}`);
  if (!(burst >= 1 && Number.isFinite(burst))) throw new RangeError(`createKnockLimiter: burst must be >= 1, got ${burst}`);
  const pending: Knock[] = [];
  const lastAt = new Map<number, number>();
  let budget = burst,
    last = Number.NaN;
  const quiet = (body: number, time: number): boolean => body > 0 && time - (lastAt.get(body) ?? -Infinity) < cooldown;
  return {
    offer(a, b, impulse) {
      if (impulse >= minImpulse) pending.push({ a, b, impulse });
    },
    take(time) {
      if (!Number.isFinite(time)) throw new RangeError(`KnockLimiter.take: time must be finite, got ${time}`);
      // A new world (time went back) starts afresh.
      if (!(time >= last)) {
        lastAt.clear();
        budget = burst;
      } else budget = Math.min(burst, budget + (time - last) * perSecond);
      last = time;
      pending.sort((p, q) => q.impulse - p.impulse);
      const out: Knock[] = [];
      for (const k of pending) {
        if (out.length === perStep || budget < 1) break;
        if (quiet(k.a, time) || quiet(k.b, time)) continue;
        out.push(k);
        budget -= 1;
        if (k.a > 0) lastAt.set(k.a, time);
        if (k.b > 0) lastAt.set(k.b, time);
      }
      pending.length = 0;
      return out;
    },
  };
}
