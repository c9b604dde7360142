import { BEACH_SHORE_X, DUNE_HEIGHT, OFFSHORE_DEPTH, seaDepth, shelfWidth } from './bathymetry';
import type { CoastField, CoastSetting, SwellComponentField } from './coastField';
import { type CoastWaveModel, fieldWaveNumber } from './coastWaveModel';
import type { SwellComponentSpec } from './swellSpectrum';

/** Sub-steps of the trapezoid rule between two texel centres when the phase ∫ k_x dx is integrated. */
const PHASE_SUBSTEPS = 16;

/**
 * The swell over the beach by exact 1-D linear theory, component by component. The contours
 * are the lines x = const, so along z nothing changes but the phase, and the wavenumber along
 * the shore k_z = k0 sin θ0 is the same everywhere (Snell's law). Across the shore
 * k_x = √(k(h)² − k_z²), and the phase is
 *   S(x, z) = ∫ k_x dx + k_z z.
 * The amplitude is a0 Ks Kr (shoaling and refraction); breaking is left to the sum of the
 * components (coastSwellSlope.ts). On land A = 0.
 */
export function buildBeachField(
  setting: CoastSetting,
  resolution: number,
  model: CoastWaveModel,
  components: readonly SwellComponentSpec[],
): CoastField {
  const slope = setting.beachSlope;
  // From a little beyond the shelf's edge (where h first reaches OFFSHORE_DEPTH) to a little beyond the dune's top.
  const shelf = shelfWidth(slope);
  const duneRun = DUNE_HEIGHT / slope;
  const margin = 0.04 * (shelf + duneRun);
  const originX = BEACH_SHORE_X - shelf - margin;
  const span = shelf + duneRun + 2 * margin;
  const spacing = span / (resolution - 1);
  const originZ = -span / 2;
  const floor = { bathymetry: 'beach' as const, beachSlope: slope, deepDepth: OFFSHORE_DEPTH };
  const grid = { originX, originZ, spacing, resolution };
  return {
    ...grid,
    floor,
    breakerIndex: model.breakerIndex,
    components: components.map((component) => beachComponent(setting, grid, model, component)),
  };
}

/** One component's phase and amplitude over the beach's grid: exactly linear theory for its ω and offshore amplitude. */
function beachComponent(
  setting: CoastSetting,
  grid: { originX: number; originZ: number; spacing: number; resolution: number },
  model: CoastWaveModel,
  component: SwellComponentSpec,
): SwellComponentField {
  const { originX, originZ, spacing, resolution } = grid;
  const omega = component.angularFrequency;
  const floor = { bathymetry: 'beach' as const, beachSlope: setting.beachSlope, deepDepth: OFFSHORE_DEPTH };
  // Direction of travel at the offshore depth, kept off ±90° where the swell would never reach the shore.
  const theta0 = clampAngle((setting.swellDirection * Math.PI) / 180);
  const k0 = model.waveNumber(omega, OFFSHORE_DEPTH);
  const kAlong = k0 * Math.sin(theta0);
  const cg0 = model.groupVelocity(k0, OFFSHORE_DEPTH);
  const amplitude0 = component.amplitude;

  const kAcross = (x: number): number => {
    const k = fieldWaveNumber(model, omega, seaDepth(floor, x, 0));
    return Math.sqrt(Math.max(0, k * k - kAlong * kAlong));
  };

  // One column profile, shared by every row: phase across the shore and amplitude.
  const phaseAcross = new Float64Array(resolution);
  const amplitude = new Float64Array(resolution);
  const subStep = spacing / PHASE_SUBSTEPS;
  let phase = 0;
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
    if (d <= 0) continue;
    const k = fieldWaveNumber(model, omega, d);
    const cosTheta = Math.sqrt(Math.max(0, k * k - kAlong * kAlong)) / k;
    const shoaling = Math.sqrt(cg0 / model.groupVelocity(k, d));
    const refraction = Math.sqrt(Math.cos(theta0) / cosTheta);
    amplitude[i] = amplitude0 * shoaling * refraction;
  }

  const texels = new Float32Array(resolution * resolution * 2);
  for (let j = 0; j < resolution; j++) {
    const alongPhase = kAlong * (originZ + j * spacing);
    for (let i = 0; i < resolution; i++) {
      const t = (j * resolution + i) * 2;
      texels[t] = phaseAcross[i] + alongPhase;
      texels[t + 1] = amplitude[i];
    }
  }
  return { angularFrequency: omega, phaseOffset: component.phaseOffset, texels };
}

/** Swell directions are kept within ±89°: a swell along the shore never arrives. */
function clampAngle(theta: number): number {
  const limit = (89 * Math.PI) / 180;
  return Math.min(limit, Math.max(-limit, theta));
}
