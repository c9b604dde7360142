import { describe, expect, it } from 'vitest';
import { cascadeLayout, inBand, TILE_RATIOS } from '../../../../../src/sim/waves/fft/cascades';
import { waveNumber } from '../../../../../src/sim/waves/dispersion';
import { fftOceanSetup } from '../../../../../src/sim/waves/fft/fftOcean';
import { signedIndex } from '../../../../../src/sim/waves/spectra/initialSpectrum';
import { DEFAULT_SEA_STATE, type SeaState, type SpectrumName } from '../../../../../src/sim/waves/spectra/seaState';
import { directionalSpectrum, frequencySpectrum, peakWavelength } from '../../../../../src/sim/waves/spectra/waveSpectrum';

const spectra: SpectrumName[] = ['pierson-moskowitz', 'jonswap', 'phillips'];

describe('cascades', () => {
  it('put the spectral peak inside the largest tile for every wind 1–30 m/s, spectrum, fetch and size', () => {
    for (const spectrum of spectra) {
      for (const fetch of [1_000, 20_000, 1_000_000]) {
        for (let u = 1; u <= 30; u++) {
          for (const n of [64, 128, 256] as const) {
            const sea: SeaState = { ...DEFAULT_SEA_STATE, spectrum, fetch, windSpeed: u, fftSize: n };
            const layout = cascadeLayout(peakWavelength(sea), n);
            const kp = waveNumber(frequencySpectrum(sea).peak, sea.depth);
            const dk0 = (2 * Math.PI) / layout[0].size;
            expect(inBand(layout[0], kp)).toBe(true);
            // resolved: the peak is 8 grid steps from k = 0 and below the tile's band edge
            expect(kp / dk0).toBeCloseTo(8, 6);
            expect(kp).toBeLessThan(layout[0].kMax / 1.5);
          }
        }
      }
    }
    // the example: at 20 m/s the PM peak wavelength is about 350 m, and the largest tile holds it 8 times
    const gale = { ...DEFAULT_SEA_STATE, windSpeed: 20 };
    expect(peakWavelength(gale)).toBeGreaterThan(340);
    expect(peakWavelength(gale)).toBeLessThan(360);
    expect(cascadeLayout(peakWavelength(gale), 128)[0].size).toBeGreaterThan(2700);
  });

  // q tiles of one never come within 0.05 of a whole number of another for q ≤ 8, so no two tiles repeat
  // together within 8 of the larger (control: 4.5 = 9/2 does; 4.37 came within 0.01 with the first).
  it('have sizes in ratios far from simple fractions, so no two tiles repeat together', () => {
    /** How far q·r comes from a whole number at best, for q = 1 … 8: the misalignment, in tiles of the smaller, of the nearest joint repeat. */
    const nearestRepeat = (r: number) => Math.min(...[1, 2, 3, 4, 5, 6, 7, 8].map((q) => Math.abs(q * r - Math.round(q * r))));
    const [r1, r2] = TILE_RATIOS;
    for (const ratio of [r1, r2, r1 * r2]) expect(nearestRepeat(ratio), String(ratio)).toBeGreaterThan(0.05);
    expect(nearestRepeat(4.5)).toBeLessThan(0.05);
    expect(nearestRepeat(r1 * 4.37)).toBeLessThan(0.05);
  });

  it('have at least 3 tiles whose bands touch without overlapping, each within its grid', () => {
    for (const n of [64, 128, 256]) {
      const layout = cascadeLayout(100, n);
      expect(layout.length).toBeGreaterThanOrEqual(3);
      expect(layout[0].kMin).toBe(0);
      expect(layout[layout.length - 1].kMax).toBe(Infinity);
      for (let i = 0; i + 1 < layout.length; i++) {
        expect(layout[i + 1].kMin).toBe(layout[i].kMax);
        expect(layout[i + 1].size).toBeLessThan(layout[i].size);
        // the band lies inside the grid's Nyquist disk (n/2 · 2π/L), and the next tile has ≥ 3 grid steps below its band
        expect(layout[i].kMax).toBeLessThanOrEqual(((n / 2) * 2 * Math.PI) / layout[i].size);
        expect(layout[i + 1].kMin / ((2 * Math.PI) / layout[i + 1].size)).toBeGreaterThan(3);
      }
      // each |k| belongs to exactly one tile
      for (let k = 1e-4; k < 50; k *= 1.01) expect(layout.filter((c) => inBand(c, k)).length).toBe(1);
    }
  });

  /** Σ over every drawn mode of F(k) Δk², the variance the tiles were built to carry. */
  function carriedVariance(sea: SeaState, countTwice: boolean): number {
    const setup = fftOceanSetup(sea);
    const density = directionalSpectrum(sea, frequencySpectrum(sea));
    let sum = 0;
    for (const tile of setup.tiles) {
      const dk = (2 * Math.PI) / tile.cascade.size;
      for (let b = 0; b < tile.n; b++) {
        for (let a = 0; a < tile.n; a++) {
          const i = b * tile.n + a;
          const drawn = tile.h0[2 * i] !== 0 || tile.h0[2 * i + 1] !== 0;
          const k = Math.hypot(signedIndex(a, tile.n), signedIndex(b, tile.n)) * dk;
          const inOwnGrid = signedIndex(a, tile.n) !== -tile.n / 2 && signedIndex(b, tile.n) !== -tile.n / 2 && k > 0;
          if (drawn || (countTwice && inOwnGrid && k >= tile.cascade.kMin)) {
            sum += density(signedIndex(a, tile.n) * dk, signedIndex(b, tile.n) * dk) * dk * dk;
          }
        }
      }
    }
    return sum;
  }

  // Planted fault: tiles without the upper cut carry > 10 % too much.
  it('count every wave once: the drawn modes carry m₀ (within 3 %)', () => {
    for (const windSpeed of [3, 10, 25]) {
      for (const spectrum of spectra) {
        const sea: SeaState = { ...DEFAULT_SEA_STATE, windSpeed, spectrum, fftSize: 64, fetch: 20_000 };
        const m0 = frequencySpectrum(sea).m0;
        // measured 0.987 (PM, Phillips: the tail beyond the last Nyquist) and 0.994 (JONSWAP, against the DNV m₀), every wind
        expect(Math.abs(carriedVariance(sea, false) / m0 - 1)).toBeLessThan(0.03);
        expect(carriedVariance(sea, true) / m0).toBeGreaterThan(1.1);
      }
    }
  });
});

describe('sea state from the parameter table', () => {
  it('maps km to m, the deepest depth to deep water, and the FFT size text to a number', async () => {
    const { defaultParams } = await import('../../../../../src/sim/params/params');
    const { seaStateFromParams } = await import('../../../../../src/sim/waves/spectra/seaState');
    const p = defaultParams();
    const s = seaStateFromParams(p);
    expect(s.fetch).toBe(100_000);
    expect(s.depth).toBe(Infinity);
    expect(s.fftSize).toBe(128);
    expect(seaStateFromParams({ ...p, depth: 20, fftSize: '256' })).toMatchObject({ depth: 20, fftSize: 256 });
  });
});
