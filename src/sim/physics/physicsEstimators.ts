import FFT from 'fft.js';

/**
 * What the physics panel measures on a running sea, through the model's CPU twin only
 * (a sampler (x, z, t) → height of the surface above that world point). Each estimator is
 * the textbook one, so a student can redo it by hand:
 * - dispersion: phases of the surface's spatial Fourier modes tracked over time;
 * - frequency spectrum: Welch's averaged, Hann-windowed periodogram of one point's heights;
 * - Hs = 4 σ(η) and the peak period 2π / ωp.
 */
export type HeightSampler = (x: number, z: number, time: number) => number;

const TWO_PI = 2 * Math.PI;

function isPowerOfTwo(n: number): boolean {
  return Number.isInteger(n) && n >= 2 && (n & (n - 1)) === 0;
}

/** Hann window w(n) = sin²(π n / N), the periodic form used for spectral estimation. */
function hann(n: number): Float64Array {
  const w = new Float64Array(n);
  for (let i = 0; i < n; i++) w[i] = Math.sin((Math.PI * i) / n) ** 2;
  return w;
}

// ───────────────────────────── dispersion ─────────────────────────────

export interface DispersionOptions {
  /** Side of the square patch sampled, metres. Modes are spaced 2π / size rad/m. */
  size: number;
  /** Samples across the patch (power of two); the highest wavenumber is π · resolution / size. */
  resolution: number;
  /** Centre of the patch, metres. */
  centre?: [number, number];
  /** Time of the first snapshot and spacing of snapshots, seconds. ω dt must stay below π. */
  startTime: number;
  timeStep: number;
  /** Snapshots taken (at least 2). */
  snapshots: number;
  /** How many of the strongest modes to report. */
  modes?: number;
}

export interface DispersionPoint {
  /** Wavenumber |k| of the mode, rad/m (power-weighted over the mode's 3 × 3 neighbourhood). */
  k: number;
  /** Measured angular frequency, rad/s: the mean rate at which the mode's phase turns. */
  omega: number;
  /** Mean power of the mode, m² (arbitrary but consistent scale): the weight of this point. */
  power: number;
}

/** In-place 2-D complex FFT of an n × n interleaved array (rows, then columns). */
function fft2(fft: FFT, data: Float64Array, n: number): Float64Array {
  const row = fft.createComplexArray() as number[];
  const out = fft.createComplexArray() as number[];
  for (let r = 0; r < n; r++) {
    for (let c = 0; c < 2 * n; c++) row[c] = data[2 * n * r + c];
    fft.transform(out, row);
    for (let c = 0; c < 2 * n; c++) data[2 * n * r + c] = out[c];
  }
  for (let c = 0; c < n; c++) {
    for (let r = 0; r < n; r++) {
      row[2 * r] = data[2 * (n * r + c)];
      row[2 * r + 1] = data[2 * (n * r + c) + 1];
    }
    fft.transform(out, row);
    for (let r = 0; r < n; r++) {
      data[2 * (n * r + c)] = out[2 * r];
      data[2 * (n * r + c) + 1] = out[2 * r + 1];
    }
  }
  return data;
}

/**
 * ω(k) of the surface, measured. Each snapshot η(x, z, tⱼ) on an n × n patch is Hann-windowed
 * (a sea is not periodic on the patch; the window keeps a wave's energy in the bins next to
 * its own k) and 2-D Fourier transformed. A wave A cos(k·x − ω t + φ) puts into the bin at
 * +k the coefficient ∝ e^{i(φ − ω t)} (FFT kernel e^{−i k·x}), so the phase of that bin falls
 * at rate ω. The rate is measured as the mean of arg(X(tⱼ₊₁) X*(tⱼ)) over the snapshots,
 * which needs ω dt < π. The heights are real, so X(−k) = X(k)*: every wave shows twice, and
 * only the half-plane k_z > 0 (and k_z = 0, kₓ > 0) is read. A wave running toward −k shows
 * in the bin at +k with a rising phase; |rate| is its ω either way.
 */
export function estimateDispersion(sampler: HeightSampler, options: DispersionOptions): DispersionPoint[] {
  return finish(dispersionSteps(sampler, options));
}

/**
 * A measurement as steps: each `next()` does one time's work (a snapshot, a row of samples)
 * and the last returns the result, so a page can spread it over several tasks.
 */
export type Steps<T> = Generator<void, T, void>;

/** Runs `steps` to the end at once. */
export function finish<T>(steps: Steps<T>): T {
  let step = steps.next();
  while (!step.done) step = steps.next();
  return step.value;
}

/** estimateDispersion, one snapshot per step. */
export function* dispersionSteps(sampler: HeightSampler, options: DispersionOptions): Steps<DispersionPoint[]> {
  const { size, resolution: n, startTime, timeStep, snapshots } = options;
  if (!isPowerOfTwo(n)) throw new Error(`Patch resolution must be a power of two, got ${n}.`);
  if (snapshots < 2) throw new Error('Dispersion needs at least two snapshots.');
  const [cx, cz] = options.centre ?? [0, 0];
  const modes = options.modes ?? 24;
  const fft = new FFT(n);
  const window = hann(n);
  const spacing = size / n;

  const bins = n * n;
  const power = new Float64Array(bins);
  const turnRe = new Float64Array(bins);
  const turnIm = new Float64Array(bins);
  let previous: Float64Array | null = null;
  for (let j = 0; j < snapshots; j++) {
    const t = startTime + j * timeStep;
    const data = new Float64Array(2 * bins);
    for (let r = 0; r < n; r++) {
      for (let c = 0; c < n; c++) {
        const x = cx + (c - n / 2) * spacing;
        const z = cz + (r - n / 2) * spacing;
        data[2 * (n * r + c)] = window[r] * window[c] * sampler(x, z, t);
      }
    }
    fft2(fft, data, n);
    for (let b = 0; b < bins; b++) {
      const re = data[2 * b];
      const im = data[2 * b + 1];
      power[b] += (re * re + im * im) / snapshots;
      if (previous) {
        // X(tⱼ₊₁) · conj(X(tⱼ)): summing these before taking the angle weights each step by
        // its power, so a step where the mode is momentarily faint does not throw the rate.
        const pr = previous[2 * b];
        const pi = previous[2 * b + 1];
        turnRe[b] += re * pr + im * pi;
        turnIm[b] += im * pr - re * pi;
      }
    }
    previous = data;
    yield;
  }

  // Bin (r, c) is the wavevector (kc, kr) with indices above n/2 standing for negative ones.
  const signed = (i: number) => (i < n / 2 ? i : i - n);
  const dk = TWO_PI / size;
  const at = (r: number, c: number) => power[n * ((r + n) % n) + ((c + n) % n)];
  const candidates: number[] = [];
  for (let r = 0; r < n; r++) {
    for (let c = 0; c < n; c++) {
      if (r === 0 && c === 0) continue;
      // Keep the local maxima of power only: the bins beside a peak are its leakage.
      const p = at(r, c);
      let isPeak = true;
      for (let a = -1; a <= 1 && isPeak; a++) for (let b = -1; b <= 1; b++) if ((a || b) && at(r + a, c + b) > p) isPeak = false;
      // The Nyquist row and column hold aliased, unsigned modes.
      const upperHalf = signed(r) > 0 || (r === 0 && signed(c) > 0);
      if (isPeak && upperHalf && r !== n / 2 && c !== n / 2) candidates.push(n * r + c);
    }
  }
  candidates.sort((a, b) => power[b] - power[a]);

  const points: DispersionPoint[] = [];
  for (const b of candidates.slice(0, modes)) {
    const r = Math.floor(b / n);
    const c = b % n;
    // The wave's k lies between bins; the power centroid of the 3 × 3 neighbourhood finds it
    // to a fraction of a bin when one wave dominates the peak.
    let sum = 0;
    let kx = 0;
    let kz = 0;
    for (let a = -1; a <= 1; a++) {
      for (let d = -1; d <= 1; d++) {
        const p = at(r + a, c + d);
        sum += p;
        kx += p * (signed(c) + d) * dk;
        kz += p * (signed(r) + a) * dk;
      }
    }
    const omega = Math.abs(Math.atan2(turnIm[b], turnRe[b])) / timeStep;
    points.push({ k: Math.hypot(kx / sum, kz / sum), omega, power: power[b] });
  }
  return points;
}

export interface DispersionFit {
  /** Power-weighted mean of ω_measured / ω_theory(k): 1 for a sea that obeys the theory. */
  ratio: number;
  /** Power-weighted root-mean-square of (ω_measured / ω_theory − 1). */
  rmsRelativeError: number;
  /** Number of points fitted. */
  points: number;
}

/** How well measured points follow a dispersion law ω_theory(k) (e.g. √(g k tanh k h)). */
export function fitDispersion(points: readonly DispersionPoint[], theory: (k: number) => number): DispersionFit {
  let weight = 0;
  let ratio = 0;
  let square = 0;
  for (const p of points) {
    const q = p.omega / theory(p.k);
    weight += p.power;
    ratio += p.power * q;
    square += p.power * (q - 1) ** 2;
  }
  if (!(weight > 0)) throw new Error('No dispersion points to fit.');
  return { ratio: ratio / weight, rmsRelativeError: Math.sqrt(square / weight), points: points.length };
}

// ───────────────────────── frequency spectrum ─────────────────────────

export interface FrequencySpectrumEstimate {
  /** Angular frequencies of the bins, rad/s, from 0 to the Nyquist frequency π / dt. */
  omega: Float64Array;
  /** One-sided spectral density S(ω), m²·s/rad: Σ S Δω is the series' variance. */
  density: Float64Array;
  /** Bin width Δω = 2π / (segment · dt), rad/s. */
  resolution: number;
}

/**
 * Welch's method (Welch 1967): the series is cut into segments of `segment` samples (a power
 * of two) overlapping by half, each has its mean removed and is Hann-windowed, and their
 * periodograms are averaged. Averaging K segments cuts the estimate's scatter by about √K.
 * Normalised by Σ w² so the density integrates to the variance whatever the window.
 */
export function frequencySpectrum(series: ArrayLike<number>, timeStep: number, segment: number): FrequencySpectrumEstimate {
  if (!isPowerOfTwo(segment)) throw new Error(`Segment length must be a power of two, got ${segment}.`);
  if (series.length < segment) throw new Error(`The series (${series.length} samples) is shorter than one segment (${segment}).`);
  const fft = new FFT(segment);
  const window = hann(segment);
  let windowPower = 0;
  for (const w of window) windowPower += w * w;
  const half = segment / 2;
  const sum = new Float64Array(half + 1);
  const input = new Array<number>(segment);
  const out = fft.createComplexArray() as number[];
  let count = 0;
  for (let start = 0; start + segment <= series.length; start += half) {
    let mean = 0;
    for (let i = 0; i < segment; i++) mean += series[start + i];
    mean /= segment;
    for (let i = 0; i < segment; i++) input[i] = (series[start + i] - mean) * window[i];
    fft.realTransform(out, input);
    for (let m = 0; m <= half; m++) sum[m] += out[2 * m] ** 2 + out[2 * m + 1] ** 2;
    count++;
  }
  const resolution = TWO_PI / (segment * timeStep);
  const omega = new Float64Array(half + 1);
  const density = new Float64Array(half + 1);
  for (let m = 0; m <= half; m++) {
    omega[m] = m * resolution;
    // By Parseval, |X|² / (N Σw²) is the two-sided power per bin; double it for one side (not at 0 or Nyquist),
    // and divide by Δω for a density.
    const sides = m === 0 || m === half ? 1 : 2;
    density[m] = (sides * sum[m]) / count / (segment * windowPower) / resolution;
  }
  return { omega, density, resolution };
}

/**
 * The spectral peak ωp: the bin of largest density after a 5-bin running mean (the raw
 * periodogram's scatter moves a lone maximum), refined by a parabola through it and its
 * neighbours, which places the peak between bins.
 */
export function spectralPeak(spectrum: FrequencySpectrumEstimate): number {
  const { density, omega, resolution } = spectrum;
  const smooth = (i: number) => (density[i - 2] + density[i - 1] + density[i] + density[i + 1] + density[i + 2]) / 5;
  let best = 3;
  for (let i = 3; i < density.length - 3; i++) if (smooth(i) > smooth(best)) best = i;
  const a = smooth(best - 1);
  const b = smooth(best);
  const c = smooth(best + 1);
  const denom = a - 2 * b + c;
  const shift = denom < 0 ? (0.5 * (a - c)) / denom : 0;
  return omega[best] + shift * resolution;
}

/** m₀ = ∫ S dω, the variance the spectrum holds. */
export function spectralMoment0(spectrum: FrequencySpectrumEstimate): number {
  let m0 = 0;
  for (const s of spectrum.density) m0 += s * spectrum.resolution;
  return m0;
}

/** Hs = 4 σ(η): the significant wave height of a height series (the standard spectral definition, 4 √m₀). */
export function significantWaveHeight(series: ArrayLike<number>): number {
  let mean = 0;
  for (let i = 0; i < series.length; i++) mean += series[i];
  mean /= series.length;
  let variance = 0;
  for (let i = 0; i < series.length; i++) variance += (series[i] - mean) ** 2;
  return 4 * Math.sqrt(variance / series.length);
}

/** Peak period Tp = 2π / ωp, seconds. */
export function peakPeriod(peakOmega: number): number {
  return TWO_PI / peakOmega;
}

/**
 * Several points' heights η(xₚ, zₚ, t₀ + i dt), i < count, one series per point. Time is the
 * outer loop: a sampler that computes a whole field per time (the FFT twin: all its inverse
 * FFTs for each new t) computes it once for all the points, so P points cost about what one
 * does.
 */
export function heightSeriesAt(
  sampler: HeightSampler,
  points: readonly (readonly [number, number])[],
  startTime: number,
  timeStep: number,
  count: number,
): Float64Array[] {
  return finish(heightSeriesSteps(sampler, points, startTime, timeStep, count));
}

/** heightSeriesAt, one time per step. */
export function* heightSeriesSteps(
  sampler: HeightSampler,
  points: readonly (readonly [number, number])[],
  startTime: number,
  timeStep: number,
  count: number,
): Steps<Float64Array[]> {
  const series = points.map(() => new Float64Array(count));
  for (let i = 0; i < count; i++) {
    const t = startTime + i * timeStep;
    for (let p = 0; p < points.length; p++) series[p][i] = sampler(points[p][0], points[p][1], t);
    yield;
  }
  return series;
}

/** Welch's estimate of each series (frequencySpectrum), averaged bin by bin: one sea's spectrum seen at several points. */
export function meanFrequencySpectrum(series: readonly ArrayLike<number>[], timeStep: number, segment: number): FrequencySpectrumEstimate {
  if (series.length === 0) throw new Error('No series to average.');
  const estimates = series.map((s) => frequencySpectrum(s, timeStep, segment));
  const density = new Float64Array(estimates[0].density.length);
  for (const e of estimates) for (let m = 0; m < density.length; m++) density[m] += e.density[m] / estimates.length;
  return { omega: estimates[0].omega, density, resolution: estimates[0].resolution };
}

/** One point's heights η(x, z, t₀ + i dt), i < count: the series the spectrum and Hs read. */
export function heightSeries(
  sampler: HeightSampler,
  x: number,
  z: number,
  startTime: number,
  timeStep: number,
  count: number,
): Float64Array {
  const series = new Float64Array(count);
  for (let i = 0; i < count; i++) series[i] = sampler(x, z, startTime + i * timeStep);
  return series;
}
