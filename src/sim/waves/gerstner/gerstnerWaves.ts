import { type DisplacementBounds, type SurfaceSample, type WaveModel } from '../waveModel';

/**
 * A sum of Gerstner (trochoidal) waves, the CPU twin of shaders/waves/gerstner.glsl.
 *
 * Each wave i moves the undisplaced grid point p = (x, z) to
 *   p + ( −Qᵢ Aᵢ k̂ᵢ sin θᵢ ,  Aᵢ cos θᵢ ),   θᵢ = kᵢ · p − ωᵢ t + φᵢ
 * (Gerstner 1802; in graphics Fournier & Reeves 1986, Tessendorf 2001 "Simulating Ocean
 * Water" eq. 6, Finch "Effective Water Simulation from Physical Models", GPU Gems ch. 1).
 * With Qᵢ = 1 a lone wave is Gerstner's exact trochoid: water particles run in circles of
 * radius Aᵢ. Qᵢ < 1 flattens the circles into ellipses and rounds the crests.
 *
 * Angles are counted in turns (θ / 2π) because that is how the shader reduces them: the
 * time part τᵢ(t) = (φᵢ − ωᵢ t) / 2π is taken mod 1 here in double precision, once per
 * frame, and the shader only ever adds fract(cₓ x) + fract(c_z z) to it. At t = 10⁶ s,
 * ωt is about 10⁶ rad, which float32 holds to only 0.06 rad; reduced, it is exact.
 */
export interface GerstnerWave {
  /** Wavevector in cycles per metre, k / 2π: the shader's unit. */
  cx: number;
  cz: number;
  /** Angular frequency ω, rad/s. */
  omega: number;
  /** Vertical amplitude A, metres. */
  amplitude: number;
  /** Horizontal amplitude Q A, metres (Q is this wave's steepness factor). */
  horizontal: number;
  /** Initial phase φ, in turns, [0, 1). */
  phase: number;
}

const TWO_PI = 2 * Math.PI;

/** x mod 1 into [0, 1), like GLSL fract. */
function fract(x: number): number {
  return x - Math.floor(x);
}

/**
 * The time part of every wave's angle, in turns and reduced to [0, 1): τᵢ = fract(φᵢ − ωᵢ t / 2π).
 * This is what the shader receives each frame (uniform uGerstnerPhases).
 */
export function gerstnerTimePhases(waves: readonly GerstnerWave[], time: number): Float64Array {
  const phases = new Float64Array(waves.length);
  for (let i = 0; i < waves.length; i++) {
    const w = waves[i];
    // ω t / 2π is split as (ω / 2π) t; both factors are doubles, so at t = 10⁶ s the product
    // (≈ 10⁵ turns) still carries ~1e-11 turns of precision before it is reduced.
    phases[i] = fract(w.phase - (w.omega / TWO_PI) * time);
  }
  return phases;
}

/**
 * Each wave's full angle at grid point (x, z), in turns, formed as the shader forms it:
 * fract(cₓ x) + fract(c_z z) + τ. The fract of each product keeps float32 exact far from the
 * origin (the integer part of the turn count carries no information).
 */
function turnsAt(w: GerstnerWave, tau: number, x: number, z: number): number {
  return fract(w.cx * x) + fract(w.cz * z) + tau;
}

/** Displacement [dx, dy, dz] of the grid point (x, z) for time phases from gerstnerTimePhases. */
export function gerstnerDisplacementAt(
  waves: readonly GerstnerWave[],
  phases: Float64Array,
  x: number,
  z: number,
): [number, number, number] {
  let dx = 0;
  let dy = 0;
  let dz = 0;
  for (let i = 0; i < waves.length; i++) {
    const w = waves[i];
    const angle = TWO_PI * turnsAt(w, phases[i], x, z);
    const s = Math.sin(angle);
    const c = Math.cos(angle);
    const inv = 1 / Math.sqrt(w.cx * w.cx + w.cz * w.cz);
    dx -= w.horizontal * w.cx * inv * s;
    dz -= w.horizontal * w.cz * inv * s;
    dy += w.amplitude * c;
  }
  return [dx, dy, dz];
}

/** The partial derivatives of [dx, dy, dz] with respect to the grid point (x, z). */
export interface GerstnerDerivatives {
  dxdx: number;
  /** ∂dx/∂z, which equals ∂dz/∂x: the horizontal Jacobian is symmetric. */
  dxdz: number;
  dzdz: number;
  dydx: number;
  dydz: number;
}

/**
 * Closed-form derivatives of the Gerstner sum at grid point (x, z). With kᵢ = 2π cᵢ and
 * k̂ᵢ = kᵢ / |kᵢ|:
 *   ∂dx/∂x = −Σ QᵢAᵢ k̂ₓ kₓ cos θ,  ∂dx/∂z = ∂dz/∂x = −Σ QᵢAᵢ k̂ₓ k_z cos θ,  ∂dz/∂z = −Σ QᵢAᵢ k̂_z k_z cos θ
 *   ∂dy/∂x = −Σ Aᵢ kₓ sin θ,         ∂dy/∂z = −Σ Aᵢ k_z sin θ
 */
export function gerstnerDerivativesAt(waves: readonly GerstnerWave[], phases: Float64Array, x: number, z: number): GerstnerDerivatives {
  let dxdx = 0;
  let dxdz = 0;
  let dzdz = 0;
  let dydx = 0;
  let dydz = 0;
  for (let i = 0; i < waves.length; i++) {
    const w = waves[i];
    const angle = TWO_PI * turnsAt(w, phases[i], x, z);
    const s = Math.sin(angle);
    const c = Math.cos(angle);
    const kx = TWO_PI * w.cx;
    const kz = TWO_PI * w.cz;
    // Q A / |k| · k k: the horizontal terms carry k̂ k = k k / |k|.
    const qc = (w.horizontal / Math.sqrt(kx * kx + kz * kz)) * c;
    dxdx -= qc * kx * kx;
    dxdz -= qc * kx * kz;
    dzdz -= qc * kz * kz;
    const as = w.amplitude * s;
    dydx -= as * kx;
    dydz -= as * kz;
  }
  return { dxdx, dxdz, dzdz, dydx, dydz };
}

/**
 * Unit normal of the displaced surface P(x, z) = (x + dx, dy, z + dz) above grid point
 * (x, z): the cross product of the closed-form tangents, ∂P/∂z × ∂P/∂x (y up; the flat
 * sea gives (0, 1, 0)).
 */
export function gerstnerNormalAt(waves: readonly GerstnerWave[], phases: Float64Array, x: number, z: number): [number, number, number] {
  const { dxdx, dxdz, dzdz, dydx, dydz } = gerstnerDerivativesAt(waves, phases, x, z);
  // Tangents tx = ∂P/∂x = (1 + dxdx, dydx, dxdz), tz = ∂P/∂z = (dxdz, dydz, 1 + dzdz).
  const tx0 = 1 + dxdx;
  const tx1 = dydx;
  const tx2 = dxdz;
  const tz0 = dxdz;
  const tz1 = dydz;
  const tz2 = 1 + dzdz;
  const nx = tz1 * tx2 - tz2 * tx1;
  const ny = tz2 * tx0 - tz0 * tx2;
  const nz = tz0 * tx1 - tz1 * tx0;
  const len = Math.hypot(nx, ny, nz);
  return [nx / len, ny / len, nz / len];
}

/**
 * Evaluations invertGerstner uses by default. Measured (tests/unit/sim/waves/gerstner/gerstnerWaves.test.ts):
 * 3 leave under 1e-5 m on every PM sea with Q = 1, 4 leave under 2e-5 m at the hard limit
 * Σ QkA = 1 with 8 or more waves, and 4 waves at that limit need 5 (1e-4 m worst).
 */
export const GERSTNER_INVERSION_STEPS = 5;

/**
 * The grid point p whose displaced position lands above the world point q = (x, z), by
 * Newton's method on p + Dₕ(p) = q with the closed-form Jacobian J = I + ∂Dₕ/∂p, after one
 * fixed-point step p₀ = q − Dₕ(q) as the start.
 *
 * Why not plain fixed-point (undoHorizontalDisplacement): its error shrinks each step by
 * the local |∂Dₕ/∂p|, up to Σ Qᵢ kᵢ Aᵢ, which the steepness limit lets reach 1. Measured
 * on PM seas with Q = 1 (tests/unit/sim/waves/gerstner/gerstnerWaves.test.ts), four fixed-point steps leave
 * residuals of centimetres on 2-m waves; Newton converges quadratically and leaves
 * micrometres in the same four evaluations. Where J is nearly singular (an exact cusp,
 * det J → 0) a Newton step is unreliable, so that step falls back to a fixed-point step.
 */
export function invertGerstner(
  waves: readonly GerstnerWave[],
  phases: Float64Array,
  x: number,
  z: number,
  steps = GERSTNER_INVERSION_STEPS,
): { x: number; z: number; residual: number } {
  const d0 = gerstnerDisplacementAt(waves, phases, x, z);
  let px = x - d0[0];
  let pz = z - d0[2];
  for (let i = 1; i < steps; i++) {
    const d = gerstnerDisplacementAt(waves, phases, px, pz);
    const rx = px + d[0] - x;
    const rz = pz + d[2] - z;
    const j = gerstnerDerivativesAt(waves, phases, px, pz);
    const a = 1 + j.dxdx;
    const b = j.dxdz;
    const c = 1 + j.dzdz;
    const det = a * c - b * b;
    if (det > 1e-6) {
      px -= (c * rx - b * rz) / det;
      pz -= (a * rz - b * rx) / det;
    } else {
      px -= rx;
      pz -= rz;
    }
  }
  const d = gerstnerDisplacementAt(waves, phases, px, pz);
  return { x: px, z: pz, residual: Math.hypot(px + d[0] - x, pz + d[2] - z) };
}

/**
 * Σ Qᵢ kᵢ Aᵢ: the bound on how far the horizontal map can compress space. Kept ≤ 1 (see
 * limitSteepness in gerstnerSpectrum.ts for why that keeps crests from looping).
 */
export function steepnessSum(waves: readonly GerstnerWave[]): number {
  let sum = 0;
  for (const w of waves) sum += TWO_PI * Math.hypot(w.cx, w.cz) * w.horizontal;
  return sum;
}

/** The Gerstner sum as a WaveModel: what the boat, the underwater switch and the physics panel read. */
export class GerstnerWaveModel implements WaveModel {
  readonly name = 'gerstner' as const;
  readonly waves: readonly GerstnerWave[];
  private readonly inversionSteps: number;

  constructor(waves: readonly GerstnerWave[], inversionSteps = GERSTNER_INVERSION_STEPS) {
    this.waves = waves;
    this.inversionSteps = inversionSteps;
  }

  /** The reduced phases of the last time asked for: callers sample many points per frame. */
  private phasesTime = Number.NaN;
  private phases: Float64Array = new Float64Array(0);

  private phasesAt(time: number): Float64Array {
    if (time !== this.phasesTime) {
      this.phases = gerstnerTimePhases(this.waves, time);
      this.phasesTime = time;
    }
    return this.phases;
  }

  displacement(x: number, z: number, time: number): [number, number, number] {
    return gerstnerDisplacementAt(this.waves, this.phasesAt(time), x, z);
  }

  normal(x: number, z: number, time: number): [number, number, number] {
    return gerstnerNormalAt(this.waves, this.phasesAt(time), x, z);
  }

  /** Height and normal above the world point; the grid point under it is found by invertGerstner. */
  sample(x: number, z: number, time: number): SurfaceSample {
    const phases = this.phasesAt(time);
    const grid = invertGerstner(this.waves, phases, x, z, this.inversionSteps);
    return {
      height: gerstnerDisplacementAt(this.waves, phases, grid.x, grid.z)[1],
      normal: gerstnerNormalAt(this.waves, phases, grid.x, grid.z),
    };
  }

  bounds(): DisplacementBounds {
    let vertical = 0;
    let horizontal = 0;
    for (const w of this.waves) {
      vertical += w.amplitude;
      horizontal += w.horizontal;
    }
    return { vertical, horizontal };
  }
}
