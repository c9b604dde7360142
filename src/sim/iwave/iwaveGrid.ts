import type { ConvolutionKernel } from './verticalDerivativeKernel';
import { hullCovers, hullSources, type MovingHull } from './movingHull';

/** Standard gravity, m/s². */
export const GRAVITY = 9.81;

export interface IWaveGridOptions {
  /** Texels along x (and along z unless `rows` says otherwise). */
  n: number;
  /** Texel rows along z: a narrow channel for plane-wave tests; n by default. */
  rows?: number;
  /** Metres per texel. */
  spacing: number;
  /** The operator standing for √(−∇²) (fittedVerticalDerivativeKernel, or a control). */
  kernel: ConvolutionKernel;
  /**
   * Another operator for the texels right of the middle (i ≥ n/2), the two halves kept apart
   * by a sponge half as wide lining the middle: two equations side by side (the stone-compare
   * preset). Needs a sponge.
   */
  rightKernel?: ConvolutionKernel | null;
  gravity?: number;
  /** Light damping everywhere, 1/s: amplitudes fall as exp(−α t / 2). */
  damping?: number;
  /** The absorbing border: its width in texels and its damping at the very edge, 1/s. */
  sponge?: SpongeLayer;
  /**
   * Which sides the sponge lines: both axes, or only the two sides across x (a channel whose
   * z wraps round, for plane-wave tests). Without wrap, what lies past the edge reads as calm.
   */
  spongeAxes?: 'xz' | 'x';
  /** Which axes the grid repeats along (a periodic box for the dispersion test, a channel for the sponge's). */
  wrap?: 'none' | 'z' | 'xz';
}

export interface SpongeLayer {
  /** Texels from the edge over which the damping rises. */
  width: number;
  /** Damping at the edge, 1/s. */
  strength: number;
}

/** The border Oceano uses: 32 texels (16 m at 0.5 m), rising to 3/s (docs/iwave.md: its reflection measured). */
export const IWAVE_SPONGE: SpongeLayer = { width: 32, strength: 3 };

/**
 * The sponge's damping at a texel whose centre lies `fromEdge` texels inside the edge: it rises
 * as the square of the depth into the layer, so a wave meets no sudden change to reflect from
 * (docs/iwave.md gives the reflection measured).
 */
export function spongeDamping(fromEdge: number, sponge: SpongeLayer): number {
  if (fromEdge >= sponge.width) return 0;
  const depth = 1 - fromEdge / sponge.width;
  return sponge.strength * depth * depth;
}

/** A disturbance: a smooth bump of `height` metres (negative: a dip) and `radius` metres. */
export interface Disturbance {
  x: number;
  z: number;
  radius: number;
  height: number;
}

/** A disturbance at a simulation time, as presets and share links carry it: [time s, x m, z m, radius m, height m]. */
export type Stone = readonly [time: number, x: number, z: number, radius: number, height: number];

/** How far a bump reaches, in radii: past it the Gaussian is below 3.4·10⁻⁴ of its height and is cut. */
export const BUMP_REACH = 2;

/**
 * The bump's shape: a Gaussian exp(−2 d²/radius²), so 13.5 % of the height at the radius and
 * cut at BUMP_REACH radii. Its spectrum, exp(−k² radius² / 8), leaves little for the waves
 * shorter than the kernel's band to carry off (a raised cosine's slower tail did).
 */
export function bumpProfile(distance: number, radius: number): number {
  if (distance >= BUMP_REACH * radius) return 0;
  return Math.exp((-2 * distance * distance) / (radius * radius));
}

/**
 * Tessendorf's iWave on a CPU grid: the reference the GPU solver (src/render/iwave/) is held to,
 * and the solver of the physics tests.
 *
 * Texel (i, j) is the point x = cx + (i + ½ − n/2)·Δx, z = cz + (j + ½ − rows/2)·Δx of a
 * rectangle centred on (cx, cz). Each step of Δt solves ∂²h/∂t² + α ∂h/∂t = −g √(−∇²) h, α per
 * texel (the light damping plus the sponge), with the damping term centred in time:
 *   h⁺ = [2h − (1 − αΔt/2) h⁻ − (g Δt² / Δx) (G ∗ h)] / (1 + αΔt/2),
 * then multiplied by the obstacle mask (0 on a solid texel), so waves reflect from solids.
 * The paper prints h⁺ = [h (2 − αΔt) − h⁻ − …] / (1 + αΔt), which also pulls the height itself
 * towards 0 at about 2α/Δt: a stiffness that grows with α, so a sponge built on it reflects
 * (docs/iwave.md).
 */
export class IWaveGrid {
  readonly n: number;
  readonly rows: number;
  readonly spacing: number;
  readonly gravity: number;
  readonly kernel: ConvolutionKernel;
  readonly rightKernel: ConvolutionKernel | null;
  /** Heights now and one step ago, row by row (z), metres. */
  height: Float64Array;
  previous: Float64Array;
  /** 1 where water, 0 where a solid stands. */
  readonly obstacle: Float32Array;
  /** α per texel, 1/s. */
  readonly damping: Float64Array;
  /** The boat during the next step (its footprint a solid, its bow and stern sources), or null. */
  hull: MovingHull | null = null;
  /** World (x, z) of the grid's centre. */
  centerX = 0;
  centerZ = 0;
  private readonly wrapX: boolean;
  private readonly wrapZ: boolean;
  private readonly padded: Float64Array;
  private readonly paddedSize: number;
  private next: Float64Array;
  private readonly convolution: Float64Array;
  private readonly rightConvolution: Float64Array;

  constructor(options: IWaveGridOptions) {
    const { n, spacing, kernel } = options;
    this.n = n;
    const m = options.rows ?? n;
    this.rows = m;
    this.spacing = spacing;
    this.kernel = kernel;
    this.rightKernel = options.rightKernel ?? null;
    this.gravity = options.gravity ?? GRAVITY;
    this.wrapX = options.wrap === 'xz';
    this.wrapZ = options.wrap === 'xz' || options.wrap === 'z';
    this.height = new Float64Array(n * m);
    this.previous = new Float64Array(n * m);
    this.next = new Float64Array(n * m);
    this.convolution = new Float64Array(n * m);
    this.obstacle = new Float32Array(n * m).fill(1);
    this.damping = new Float64Array(n * m);
    const axes = options.spongeAxes ?? 'xz';
    for (let j = 0; j < m; j++) {
      for (let i = 0; i < n; i++) {
        const fromX = Math.min(i, n - 1 - i) + 0.5;
        const fromZ = Math.min(j, m - 1 - j) + 0.5;
        const fromEdge = axes === 'x' ? fromX : Math.min(fromX, fromZ);
        let sponge = options.sponge ? spongeDamping(fromEdge, options.sponge) : 0;
        if (options.sponge && this.rightKernel)
          sponge = Math.max(sponge, spongeDamping(Math.abs(i + 0.5 - n / 2), { ...options.sponge, width: options.sponge.width / 2 }));
        this.damping[j * n + i] = (options.damping ?? 0) + sponge;
      }
    }
    const reach = Math.max(kernel.radius, this.rightKernel?.radius ?? 0);
    this.paddedSize = n + 2 * reach;
    this.padded = new Float64Array(this.paddedSize * (m + 2 * reach));
    this.rightConvolution = new Float64Array(this.rightKernel ? n * m : 0);
  }

  /** World x of texel column i (its centre). */
  texelX(i: number): number {
    return this.centerX + (i + 0.5 - this.n / 2) * this.spacing;
  }

  texelZ(j: number): number {
    return this.centerZ + (j + 0.5 - this.rows / 2) * this.spacing;
  }

  /** Adds a bump at rest (to h and h⁻ alike): an initial elevation, as a dropped stone leaves. */
  disturb(d: Disturbance): void {
    this.addAtRest(d, this.obstacle);
  }

  private addAtRest(d: Disturbance, mask: Float32Array): void {
    const { n, rows } = this;
    const reach = Math.ceil((BUMP_REACH * d.radius) / this.spacing) + 1;
    const ci = Math.round((d.x - this.centerX) / this.spacing + n / 2 - 0.5);
    const cj = Math.round((d.z - this.centerZ) / this.spacing + rows / 2 - 0.5);
    for (let j = Math.max(0, cj - reach); j <= Math.min(rows - 1, cj + reach); j++) {
      for (let i = Math.max(0, ci - reach); i <= Math.min(n - 1, ci + reach); i++) {
        const bump = d.height * bumpProfile(Math.hypot(this.texelX(i) - d.x, this.texelZ(j) - d.z), d.radius) * mask[j * n + i];
        this.height[j * n + i] += bump;
        this.previous[j * n + i] += bump;
      }
    }
  }

  /** Moves the square by whole texels (di along x, dj along z): what scrolls in starts calm. */
  scroll(di: number, dj: number): void {
    const { n, rows } = this;
    for (const field of [this.height, this.previous]) {
      const moved = new Float64Array(n * rows);
      for (let j = 0; j < rows; j++) {
        const sj = j + dj;
        if (sj < 0 || sj >= rows) continue;
        for (let i = 0; i < n; i++) {
          const si = i + di;
          if (si >= 0 && si < n) moved[j * n + i] = field[sj * n + si];
        }
      }
      field.set(moved);
    }
    this.centerX += di * this.spacing;
    this.centerZ += dj * this.spacing;
  }

  /** Scrolls so that the centre is the texel-aligned point nearest (x, z); returns the whole texels moved. */
  recentre(x: number, z: number): [number, number] {
    const di = Math.round((x - this.centerX) / this.spacing);
    const dj = Math.round((z - this.centerZ) / this.spacing);
    if (di !== 0 || dj !== 0) this.scroll(di, dj);
    return [di, dj];
  }

  /** G ∗ h at every texel, into `out` (texel units: √(−∇²)h times Δx). */
  convolve(h: Float64Array, out: Float64Array, kernel = this.kernel): void {
    const { n, rows } = this;
    const r = kernel.radius;
    const size = 2 * r + 1;
    const p = this.paddedSize;
    const padded = this.padded;
    padded.fill(0);
    for (let j = -r; j < rows + r; j++) {
      for (let i = -r; i < n + r; i++) {
        const si = this.wrapX ? ((i % n) + n) % n : i;
        const sj = this.wrapZ ? ((j % rows) + rows) % rows : j;
        if (si < 0 || si >= n || sj < 0 || sj >= rows) continue;
        padded[(j + r) * p + (i + r)] = h[sj * n + si];
      }
    }
    const taps: { offset: number; weight: number }[] = [];
    for (let b = 0; b < size; b++) {
      for (let a = 0; a < size; a++) {
        const weight = kernel.weights[b * size + a];
        if (weight !== 0) taps.push({ offset: (b - r) * p + (a - r), weight });
      }
    }
    const offsets = Int32Array.from(taps, (t) => t.offset);
    const weights = Float64Array.from(taps, (t) => t.weight);
    for (let j = 0; j < rows; j++) {
      for (let i = 0; i < n; i++) {
        const centre = (j + r) * p + (i + r);
        let sum = 0;
        for (let t = 0; t < offsets.length; t++) sum += weights[t] * padded[centre + offsets[t]];
        out[j * n + i] = sum;
      }
    }
  }

  /**
   * One step of `dt` seconds. With a hull, its footprint is solid like the obstacle mask, and
   * after the step its two sources (hullSources) are added at rest, `dt` times their rate, to
   * the water outside it.
   */
  step(dt: number): void {
    const cells = this.n * this.rows;
    const conv = this.convolution;
    this.convolve(this.height, conv);
    if (this.rightKernel) {
      this.convolve(this.height, this.rightConvolution, this.rightKernel);
      for (let j = 0; j < this.rows; j++)
        for (let i = this.n / 2; i < this.n; i++) conv[j * this.n + i] = this.rightConvolution[j * this.n + i];
    }
    const kick = (this.gravity * dt * dt) / this.spacing;
    const out = this.next;
    const mask = this.hull ? this.hullMask(this.hull) : this.obstacle;
    for (let c = 0; c < cells; c++) {
      const half = 0.5 * this.damping[c] * dt;
      out[c] = ((2 * this.height[c] - (1 - half) * this.previous[c] - kick * conv[c]) / (1 + half)) * mask[c];
    }
    this.next = this.previous;
    this.previous = this.height;
    this.height = out;
    if (this.hull)
      for (const source of hullSources(this.hull))
        this.addAtRest({ x: source.x, z: source.z, radius: source.radius, height: source.rate * dt }, mask);
  }

  /** The obstacle mask with the hull's footprint made solid. */
  private hullMask(hull: MovingHull): Float32Array {
    const mask = Float32Array.from(this.obstacle);
    for (let j = 0; j < this.rows; j++) {
      for (let i = 0; i < this.n; i++) if (hullCovers(hull, this.texelX(i), this.texelZ(j))) mask[j * this.n + i] = 0;
    }
    return mask;
  }

  /** Height at the world point (x, z), bilinear between texel centres; 0 off the grid. */
  sample(x: number, z: number): number {
    const { n, rows } = this;
    const u = (x - this.centerX) / this.spacing + n / 2 - 0.5;
    const v = (z - this.centerZ) / this.spacing + rows / 2 - 0.5;
    const i = Math.floor(u);
    const j = Math.floor(v);
    const fu = u - i;
    const fv = v - j;
    const at = (a: number, b: number) => (a < 0 || a >= n || b < 0 || b >= rows ? 0 : this.height[b * n + a]);
    return (at(i, j) * (1 - fu) + at(i + 1, j) * fu) * (1 - fv) + (at(i, j + 1) * (1 - fu) + at(i + 1, j + 1) * fu) * fv;
  }

  /** Σ h² Δx² over the grid (m⁴): a measure of how much is moving. */
  heightSquared(): number {
    let s = 0;
    for (const h of this.height) s += h * h;
    return s * this.spacing * this.spacing;
  }
}
