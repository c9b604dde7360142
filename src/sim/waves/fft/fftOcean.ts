import { timeInPeriod } from '../dispersion';
import { cascadeLayout, type Cascade } from './cascades';
import { InverseFft2d } from './fft2d';
import { initialSpectrum, REPEAT_PERIOD, type SpectralTile } from '../spectra/initialSpectrum';
import type { SeaState } from '../spectra/seaState';
import { spectralBounds } from '../spectra/spectralBounds';
import { evolveSpectra } from './spectralFields';
import { directionalSpectrum, frequencySpectrum, peakWavelength } from '../spectra/waveSpectrum';
import { undoHorizontalDisplacement, type DisplacementBounds, type SurfaceSample, type WaveModel } from '../waveModel';

/** Revisions of every FftOcean's fields, from one counter, so no two oceans' fields share one. */
let fieldRevisions = 0;

/**
 * The spatial fields of one cascade at one time, laid out as the GPU's two RGBA textures:
 * n × n texels, texel (p, q) at index 4(q·n + p), p along x, q along z.
 *   displacement: (dx, dy, dz, ∂Dx/∂x)
 *   derivatives:  (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)      (D already times λ)
 */
export interface CascadeFields {
  displacement: Float64Array;
  derivatives: Float64Array;
}

/** Everything the GPU needs to draw the same sea: per cascade its tile and h₀ (the CPU draws h₀ once, the GPU evolves it). */
export interface FftOceanSetup {
  sea: SeaState;
  cascades: Cascade[];
  tiles: SpectralTile[];
}

export function fftOceanSetup(sea: SeaState): FftOceanSetup {
  const spectrum = frequencySpectrum(sea);
  const cascades = cascadeLayout(peakWavelength(sea), sea.fftSize);
  const density = directionalSpectrum(sea, spectrum);
  const tiles = cascades.map((c, i) => initialSpectrum(c, sea.fftSize, density, sea.depth, sea.seed, i));
  return { sea, cascades, tiles };
}

/**
 * CPU twin of the spectral sea, float64 (the seed report's "CPU Shader" idea for an FFT sea).
 * setTime(t) runs the time evolution and 4 inverse FFTs per cascade (the costly part, once per
 * time step; a Worker may own it and post `fields` back). displacement/sample then only read the
 * fields, bilinearly, exactly as the GPU reads its textures (texel (p, q) of a tile of side L
 * sits at x = p L/n, z = q L/n, tiles repeat), so the two agree to float32 rounding.
 * Synchronous: displacement(x, z, t) and sample(x, z, t) call setTime(t) themselves when t changes.
 */
export class FftOcean implements WaveModel {
  readonly name = 'fft' as const;
  readonly setup: FftOceanSetup;
  readonly fields: CascadeFields[];
  private time = Number.NaN;
  /** Changes whenever the fields change (computed or adopted): FftWaveModel.surfaceRevision. */
  fieldsRevision = ++fieldRevisions;
  private readonly fft: InverseFft2d;
  private readonly spectra: Float64Array[][];
  private readonly bound: DisplacementBounds;
  /** Texels per metre of each cascade. */
  private readonly scale: number[];
  private readonly acc = new Float64Array(4);
  /**
   * fieldSums' answer: the displacement's x and z, the four derivative channels, the height and
   * ∂Dx/∂x. A typed array, not number fields: a double stored in a field is a new heap number
   * each time, and the inversion stores one twice a step (270 bytes of garbage per sample).
   */
  private readonly sums = new Float64Array(8);
  /** invertInPlace's answer: the grid point p (x, z). */
  private readonly point = new Float64Array(2);

  constructor(sea: SeaState) {
    this.setup = fftOceanSetup(sea);
    const n = sea.fftSize;
    this.fft = new InverseFft2d(n);
    this.spectra = this.setup.tiles.map(() => [0, 1, 2, 3].map(() => new Float64Array(2 * n * n)));
    this.fields = this.setup.tiles.map(() => ({ displacement: new Float64Array(4 * n * n), derivatives: new Float64Array(4 * n * n) }));
    this.scale = this.setup.cascades.map((c) => n / c.size);
    // From the spectrum's spread and the Gaussian's extremes over a tile and a repeat period
    // (src/sim/waves/spectra/spectralBounds.ts), not the strict 2 Σ|h₀| (all modes in phase: 97 m in a gale).
    this.bound = spectralBounds(this.setup.tiles, sea.depth, sea.choppiness);
  }

  /** The time the fields hold (NaN before the first setTime). */
  get fieldsTime(): number {
    return this.time;
  }

  /**
   * Takes fields computed elsewhere for time t: a Worker running setTime(t) on an FftOcean of
   * the same SeaState (same seed, hence the same h₀) gives bit-identical arrays. Returns the
   * arrays it held before, which this ocean no longer reads (a Worker may fill them again).
   */
  adoptFields(time: number, fields: readonly CascadeFields[]): CascadeFields[] {
    if (fields.length !== this.fields.length)
      throw new RangeError(`Expected ${this.fields.length} cascades of fields, got ${fields.length}.`);
    const replaced = this.fields.slice();
    fields.forEach((f, c) => (this.fields[c] = f));
    this.time = time;
    this.fieldsRevision = ++fieldRevisions;
    return replaced;
  }

  /** Evolves to time t (s). Only t mod T matters (quantised dispersion), reduced here in float64. */
  setTime(time: number): void {
    if (time === this.time) return;
    this.time = time;
    this.fieldsRevision = ++fieldRevisions;
    const tau = timeInPeriod(time, REPEAT_PERIOD);
    const n = this.setup.sea.fftSize;
    this.setup.tiles.forEach((tile, c) => {
      const spectra = evolveSpectra(tile, tau, this.setup.sea.choppiness, this.spectra[c]);
      for (const s of spectra) this.fft.transform(s);
      const { displacement, derivatives } = this.fields[c];
      const [a, b, d, e] = spectra;
      for (let i = 0; i < n * n; i++) {
        displacement[4 * i] = a[2 * i];
        displacement[4 * i + 1] = a[2 * i + 1];
        displacement[4 * i + 2] = b[2 * i];
        displacement[4 * i + 3] = b[2 * i + 1];
        derivatives[4 * i] = d[2 * i];
        derivatives[4 * i + 1] = d[2 * i + 1];
        derivatives[4 * i + 2] = e[2 * i];
        derivatives[4 * i + 3] = e[2 * i + 1];
      }
    });
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    this.setTime(time);
    const r = this.accumulate(x, z, 'displacement');
    return [r[0], r[1], r[2]];
  }

  /** Sum over cascades of the derivative fields at the undisplaced grid point (x, z). */
  derivatives(x: number, z: number, time: number): { sx: number; sz: number; jxx: number; jzz: number; jxz: number } {
    this.setTime(time);
    const jxx = this.accumulate(x, z, 'displacement')[3];
    const r = this.accumulate(x, z, 'derivatives');
    return { sx: r[0], sz: r[1], jxx, jzz: r[2], jxz: r[3] };
  }

  /**
   * The height of the surface above the world point (x, z) at `time`: the same fixed-point
   * inversion as undoHorizontalDisplacement over displacement() with `steps` steps at most
   * (fewer once a step moves p by `tolerance` metres or less), then the height there, bit for bit (each channel's sum is the same arithmetic in the same order).
   * But it reads only the channels each step uses (x and z while inverting, the height at the
   * end), allocates nothing, and skips the residual: the frame loop asks this about ten
   * times a frame (the boat, the underwater switch), and the full reads were half its cost.
   */
  heightAt(x: number, z: number, time: number, steps: number, tolerance = 0): number {
    this.setTime(time);
    this.invertInPlace(x, z, steps, tolerance);
    return this.accumulate(this.point[0], this.point[1], 'displacement', 1, 4)[1];
  }

  /**
   * undoHorizontalDisplacement's fixed point p ← q − D(p) for q = (x, z), step for step and
   * stopping by the same rule, leaving p in point[0], point[1] (the fields of the current time).
   */
  private invertInPlace(x: number, z: number, steps: number, tolerance: number): void {
    const p = this.point;
    const sums = this.sums;
    p[0] = x;
    p[1] = z;
    for (let i = 0; i < steps; i++) {
      this.fieldSums(false);
      const nx = x - sums[0];
      const nz = z - sums[1];
      const settled = Math.abs(nx - p[0]) <= tolerance && Math.abs(nz - p[1]) <= tolerance;
      p[0] = nx;
      p[1] = nz;
      if (settled) break;
    }
  }

  /**
   * Height and normal above the world point (x, z) at `time`, written to out[at..at+3] as
   * [height, nx, ny, nz]: what undoHorizontalDisplacement with `steps` and `tolerance`,
   * displacement() and normalAt() give, bit for bit, but with nothing allocated and only the channels each
   * read uses (the fixed-point steps read x and z alone, summed in locals). Many floating
   * bodies ask this every frame: sampleSurfaces answers a thousand points with it.
   */
  sampleInto(x: number, z: number, time: number, steps: number, tolerance: number, out: { [i: number]: number }, at: number): void {
    this.setTime(time);
    this.invertInPlace(x, z, steps, tolerance);
    this.surfaceInto(out, at);
  }

  /** sampleInto for many points at one time: points[2i], points[2i + 1] are world x, z; out[4i..4i+3] gets the sample. */
  sampleManyInto(points: ArrayLike<number>, time: number, steps: number, tolerance: number, out: { [i: number]: number }): void {
    this.setTime(time);
    const count = points.length >> 1;
    for (let i = 0; i < count; i++) {
      this.invertInPlace(points[2 * i], points[2 * i + 1], steps, tolerance);
      this.surfaceInto(out, 4 * i);
    }
  }

  /** Height and normal at the grid point held in `point` (normalAt's arithmetic) into out[at..at+3]. */
  private surfaceInto(out: { [i: number]: number }, at: number): void {
    this.fieldSums(true);
    const r = this.sums;
    const height = r[6];
    // normalAt's arithmetic, term for term.
    const tx0 = 1 + r[7];
    const tx1 = r[2];
    const tx2 = r[5];
    const tz0 = r[5];
    const tz1 = r[3];
    const tz2 = 1 + r[4];
    const nx = tz1 * tx2 - tz2 * tx1;
    const ny = tz2 * tx0 - tz0 * tx2;
    const nz = tz0 * tx1 - tz1 * tx0;
    const len = Math.sqrt(nx * nx + ny * ny + nz * nz);
    out[at] = height;
    out[at + 1] = nx / len;
    out[at + 2] = ny / len;
    out[at + 3] = nz / len;
  }

  /**
   * The fields at the grid point (x, z) held in `point` (a typed array, not arguments: a
   * double passed to a call that is not inlined is boxed, a new heap number), each channel summed over the cascades in accumulate's
   * arithmetic and order, with one set of texel indices and weights per cascade for every read:
   * always the displacement's x and z, into sums[0..1] (all a fixed-point step needs); with
   * `full`, also the four derivative channels, then the height and ∂Dx/∂x, into sums[2..7].
   * Sums in locals, reads straight from the typed arrays: the inversion's steps are most of a
   * sample's cost.
   */
  private fieldSums(full: boolean): void {
    const x = this.point[0];
    const z = this.point[1];
    const mask = this.setup.sea.fftSize - 1;
    const row = this.setup.sea.fftSize * 4;
    let sx = 0;
    let sz = 0;
    let d0 = 0;
    let d1 = 0;
    let d2 = 0;
    let d3 = 0;
    let h = 0;
    let jxx = 0;
    const cascades = this.fields;
    const scales = this.scale;
    for (let c = 0; c < cascades.length; c++) {
      const fields = cascades[c];
      const f = fields.displacement;
      const scale = scales[c];
      const u = x * scale;
      const v = z * scale;
      const fu = Math.floor(u);
      const fv = Math.floor(v);
      const wx = u - fu;
      const wz = v - fv;
      // wrapTexel, inlined: the mask is i mod n for these powers of two.
      const p0 = (fu | 0) & mask;
      const q0 = (fv | 0) & mask;
      const c0 = 4 * p0;
      const c1 = 4 * ((p0 + 1) & mask);
      const r0 = row * q0;
      const r1 = row * ((q0 + 1) & mask);
      const i00 = r0 + c0;
      const i10 = r0 + c1;
      const i01 = r1 + c0;
      const i11 = r1 + c1;
      const topX = f[i00] + (f[i10] - f[i00]) * wx;
      const bottomX = f[i01] + (f[i11] - f[i01]) * wx;
      sx += topX + (bottomX - topX) * wz;
      const topZ = f[i00 + 2] + (f[i10 + 2] - f[i00 + 2]) * wx;
      const bottomZ = f[i01 + 2] + (f[i11 + 2] - f[i01 + 2]) * wx;
      sz += topZ + (bottomZ - topZ) * wz;
      if (full) {
        const g = fields.derivatives;
        d0 += bilinear(g, i00, i10, i01, i11, wx, wz);
        d1 += bilinear(g, i00 + 1, i10 + 1, i01 + 1, i11 + 1, wx, wz);
        d2 += bilinear(g, i00 + 2, i10 + 2, i01 + 2, i11 + 2, wx, wz);
        d3 += bilinear(g, i00 + 3, i10 + 3, i01 + 3, i11 + 3, wx, wz);
        h += bilinear(f, i00 + 1, i10 + 1, i01 + 1, i11 + 1, wx, wz);
        jxx += bilinear(f, i00 + 3, i10 + 3, i01 + 3, i11 + 3, wx, wz);
      }
    }
    const r = this.sums;
    r[0] = sx;
    r[1] = sz;
    if (full) {
      r[2] = d0;
      r[3] = d1;
      r[4] = d2;
      r[5] = d3;
      r[6] = h;
      r[7] = jxx;
    }
  }

  /**
   * Bilinear read of one RGBA field of every cascade, summed, into this.acc (reused: no
   * allocation per call). Only channels first, first + stride, … below 4 are read; the others are 0.
   */
  private accumulate(x: number, z: number, which: keyof CascadeFields, first = 0, stride = 1): Float64Array {
    const acc = this.acc;
    acc[0] = acc[1] = acc[2] = acc[3] = 0;
    const n = this.setup.sea.fftSize;
    for (let c = 0; c < this.fields.length; c++) {
      const f = this.fields[c][which];
      const u = x * this.scale[c];
      const v = z * this.scale[c];
      const fu = Math.floor(u);
      const fv = Math.floor(v);
      const wx = u - fu;
      const wz = v - fv;
      const p0 = wrapTexel(fu, n);
      const q0 = wrapTexel(fv, n);
      const p1 = p0 + 1 === n ? 0 : p0 + 1;
      const q1 = q0 + 1 === n ? 0 : q0 + 1;
      const i00 = 4 * (q0 * n + p0);
      const i10 = 4 * (q0 * n + p1);
      const i01 = 4 * (q1 * n + p0);
      const i11 = 4 * (q1 * n + p1);
      for (let ch = first; ch < 4; ch += stride) {
        const top = f[i00 + ch] + (f[i10 + ch] - f[i00 + ch]) * wx;
        const bottom = f[i01 + ch] + (f[i11 + ch] - f[i01 + ch]) * wx;
        acc[ch] += top + (bottom - top) * wz;
      }
    }
    return acc;
  }

  /**
   * Normal of the displaced surface P(x, z) = (x + Dx, h, z + Dz) at the grid point (x, z):
   * the cross product of its tangents ∂P/∂z × ∂P/∂x, exact from the spectral derivatives.
   */
  normalAt(x: number, z: number, time: number): [number, number, number] {
    const d = this.derivatives(x, z, time);
    const tx = [1 + d.jxx, d.sx, d.jxz];
    const tz = [d.jxz, d.sz, 1 + d.jzz];
    const nx = tz[1] * tx[2] - tz[2] * tx[1];
    const ny = tz[2] * tx[0] - tz[0] * tx[2];
    const nz = tz[0] * tx[1] - tz[1] * tx[0];
    // Not Math.hypot: its overflow guard costs more than the rest of the normal, and no sum of three squares of these tangents' terms comes near it.
    const len = Math.sqrt(nx * nx + ny * ny + nz * nz);
    return [nx / len, ny / len, nz / len];
  }

  /** Jacobian of the horizontal map at grid point (x, z): below 1 compresses, below 0 folds (foam). */
  jacobian(x: number, z: number, time: number): number {
    const d = this.derivatives(x, z, time);
    return (1 + d.jxx) * (1 + d.jzz) - d.jxz * d.jxz;
  }

  sample(x: number, z: number, time: number): SurfaceSample {
    this.setTime(time);
    const p = undoHorizontalDisplacement((px, pz) => this.displacement(px, pz, time), x, z);
    return { height: this.displacement(p.x, p.z, time)[1], normal: this.normalAt(p.x, p.z, time) };
  }

  bounds(): DisplacementBounds {
    return this.bound;
  }
}

/** A bilinear read of one channel at its four texels' indices: accumulate's arithmetic. */
function bilinear(f: Float64Array, i00: number, i10: number, i01: number, i11: number, wx: number, wz: number): number {
  const top = f[i00] + (f[i10] - f[i00]) * wx;
  const bottom = f[i01] + (f[i11] - f[i01]) * wx;
  return top + (bottom - top) * wz;
}

/**
 * A texel index i mod n in [0, n) for an integer-valued i. The fields' sizes are powers of two
 * (fft.js takes nothing else) and ToInt32 (i | 0) is i mod 2³², a multiple of n, so the mask is
 * i mod n for every finite integer, past int32 too. The float remainder ((i % n) + n) % n it
 * replaces was more than half of a height's cost in node: 5.1 -> 2.0 µs per heightAt (n = 128,
 * 12 steps, 10⁴ calls; the same indices, so the same floats, bit for bit).
 */
export function wrapTexel(i: number, n: number): number {
  return (i | 0) & (n - 1);
}
