/** Summary of per-step times. */
export interface TimeSummary {
  /** Median, ms (mean of the two middle values for an even count). */
  readonly median: number;
  /** Fastest step, ms. */
  readonly min: number;
  /** Slowest step, ms. */
  readonly max: number;
  /** Arithmetic mean, ms. */
  readonly mean: number;
  /** 90th percentile (nearest rank), ms. */
  readonly p90: number;
}

/**
 * Median, min, max, mean and 90th percentile of `times` (ms).
 * @throws RangeError if `times` is empty.
 */
export function summarize(times: ArrayLike<number>): TimeSummary {
  const n = times.length;
  if (n === 0) throw new RangeError('summarize: no times');
  const sorted = Float64Array.from(times).sort();
  let sum = 0;
  for (let i = 0; i < n; i++) sum += sorted[i]!;
  const median = n % 2 === 1 ? sorted[(n - 1) / 2]! : 0.5 * (sorted[n / 2 - 1]! + sorted[n / 2]!);
  return {
    median,
    min: sorted[0]!,
    max: sorted[n - 1]!,
    mean: sum / n,
    p90: sorted[Math.min(n - 1, Math.ceil(0.9 * n) - 1)]!,
  };
}

/** Median of `values` (mean of the two middle values for an even count). @throws RangeError if empty. */
export function median(values: ArrayLike<number>): number {
  return summarize(values).median;
}
