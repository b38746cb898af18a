/**
 * Scaling of a threaded run from one measured speedup (`--threads n`): the serial fraction and the
 * speedup Amdahl's law then projects to more cores.
 *
 * Serial fraction (Karp and Flatt, "Measuring parallel processor performance", Commun. ACM 33 (1990)
 * 539): with speedup S measured on p threads, e = (1/S - 1/p) / (1 - 1/p), the fraction of the
 * one-thread step that, under Amdahl's law, would give exactly S on p threads. It includes whatever
 * the threads cost (waking them, waiting for the slowest, work they repeat), so it is the serial
 * fraction as measured, not only the code that runs on one thread. On a loaded machine the other
 * processes take cores from the threads and e comes out larger.
 *
 * Projection (Amdahl, AFIPS 1967): S(N) = 1 / (e + (1 - e) / N) on N cores, assuming the serial
 * fraction stays e (it usually grows with N: more threads to wake, more repeated work at the cuts).
 */

/**
 * Karp-Flatt serial fraction from speedup `speedup` (> 0) on `threads` (>= 2) threads, clamped to
 * [0, 1] (a superlinear speedup gives 0; a speedup below 1, threads slower than one, can exceed 1
 * unclamped). NaN when threads < 2 or the speedup is not a positive finite number.
 */
export function serialFraction(speedup: number, threads: number): number {
  if (!(threads >= 2) || !(speedup > 0) || !Number.isFinite(speedup)) return NaN;
  const e = (1 / speedup - 1 / threads) / (1 - 1 / threads);
  return Math.min(1, Math.max(0, e));
}

/** Amdahl's speedup on `cores` (>= 1) cores for serial fraction `e` in [0, 1]: 1 / (e + (1 - e) / cores). */
export function amdahlSpeedup(e: number, cores: number): number {
  return 1 / (e + (1 - e) / cores);
}

/** Cores the bench projects the speedup to. */
export const PROJECTED_CORES = [8, 16] as const;
