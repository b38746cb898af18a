/**
 * Chooses, loop by loop, between running a parallel loop on the pool's threads and running the same
 * kernel on the calling thread alone, by the time each took (per element). A loop that the
 * threads do not speed up (too short to pay for waking the workers, or a machine whose other cores
 * are busy) so falls back to one thread by itself, and probes the threads again now and then. Both
 * ways run the same kernel on the same data, so the choice never changes a result, only the time.
 *
 * Policy per loop (a `site`): the first three calls run parallel (the first is not timed: it may pay
 * for sending arrays to the workers), the next two on one thread; from then on the faster way by its
 * estimate, except every probePeriod-th call, which runs the other way to keep its estimate current
 * (a machine that got quieter or busier is noticed within a few probes): often while the loop is
 * young and the two ways are close, rarely once one way is clearly faster.
 *
 * A way's estimate is the least of its last WINDOW times. On a shared machine a delay is another
 * process's, or a worker the system did not schedule, or a garbage collection: it says nothing of
 * what the way costs, and one delayed call must not switch a loop. It takes WINDOW slow calls in a row
 * to raise the estimate, so a loop whose work grows (a pile forming) is followed within WINDOW calls.
 * The average this replaced (a faster time taken at once, a slower one weighted 0.3) let one delayed
 * call switch a loop to the other way until the next probe, up to PROBE_EVERY calls: balls-in-box's
 * cell pass (20,000 balls, 2 threads) ran 92 of 181 steps on one thread at 4.8 ms a call against 2.6
 * ms on the threads, after delays of 5 to 40 ms in single calls of the threads.
 */

/** Calls between two runs of the way not currently preferred. */
export const PROBE_EVERY = 16;

/** Calls, from the first, during which an undecided loop is probed more often (EARLY_PROBE_EVERY). */
export const EARLY_CALLS = 64;
/** Calls between two probes while a loop is young and the two ways are within CLEAR_RATIO of each other. */
export const EARLY_PROBE_EVERY = 4;
/** Calls between two probes once a loop's ways differ by more than CLEAR_RATIO, after EARLY_CALLS. */
export const CLEAR_PROBE_EVERY = 64;
/**
 * Ratio of the two ways' estimates above which the choice is clear (probed less often). A probe of
 * the slower way costs the difference once: at 1.25 and CLEAR_PROBE_EVERY that is under 0.4 % of the
 * loop's time, where probing every PROBE_EVERY calls cost 3 % of balls-in-box's coloured solve
 * (20,000 balls, 2 threads, 6 ms a probe at a ratio of 1.48, under the 1.5 this was).
 */
export const CLEAR_RATIO = 1.25;

/**
 * Calls between probes of the way not preferred, at call `c` with estimates `a` and `b` (ms per
 * element, positive): a close call is probed every EARLY_PROBE_EVERY calls while the loop is young
 * (one noisy first sample, such as a worker still compiling the kernel or a burst of other
 * processes, is then undone within a few calls instead of sixteen) and every PROBE_EVERY after; a
 * clear one (a ratio above CLEAR_RATIO) every PROBE_EVERY while young and every CLEAR_PROBE_EVERY
 * after (a probe of a way that is twice as slow costs a whole extra run of the loop).
 */
export function probePeriod(c: number, a: number, b: number): number {
  const clear = a > CLEAR_RATIO * b || b > CLEAR_RATIO * a;
  if (c < EARLY_CALLS) return clear ? PROBE_EVERY : EARLY_PROBE_EVERY;
  return clear ? CLEAR_PROBE_EVERY : PROBE_EVERY;
}

/** Times a way's estimate is the least of (see the file's header). */
export const WINDOW = 3;

/** What is known of one loop. */
interface Site {
  /** Calls so far. */
  calls: number;
  /** The last WINDOW times per element, ms, of each way (NaN: none yet; the estimate is the least, see `least`), and where each way writes its next. */
  parallelTimes: Float64Array;
  serialTimes: Float64Array;
  parallelNext: number;
  serialNext: number;
}

/** Clock in milliseconds: performance.now where the host has it (Node, browsers, workers), else Date.now. */
export function nowMs(): number {
  const p = (globalThis as { performance?: { now(): number } }).performance;
  return p !== undefined ? p.now() : Date.now();
}

/** The choices of one pool (see the file's header). */
export class LoopChooser {
  private readonly sites = new Map<string, Site>();

  /** Whether the next call of loop `site` should run on the threads (true) or on one thread. */
  choose(site: string): boolean {
    let s = this.sites.get(site);
    if (s === undefined) {
      s = {
        calls: 0, parallelTimes: new Float64Array(WINDOW).fill(NaN),
        serialTimes: new Float64Array(WINDOW).fill(NaN), parallelNext: 0, serialNext: 0,
      };
      this.sites.set(site, s);
    }
    const c = s.calls;
    if (c < 3) return true;
    const parallel = least(s.parallelTimes), serial = least(s.serialTimes);
    if (c < 5 || Number.isNaN(serial)) return false;
    if (Number.isNaN(parallel)) return true;
    const preferParallel = parallel <= serial;
    return c % probePeriod(c, parallel, serial) === 0 ? !preferParallel : preferParallel;
  }

  /** Records that a call of `site` ran `parallel` or not and took `ms` for `n` (> 0) elements. */
  record(site: string, parallel: boolean, ms: number, n: number): void {
    const s = this.sites.get(site);
    if (s === undefined) return;
    const first = s.calls === 0;
    s.calls++;
    if (first || !(n > 0) || !(ms >= 0)) return;
    const v = ms / n;
    // Into the way's window of its last WINDOW times (see the file's header). Both ways follow the
    // same rule, probes included, so neither is favoured by having more samples.
    const at = parallel ? s.parallelNext : s.serialNext;
    (parallel ? s.parallelTimes : s.serialTimes)[at] = v;
    if (parallel) s.parallelNext = (at + 1) % WINDOW; else s.serialNext = (at + 1) % WINDOW;
  }

  /** The current preference of `site`: true threads, false one thread, null not decided yet. */
  preference(site: string): boolean | null {
    const s = this.sites.get(site);
    if (s === undefined) return null;
    const parallel = least(s.parallelTimes), serial = least(s.serialTimes);
    if (Number.isNaN(parallel) || Number.isNaN(serial)) return null;
    return parallel <= serial;
  }
}

/** A way's estimate, ms per element: the least of its window's times (NaN when it has none). */
function least(times: Float64Array): number {
  let est = Infinity;
  for (let k = 0; k < times.length; k++) if (times[k]! < est) est = times[k]!; // NaN (no time) is never less
  return est === Infinity ? NaN : est;
}
