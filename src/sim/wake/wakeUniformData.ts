import {
  FOOTPRINT_PER_LENGTH,
  GRAVITY,
  TAPER_END,
  TAPER_START,
  wakeAmplitudeConstant,
  wakeHeightAndGradient,
  wakeSources,
  type WakeParams,
  type WakeSource,
} from './kelvinWake';
import { BOW_DECAY, TRAIL_DECAY } from './wakeFoam';
import { TRACK_POINTS, type TrackPoint } from './wakeTrack';

/**
 * Everything shaders/wake.glsl reads, packed on the CPU (pure, so node tests and the parity
 * probe can use it). Positions go up relative to a reduced origin, the boat's latest
 * position, so a vertex computes `worldXZ − uWakeOrigin`, a difference of two nearby float32
 * numbers, and the track itself is small numbers (a few hundred metres at most): float32
 * stays at the tenth of a millimetre far from the world's origin.
 */
export interface WakeUniformData {
  /** uWakeOrigin: world (x, z) of the reduced origin, the boat's latest position rounded to float32. */
  origin: [number, number];
  /** uWakeTrack: TRACK_POINTS × (x − ox, z − oz, age s, speed m/s), newest first; unused entries zero. */
  track: Float32Array;
  /** uWakeCount: points in use (0 or ≥ 2 for a wake). */
  count: number;
  /** uWakeParams: (C, σ, radius, g) with C the amplitude constant (strength included), σ the footprint radius, radius the early-out distance from the origin. */
  params: [number, number, number, number];
  /** uWakeTaper: history taper (start, end) in seconds of age. */
  taper: [number, number];
  /** uWakeFoam: (hull length, hull beam, trail decay s, bow decay s). */
  foam: [number, number, number, number];
}

/**
 * How far from the origin the wake can reach: waves from a source of age τ that matter (k ≥
 * g/U², the transverse waves and shorter) travel at most at ½U, so no farther than
 * |source| + 0.6 |U| τ, plus four footprints for the near field. Outside, the wake is zero
 * (both twins cut there, so they agree).
 */
export function wakeRadius(sources: readonly WakeSource[], hullLength: number): number {
  let radius = 0;
  for (const s of sources) radius = Math.max(radius, Math.hypot(s.x, s.z) + 0.6 * Math.abs(s.speed) * s.age);
  return radius + 4 * FOOTPRINT_PER_LENGTH * hullLength;
}

export function packWakeUniforms(points: readonly TrackPoint[], time: number, params: WakeParams, hullBeam: number): WakeUniformData {
  const head = points[0];
  // Snapped to float32, so the GPU's origin is this very number and the track is relative to it.
  const origin: [number, number] = head ? [Math.fround(head.x), Math.fround(head.z)] : [0, 0];
  const sources = wakeSources(points, time, origin[0], origin[1]);
  const track = new Float32Array(TRACK_POINTS * 4);
  sources.forEach((s, i) => track.set([s.x, s.z, s.age, s.speed], i * 4));
  const on = params.strength !== 0 && sources.length >= 2;
  return {
    origin,
    track,
    count: on ? sources.length : 0,
    params: [
      on ? wakeAmplitudeConstant(params) : 0,
      FOOTPRINT_PER_LENGTH * params.hullLength,
      on ? wakeRadius(sources, params.hullLength) : 0,
      params.gravity ?? GRAVITY,
    ],
    taper: [TAPER_START, TAPER_END],
    foam: [params.hullLength, hullBeam, TRAIL_DECAY, BOW_DECAY],
  };
}

/** The sources exactly as the GPU sees them (float32-rounded), for the parity probe's CPU side. */
export function sourcesFromUniforms(data: WakeUniformData): WakeSource[] {
  const out: WakeSource[] = [];
  for (let i = 0; i < data.count; i++)
    out.push({ x: data.track[i * 4], z: data.track[i * 4 + 1], age: data.track[i * 4 + 2], speed: data.track[i * 4 + 3] });
  return out;
}

/**
 * The wake exactly as the GPU computes it from `data` (float32 track, the radius cut), at
 * world (x, z): [η, ∂η/∂x, ∂η/∂z]. What `sampleSurface` and the parity probe should add to
 * the active wave model, so CPU and GPU agree to float32 rounding.
 */
export function wakeAtWorld(x: number, z: number, data: WakeUniformData, params: WakeParams): [number, number, number] {
  if (data.count < 2 || data.params[0] === 0) return [0, 0, 0];
  const ox = Math.fround(data.origin[0]);
  const oz = Math.fround(data.origin[1]);
  return wakeHeightAndGradient(x - ox, z - oz, sourcesFromUniforms(data), { ...params, radius: data.params[2] });
}
