import { seaDepth, seaDepthGradient } from './bathymetry';
import type { CoastField, SwellComponentField } from './coastField';
import { breakingFraction } from './waveTransformation';

/**
 * The swell at a world point from one reading of the coast's field, the CPU twin of
 * shaders/coast.glsl line for line (coastComponentAt, coastComponentSum, coastEnvelopeLimit):
 *
 * 1. Each component's phase S_m and amplitude A_m, bilinear between texel centres, with their
 *    exact rates of change within the cell (beyond the grid the field stands still but for the
 *    phase, which grows at the edge's rate, as sampleCoastField has it).
 * 2. Their sum Z = Σ A_m e^{iθ_m}, θ_m = S_m − ω_m t + φ_m, and its gradient
 *    ∇Z = Σ (∇A_m + i A_m ∇S_m) e^{iθ_m}.
 * 3. The envelope limit: a narrow-band sea's local wave height is H = 2|Z|. Where H > γ h
 *    (McCowan) the sum is scaled by s = γ h / H, so no wave is higher than the depth can carry:
 *    in a set the big waves break further out, between sets the small ones reach the shore.
 *    η = s Re Z, and ∇η = s ∇Re Z + Re Z ∇s, with ∇s = s (∇h / h − ∇|Z| / |Z|) where it is
 *    saturated (∇h analytic, seaDepthGradient). For one component this is a = min(A, γ h / 2).
 */
export interface CoastSwell {
  /** η, metres. */
  height: number;
  /** ∂η/∂x and ∂η/∂z. */
  slopeX: number;
  slopeZ: number;
  /** How much the wave here breaks now: smoothstep of H / (γ h) from 0.9 to 1 (breakingFraction). */
  breaking: number;
  /**
   * The carrier's phase arg Z in two parts that interpolate between vertices without wrapping:
   * the components' amplitude-weighted mean phase θ̄ (radians, unwrapped, smooth as the S_m are)
   * and the unit vector Z e^{−iθ̄} / |Z| ((1, 0) where Z = 0), which turns only over a group.
   * arg Z = meanPhase + atan2(relative). The surf's foam sits on it.
   */
  meanPhase: number;
  relative: [number, number];
  /** The still water's depth, metres. */
  depth: number;
}

/** A component's phase and amplitude at a world point, and their rates of change per metre. */
export interface ComponentSample {
  phase: number;
  amplitude: number;
  phaseX: number;
  phaseZ: number;
  amplitudeX: number;
  amplitudeZ: number;
}

/**
 * The phase advance of a component at `time`: ω (t mod T) − φ, T = 2π / ω, reduced in double
 * precision so that the GPU, which gets it as a uniform, keeps it exact in float32.
 */
export function componentAdvance(component: Pick<SwellComponentField, 'angularFrequency' | 'phaseOffset'>, time: number): number {
  const period = (2 * Math.PI) / component.angularFrequency;
  return component.angularFrequency * (time - period * Math.floor(time / period)) - component.phaseOffset;
}

/** Component m's phase and amplitude at world (x, z) (coastComponentAt in shaders/coast.glsl). */
export function componentAt(field: CoastField, m: number, x: number, z: number): ComponentSample {
  const texels = field.components[m].texels;
  const last = field.resolution - 1;
  const u = (x - field.originX) / field.spacing;
  const v = (z - field.originZ) / field.spacing;
  const cu = Math.min(last, Math.max(0, u));
  const cv = Math.min(last, Math.max(0, v));
  const here = cell(texels, field.resolution, cu, cv);
  // Clamped, the field stands still along that axis but for the phase, which goes on growing at
  // the edge cell's rate (the field is linear across a cell: the edge texel less its inward neighbour).
  const phaseU = here.alongU[0];
  const phaseV = here.alongV[0];
  const amplitudeU = u !== cu ? 0 : here.alongU[1];
  const amplitudeV = v !== cv ? 0 : here.alongV[1];
  const phase = here.value[0] + (u !== cu ? phaseU * (u - cu) : 0) + (v !== cv ? phaseV * (v - cv) : 0);
  const perMetre = 1 / field.spacing;
  return {
    phase,
    amplitude: here.value[1],
    phaseX: phaseU * perMetre,
    phaseZ: phaseV * perMetre,
    amplitudeX: amplitudeU * perMetre,
    amplitudeZ: amplitudeV * perMetre,
  };
}

/** The swell at world (x, z) and time t: the components summed, then limited by the depth (see above). */
export function coastSwellAt(field: CoastField, x: number, z: number, time: number, limited = true): CoastSwell {
  // The component sum: Z and its gradient, real and imaginary parts.
  let re = 0;
  let im = 0;
  let reX = 0;
  let imX = 0;
  let reZ = 0;
  let imZ = 0;
  let weightedPhase = 0;
  let weight = 0;
  let phaseSum = 0;
  for (let m = 0; m < field.components.length; m++) {
    const c = componentAt(field, m, x, z);
    const theta = c.phase - componentAdvance(field.components[m], time);
    const cos = Math.cos(theta);
    const sin = Math.sin(theta);
    re += c.amplitude * cos;
    im += c.amplitude * sin;
    reX += c.amplitudeX * cos - c.amplitude * c.phaseX * sin;
    imX += c.amplitudeX * sin + c.amplitude * c.phaseX * cos;
    reZ += c.amplitudeZ * cos - c.amplitude * c.phaseZ * sin;
    imZ += c.amplitudeZ * sin + c.amplitude * c.phaseZ * cos;
    weightedPhase += c.amplitude * theta;
    weight += c.amplitude;
    phaseSum += theta;
  }
  // The envelope limit: H = 2|Z| at most γ h.
  const depth = seaDepth(field.floor, x, z);
  const modulus = Math.hypot(re, im);
  const height = 2 * modulus;
  const limit = field.breakerIndex * Math.max(depth, 0);
  let scale = 1;
  let scaleX = 0;
  let scaleZ = 0;
  if (limited && height > limit) {
    scale = limit / height;
    if (depth > 0) {
      const [depthX, depthZ] = seaDepthGradient(field.floor, x, z);
      const modulusX = (re * reX + im * imX) / modulus;
      const modulusZ = (re * reZ + im * imZ) / modulus;
      scaleX = scale * (depthX / depth - modulusX / modulus);
      scaleZ = scale * (depthZ / depth - modulusZ / modulus);
    }
  }
  const mean = weight > 0 ? weightedPhase / weight : phaseSum / field.components.length;
  const relativeRe = re * Math.cos(mean) + im * Math.sin(mean);
  const relativeIm = im * Math.cos(mean) - re * Math.sin(mean);
  return {
    height: scale * re,
    slopeX: scale * reX + re * scaleX,
    slopeZ: scale * reZ + re * scaleZ,
    breaking: breakingFraction(height, depth, field.breakerIndex),
    meanPhase: mean,
    relative: modulus > 0 ? [relativeRe / modulus, relativeIm / modulus] : [1, 0],
    depth,
  };
}

/** The swell's height and slope at a world point, [η, ∂η/∂x, ∂η/∂z] (coastSwellAt). */
export function coastSwellWithSlope(field: CoastField, x: number, z: number, time: number): [number, number, number] {
  const swell = coastSwellAt(field, x, z, time);
  return [swell.height, swell.slopeX, swell.slopeZ];
}

/** Phase and amplitude at texel-index coordinates (u, v) inside [0, N − 1]², and their rates per texel along u and v within the cell. */
function cell(
  texels: Float32Array,
  resolution: number,
  u: number,
  v: number,
): { value: [number, number]; alongU: [number, number]; alongV: [number, number] } {
  const last = resolution - 1;
  const i0 = Math.min(Math.floor(u), last - 1);
  const j0 = Math.min(Math.floor(v), last - 1);
  const fu = u - i0;
  const fv = v - j0;
  const at = (i: number, j: number, channel: number): number => texels[(j * resolution + i) * 2 + channel];
  const value: [number, number] = [0, 0];
  const alongU: [number, number] = [0, 0];
  const alongV: [number, number] = [0, 0];
  for (let c = 0; c < 2; c++) {
    const t00 = at(i0, j0, c);
    const t10 = at(i0 + 1, j0, c);
    const t01 = at(i0, j0 + 1, c);
    const t11 = at(i0 + 1, j0 + 1, c);
    const bottom = t00 * (1 - fu) + t10 * fu;
    const top = t01 * (1 - fu) + t11 * fu;
    value[c] = bottom * (1 - fv) + top * fv;
    alongU[c] = (t10 - t00) * (1 - fv) + (t11 - t01) * fv;
    alongV[c] = top - bottom;
  }
  return { value, alongU, alongV };
}
