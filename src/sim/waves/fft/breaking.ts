import { gaussianRandom } from '../../noise/gaussianRandom';
import { signedIndex, type SpectralTile } from '../spectra/initialSpectrum';

/**
 * Where the spectral sea breaks. The choppy map x ↦ x + D(x) has the Jacobian matrix
 *   [1 + Jxx, Jxz; Jxz, 1 + Jzz]   (Jxx = ∂Dx/∂x, Jzz = ∂Dz/∂z, Jxz = ∂Dx/∂z = ∂Dz/∂x),
 * symmetric because D = −iλ k̂ h is a gradient. Its determinant falls below 0 where the
 * surface loops over itself (Tessendorf 2001, §4.3); its smaller eigenvalue λ_min falls below 0
 * where the surface folds along one direction, which a crest does while it is stretched along
 * its length (the determinant alone misses it: λ_min λ_max can stay positive). Dupuy &
 * Bruneton (2012, "Real-time animation and rendering of ocean whitecaps", SIGGRAPH Asia
 * Technical Briefs) put whitecaps where λ_min drops below a threshold. Here the sea breaks
 * where the smaller of the two, det or λ_min, is below it: a fold in either sense.
 */
export function jacobianMinEigenvalue(jxx: number, jzz: number, jxz: number): number {
  const half = 0.5 * (jxx - jzz);
  return 1 + 0.5 * (jxx + jzz) - Math.sqrt(half * half + jxz * jxz);
}

export function jacobianDeterminant(jxx: number, jzz: number, jxz: number): number {
  return (1 + jxx) * (1 + jzz) - jxz * jxz;
}

/** The breaking measure: min(det J, λ_min J); the sea breaks where it is low (GLSL twin: shaders/waves/fft.glsl fftBreaking). */
export function breakingMeasure(jxx: number, jzz: number, jxz: number): number {
  return Math.min(jacobianDeterminant(jxx, jzz, jxz), jacobianMinEigenvalue(jxx, jzz, jxz));
}

/**
 * The covariance of (Jxx, Jzz, Jxz) over the sea as it is drawn, row-major 3 × 3. Each is a
 * linear filter of the height field: with D = −iλ k̂ h, Jxx = λ kx²/k h, Jzz = λ kz²/k h,
 * Jxz = λ kx kz/k h, so each pair's covariance is λ² Σ 2|h₀(k)|² a_i(k) a_j(k) over every
 * cascade's modes (the factor 2: mode k appears as h₀(k) and as conj h₀(−k); the tiles' bands
 * do not overlap). Between texels the fields are read bilinearly, which damps a mode whose
 * phase turns by θ per texel: averaged over where a point falls between texels, its power is
 * kept by (2 + cos θ)/3 along each axis (⅓ at the grid's Nyquist), on the GPU and in the twin alike.
 */
export function jacobianCovariance(tiles: readonly SpectralTile[], choppiness: number): number[] {
  const c = new Array<number>(9).fill(0);
  for (const tile of tiles) {
    const { n, h0 } = tile;
    const dk = (2 * Math.PI) / tile.cascade.size;
    const texel = tile.cascade.size / n;
    for (let b = 0; b < n; b++) {
      for (let a = 0; a < n; a++) {
        const i = b * n + a;
        const power = h0[2 * i] ** 2 + h0[2 * i + 1] ** 2;
        if (power === 0) continue;
        const kx = signedIndex(a, n) * dk;
        const kz = signedIndex(b, n) * dk;
        const k = Math.hypot(kx, kz);
        const kept = ((2 + Math.cos(kx * texel)) / 3) * ((2 + Math.cos(kz * texel)) / 3);
        const f = [(kx * kx) / k, (kz * kz) / k, (kx * kz) / k];
        for (let r = 0; r < 3; r++) for (let s = 0; s < 3; s++) c[3 * r + s] += 2 * power * kept * f[r] * f[s];
      }
    }
  }
  return c.map((v) => v * choppiness * choppiness);
}

/** Draws this many seeded samples of (Jxx, Jzz, Jxz) for the quantile: its error in the share is about √(W/N), 2 % of W = 1 %. */
const SAMPLES = 40_000;

/**
 * Seeded Gaussian samples of (Jxx, Jzz, Jxz) with the given covariance (Cholesky factor of it),
 * each with `extra()` added to its breaking measure (a shift the pixels add, independent of
 * the waves: foamBreakup.ts) and with the area it covers on the displaced surface,
 * max(det J, 0) (a compressed patch covers less of the picture than of the grid; a looped one
 * is drawn over).
 */
function sampleMeasures(covariance: readonly number[], extra: () => number): { measure: Float64Array; area: Float64Array } {
  const [a, b, c, , d, e, , , f] = covariance;
  const l11 = Math.sqrt(Math.max(a, 0));
  const l21 = l11 > 0 ? b / l11 : 0;
  const l31 = l11 > 0 ? c / l11 : 0;
  const l22 = Math.sqrt(Math.max(d - l21 * l21, 0));
  const l32 = l22 > 0 ? (e - l31 * l21) / l22 : 0;
  const l33 = Math.sqrt(Math.max(f - l31 * l31 - l32 * l32, 0));
  const normal = gaussianRandom(0x0b5e, 7);
  const measure = new Float64Array(SAMPLES);
  const area = new Float64Array(SAMPLES);
  for (let s = 0; s < SAMPLES; s++) {
    const u = normal();
    const v = normal();
    const w = normal();
    const jxx = l11 * u;
    const jzz = l21 * u + l22 * v;
    const jxz = l31 * u + l32 * v + l33 * w;
    measure[s] = breakingMeasure(jxx, jzz, jxz) + extra();
    area[s] = Math.max(jacobianDeterminant(jxx, jzz, jxz), 0);
  }
  return { measure, area };
}

/**
 * The threshold on the breaking measure (plus the shift `extra` draws) below which the given
 * share of the displaced surface lies: the sea's Jacobian statistics from its spectrum, the
 * share of the picture from Monahan's coverage. The share of area is measured on the displaced
 * surface, so it is what a picture from above sees.
 */
export function breakingThreshold(covariance: readonly number[], coverage: number, extra: () => number = () => 0): number {
  const { measure, area } = sampleMeasures(covariance, extra);
  const order = Array.from(measure.keys()).sort((i, j) => measure[i] - measure[j]);
  const total = area.reduce((sum, x) => sum + x, 0);
  const target = Math.min(Math.max(coverage, 0), 1) * total;
  let covered = 0;
  for (const i of order) {
    covered += area[i];
    if (covered >= target) return measure[i];
  }
  return measure[order[order.length - 1]];
}

/** The spread (standard deviation) of the breaking measure, for soft edges around the threshold. */
export function breakingSpread(covariance: readonly number[]): number {
  const { measure } = sampleMeasures(covariance, () => 0);
  let mean = 0;
  for (const m of measure) mean += m;
  mean /= measure.length;
  let variance = 0;
  for (const m of measure) variance += (m - mean) ** 2;
  return Math.sqrt(variance / measure.length);
}
