import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { BAND_STEPS, BASE_STEP, DETAIL_NORMALS_FROM, bandHasDetailNormals } from '../../../../src/sim/lod/lodBands';

// ocean.frag fades the far bands' per-pixel detail normals in with
// smoothstep(DETAIL_FROM, DETAIL_FULL, vertexSpacing); the bands drawn without that code
// (OceanMaterial.near) must be exactly those where the fade is 0.
function smoothstep(edge0: number, edge1: number, x: number): number {
  const t = Math.min(1, Math.max(0, (x - edge0) / (edge1 - edge0)));
  return t * t * (3 - 2 * t);
}

describe('bands drawn without per-pixel detail normals', () => {
  const shader = readFileSync('shaders/ocean.frag', 'utf8');
  const full = Number(/const float DETAIL_FULL = ([\d.]+);/.exec(shader)?.[1]);

  it('reads its fade start from the shared constant', () => {
    expect(shader).toContain('const float DETAIL_FROM = DETAIL_NORMALS_FROM;');
    expect(full).toBeGreaterThan(DETAIL_NORMALS_FROM);
  });

  it('are exactly the bands whose detail weight is 0 (bands 0-2 at 2, 4, 6 m)', () => {
    const withDetail = BAND_STEPS.map((_, band) => bandHasDetailNormals(band));
    const weighted = BAND_STEPS.map((step) => smoothstep(DETAIL_NORMALS_FROM, full, step * BASE_STEP) > 0);
    expect(withDetail).toEqual(weighted);
    expect(withDetail).toEqual([false, false, false, true, true, true]);
  });
});
