import { describe, expect, it } from 'vitest';
import { defaultParams } from '../../../../../src/sim/params/params';
import { gerstnerWavesFor } from '../../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { gerstnerFinestVertexStep, STEEP_SLOPE } from '../../../../../src/sim/waves/gerstner/gerstnerVertexStep';
import type { GerstnerWave } from '../../../../../src/sim/waves/gerstner/gerstnerWaves';
import {
  BAND_STEPS,
  BASE_STEP,
  CHUNK_QUADS,
  MAX_REFINEMENT,
  nearBandRefinement,
  refinedEdgeStep,
} from '../../../../../src/sim/lod/lodBands';
import { snappedEdge } from '../../../../../src/sim/lod/edgeSnap';
import { PRESETS } from '../../../../../src/app/url/presets';

/** One wave of wavelength λ and peak slope Ak, no horizontal motion. */
function wave(wavelength: number, slope: number, horizontalSlope = 0): GerstnerWave {
  const k = (2 * Math.PI) / wavelength;
  return { cx: 1 / wavelength, cz: 0, omega: Math.sqrt(9.81 * k), amplitude: slope / k, horizontal: horizontalSlope / k, phase: 0 };
}

describe('the mesh a Gerstner sea asks for near the eye', () => {
  // A sine wave just below it asks for nothing, its trochoid (q = 0.6) does.
  it('8 vertices on the shortest wave whose slope reaches 0.15, for a trochoid but not a sine', () => {
    expect(gerstnerFinestVertexStep([wave(40, 0.3), wave(4, 0.2)])).toBeCloseTo(0.5, 12);
    expect(gerstnerFinestVertexStep([wave(40, 0.3), wave(4, 0.1)])).toBeCloseTo(5, 12);
    expect(gerstnerFinestVertexStep([wave(4, 0.9 * STEEP_SLOPE)])).toBe(Infinity);
    // Ak / √(1 − q²) = 0.135 / 0.8 = 0.169 ≥ 0.15.
    expect(gerstnerFinestVertexStep([wave(4, 0.9 * STEEP_SLOPE, 0.6)])).toBeCloseTo(0.5, 12);
  });

  it('the lessons’ 4-wave seas are split to 0.5 m, the default 32-wave sea at any wind is not', () => {
    for (const name of ['gerstner-steepness', 'gerstner-gentle'] as const) {
      const waves = gerstnerWavesFor({ ...defaultParams(), ...PRESETS[name].params } as ReturnType<typeof defaultParams>);
      expect(nearBandRefinement(gerstnerFinestVertexStep(waves))).toBe(MAX_REFINEMENT);
    }
    for (const windSpeed of [3, 10, 30]) {
      const waves = gerstnerWavesFor({ ...defaultParams(), windSpeed });
      expect(nearBandRefinement(gerstnerFinestVertexStep(waves))).toBe(1);
    }
  });
});

describe('the nearest band split for finer vertices', () => {
  it('halves the step until it reaches the spacing asked for, at most to 0.5 m', () => {
    expect(nearBandRefinement(Infinity)).toBe(1);
    expect(nearBandRefinement(BASE_STEP)).toBe(1);
    expect(nearBandRefinement(1.9)).toBe(2);
    expect(nearBandRefinement(1)).toBe(2);
    expect(nearBandRefinement(0.6)).toBe(4);
    expect(nearBandRefinement(0.01)).toBe(MAX_REFINEMENT);
  });

  // Control: the shared step left unscaled puts vertices between the coarse ones (cracks).
  it('a split chunk’s side meets a coarser neighbour’s vertices exactly and a split neighbour’s all', () => {
    for (const refine of [2, 4]) {
      const unit = BASE_STEP / refine;
      const metres = (units: number[], step: number) => units.map((u) => u * step);
      // Beside band 1 (step 2): the split side, snapped, has exactly the neighbour's vertices.
      const coarse = metres(snappedEdge(CHUNK_QUADS, BAND_STEPS[1], BAND_STEPS[1]), BASE_STEP);
      expect(metres(snappedEdge(CHUNK_QUADS * refine, 1, refinedEdgeStep(BAND_STEPS[1], refine)), unit)).toEqual(coarse);
      const unscaled = metres(snappedEdge(CHUNK_QUADS * refine, 1, BAND_STEPS[1]), unit);
      expect(unscaled.some((z) => !coarse.includes(z))).toBe(true);
      // Beside another split chunk: every split vertex is shared.
      expect(snappedEdge(CHUNK_QUADS * refine, 1, refinedEdgeStep(BAND_STEPS[0], refine))).toHaveLength(CHUNK_QUADS * refine + 1);
    }
  });
});
