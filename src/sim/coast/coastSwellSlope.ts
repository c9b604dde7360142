import type { CoastField } from './coastField';

/**
 * The swell's height and slope at a world point from one reading of the coast's field, the
 * CPU twin of shaders/coast.glsl (coastFieldAt, coastSwellOf): the bilinear field of
 * sampleCoastField (coastFieldSampling.ts) and, within its cell, the exact rates of change of
 * the phase S and amplitude a, so that
 *   η = a cos θ,  ∂η/∂x = ∂a/∂x cos θ − a sin θ ∂S/∂x,  θ = S − ω t.
 * One reading instead of the five that central differences take (coastSwellNormal): the
 * vertex shader reads the field once per vertex. Beyond the grid, the field stands still but
 * for the phase, which grows at the edge's rate, as sampleCoastField has it.
 */
export function coastSwellWithSlope(field: CoastField, x: number, z: number, time: number): [number, number, number] {
  const last = field.resolution - 1;
  const u = (x - field.originX) / field.spacing;
  const v = (z - field.originZ) / field.spacing;
  const cu = Math.min(last, Math.max(0, u));
  const cv = Math.min(last, Math.max(0, v));
  const here = cell(field, cu, cv);
  let phase = here.value[0];
  let phaseU = u !== cu ? 0 : here.alongU[0];
  let phaseV = v !== cv ? 0 : here.alongV[0];
  const amplitudeU = u !== cu ? 0 : here.alongU[1];
  const amplitudeV = v !== cv ? 0 : here.alongV[1];
  const edge = phase;
  if (u !== cu) {
    const inward = u > cu ? -1 : 1;
    const rate = (edge - cell(field, cu + inward, cv).value[0]) * -inward;
    phase += rate * (u - cu);
    phaseU = rate;
  }
  if (v !== cv) {
    const inward = v > cv ? -1 : 1;
    const rate = (edge - cell(field, cu, cv + inward).value[0]) * -inward;
    phase += rate * (v - cv);
    phaseV = rate;
  }
  const amplitude = here.value[1];
  const theta = phase - field.angularFrequency * time;
  const cos = Math.cos(theta);
  const sin = Math.sin(theta);
  const perMetre = 1 / field.spacing;
  return [
    amplitude * cos,
    (amplitudeU * cos - amplitude * sin * phaseU) * perMetre,
    (amplitudeV * cos - amplitude * sin * phaseV) * perMetre,
  ];
}

/** Phase and amplitude at texel-index coordinates (u, v) inside [0, N − 1]², and their rates per texel along u and v within the cell. */
function cell(field: CoastField, u: number, v: number): { value: [number, number]; alongU: [number, number]; alongV: [number, number] } {
  const last = field.resolution - 1;
  const i0 = Math.min(Math.floor(u), last - 1);
  const j0 = Math.min(Math.floor(v), last - 1);
  const fu = u - i0;
  const fv = v - j0;
  const at = (i: number, j: number, channel: number): number => field.texels[(j * field.resolution + i) * 4 + channel];
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
