import { TRACK_POINTS, type TrackPoint } from './wakeTrack';

/**
 * The boat's Kelvin wake: the CPU twin of shaders/wake.glsl. Keep the two in step.
 *
 * Method, a superposition of sources along the recorded track:
 * the hull is a moving patch of pressure, and the sea's linear response to it is the sum,
 * over the hull's past positions x_s(t − τ), of the response to a pressure impulse applied
 * there τ seconds ago (Lighthill, Waves in Fluids, 1978, §3.10; Darmon, Benzaquen & Raphaël,
 * J. Fluid Mech. 738, 2014, who compute the Kelvin wake exactly this way):
 *
 *   η(x, t) = ∫₀^∞ G(|x − x_s(t − τ)|, τ) dτ.
 *
 * G is the Cauchy–Poisson response of deep water (ω² = g k) to a point impulse, in its far
 * field by stationary phase over k (Lamb, Hydrodynamics, §255): the waves at distance r,
 * τ seconds after the impulse, are those whose group velocity ½√(g/k) is r/τ, so
 *
 *   k* = g τ² / (4 r²),   phase Φ = k* r − ω* τ → g τ² / (4 r),
 *   G(r, τ) = −(√2 / 16π) (W / ρ) g τ³ / r⁴ · P̂(k*) · sin Φ,
 *
 * with W = ρ g V the hull's weight (V its displaced volume) and P̂(k) = exp(−k² σ² / 4) the
 * spectrum of a Gaussian pressure patch of radius σ (the hull's footprint). Nothing here
 * knows about 19.47°: the wedge, its cusps, the transverse wavelength 2πU²/g and the
 * bending of a turning boat's wake all come out of the τ-integral over the real track,
 * and the tests measure them. The Froude number enters through P̂: transverse waves have
 * k₀ = g/U², so k₀σ ∝ 1/Fr² with Fr = U/√(g L), and the hull filters out the short waves of a
 * slow boat. With σ and V proportional to L and L³, η/L depends only on Fr and x/L.
 *
 * Why this method rather than a kernel texture or a simulation: it follows a curved track
 * with no extra machinery (each source is where the hull really was), needs only the
 * track (64 points, a uniform array) instead of a texture pipeline, and each vertex costs
 * a fixed, bounded loop (TRACK_POINTS sources) with no state to advect.
 *
 * Quadrature: the track is piecewise linear between samples 0.5 s apart, and on each
 * segment the phase is taken as linear, whose integral is exact:
 *   ∫ A sin Φ dτ ≈ Ā Δτ sin(Φ̄) · sinc(ΔΦ / 2),
 * so a segment across which the phase turns fast (a non-stationary part of the integral)
 * contributes what it should, little, instead of aliasing. Two details are not physics:
 * r is softened to √(r² + σ²) under the hull, where the far-field G does not hold, and the
 * history is tapered to zero between 56 and 76 s of age so the end of the ring buffer leaves no
 * ring of its own.
 */

export const GRAVITY = 9.81;
/** Pressure-patch radius as a fraction of the hull's length. */
export const FOOTPRINT_PER_LENGTH = 0.25;
/**
 * Displaced volume / L³. The project's boat (8 m × 2.6 m, draft 0.62 m, block coefficient
 * ≈ 0.5) displaces ≈ 6.4 m³, 0.0125 L³.
 */
export const VOLUME_PER_LENGTH_CUBED = 0.0125;
/** History taper, seconds of age: full weight before TAPER_START, none after TAPER_END (under 78 s, about the age of the oldest point a full track holds: 16 s of fine samples, then 2 s ones up to 64 points). */
export const TAPER_START = 56;
export const TAPER_END = 76;

export interface WakeParams {
  /** Multiplies the physical amplitude (the `wakeStrength` parameter); 0 turns the wake off. */
  strength: number;
  /** Hull length L, metres. */
  hullLength: number;
  /** Gravity, m/s²; only tests change it (negative controls). */
  gravity?: number;
  /**
   * Dispersion exponent n in ω = √g kⁿ (deep water: ½). Only negative controls change it;
   * the GLSL twin always uses ½.
   */
  dispersionPower?: number;
  /** Beyond this distance from the sources' origin the wake is zero (see wakeRadius); none if absent. */
  radius?: number;
}

/** A source of the wake: where the hull was, relative to an origin, and how long ago. */
export interface WakeSource {
  x: number;
  z: number;
  /** Seconds since the hull was there, ≥ 0, increasing along the list. */
  age: number;
  speed: number;
}

/**
 * The track seen from `time`: newest first, ages ≥ 0 (points recorded after `time`, e.g. by
 * a clock that stepped back, are left out), positions relative to (originX, originZ).
 */
export function wakeSources(points: readonly TrackPoint[], time: number, originX = 0, originZ = 0): WakeSource[] {
  const out: WakeSource[] = [];
  for (const p of points) {
    const age = time - p.time;
    if (age < 0) continue;
    if (out.length > 0 && age <= out[out.length - 1].age) continue;
    out.push({ x: p.x - originX, z: p.z - originZ, age, speed: p.speed });
    if (out.length === TRACK_POINTS) break;
  }
  return out;
}

/** The history taper, shared with the GLSL (1 − smoothstep). */
export function historyWeight(age: number): number {
  const s = Math.min(1, Math.max(0, (age - TAPER_START) / (TAPER_END - TAPER_START)));
  return 1 - s * s * (3 - 2 * s);
}

/** The constant C of G = C τ³/r⁴ P̂ sin Φ, metres⁻¹·s⁻³·m⁴… so that η comes out in metres. */
export function wakeAmplitudeConstant(params: WakeParams): number {
  const g = params.gravity ?? GRAVITY;
  const volume = VOLUME_PER_LENGTH_CUBED * params.hullLength ** 3;
  // W/ρ = g V.
  return -params.strength * (Math.SQRT2 / (16 * Math.PI)) * g * g * volume;
}

/**
 * Height of the wake, metres, at (x, z) relative to the sources' origin, and its gradient
 * (∂η/∂x, ∂η/∂z), for the normal: each segment's Ā sin Φ̄ differentiated through Φ and A, the
 * sinc taken as constant (as the GLSL does).
 */
export function wakeHeightAndGradient(x: number, z: number, sources: readonly WakeSource[], params: WakeParams): [number, number, number] {
  if (params.strength === 0 || sources.length < 2) return [0, 0, 0];
  if (params.radius !== undefined && x * x + z * z > params.radius * params.radius) return [0, 0, 0];
  const g = params.gravity ?? GRAVITY;
  const n = params.dispersionPower ?? 0.5;
  const sigma = FOOTPRINT_PER_LENGTH * params.hullLength;
  const c = wakeAmplitudeConstant(params);
  let h = 0;
  let gx = 0;
  let gz = 0;
  let prev = evaluateSource(x, z, sources[0], g, n, sigma);
  for (let i = 1; i < sources.length; i++) {
    const cur = evaluateSource(x, z, sources[i], g, n, sigma);
    const dt = sources[i].age - sources[i - 1].age;
    const amplitude = 0.5 * (prev.amplitude + cur.amplitude) * dt * c;
    const phase = 0.5 * (prev.phase + cur.phase);
    const half = 0.5 * (cur.phase - prev.phase);
    const sinc = Math.abs(half) < 1e-4 ? 1 - (half * half) / 6 : Math.sin(half) / half;
    const wave = Math.sin(phase) * sinc;
    h += amplitude * wave;
    // d(Ā sin Φ̄)/dx = Ā' sin Φ̄ + Ā cos Φ̄ Φ̄' (the sinc taken as constant).
    const slope = amplitude * Math.cos(phase) * sinc;
    const w = 0.5 * dt * c * wave;
    gx += slope * 0.5 * (prev.dPhaseX + cur.dPhaseX) + w * (prev.dAmplitudeX + cur.dAmplitudeX);
    gz += slope * 0.5 * (prev.dPhaseZ + cur.dPhaseZ) + w * (prev.dAmplitudeZ + cur.dAmplitudeZ);
    prev = cur;
  }
  return [h, gx, gz];
}

interface SourceTerm {
  amplitude: number;
  phase: number;
  dPhaseX: number;
  dPhaseZ: number;
  dAmplitudeX: number;
  dAmplitudeZ: number;
}

function evaluateSource(x: number, z: number, s: WakeSource, g: number, n: number, sigma: number): SourceTerm {
  const dx = x - s.x;
  const dz = z - s.z;
  const r = Math.sqrt(dx * dx + dz * dz + sigma * sigma);
  const tau = s.age;
  let k: number;
  let phase: number;
  if (n === 0.5) {
    k = (g * tau * tau) / (4 * r * r);
    phase = k * r;
  } else {
    // ω = √g kⁿ: group velocity n √g kⁿ⁻¹ = r/τ, phase ω τ − k r (negative control only).
    k = Math.pow(r / (tau * n * Math.sqrt(g)), 1 / (n - 1));
    phase = Math.sqrt(g) * Math.pow(k, n) * tau - k * r;
  }
  const filter = Math.exp(-0.25 * k * k * sigma * sigma);
  const r2 = r * r;
  const amplitude = ((tau * tau * tau) / (r2 * r2)) * filter * historyWeight(tau);
  // ∂Φ/∂r = −k for the deep-water phase g τ²/(4r); ∂r/∂x = dx/r. With k ∝ r⁻², the amplitude
  // τ³ r⁻⁴ exp(−k²σ²/4) has ∂ln A/∂r = (−4 + k²σ²) / r.
  const dA = (amplitude * (-4 + k * k * sigma * sigma)) / (r * r);
  return { amplitude, phase, dPhaseX: (-k * dx) / r, dPhaseZ: (-k * dz) / r, dAmplitudeX: dA * dx, dAmplitudeZ: dA * dz };
}

/** The CPU twin of the GLSL `wakeHeight`: η at world (x, z) at `time`, from the recorded track. */
export function wakeHeight(x: number, z: number, time: number, track: readonly TrackPoint[], params: WakeParams): number {
  return wakeHeightAndGradient(x, z, wakeSources(track, time), params)[0];
}

/** Froude number of a hull of length L at speed U: Fr = |U| / √(g L). */
export function froudeNumber(speed: number, hullLength: number, gravity = GRAVITY): number {
  return Math.abs(speed) / Math.sqrt(gravity * hullLength);
}
