/**
 * iWave's vertical-derivative operator √(−∇²) as a convolution kernel on the grid (Tessendorf,
 * "Interactive Water Surfaces", Game Programming Gems 4, 2004). On a plane wave e^{i k·x} the
 * operator multiplies by |k|, and with ∂²h/∂t² = −g √(−∇²) h that is deep water's ω² = g|k|.
 *
 * A kernel is a (2R+1)² table of weights in texel units: convolved with the heights it gives
 * √(−∇²)h times the texel size. Its Fourier response R(k) = Σ w cos(k·offset) (k in radians
 * per texel) is what the grid's waves obey: ω² = g R(k) / Δx.
 */
export interface ConvolutionKernel {
  /** Taps reach this many texels from the centre along each axis. */
  readonly radius: number;
  /** (2·radius + 1)², row by row (z), each row along x; the centre is index radius·(2·radius + 2). */
  readonly weights: Float64Array;
}

/** The kernel's size: 13 × 13 taps. */
export const IWAVE_KERNEL_RADIUS = 6;
/** Its distinct weights, one per orbit (a, b), 0 ≤ b ≤ a ≤ radius, under the grid's eightfold symmetry: 28. */
export const IWAVE_KERNEL_ORBITS = ((IWAVE_KERNEL_RADIUS + 1) * (IWAVE_KERNEL_RADIUS + 2)) / 2;

/**
 * The band (radians per texel) over which the fitted kernel's response is held to |k| and its
 * group velocity to d|k|^½/dk: 0.3 to 2.2, wavelengths from 21 texels down to 2.9. Below it a
 * 13-tap stencil cannot follow |k|'s cusp at k = 0 and flattens to R(0) > 0 (the longest waves
 * ring in place instead of running away); above it the response keeps rising, more slowly, and
 * stays positive everywhere, so every mode is stable.
 */
export const IWAVE_KERNEL_BAND: readonly [number, number] = [0.3, 2.2];

/** Every offset (a, b) with 0 ≤ b ≤ a ≤ radius stands for its up to eight mirror images: the weights share the grid's symmetry. */
function orbits(radius: number): [number, number][] {
  const list: [number, number][] = [];
  for (let a = 0; a <= radius; a++) for (let b = 0; b <= a; b++) list.push([a, b]);
  return list;
}

function mirrorImages(a: number, b: number): [number, number][] {
  const seen = new Set<string>();
  const images: [number, number][] = [];
  for (const [x, y] of [
    [a, b],
    [b, a],
  ]) {
    for (const sx of [1, -1]) {
      for (const sy of [1, -1]) {
        const key = `${sx * x},${sy * y}`;
        if (seen.has(key)) continue;
        seen.add(key);
        images.push([sx * x, sy * y]);
      }
    }
  }
  return images;
}

/** The response of one orbit's taps (weight 1 each) to a wave of wavenumber k (radians per texel) heading `angle` from +x. */
function orbitResponse(a: number, b: number, k: number, angle: number): number {
  let sum = 0;
  for (const [x, y] of mirrorImages(a, b)) sum += Math.cos(k * (x * Math.cos(angle) + y * Math.sin(angle)));
  return sum;
}

/** d/dk of orbitResponse at fixed heading. */
function orbitSlope(a: number, b: number, k: number, angle: number): number {
  let sum = 0;
  for (const [x, y] of mirrorImages(a, b)) {
    const along = x * Math.cos(angle) + y * Math.sin(angle);
    sum -= along * Math.sin(k * along);
  }
  return sum;
}

/** The kernel's Fourier response R(kx, kz), radians per texel: the grid's |k|. */
export function kernelResponse(kernel: ConvolutionKernel, kx: number, kz: number): number {
  const r = kernel.radius;
  const size = 2 * r + 1;
  let sum = 0;
  for (let j = 0; j < size; j++) {
    for (let i = 0; i < size; i++) {
      const w = kernel.weights[j * size + i];
      if (w !== 0) sum += w * Math.cos(kx * (i - r) + kz * (j - r));
    }
  }
  return sum;
}

/**
 * One weight per orbit of `radius` (orbits' order: a from 0, b from 0 to a), read from a
 * kernel of that radius or less (a smaller one's orbits beyond its reach are 0): what the GPU
 * step reads (shaders/iwaveStep.frag). A kernel without the grid's symmetry throws.
 */
export function kernelOrbitWeights(kernel: ConvolutionKernel, radius = IWAVE_KERNEL_RADIUS): Float32Array {
  const r = kernel.radius;
  if (r > radius) throw new RangeError(`A kernel of radius ${r} does not fit in ${radius}.`);
  const size = 2 * r + 1;
  const list = orbits(radius);
  const out = new Float32Array(list.length);
  list.forEach(([a, b], o) => {
    if (a > r) return;
    const images = mirrorImages(a, b).map(([x, y]) => kernel.weights[(y + r) * size + (x + r)]);
    if (images.some((w) => w !== images[0])) throw new RangeError(`The kernel is not symmetric at offset (${a}, ${b}).`);
    out[o] = images[0];
  });
  return out;
}

function kernelFromOrbits(radius: number, orbitWeights: ArrayLike<number>): ConvolutionKernel {
  const size = 2 * radius + 1;
  const weights = new Float64Array(size * size);
  orbits(radius).forEach(([a, b], o) => {
    for (const [x, y] of mirrorImages(a, b)) weights[(y + radius) * size + (x + radius)] = orbitWeights[o];
  });
  return { radius, weights };
}

/** Solves the symmetric positive definite system A x = b (n × n, row-major) by Gaussian elimination with partial pivoting. */
function solve(a: Float64Array, b: Float64Array, n: number): Float64Array {
  const m = Float64Array.from(a);
  const x = Float64Array.from(b);
  for (let c = 0; c < n; c++) {
    let pivot = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(m[r * n + c]) > Math.abs(m[pivot * n + c])) pivot = r;
    if (pivot !== c) {
      for (let k = 0; k < n; k++) [m[c * n + k], m[pivot * n + k]] = [m[pivot * n + k], m[c * n + k]];
      [x[c], x[pivot]] = [x[pivot], x[c]];
    }
    for (let r = c + 1; r < n; r++) {
      const f = m[r * n + c] / m[c * n + c];
      if (f === 0) continue;
      for (let k = c; k < n; k++) m[r * n + k] -= f * m[c * n + k];
      x[r] -= f * x[c];
    }
  }
  for (let c = n - 1; c >= 0; c--) {
    let s = x[c];
    for (let k = c + 1; k < n; k++) s -= m[c * n + k] * x[k];
    x[c] = s / m[c * n + c];
  }
  return x;
}

/**
 * The kernel Oceano runs: 13 × 13 weights with the grid's eightfold symmetry (28 distinct
 * values), fitted by least squares so that across the band, in every direction, both the
 * response R(k) and its slope dR/dk match |k|'s (R/|k| = 1 and dR/dk = 1: the phase speed and
 * the group velocity, which sets where a stone's waves of each length have got to). Rows sample
 * the band at 60 wavenumbers spaced geometrically × 8 headings from 0° to 45°; weaker rows from
 * the band's top to 3.2 ask for dR/dk = ½, so short waves still run outwards and the response
 * stays positive. Tessendorf's own construction, tessendorfKernel below, keeps ω² = g k to 5 %
 * only in a sliver of this band once truncated to 13 × 13 (docs/iwave.md gives the figures).
 */
export function fittedVerticalDerivativeKernel(
  radius = IWAVE_KERNEL_RADIUS,
  band: readonly [number, number] = IWAVE_KERNEL_BAND,
): ConvolutionKernel {
  const basis = orbits(radius);
  const unknowns = basis.length;
  const normal = new Float64Array(unknowns * unknowns);
  const rhs = new Float64Array(unknowns);
  const accumulate = (row: number[], target: number, weight: number) => {
    const w2 = weight * weight;
    for (let i = 0; i < unknowns; i++) {
      rhs[i] += w2 * row[i] * target;
      for (let j = 0; j < unknowns; j++) normal[i * unknowns + j] += w2 * row[i] * row[j];
    }
  };
  const [low, high] = band;
  const headings = 8;
  const steps = 60;
  const above = 30;
  const top = 3.2;
  for (let d = 0; d < headings; d++) {
    const angle = (d / (headings - 1)) * (Math.PI / 4);
    for (let s = 0; s < steps; s++) {
      const k = low * (high / low) ** (s / (steps - 1));
      accumulate(
        basis.map(([a, b]) => orbitResponse(a, b, k, angle) / k),
        1,
        1,
      );
      accumulate(
        basis.map(([a, b]) => orbitSlope(a, b, k, angle)),
        1,
        1,
      );
    }
    for (let s = 0; s < above; s++) {
      const k = high + ((top - high) * s) / (above - 1);
      accumulate(
        basis.map(([a, b]) => orbitSlope(a, b, k, angle)),
        0.5,
        0.1,
      );
    }
  }
  return kernelFromOrbits(radius, solve(normal, rhs, unknowns));
}

/**
 * Bessel's J0, by the polynomial and asymptotic approximations of Abramowitz & Stegun 9.4.1 and
 * 9.4.3 (absolute error below 1e-7).
 */
export function besselJ0(x: number): number {
  const ax = Math.abs(x);
  if (ax <= 3) {
    const y = (x / 3) ** 2;
    return 1 + y * (-2.2499997 + y * (1.2656208 + y * (-0.3163866 + y * (0.0444479 + y * (-0.0039444 + y * 0.00021)))));
  }
  const y = 3 / ax;
  const f0 = 0.79788456 + y * (-0.00000077 + y * (-0.0055274 + y * (-0.00009512 + y * (0.00137237 + y * (-0.00072805 + y * 0.00014476)))));
  const theta0 =
    ax - 0.78539816 + y * (-0.04166397 + y * (-0.00003954 + y * (0.00262573 + y * (-0.00054125 + y * (-0.00029333 + y * 0.00013558)))));
  return (f0 * Math.cos(theta0)) / Math.sqrt(ax);
}

/**
 * Tessendorf's kernel as the paper builds it: G(r) = Σₙ qₙ² exp(−σ qₙ²) J0(qₙ r) / G0 with
 * qₙ = n Δq, Δq = 0.001, n = 1 … 10000, G0 = Σₙ qₙ² exp(−σ qₙ²) (so G(0) = 1), σ = 1, r in
 * texels. The paper folds the unknown scale into its gravity; `physical` divides by 2π instead
 * of G0, the scale at which the untruncated continuous kernel's response is |k| exp(−σk²).
 */
export function tessendorfKernel(radius = IWAVE_KERNEL_RADIUS, sigma = 1, physical = true): ConvolutionKernel {
  const dq = 0.001;
  const count = 10000;
  let g0 = 0;
  for (let n = 1; n <= count; n++) {
    const q = n * dq;
    g0 += q * q * Math.exp(-sigma * q * q);
  }
  const values = orbits(radius).map(([a, b]) => {
    const r = Math.hypot(a, b);
    let sum = 0;
    for (let n = 1; n <= count; n++) {
      const q = n * dq;
      sum += q * q * Math.exp(-sigma * q * q) * besselJ0(q * r);
    }
    return physical ? (sum * dq) / (2 * Math.PI) : sum / g0;
  });
  return kernelFromOrbits(radius, values);
}

/**
 * The plain wave equation ∂²h/∂t² = c²∇²h as a kernel for the same solver: the five-point −∇²
 * scaled so that g R(k)/Δx = c²k² for long waves. Not dispersive: every wave runs at c.
 * `speed` c in m/s, `spacing` Δx in metres.
 */
export function waveEquationKernel(speed: number, spacing: number, gravity: number): ConvolutionKernel {
  const scale = (speed * speed) / (gravity * spacing);
  const weights = new Float64Array(9);
  weights[4] = 4 * scale;
  for (const i of [1, 3, 5, 7]) weights[i] = -scale;
  return { radius: 1, weights };
}
