import { describe, expect, it } from 'vitest';
import type { Vector4 } from 'three';
import { GERSTNER_MAX_WAVES, GerstnerWaveUniforms } from '../../../../../src/render/waves/gerstner/gerstnerWaveUniforms';
import { gerstnerSea } from '../../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { gerstnerTimePhases } from '../../../../../src/sim/waves/gerstner/gerstnerWaves';
import { cosineSquared, piersonMoskowitz } from '../../../../support/testSeas';

const sea = gerstnerSea({
  count: 37,
  seed: 4,
  spectrum: piersonMoskowitz(9).spectrum,
  spreading: cosineSquared,
  windDirection: 2,
  steepness: 0.7,
});

describe('GerstnerWaveUniforms', () => {
  it('uploads the wave table once and zeroes the unused slots', () => {
    const u = new GerstnerWaveUniforms(sea);
    const table = u.uniforms.uGerstnerWaves.value as Vector4[];
    expect(u.uniforms.uGerstnerCount.value).toBe(37);
    expect(table).toHaveLength(GERSTNER_MAX_WAVES);
    expect(table[5].toArray()).toEqual([sea[5].cx, sea[5].cz, sea[5].amplitude, sea[5].horizontal]);
    expect(table[37].toArray()).toEqual([0, 0, 0, 0]);
  });

  it('packs the reduced time phases four to a vec4, wave i at [i >> 2][i & 3], at t = 1e6 s', () => {
    const u = new GerstnerWaveUniforms(sea);
    const t = 1e6 + 0.37;
    u.update(t);
    const packed = u.uniforms.uGerstnerPhases.value as Vector4[];
    const expected = gerstnerTimePhases(sea, t);
    for (let i = 0; i < sea.length; i++) expect(packed[i >> 2].getComponent(i & 3)).toBe(expected[i]);
    for (let i = sea.length; i < GERSTNER_MAX_WAVES; i++) expect(packed[i >> 2].getComponent(i & 3)).toBe(0);
    // Every phase is reduced to [0, 1) turns: what keeps float32 exact.
    for (const v of expected) expect(v >= 0 && v < 1).toBe(true);
  });

  it('a new sea replaces the old one, and more than 64 waves is refused', () => {
    const u = new GerstnerWaveUniforms(sea);
    u.setWaves(sea.slice(0, 4));
    expect(u.uniforms.uGerstnerCount.value).toBe(4);
    expect((u.uniforms.uGerstnerWaves.value as Vector4[])[4].toArray()).toEqual([0, 0, 0, 0]);
    expect(() => u.setWaves([...sea, ...sea])).toThrow(/At most 64/);
  });

  it('carries the GLSL text', () => {
    expect(GerstnerWaveUniforms.chunk).toContain('vec3 waveDisplacement(vec2 gridXZ)');
  });
});
