/**
 * What the probe measures on a record of the sea's height at one point, η(tᵢ): the figures a
 * wave buoy reports, each as a student could work it out by hand from the chart.
 * - The mean zero up-crossing period Tz: the mean time between successive moments when η
 *   rises through its mean (Holthuijsen, "Waves in Oceanic and Coastal Waters", 2007, §4.1).
 * - The significant height Hs = 4σ(η) (the same, §4.2: 4√m₀ for a sea drawn from a spectrum).
 * - The crest-to-trough height: the highest η less the lowest, over the record.
 * The samples need not be evenly spaced (a record taken once per drawn frame is not).
 */

export interface HeightRecord {
  /** Sample times, seconds, increasing. */
  times: ArrayLike<number>;
  /** η at those times, metres. */
  heights: ArrayLike<number>;
}

/** Mean of the heights, each weighted by the time it stands for (half the gap to each neighbour). */
export function timeMean(record: HeightRecord): number {
  const { times, heights } = record;
  const n = heights.length;
  if (n === 0) return Number.NaN;
  if (n === 1) return heights[0];
  let sum = 0;
  let total = 0;
  for (let i = 0; i < n; i++) {
    const w = (times[Math.min(i + 1, n - 1)] - times[Math.max(i - 1, 0)]) / 2;
    sum += w * heights[i];
    total += w;
  }
  return total > 0 ? sum / total : Number.NaN;
}

/**
 * The times at which η rises through `level`, each found by linear interpolation between the
 * two samples that straddle it (a sample exactly at the level counts as the crossing).
 */
export function upCrossings(record: HeightRecord, level = timeMean(record)): number[] {
  const { times, heights } = record;
  const crossings: number[] = [];
  for (let i = 1; i < heights.length; i++) {
    const a = heights[i - 1] - level;
    const b = heights[i] - level;
    if (a < 0 && b >= 0) crossings.push(times[i - 1] + ((times[i] - times[i - 1]) * -a) / (b - a));
  }
  return crossings;
}

/**
 * Tz: the span from the first up-crossing to the last, over the number of waves between them.
 * Counting whole waves between crossings (rather than dividing the record's length by a count)
 * leaves no half wave at either end to bias it. NaN with fewer than two up-crossings.
 */
export function meanUpCrossingPeriod(record: HeightRecord): number {
  const crossings = upCrossings(record);
  if (crossings.length < 2) return Number.NaN;
  return (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
}

/** Hs = 4σ(η), σ the time-weighted standard deviation about the mean. */
export function significantHeight(record: HeightRecord): number {
  const { times, heights } = record;
  const n = heights.length;
  if (n < 2) return Number.NaN;
  const mean = timeMean(record);
  let sum = 0;
  let total = 0;
  for (let i = 0; i < n; i++) {
    const w = (times[Math.min(i + 1, n - 1)] - times[Math.max(i - 1, 0)]) / 2;
    sum += w * (heights[i] - mean) ** 2;
    total += w;
  }
  return 4 * Math.sqrt(sum / total);
}

/** The highest height less the lowest, metres. */
export function crestToTrough(record: HeightRecord): number {
  const { heights } = record;
  if (heights.length === 0) return Number.NaN;
  let lo = Infinity;
  let hi = -Infinity;
  for (let i = 0; i < heights.length; i++) {
    lo = Math.min(lo, heights[i]);
    hi = Math.max(hi, heights[i]);
  }
  return hi - lo;
}

/** The probe's figures for one record. */
export interface ProbeFigures {
  /** Tz, seconds (NaN when fewer than two waves were recorded). */
  period: number;
  /** 4σ(η), metres. */
  significantHeight: number;
  /** max η − min η, metres. */
  crestToTrough: number;
  /** Up-crossings counted. */
  crossings: number;
}

export function probeFigures(record: HeightRecord): ProbeFigures {
  return {
    period: meanUpCrossingPeriod(record),
    significantHeight: significantHeight(record),
    crestToTrough: crestToTrough(record),
    crossings: upCrossings(record).length,
  };
}
