/**
 * How a pool cuts a loop of n elements into its threads' ranges (pool.ts). The threads are not equally
 * fast at a loop: a worker reads data the calling thread has just written (the grid, the contacts),
 * which its core fetches from the other core's cache, and it starts only once it has been woken. With
 * equal ranges the worker's half of a loop can take well over the caller's, which then waits.
 *
 * So each kernel keeps a share of the elements per thread, learnt from when each thread finished:
 * after a run, thread i's time is from the caller waking the workers to the end of its range
 * (wake-up included; the workers stamp their end on the clock every thread shares,
 * performance.timeOrigin + now()), and the shares move `RATE` of the way towards shares in
 * proportion to share / time, normalised. That leaves the shares where every thread finishes at
 * once. Equal shares to begin with.
 *
 * Which thread runs which range never changes a result: every kernel writes per-element outputs or
 * per-range buffers appended in range order (the one-thread order), as it must for its results not to
 * depend on the number of threads (step/kernel-table.ts). Loops shorter than `BALANCE_MIN_PER_THREAD`
 * elements a thread (such as the coloured solve's, whose n is the thread count and whose blocks are
 * claimed dynamically) are cut equally.
 */

/**
 * Fewest elements a thread for a loop's ranges to follow its learnt shares (else equal ranges).
 * @category Threads
 */
export const BALANCE_MIN_PER_THREAD = 256;

/** Fraction of the way the shares move towards the measured balance after each run. */
const RATE = 0.25;

/** Least share of a loop any thread keeps (so its time is still measured). */
const MIN_SHARE = 0.05;

/** Kernels a pool can hold shares for (step/kernel-table.ts has fewer). */
const MAX_KERNELS = 64;

/**
 * Milliseconds since the epoch with the resolution of performance.now(), on one clock across the
 * threads of a process (Node's worker_threads and a page's workers: their timeOrigin differs, the sum
 * does not); Date.now() where there is no performance.
 * @category Threads
 */
export function epochMs(): number {
  const p = (globalThis as { performance?: { now(): number; timeOrigin: number } }).performance;
  return p !== undefined ? p.timeOrigin + p.now() : Date.now();
}

/**
 * The learnt shares of one pool's loops (see the file's header).
 * @category Threads
 */
export class RangeBalance {
  private readonly threads: number;
  /** Shares: kernel k's thread i at k * threads + i, summing to 1 per kernel. */
  private readonly shares: Float64Array;
  /** Whether the shares are held (`hold`), not learnt. */
  private held = false;
  /** Scratch of `record`: each thread's share per ms in the run. */
  private readonly speed: Float64Array;

  constructor(threads: number) {
    this.threads = threads;
    this.shares = new Float64Array(MAX_KERNELS * threads).fill(1 / threads);
    this.speed = new Float64Array(threads);
  }

  /**
   * Writes the first element of each thread's range of kernel `kernel`'s loop of `n` elements into
   * out[at .. at + threads] (out[at] = 0, out[at + threads] = n, non-decreasing).
   */
  bounds(kernel: number, n: number, out: Int32Array, at: number): void {
    const t = this.threads,
      sh = this.shares,
      o = kernel * t;
    const balanced = kernel < MAX_KERNELS && n >= BALANCE_MIN_PER_THREAD * t;
    out[at] = 0;
    let acc = 0;
    for (let i = 1; i < t; i++) {
      acc += balanced ? sh[o + i - 1]! : 1 / t;
      out[at + i] = balanced ? Math.min(n, Math.round(n * acc)) : Math.floor((n * i) / t);
    }
    out[at + t] = n;
  }

  /**
   * Learns from a run of kernel `kernel` over `n` elements that the caller started at `start` (epochMs,
   * before waking the workers), the caller finishing its range at `own` and worker i at `finished[i]`.
   * Loops cut equally (short ones) teach nothing.
   */
  record(kernel: number, n: number, start: number, own: number, finished: Float64Array): void {
    const t = this.threads;
    if (this.held || kernel >= MAX_KERNELS || n < BALANCE_MIN_PER_THREAD * t) return;
    const sh = this.shares,
      o = kernel * t,
      speed = this.speed;
    let sum = 0;
    for (let i = 0; i < t; i++) {
      const time = (i === 0 ? own : finished[i]!) - start;
      if (!(time > 0)) return; // a clock without the resolution to tell
      speed[i] = sh[o + i]! / time; // share per ms
      sum += speed[i]!;
    }
    let norm = 0;
    for (let i = 0; i < t; i++) {
      const next = Math.max(MIN_SHARE, sh[o + i]! + RATE * (speed[i]! / sum - sh[o + i]!));
      sh[o + i] = next;
      norm += next;
    }
    for (let i = 0; i < t; i++) sh[o + i] = sh[o + i]! / norm;
  }

  /**
   * Holds every kernel's loop at `shares` (one per thread, each >= 0, summing to 1 within 1e-9) and
   * stops learning; null: equal shares, learning again. For a caller that knows its machine, and for
   * tests (results do not depend on the shares).
   * @throws RangeError `RangeBalance.hold: shares must be ...` naming the value, on a wrong length, a
   *   negative or non-finite share or a sum other than 1.
   */
  hold(shares: ArrayLike<number> | null): void {
    const t = this.threads;
    if (shares === null) {
      this.held = false;
      this.shares.fill(1 / t);
      return;
    }
    let sum = 0;
    for (let i = 0; i < shares.length; i++) {
      const v = shares[i]!;
      if (!(v >= 0) || !Number.isFinite(v)) throw new RangeError(`RangeBalance.hold: shares must be finite and >= 0, got ${v} at ${i}`);
      sum += v;
    }
    if (shares.length !== t || Math.abs(sum - 1) > 1e-9) {
      throw new RangeError(
        `RangeBalance.hold: shares must be ${t} numbers (one a thread) summing to 1, got ${shares.length} summing to ${sum}`,
      );
    }
    for (let k = 0; k < MAX_KERNELS; k++) for (let i = 0; i < t; i++) this.shares[k * t + i] = shares[i]!;
    this.held = true;
  }

  /** Kernel `kernel`'s current share of thread `thread` (for tests). */
  share(kernel: number, thread: number): number {
    return this.shares[kernel * this.threads + thread]!;
  }
}
