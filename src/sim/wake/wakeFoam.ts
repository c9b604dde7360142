import { froudeNumber } from './kelvinWake';
import type { TrackPoint } from './wakeTrack';
import { smoothstep } from '../math/smoothstep';

/**
 * Foam behind the boat, read from the same recorded track as the wake (the GLSL twin is
 * `wakeFoam` in shaders/wake.glsl). Two parts:
 * - the hull's trail: water churned by the hull and propeller along the path, a band as wide
 *   as the beam that slowly widens and fades with the age of the water it marks;
 * - the bow wave: water broken at the bow, left behind as two lines that spread outwards
 *   from the path as they age, fading faster.
 * Real trails last about a minute in calm water and the whitecap of a bow wave a few tens
 * of seconds; the e-folding times below sit there. Neither is a fluid simulation: foam is
 * a look, its ages come from the track. A slow hull (Fr under ≈ 0.1) breaks no water, so the
 * intensity rises with the Froude number to its full value at Fr ≈ 0.35.
 */
export interface FoamParams {
  hullLength: number;
  hullBeam: number;
  /** e-folding time of the trail, seconds (tests change it for negative controls). */
  trailDecay?: number;
  /** e-folding time of the bow wave's foam, seconds. */
  bowDecay?: number;
}

export const TRAIL_DECAY = 20;
export const BOW_DECAY = 4;
/** The bow wave's foam spreads sideways at this fraction of the boat's speed (its crest leaves the bow at ≈ 20°, tan 20° ≈ 0.36). */
export const BOW_SPREAD = 0.36;

/**
 * Foam intensity in [0, 1] at world (x, z) at `time`, from the track (newest first, as
 * TrackRecorder.points / WakeTrack.points give it). Per track segment, the point's closest
 * approach gives the age and speed of the water there and its distance from the path; the
 * strongest segment wins, so joints are not counted twice.
 */
export function wakeFoam(x: number, z: number, time: number, points: readonly TrackPoint[], params: FoamParams): number {
  const trailDecay = params.trailDecay ?? TRAIL_DECAY;
  const bowDecay = params.bowDecay ?? BOW_DECAY;
  const halfBeam = 0.5 * params.hullBeam;
  let trail = 0;
  let bow = 0;
  for (let i = 1; i < points.length; i++) {
    const a = points[i - 1];
    const b = points[i];
    const ex = b.x - a.x;
    const ez = b.z - a.z;
    const len2 = ex * ex + ez * ez;
    if (len2 < 1e-8) continue;
    const along = ((x - a.x) * ex + (z - a.z) * ez) / len2;
    // Ahead of the boat (before the newest point) there is no foam. Elsewhere the trail uses
    // the closest point of the segment, ends included, so the outside of a bend has no gap.
    if (i === 1 && along < 0) continue;
    const f = Math.min(1, Math.max(0, along));
    const d = Math.hypot(x - (a.x + ex * f), z - (a.z + ez * f));
    const age = time - (a.time + (b.time - a.time) * f);
    if (age < 0) continue;
    const speed = Math.abs(a.speed + (b.speed - a.speed) * f);
    const breaking = smoothstep(0.1, 0.35, froudeNumber(speed, params.hullLength));
    if (breaking === 0) continue;
    // Trail: a Gaussian band of half-width the half-beam, widening by 5 % of the beam per second.
    const width = halfBeam * (1 + 0.1 * age);
    trail = Math.max(trail, breaking * Math.exp(-age / trailDecay) * Math.exp((-0.5 * d * d) / (width * width)));
    // Bow wave: born at the bow, half a hull ahead of the centre the track records. Only
    // where the point projects inside the segment: a clamped end would draw circles.
    if (along < 0 || along > 1) continue;
    const bowAge = age + (0.5 * params.hullLength) / Math.max(speed, 1e-3);
    const offset = halfBeam + BOW_SPREAD * speed * bowAge;
    const bowWidth = 0.3 + 0.05 * speed * bowAge;
    const off = d - offset;
    bow = Math.max(bow, breaking * Math.exp(-bowAge / bowDecay) * Math.exp((-0.5 * off * off) / (bowWidth * bowWidth)));
  }
  return Math.min(1, trail + bow);
}
