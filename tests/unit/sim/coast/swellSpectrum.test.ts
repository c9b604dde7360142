import { describe, expect, it } from 'vitest';
import {
  equalEnergyFrequencies,
  regularSwell,
  setPeriod,
  SWELL_BAND,
  SWELL_COMPONENTS,
  swellComponents,
  swellSpectralShape,
  type SwellComponentSpec,
} from '../../../../src/sim/coast/swellSpectrum';

const SETTINGS = { swellHeight: 1.5, swellPeriod: 10, seed: 1 };
const COMPONENTS = swellComponents(SETTINGS);
/** Σ a² / 2: the variance m0 of the components' sum. */
const variance = (components: SwellComponentSpec[]) => components.reduce((sum, c) => sum + c.amplitude ** 2 / 2, 0);

describe('the swell from a spectrum: JONSWAP sampled at four frequencies', () => {
  it('holds the variance of Hs: Σ a² / 2 = (Hs / 4)², for three heights', () => {
    expect(COMPONENTS).toHaveLength(SWELL_COMPONENTS);
    for (const swellHeight of [0.5, 1.5, 4])
      expect(variance(swellComponents({ ...SETTINGS, swellHeight }))).toBeCloseTo((swellHeight / 4) ** 2, 12);
  });

  it('a planted fault, a = √(m0 / K) (the factor 2 lost), misses the variance (negative control)', () => {
    const wrong = COMPONENTS.map((c) => ({ ...c, amplitude: c.amplitude / Math.SQRT2 }));
    expect(Math.abs(variance(wrong) - (SETTINGS.swellHeight / 4) ** 2)).toBeGreaterThan(1e-3);
  });

  it('its frequencies bracket the peak 1/Tp, rise one after another and stay inside the band', () => {
    for (const swellPeriod of [6, 10, 16]) {
      const hertz = swellComponents({ ...SETTINGS, swellPeriod }).map((c) => c.angularFrequency / (2 * Math.PI));
      expect(Math.min(...hertz)).toBeLessThan(1 / swellPeriod);
      expect(Math.max(...hertz)).toBeGreaterThan(1 / swellPeriod);
      for (let m = 1; m < hertz.length; m++) expect(hertz[m]).toBeGreaterThan(hertz[m - 1]);
      expect(hertz[0]).toBeGreaterThan(SWELL_BAND[0] / swellPeriod);
      expect(hertz[hertz.length - 1]).toBeLessThan(SWELL_BAND[1] / swellPeriod);
    }
  });

  it('frequencies taken in cycles per second where rad/s are meant (a planted fault) do not bracket 2π/Tp', () => {
    const peak = (2 * Math.PI) / SETTINGS.swellPeriod;
    const wrong = equalEnergyFrequencies(1 / SETTINGS.swellPeriod);
    expect(Math.max(...wrong)).toBeLessThan(peak);
  });

  it('each frequency is its bin’s energy-weighted mean: the bins hold equal shares, checked by a fresh integral', () => {
    const peak = (2 * Math.PI) / SETTINGS.swellPeriod;
    const frequencies = equalEnergyFrequencies(peak);
    // Simpson's rule across the band, independent of the code's trapezoid.
    const integral = (f: (w: number) => number, a: number, b: number) => {
      const steps = 4000;
      const h = (b - a) / steps;
      let sum = f(a) + f(b);
      for (let s = 1; s < steps; s++) sum += (s % 2 ? 4 : 2) * f(a + s * h);
      return (sum * h) / 3;
    };
    const shape = (w: number) => swellSpectralShape(w, peak);
    const total = integral(shape, SWELL_BAND[0] * peak, SWELL_BAND[1] * peak);
    // The band holds nearly all of JONSWAP's energy: what lies beyond 3 ωp is about 1 %.
    expect(integral(shape, SWELL_BAND[1] * peak, 20 * peak) / total).toBeLessThan(0.015);
    // The mean of all four is the band's mean frequency m1 / m0, as equal shares require.
    const meanFrequency = integral((w) => w * shape(w), SWELL_BAND[0] * peak, SWELL_BAND[1] * peak) / total;
    expect(frequencies.reduce((a, b) => a + b, 0) / frequencies.length).toBeCloseTo(meanFrequency, 4);
    // A planted fault: frequencies evenly spaced across the band miss that mean.
    const even = [0, 1, 2, 3].map((m) => (SWELL_BAND[0] + ((m + 0.5) * (SWELL_BAND[1] - SWELL_BAND[0])) / 4) * peak);
    expect(Math.abs(even.reduce((a, b) => a + b, 0) / 4 - meanFrequency)).toBeGreaterThan(0.05);
  });

  it('draws the same phases from the same seed, and other phases from another seed (negative control)', () => {
    expect(swellComponents(SETTINGS)).toEqual(COMPONENTS);
    const other = swellComponents({ ...SETTINGS, seed: 2 });
    expect(other.map((c) => c.phaseOffset)).not.toEqual(COMPONENTS.map((c) => c.phaseOffset));
    expect(other.map((c) => c.angularFrequency)).toEqual(COMPONENTS.map((c) => c.angularFrequency));
    for (const c of COMPONENTS) expect(c.phaseOffset).toBeGreaterThanOrEqual(0);
    for (const c of COMPONENTS) expect(c.phaseOffset).toBeLessThan(2 * Math.PI);
  });

  it('beats in sets 2π/Δω long: over four of them the envelope swings from over 0.8 Σa to under 0.3 Σa', () => {
    // At a point, the envelope |Σ a e^{i(φ − ω t)}| over two set periods: highest near a set, lowest between.
    const envelope = (t: number) => {
      let re = 0;
      let im = 0;
      for (const c of COMPONENTS) {
        re += c.amplitude * Math.cos(c.phaseOffset - c.angularFrequency * t);
        im += c.amplitude * Math.sin(c.phaseOffset - c.angularFrequency * t);
      }
      return Math.hypot(re, im);
    };
    const period = setPeriod(COMPONENTS);
    expect(period).toBeGreaterThan(4 * SETTINGS.swellPeriod);
    const samples = Array.from({ length: 4000 }, (_, s) => envelope((s / 4000) * 4 * period));
    const sum = COMPONENTS.reduce((a, c) => a + c.amplitude, 0);
    expect(Math.max(...samples)).toBeGreaterThan(0.8 * sum);
    expect(Math.min(...samples)).toBeLessThan(0.3 * sum);
    // A regular swell (one component) has no sets: its envelope never changes (negative control).
    const [one] = regularSwell(SETTINGS);
    expect(one.amplitude).toBe(SETTINGS.swellHeight / 2);
    expect(setPeriod([one])).toBe(Infinity);
  });
});
