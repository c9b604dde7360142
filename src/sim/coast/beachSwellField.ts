import { BEACH_SHORE_X, DUNE_HEIGHT, OFFSHORE_DEPTH, seaDepth, shelfWidth } from './bathymetry';
import type { CoastField, CoastSetting } from './coastField';
import { type CoastWaveModel, fieldWaveNumber } from './coastWaveModel';
import { breakingFraction, breakingHeight } from './waveTransformation';

/** Sub-steps of the trapezoid rule between two texel centres when the phase ∫ k_x dx is integrated. */
const PHASE_SUBSTEPS = 16;

/**
 * The swell over the beach by exact 1-D linear theory. The contours are the lines x = const,
 * so along z nothing changes but the phase, and the wavenumber along the shore k_z = k0 sin θ0
 * is the same everywhere (Snell's law). Across the shore k_x = √(k(h)² − k_z²), and the phase is
 *   S(x, z) = ∫ k_x dx + k_z z.
 * The height is H0 Ks Kr (shoaling and refraction), limited to γ h where the wave breaks, so the
 * surf zone is saturated down to the shoreline (Thornton & Guza 1983). On land a = 0.
 */
export function buildBeachField(setting: CoastSetting, resolution: number, model: CoastWaveModel): CoastField {
  const omega = (2 * Math.PI) / setting.swellPeriod;
  const slope = setting.beachSlope;
  // From a little beyond the shelf's edge (where h first reaches OFFSHORE_DEPTH) to a little beyond the dune's top.
  const shelf = shelfWidth(slope);
  const duneRun = DUNE_HEIGHT / slope;
  const margin = 0.04 * (shelf + duneRun);
  const originX = BEACH_SHORE_X - shelf - margin;
  const span = shelf + duneRun + 2 * margin;
  const spacing = span / (resolution - 1);
  const originZ = -span / 2;

  // Direction of travel at the offshore depth, kept off ±90° where the swell would never reach the shore.
  const theta0 = clampAngle((setting.swellDirection * Math.PI) / 180);
  const k0 = model.waveNumber(omega, OFFSHORE_DEPTH);
  const kAlong = k0 * Math.sin(theta0);
  const cg0 = model.groupVelocity(k0, OFFSHORE_DEPTH);
  const height0 = setting.swellHeight;
  const gamma = model.breakerIndex;
  const floor = { bathymetry: 'beach' as const, beachSlope: slope, deepDepth: OFFSHORE_DEPTH };

  const kAcross = (x: number): number => {
    const k = fieldWaveNumber(model, omega, seaDepth(floor, x, 0));
    return Math.sqrt(Math.max(0, k * k - kAlong * kAlong));
  };

  // One column profile, shared by every row: phase across the shore, amplitude, depth, breaking.
  const phaseAcross = new Float64Array(resolution);
  const amplitude = new Float64Array(resolution);
  const depth = new Float64Array(resolution);
  const breaking = new Float64Array(resolution);
  const subStep = spacing / PHASE_SUBSTEPS;
  let phase = 0;
  let broken = 0;
  for (let i = 0; i < resolution; i++) {
    const x = originX + i * spacing;
    if (i > 0) {
      // Trapezoid rule on PHASE_SUBSTEPS sub-intervals from the previous texel centre.
      let sum = 0.5 * (kAcross(x - spacing) + kAcross(x));
      for (let s = 1; s < PHASE_SUBSTEPS; s++) sum += kAcross(x - spacing + s * subStep);
      phase += sum * subStep;
    }
    phaseAcross[i] = phase;
    const d = seaDepth(floor, x, 0);
    depth[i] = d;
    if (d <= 0) continue;
    const k = fieldWaveNumber(model, omega, d);
    const cosTheta = Math.sqrt(Math.max(0, k * k - kAlong * kAlong)) / k;
    const shoaled = height0 * Math.sqrt(cg0 / model.groupVelocity(k, d)) * Math.sqrt(Math.cos(theta0) / cosTheta);
    // Once a wave has broken it stays broken on its way to the shore.
    broken = Math.max(broken, breakingFraction(shoaled, d, gamma));
    breaking[i] = broken;
    amplitude[i] = 0.5 * Math.min(shoaled, breakingHeight(d, gamma));
  }

  const texels = new Float32Array(resolution * resolution * 4);
  for (let j = 0; j < resolution; j++) {
    const alongPhase = kAlong * (originZ + j * spacing);
    for (let i = 0; i < resolution; i++) {
      const t = (j * resolution + i) * 4;
      texels[t] = phaseAcross[i] + alongPhase;
      texels[t + 1] = amplitude[i];
      texels[t + 2] = depth[i];
      texels[t + 3] = breaking[i];
    }
  }
  return { originX, originZ, spacing, resolution, angularFrequency: omega, texels };
}

/** Swell directions are kept within ±89°: a swell along the shore never arrives. */
function clampAngle(theta: number): number {
  const limit = (89 * Math.PI) / 180;
  return Math.min(limit, Math.max(-limit, theta));
}
