import { describe, expect, it } from 'vitest';
import { GRAVITY, quantiseFrequency } from '../../../../../src/sim/waves/dispersion';
import { InverseFft2d } from '../../../../../src/sim/waves/fft/fft2d';
import { FftOcean, fftOceanSetup, wrapTexel } from '../../../../../src/sim/waves/fft/fftOcean';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';
import { REPEAT_PERIOD, signedIndex, type SpectralTile } from '../../../../../src/sim/waves/spectra/initialSpectrum';
import { windAt19_5 } from '../../../../../src/sim/waves/spectra/piersonMoskowitz';
import { DEFAULT_SEA_STATE, type SeaState } from '../../../../../src/sim/waves/spectra/seaState';
import { evolveSpectra } from '../../../../../src/sim/waves/fft/spectralFields';
import { frequencySpectrum } from '../../../../../src/sim/waves/spectra/waveSpectrum';
import { undoHorizontalDisplacement } from '../../../../../src/sim/waves/waveModel';

const sea = (over: Partial<SeaState>): SeaState => ({ ...DEFAULT_SEA_STATE, fftSize: 64, ...over });

/** Spatial variance of the synthesised height: mean of h² over each tile's grid, summed over tiles (independent bands). */
function synthesisedVariance(ocean: FftOcean, time: number): number {
  ocean.setTime(time);
  let variance = 0;
  for (const f of ocean.fields) {
    let s = 0;
    for (let i = 1; i < f.displacement.length; i += 4) s += f.displacement[i] ** 2;
    variance += s / (f.displacement.length / 4);
  }
  return variance;
}

describe('the synthesised spectral sea', { timeout: 600_000 }, () => {
  // Planted fault: without the conj(h₀(−k)) term it is not.
  it('is real: Hermitian symmetry leaves an imaginary part below 1e-6 of the real', () => {
    const setup = fftOceanSetup(sea({ windSpeed: 12, choppiness: 0 }));
    const fft = new InverseFft2d(64);
    for (const tile of setup.tiles) {
      // λ = 0: spectra[0] = 0 + i h̃, so after the FFT real part = −Im h, imaginary part = Re h.
      const [s0] = evolveSpectra(tile, 123.4, 0);
      fft.transform(s0);
      let re = 0;
      let im = 0;
      for (let i = 0; i < s0.length; i += 2) {
        im = Math.max(im, Math.abs(s0[i]));
        re = Math.max(re, Math.abs(s0[i + 1]));
      }
      // measured: 1e-16 .. 1e-15
      expect(im / re).toBeLessThan(1e-6);
      // planted fault: h̃ = h₀(k) e^{iωt} alone
      const broken = new Float64Array(2 * 64 * 64);
      for (let i = 0; i < 64 * 64; i++) {
        const c = Math.cos(tile.omega[i] * 123.4);
        const s = Math.sin(tile.omega[i] * 123.4);
        broken[2 * i] = tile.h0[2 * i] * c - tile.h0[2 * i + 1] * s;
        broken[2 * i + 1] = tile.h0[2 * i] * s + tile.h0[2 * i + 1] * c;
      }
      fft.transform(broken);
      let bre = 0;
      let bim = 0;
      for (let i = 0; i < broken.length; i += 2) {
        bre = Math.max(bre, Math.abs(broken[i]));
        bim = Math.max(bim, Math.abs(broken[i + 1]));
      }
      expect(bim / bre).toBeGreaterThan(0.1);
    }
  });

  // Planted fault: amplitudes without the ½ fail.
  it('has the variance of its spectrum: Hs = 4σ within 10 % of 4√m₀ for winds 3–25 m/s', () => {
    const ratios: number[] = [];
    for (let u = 3; u <= 25; u += 2) {
      const s = sea({ windSpeed: u, seed: u });
      const ratio = Math.sqrt(synthesisedVariance(new FftOcean(s), 17) / frequencySpectrum(s).m0);
      ratios.push(ratio);
      // measured 0.95–1.05 over these winds and seeds (a tile holds a finite number of random waves)
      expect(Math.abs(ratio - 1)).toBeLessThan(0.1);
      // planted fault: E|h₀|² = F Δk² (Tessendorf's P without our ½) would scale Hs by √2
      expect(Math.abs(ratio * Math.SQRT2 - 1)).toBeGreaterThan(0.1);
    }
    expect(ratios.length).toBe(12);
  });

  it('is a fully developed Pierson–Moskowitz sea: Hs within 15 % of 0.21 U19.5²/g (Pierson & Moskowitz 1964)', () => {
    for (const u of [5, 12, 20]) {
      const hs = 4 * Math.sqrt(synthesisedVariance(new FftOcean(sea({ windSpeed: u, seed: 7 })), 3));
      expect(Math.abs(hs / ((0.21 * windAt19_5(u) ** 2) / GRAVITY) - 1)).toBeLessThan(0.15);
    }
  });

  /**
   * The height series at the origin of every tile (Σ over the evolved spectrum), summed over
   * tiles, sampled at Δt = π/(2ωp) (Nyquist 2ωp) for 512 steps; periodograms averaged over several seeds
   * (independent seas) and smoothed over ±2 bins (±3 % of ωp). Returns the frequency of the
   * largest smoothed value.
   */
  function temporalPeak(seas: SpectralTile[][], peak: number): number {
    const steps = 512;
    const dt = Math.PI / (2 * peak);
    const bins = steps / 2;
    const power = new Float64Array(bins);
    const cosTable = Float64Array.from({ length: steps }, (_, i) => Math.cos((2 * Math.PI * i) / steps));
    const sinTable = Float64Array.from({ length: steps }, (_, i) => Math.sin((2 * Math.PI * i) / steps));
    for (const tiles of seas) {
      const series = new Float64Array(steps);
      for (const tile of tiles) {
        const buffers = [0, 1, 2, 3].map(() => new Float64Array(2 * tile.n * tile.n));
        for (let s = 0; s < steps; s++) {
          const [h] = evolveSpectra(tile, s * dt, 0, buffers); // λ = 0: spectra[0] = i h̃, so Im = Re h̃
          let sum = 0;
          for (let i = 1; i < h.length; i += 2) sum += h[i];
          series[s] += sum;
        }
      }
      for (let m = 1; m < bins; m++) {
        let re = 0;
        let im = 0;
        for (let s = 0; s < steps; s++) {
          const idx = (m * s) % steps;
          re += series[s] * cosTable[idx];
          im -= series[s] * sinTable[idx];
        }
        power[m] += re * re + im * im;
      }
    }
    let best = 0;
    let bestValue = -1;
    for (let m = 3; m < bins - 3; m++) {
      let v = 0;
      for (let j = -2; j <= 2; j++) v += power[m + j];
      if (v > bestValue) [best, bestValue] = [m, v];
    }
    return (2 * Math.PI * best) / (steps * dt);
  }

  // Planted fault: ω² = g k (1 + k²) does not.
  it('oscillates at the spectral peak: a point’s height series peaks within 10 % of ωp', () => {
    for (const u of [3, 10]) {
      const s = sea({ windSpeed: u, choppiness: 0 });
      const peak = frequencySpectrum(s).peak;
      const seas = [1, 2, 3].map((seed) => fftOceanSetup({ ...s, seed }).tiles);
      const measured = temporalPeak(seas, peak);
      console.log('temporal peak / ωp', u, measured / peak);
      // measured: 3 m/s → 1.02 ωp, 10 m/s → 1.02 ωp
      expect(Math.abs(measured / peak - 1)).toBeLessThan(0.1);
      if (u === 3) {
        const wrong = seas.map((tiles) =>
          tiles.map((tile) => {
            const dk = (2 * Math.PI) / tile.cascade.size;
            const omega = tile.omega.map((_, i) => {
              const k = Math.hypot(signedIndex(i % tile.n, tile.n), signedIndex(Math.floor(i / tile.n), tile.n)) * dk;
              return quantiseFrequency(Math.sqrt(GRAVITY * k * (1 + k * k)), REPEAT_PERIOD);
            });
            return { ...tile, omega };
          }),
        );
        const wrongPeak = temporalPeak(wrong, peak);
        console.log('wrong dispersion: temporal peak / ωp', wrongPeak / peak);
        expect(Math.abs(wrongPeak / peak - 1)).toBeGreaterThan(0.1);
      }
    }
  });

  it('pulls points towards the crests (Gerstner’s trochoid), with exact slopes and Jacobian', () => {
    // One mode: h = cos(k x), k = 2 · 2π/100.
    const n = 16;
    const L = 100;
    const k = (2 * 2 * Math.PI) / L;
    const h0 = new Float64Array(2 * n * n);
    h0[2 * 2] = 0.5;
    const tile: SpectralTile = { cascade: { size: L, kMin: 0, kMax: Infinity }, n, h0, omega: new Float64Array(n * n) };
    const lambda = 0.8;
    const spectra = evolveSpectra(tile, 0, lambda);
    const fft = new InverseFft2d(n);
    for (const s of spectra) fft.transform(s);
    for (let p = 0; p < n; p++) {
      const x = (p * L) / n;
      const i = 2 * p; // row z = 0
      expect(spectra[0][i + 1]).toBeCloseTo(Math.cos(k * x), 12); // h
      expect(spectra[0][i]).toBeCloseTo(-lambda * Math.sin(k * x), 12); // dx
      expect(spectra[1][i]).toBeCloseTo(0, 12); // dz
      expect(spectra[1][i + 1]).toBeCloseTo(-lambda * k * Math.cos(k * x), 12); // ∂Dx/∂x
      expect(spectra[2][i]).toBeCloseTo(-k * Math.sin(k * x), 12); // ∂h/∂x
    }
    // At the crest (x = 0) J = 1 − λk < 1: compressed; in the trough J > 1.
    expect(1 + spectra[1][1]).toBeLessThan(1);
    expect(1 + spectra[1][2 * (n / 4) + 1]).toBeGreaterThan(1);
  });
});

describe('the CPU twin', { timeout: 120_000 }, () => {
  const ocean = new FftOcean(sea({ windSpeed: 12, seed: 3 }));

  // Planted fault: no inversion.
  it('undoes the horizontal displacement: the surface above the displaced point is its height', () => {
    let worst = 0;
    let withoutUndo = 0;
    for (let i = 0; i < 40; i++) {
      const x = (i * 37.3) % 500;
      const z = (i * 91.7) % 500;
      const [dx, dy, dz] = ocean.displacement(x, z, 42);
      const s = ocean.sample(x + dx, z + dz, 42);
      worst = Math.max(worst, Math.abs(s.height - dy));
      withoutUndo = Math.max(withoutUndo, Math.abs(ocean.displacement(x + dx, z + dz, 42)[1] - dy));
      const r = undoHorizontalDisplacement((px, pz) => ocean.displacement(px, pz, 42), x + dx, z + dz);
      expect(r.residual).toBeLessThan(1e-3);
    }
    // measured ≈ 1e-5 m with 4 steps
    expect(worst).toBeLessThan(1e-3);
    expect(withoutUndo).toBeGreaterThan(1e-2);
  });

  it('repeats exactly every T = 1000 s, so t = 10⁶ + 10 s is the sea of t = 10 s', () => {
    const a = ocean.displacement(12.5, -7.25, 10);
    const b = ocean.displacement(12.5, -7.25, 1e6 + 10);
    expect(b).toEqual(a);
    const c = ocean.displacement(12.5, -7.25, 10.5);
    expect(Math.abs(c[1] - a[1])).toBeGreaterThan(1e-3);
  });

  it('gives the same sea for the same seed and another for another seed', () => {
    const again = new FftOcean(sea({ windSpeed: 12, seed: 3 }));
    const other = new FftOcean(sea({ windSpeed: 12, seed: 4 }));
    expect(again.displacement(3, 4, 5)).toEqual(ocean.displacement(3, 4, 5));
    expect(Math.abs(other.displacement(3, 4, 5)[1] - ocean.displacement(3, 4, 5)[1])).toBeGreaterThan(1e-3);
  });

  it('has unit normals that lean against the slope, and bounds that hold every grid value', () => {
    const s = ocean.sample(10, 20, 42);
    expect(Math.hypot(...s.normal)).toBeCloseTo(1, 12);
    expect(s.normal[1]).toBeGreaterThan(0.5);
    const { vertical, horizontal } = ocean.bounds();
    for (const f of ocean.fields) {
      for (let i = 0; i < f.displacement.length; i += 4) {
        expect(Math.abs(f.displacement[i + 1])).toBeLessThanOrEqual(vertical);
        expect(Math.max(Math.abs(f.displacement[i]), Math.abs(f.displacement[i + 2]))).toBeLessThanOrEqual(horizontal);
      }
    }
  });
});

describe('wrapTexel', () => {
  // Control: i % n alone (negative for negative i) fails.
  it('is i mod n in [0, n) for integers of either sign, inside int32 and beyond it', () => {
    const random = seededRandom(1122);
    for (const n of [64, 128, 256]) {
      for (let k = 0; k < 2000; k++) {
        const scale = [1e3, 3e9, 1e14][k % 3];
        const i = Math.floor((random() - 0.5) * 2 * scale);
        expect(wrapTexel(i, n)).toBe(((i % n) + n) % n);
      }
      for (const i of [0, -1, n - 1, n, -n, 2147483647, -2147483648, 2147483648, -2147483649])
        expect(wrapTexel(i, n)).toBe(((i % n) + n) % n);
    }
  });
});
