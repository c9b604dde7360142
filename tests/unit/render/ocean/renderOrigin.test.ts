import { describe, expect, it } from 'vitest';
import { renderOrigin, RENDER_ORIGIN_STEP } from '../../../../src/render/ocean/renderOrigin';

describe('renderOrigin', () => {
  it('is the world origin near it, so views there are drawn as before', () => {
    expect(renderOrigin(0, 40)).toEqual([0, 0]);
    expect(renderOrigin(-2000, 2000)).toEqual([0, 0]);
    expect(Object.is(renderOrigin(-1, -1)[0], 0)).toBe(true);
  });

  it('lies within half a step of the camera, on a point float32 holds exactly', () => {
    for (const [x, z] of [
      [999000, 999040],
      [-1e6, 123456.75],
      [3000, -5000],
    ]) {
      const [ox, oz] = renderOrigin(x, z);
      expect(Math.abs(ox - x)).toBeLessThanOrEqual(RENDER_ORIGIN_STEP / 2);
      expect(Math.abs(oz - z)).toBeLessThanOrEqual(RENDER_ORIGIN_STEP / 2);
      expect(Math.fround(ox)).toBe(ox);
      expect(Math.fround(oz)).toBe(oz);
      // A chunk corner (a multiple of 2 m) less the origin is a multiple of 2 m too.
      expect(Math.abs(ox % 2)).toBe(0);
    }
  });
});
