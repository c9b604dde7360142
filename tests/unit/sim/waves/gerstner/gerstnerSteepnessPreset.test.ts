import { describe, expect, it } from 'vitest';
import { PRESETS } from '../../../../../src/app/url/presets';
import { gerstnerWavesFor } from '../../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { GerstnerWaveModel, type GerstnerWave } from '../../../../../src/sim/waves/gerstner/gerstnerWaves';
import { defaultParams, type OceanParams } from '../../../../../src/sim/params/params';

/**
 * The gerstner-steepness preset is there to show crests sharpening as Q goes from 0.2
 * (gerstner-gentle) to 1. Sharpening is measured on the CPU twin, on the surface as it stands
 * in the world (heights above world points, the horizontal motion undone): how much more
 * curved the crests are than the troughs. A sum of sines curves its crests and troughs alike
 * (ratio 1); a trochoid's crests curve (1 + QkA)² / (1 − QkA)² times more than its troughs, so
 * the ratio grows with Q, fastest for the steepest waves, which are also what the eye sees.
 */

const TIME = 10;
/** A 30 m square sampled every 10 cm: several wavelengths of the shortest wave, each with 40 samples. */
const STEP = 0.1;
const SIDE = 300;
/** The inversion sweeps take about 1 s each alone; the shared 2-core machine can triple that. */
const SLOW = 30_000;

/** The preset's sea: the defaults with the preset's parameters, at steepness Q. */
function presetSea(name: 'gerstner-steepness' | 'gerstner-gentle', steepness?: number): GerstnerWave[] {
  const params: OceanParams = { ...defaultParams(), ...PRESETS[name].params };
  return gerstnerWavesFor({ ...params, gerstnerSteepness: steepness ?? params.gerstnerSteepness });
}

/**
 * Crest-to-trough curvature ratio: −P₁ / P₉₉ of the Laplacian ∇²η of the world-space height
 * over the square (the 1st percentile is the sharpest crests, the 99th the sharpest troughs;
 * percentiles rather than extremes, so one sample does not decide it).
 */
function crestToTroughCurvature(waves: readonly GerstnerWave[]): number {
  const model = new GerstnerWaveModel([...waves]);
  const height = new Float64Array(SIDE * SIDE);
  for (let j = 0; j < SIDE; j++) {
    for (let i = 0; i < SIDE; i++) height[j * SIDE + i] = model.sample(i * STEP - 15, j * STEP - 15, TIME).height;
  }
  const laplacian: number[] = [];
  for (let j = 1; j < SIDE - 1; j++) {
    for (let i = 1; i < SIDE - 1; i++) {
      const k = j * SIDE + i;
      laplacian.push((height[k - 1] + height[k + 1] + height[k - SIDE] + height[k + SIDE] - 4 * height[k]) / (STEP * STEP));
    }
  }
  laplacian.sort((a, b) => a - b);
  const percentile = (q: number) => laplacian[Math.round(q * (laplacian.length - 1))];
  return -percentile(0.01) / percentile(0.99);
}

describe('the gerstner-steepness preset sharpens crests as Q goes from 0.2 to 1', () => {
  it("is the gentle preset's sea at a higher Q, nothing else changed", () => {
    const { gerstnerSteepness: steep, ...steepRest } = PRESETS['gerstner-steepness'].params;
    const { gerstnerSteepness: gentle, ...gentleRest } = PRESETS['gerstner-gentle'].params;
    expect([gentle, steep]).toEqual([0.2, 1]);
    expect(steepRest).toEqual(gentleRest);
    expect(PRESETS['gerstner-steepness'].camera).toEqual(PRESETS['gerstner-gentle'].camera);
  });

  it('crests grow more curved than troughs with Q: about 1.5 times at Q = 0.2, over 6 at Q = 1', { timeout: SLOW }, () => {
    const ratios = [0.2, 0.6, 1].map((q) => crestToTroughCurvature(presetSea('gerstner-steepness', q)));
    // Measured: 1.53, 3.34, 6.41. (The preset's earlier 64-wave sea measured 0.96, 1.30, 1.73:
    // its sharpening stayed below what its camera could show.)
    expect(ratios[0]).toBeLessThan(2);
    expect(ratios[1]).toBeGreaterThan(ratios[0] * 1.5);
    expect(ratios[2]).toBeGreaterThan(ratios[1] * 1.5);
    expect(ratios[2]).toBeGreaterThan(5);
  });

  // The same sea otherwise.
  it('negative control: the horizontal motion reversed rounds the crests and sharpens the troughs', { timeout: SLOW }, () => {
    // The planted fault: +Q A k̂ sin θ instead of −Q A k̂ sin θ (a sign slip in the twin or shader).
    const reversed = presetSea('gerstner-steepness').map((w) => ({ ...w, horizontal: -w.horizontal }));
    // Measured: 0.16 (the troughs now carry the cusps).
    expect(crestToTroughCurvature(reversed)).toBeLessThan(0.5);
  });
});
