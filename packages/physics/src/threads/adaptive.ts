/**
 * Chooses, loop by loop, between running a parallel loop on the pool's threads and running the same
 * kernel on the calling thread alone, by the time each took (per element). A loop that the
 * threads do not speed up (too short to pay for waking the workers, or a machine whose other cores
 * are busy) so falls back to one thread by itself, and probes the threads again now and then. Both
 * ways run the same kernel on the same data, so the choice never changes a result, only the time.
 *
 * Policy per loop (a `site`): the first three calls run parallel (the first is not timed: it may pay
 * for sending arrays to the workers), the next two on one thread; from then on the faster way by its
 * estimate, except that now and then a call runs the other way (a probe) to keep its estimate
 * current, so a machine that got quieter or busier is noticed. The calls between probes back off: a
 * probe that confirms the choice doubles them from MIN_PROBE_PERIOD up to PROBE_EVERY while the two
 * ways are within CLEAR_RATIO of each other, and quadruples them up to CLEAR_PROBE_EVERY once one is
 * clearly faster (nextProbePeriod); a change of the preferred way, by a probe or by the preferred
 * way's own calls getting slower, resets them to MIN_PROBE_PERIOD. So a switch that a passing delay
 * caused is undone within a few calls, and a choice that holds is probed rarely (with a fixed period,
 * WINDOW delayed calls of the threads in a row would put a loop on the slower way for a whole
 * CLEAR_PROBE_EVERY calls). The way not preferred takes over only when
 * its estimate is below SWITCH_RATIO times the preferred way's, so close ways do not trade places
 * back and forth.
 *
 * A way's estimate is the least of its last WINDOW times. On a shared machine a delay is another
 * process's, or a worker the system did not schedule, or a garbage collection: it says nothing of
 * what the way costs, and one delayed call must not switch a loop. It takes WINDOW slow calls in a row
 * to raise the estimate, so a loop whose work grows (a pile forming) is followed within WINDOW calls.
 * But the way not preferred runs only as probes, up to CLEAR_PROBE_EVERY calls apart, and its older
 * probes tell what it cost long ago: a time older than MAX_AGE calls counts only while it is its way's
 * newest. And when the preferred way's own calls have grown past the other way's estimate and the
 * other way's newest time is older than MIN_PROBE_PERIOD calls, the call runs the other way as a probe
 * instead of switching, its time replaces that way's window, and the two estimates then decide
 * (switching on the old times would move a loop whose work grows on both ways, a pile forming, to the
 * slower way). A least-of-window estimate, unlike an average, cannot be switched by one delayed call.
 */

/**
 * Calls between two probes right after a loop's preferred way changed (and at its start).
 * @category Threads
 */
export const MIN_PROBE_PERIOD = 4;
/**
 * Most calls between two probes while the two ways' estimates are within CLEAR_RATIO of each other.
 * @category Threads
 */
export const PROBE_EVERY = 16;
/**
 * Most calls between two probes once one way's estimate is more than CLEAR_RATIO times the other's.
 * @category Threads
 */
export const CLEAR_PROBE_EVERY = 64;
/**
 * Ratio of the two ways' estimates above which the choice is clear (probed at most every
 * CLEAR_PROBE_EVERY calls). A probe of the slower way costs the difference once: at 1.25 and
 * CLEAR_PROBE_EVERY that is under 0.4 % of the loop's time, where probing every PROBE_EVERY calls
 * costs several percent.
 * @category Threads
 */
export const CLEAR_RATIO = 1.25;

/**
 * Calls until the next probe after a probe that confirmed the choice, from the calls `period` before
 * it and the two ways' estimates `a` and `b` (ms per element, positive): when one estimate is more
 * than CLEAR_RATIO times the other, four times `period`, at most CLEAR_PROBE_EVERY (a probe of a clearly
 * slower way costs the most and tells the least); else twice `period`, at most PROBE_EVERY.
 * @category Threads
 */
export function nextProbePeriod(period: number, a: number, b: number): number {
  const clear = a > CLEAR_RATIO * b || b > CLEAR_RATIO * a;
  return clear ? Math.min(4 * period, CLEAR_PROBE_EVERY) : Math.min(2 * period, PROBE_EVERY);
}

/**
 * How much faster the way not preferred must look to take over (its estimate below this times the
 * preferred way's). Two ways within 10 % of each other cost about the same, but each change of the
 * preferred way brings probes MIN_PROBE_PERIOD calls apart, and a least-of-WINDOW estimate can be one
 * lucky call (a worker that happened to be awake): balls-in-box's cell pass (20,000 balls, 2 threads)
 * ran at 0.7 to 1.0 of its one-thread time and changed ways 7 times in 40 steps. With the margin a
 * step took 0.979, 0.982, 0.997, 1.002 and 0.977 of before in process (0.93 in steps 150 to 180).
 * @category Threads
 */
export const SWITCH_RATIO = 0.9;

/**
 * Times a way's estimate is the least of (see the file's header).
 * @category Threads
 */
export const WINDOW = 3;

/**
 * Calls after which a time no longer counts in its way's estimate, unless it is the way's newest (see the file's header).
 * @category Threads
 */
export const MAX_AGE = PROBE_EVERY;

/** What is known of one loop. */
interface Site {
  /** Calls so far. */
  calls: number;
  /** The last WINDOW times per element, ms, of each way (NaN: none yet; the estimate is the least, see `least`), and where each way writes its next. */
  parallelTimes: Float64Array;
  serialTimes: Float64Array;
  parallelNext: number;
  serialNext: number;
  /** The way preferred at the last choice (null: none yet), calls between probes now, calls since the last probe or change. */
  preferred: boolean | null;
  period: number;
  since: number;
  /** Whether the call chosen last is a probe, and whether it checks a switch the estimates asked for (see the file's header). */
  probing: boolean;
  checking: boolean;
  /** The call (`calls` before it) that gave each time of the windows. */
  parallelCalls: Float64Array;
  serialCalls: Float64Array;
}

/**
 * Clock in milliseconds: performance.now where the host has it (Node, browsers, workers), else Date.now.
 * @category Threads
 */
export function nowMs(): number {
  const p = (globalThis as { performance?: { now(): number } }).performance;
  return p !== undefined ? p.now() : Date.now();
}

/**
 * The choices of one pool (see the file's header).
 * @category Threads
 */
export class LoopChooser {
  private readonly sites = new Map<string, Site>();

  /** Whether the next call of loop `site` should run on the threads (true) or on one thread. */
  choose(site: string): boolean {
    let s = this.sites.get(site);
    if (s === undefined) {
      s = {
        calls: 0,
        parallelTimes: new Float64Array(WINDOW).fill(NaN),
        serialTimes: new Float64Array(WINDOW).fill(NaN),
        parallelNext: 0,
        serialNext: 0,
        preferred: null,
        period: MIN_PROBE_PERIOD,
        since: 0,
        probing: false,
        checking: false,
        parallelCalls: new Float64Array(WINDOW),
        serialCalls: new Float64Array(WINDOW),
      };
      this.sites.set(site, s);
    }
    const c = s.calls;
    if (c < 3) return true;
    const parallel = least(s.parallelTimes, s.parallelCalls, c),
      serial = least(s.serialTimes, s.serialCalls, c);
    if (c < 5 || Number.isNaN(serial)) return false;
    if (Number.isNaN(parallel)) return true;
    const preferParallel = prefers(s.preferred, parallel, serial);
    if (s.preferred !== null && s.preferred !== preferParallel) {
      // The preferred way's own calls got slower. If the other way's newest time is older than
      // MIN_PROBE_PERIOD calls, this call runs it as a probe: its time then decides (record).
      const otherAt = s.preferred ? newestCall(s.serialTimes, s.serialCalls) : newestCall(s.parallelTimes, s.parallelCalls);
      if (c - otherAt > MIN_PROBE_PERIOD) {
        s.probing = true;
        s.checking = true;
        s.since = 0;
        return preferParallel;
      }
    }
    // A change of the preferred way is checked back on soon.
    if (s.preferred !== preferParallel) {
      s.preferred = preferParallel;
      s.period = MIN_PROBE_PERIOD;
      s.since = 0;
    }
    s.probing = ++s.since >= s.period;
    if (!s.probing) return preferParallel;
    s.since = 0;
    return !preferParallel;
  }

  /** Records that a call of `site` ran `parallel` or not and took `ms` for `n` (> 0) elements. */
  record(site: string, parallel: boolean, ms: number, n: number): void {
    const s = this.sites.get(site);
    if (s === undefined) return;
    const first = s.calls === 0,
      probe = s.probing,
      checking = s.checking,
      call = s.calls;
    s.calls++;
    s.probing = false;
    s.checking = false;
    if (first || !(n > 0) || !(ms >= 0)) return;
    const v = ms / n;
    // Into the way's window of its last WINDOW times (see the file's header). Both ways follow the
    // same rule, probes included, so neither is favoured by having more samples; but the time of a
    // probe that checks a switch replaces the window, so the switch is judged by what the way costs now.
    const times = parallel ? s.parallelTimes : s.serialTimes;
    if (checking) times.fill(NaN);
    const at = checking ? 0 : parallel ? s.parallelNext : s.serialNext;
    times[at] = v;
    (parallel ? s.parallelCalls : s.serialCalls)[at] = call;
    if (parallel) s.parallelNext = (at + 1) % WINDOW;
    else s.serialNext = (at + 1) % WINDOW;
    if (!probe) return;
    // A probe: the choice confirmed backs off; a changed one is checked back on soon (the probe that
    // made the change counts as the first call of the new way when it checked a switch).
    const a = least(s.parallelTimes, s.parallelCalls, s.calls),
      b = least(s.serialTimes, s.serialCalls, s.calls);
    const p = prefers(s.preferred, a, b);
    if (p === s.preferred) s.period = nextProbePeriod(s.period, a, b);
    else {
      s.preferred = p;
      s.period = MIN_PROBE_PERIOD;
      s.since = checking ? 1 : 0;
    }
  }

  /** The current preference of `site`: true threads, false one thread, null not decided yet. */
  preference(site: string): boolean | null {
    const s = this.sites.get(site);
    if (s === undefined) return null;
    const parallel = least(s.parallelTimes, s.parallelCalls, s.calls),
      serial = least(s.serialTimes, s.serialCalls, s.calls);
    if (Number.isNaN(parallel) || Number.isNaN(serial)) return null;
    return parallel <= serial;
  }
}

/**
 * Whether the threads are preferred, from the estimates `a` (threads) and `b` (one thread) and the
 * preference so far `was` (null: none yet, the smaller estimate wins): the other way takes over only
 * when its estimate is below SWITCH_RATIO times the preferred way's (NaN: never).
 */
function prefers(was: boolean | null, a: number, b: number): boolean {
  if (was === null) return a <= b;
  return was ? !(b < SWITCH_RATIO * a) : a < SWITCH_RATIO * b;
}

/**
 * A way's estimate, ms per element, at call `now`: the least of its window's `times` taken within the
 * last MAX_AGE calls (`calls`: the call of each), or its newest time when none is (NaN when it has none).
 */
function least(times: Float64Array, calls: Float64Array, now: number): number {
  let est = Infinity,
    newest = NaN,
    at = -1;
  for (let k = 0; k < times.length; k++) {
    const t = times[k]!;
    if (t !== t) continue; // NaN: no time
    if (now - calls[k]! <= MAX_AGE && t < est) est = t;
    if (calls[k]! > at) {
      at = calls[k]!;
      newest = t;
    }
  }
  return est === Infinity ? newest : est;
}

/** The call that gave a way's newest time (`times` and `calls` as least's), -1 when it has none. */
function newestCall(times: Float64Array, calls: Float64Array): number {
  let at = -1;
  for (let k = 0; k < times.length; k++) if (times[k] === times[k] && calls[k]! > at) at = calls[k]!;
  return at;
}
