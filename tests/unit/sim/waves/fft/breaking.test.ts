import { describe, expect, it } from 'vitest';
import {
  breakingMeasure,
  breakingThreshold,
  jacobianCovariance,
  jacobianDeterminant,
  jacobianMinEigenvalue,
} from '../../../../../src/sim/waves/fft/breaking';
import { upperNormalQuantile, whitecapCoverage } from '../../../../../src/sim/waves/fft/whitecaps';
import { FftOcean } from '../../../../../src/sim/waves/fft/fftOcean';
import { DEFAULT_SEA_STATE } from '../../../../../src/sim/waves/spectra/seaState';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

describe('the breaking measure: min(det J, λ_min J) of the choppy map (Dupuy & Bruneton 2012)', () => {
  // Seed 11, 200 random matrices.
  it('λ_min is the smaller root of the characteristic polynomial, the determinant their product', () => {
    const random = seededRandom(11);
    for (let i = 0; i < 200; i++) {
      const [jxx, jzz, jxz] = [random() - 0.5, random() - 0.5, random() - 0.5].map((v) => 1.6 * v);
      const trace = 2 + jxx + jzz;
      const det = jacobianDeterminant(jxx, jzz, jxz);
      const root = (trace - Math.sqrt(trace * trace - 4 * det)) / 2;
      const other = trace - root;
      expect(jacobianMinEigenvalue(jxx, jzz, jxz)).toBeCloseTo(root, 12);
      expect(root * other).toBeCloseTo(det, 12);
    }
  });

  it('catches a crest folded across and stretched along, which the determinant alone misses (control: det says no)', () => {
    // Compressed to 0.3 across the crest (x), stretched to 1.6 along it (z): det 0.48.
    const [jxx, jzz, jxz] = [-0.7, 0.6, 0];
    expect(jacobianMinEigenvalue(jxx, jzz, jxz)).toBeCloseTo(0.3, 12);
    expect(breakingMeasure(jxx, jzz, jxz)).toBeCloseTo(0.3, 12);
    const threshold = 0.4;
    expect(breakingMeasure(jxx, jzz, jxz)).toBeLessThan(threshold);
    expect(jacobianDeterminant(jxx, jzz, jxz)).toBeGreaterThan(threshold);
  });
});

describe("the breaking threshold from the sea's Jacobian statistics", { timeout: 120_000 }, () => {
  const sea = { ...DEFAULT_SEA_STATE, windSpeed: 15, fftSize: 64 as const };
  const ocean = new FftOcean(sea);
  ocean.setTime(10);
  const { tiles } = ocean.setup;

  // Read bilinearly at 40 000 seeded points, within 3 % (control: the same fields at their texels, undamped,
  // are more than 5 % above it in the smallest tile, which reaches the grid's Nyquist).
  it("each cascade's (Jxx, Jzz, Jxz) covariance from its h₀ is the variance its fields have", () => {
    tiles.forEach((tile, c) => {
      const cov = jacobianCovariance([tile], sea.choppiness);
      const single = new FftOcean(sea);
      single.adoptFields(
        10,
        ocean.fields.map((f, k) =>
          k === c ? f : { displacement: new Float64Array(f.displacement.length), derivatives: new Float64Array(f.derivatives.length) },
        ),
      );
      const random = seededRandom(3 + c);
      const n = 40_000;
      let xx = 0;
      let zz = 0;
      let xz = 0;
      let xxzz = 0;
      for (let i = 0; i < n; i++) {
        const d = single.derivatives(random() * tile.cascade.size, random() * tile.cascade.size, 10);
        const { jxx, jzz, jxz } = d;
        xx += jxx * jxx;
        zz += jzz * jzz;
        xz += jxz * jxz;
        xxzz += jxx * jzz;
      }
      console.log(
        `[oceano] cascade ${c}: var Jxx ${(xx / n).toExponential(3)} vs ${cov[0].toExponential(3)}, Jzz ${(zz / n).toExponential(3)} vs ${cov[4].toExponential(3)}, Jxz ${(xz / n).toExponential(3)} vs ${cov[8].toExponential(3)}`,
      );
      expect(Math.abs(xx / n / cov[0] - 1)).toBeLessThan(0.03);
      expect(Math.abs(zz / n / cov[4] - 1)).toBeLessThan(0.03);
      expect(Math.abs(xz / n / cov[8] - 1)).toBeLessThan(0.03);
      // Jxz² and Jxx·Jzz carry the same filter, kx² kz²/k².
      expect(cov[8]).toBeCloseTo(cov[1], 12);
      expect(Math.abs(xxzz / n / cov[1] - 1)).toBeLessThan(0.03);
      if (c === tiles.length - 1) {
        const f = ocean.fields[c];
        let atTexels = 0;
        for (let i = 0; i < sea.fftSize * sea.fftSize; i++) atTexels += f.derivatives[4 * i + 2] ** 2;
        expect(atTexels / (sea.fftSize * sea.fftSize) / cov[4]).toBeGreaterThan(1.05);
      }
    });
  });

  // 128², t = 10 s and 200 s (control: the Gaussian threshold on det J alone misses it).
  it("marks Monahan's share of the displaced sea, within ±15 % at 10, 15 and 20 m/s", () => {
    for (const windSpeed of [10, 15, 20]) {
      const windy = new FftOcean({ ...sea, windSpeed, fftSize: 128 });
      const cov = jacobianCovariance(windy.setup.tiles, sea.choppiness);
      const coverage = whitecapCoverage(windSpeed);
      const threshold = breakingThreshold(cov, coverage);
      // The whole sea at 2 × 20 000 seeded points over the largest tile, each weighted by the
      // area it covers once displaced. One instant's tail scatters by ±10 % (measured at 4 instants).
      const random = seededRandom(5);
      const size = windy.setup.cascades[0].size;
      let area = 0;
      let breaking = 0;
      let oldBreaking = 0;
      // The threshold foam had before: det J taken as Gaussian about 1 with spread 0.125 λ.
      const oldThreshold = 1 - 0.125 * sea.choppiness * upperNormalQuantile(coverage);
      for (let s = 0; s < 40_000; s++) {
        const d = windy.derivatives(random() * size, random() * size, s < 20_000 ? 10 : 200);
        const det = jacobianDeterminant(d.jxx, d.jzz, d.jxz);
        const a = Math.max(det, 0);
        area += a;
        if (breakingMeasure(d.jxx, d.jzz, d.jxz) < threshold) breaking += a;
        if (det < oldThreshold) oldBreaking += a;
      }
      const share = breaking / area;
      const oldShare = oldBreaking / area;
      console.log(
        `[oceano] ${windSpeed} m/s: Monahan ${(100 * coverage).toFixed(2)} %, breaking measure below threshold ${(100 * share).toFixed(2)} %, old det threshold ${(100 * oldShare).toFixed(2)} %`,
      );
      expect(Math.abs(share / coverage - 1)).toBeLessThan(0.15);
      if (windSpeed === 20) expect(Math.abs(oldShare / coverage - 1)).toBeGreaterThan(0.15);
    }
  });
});
