/**
 * Order statistics of timing samples, shared by the app's `stats()` and the benchmark so
 * both report the same figure under the same name.
 */

/** The middle value; the mean of the two middle values for an even count; NaN when empty. */
export function median(samples: readonly number[]): number {
  if (samples.length === 0) return Number.NaN;
  const sorted = [...samples].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 === 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
}

/**
 * Nearest-rank percentile: the smallest sample with at least p % of the samples at or
 * below it. Always one of the samples, so a p95 of 30 frames is the second slowest frame.
 */
export function percentile(samples: readonly number[], p: number): number {
  if (!(p > 0 && p <= 100)) throw new RangeError(`percentile needs 0 < p <= 100, got ${p}.`);
  if (samples.length === 0) return Number.NaN;
  const sorted = [...samples].sort((a, b) => a - b);
  return sorted[Math.ceil((p / 100) * sorted.length) - 1];
}
