import { describe, expect, it } from 'vitest';
import { BREAKER_INDEX, windSeaFactor, windSeaHeightOf } from '../../../../src/sim/coast/windSeaDamping';

describe('the wind sea at the coast', () => {
  it('is whole where the water holds its largest wave (γ h ≥ H) and nothing on land', () => {
    expect(windSeaFactor(10, 4)).toBe(1);
    expect(windSeaFactor(4 / BREAKER_INDEX, 4)).toBe(1);
    expect(windSeaFactor(0, 4)).toBe(0);
    expect(windSeaFactor(-2, 4)).toBe(0);
  });

  it('limits the largest wave to γ h in the shallows (depth-limited, McCowan)', () => {
    for (const depth of [0.5, 1, 2, 3]) expect(windSeaFactor(depth, 4) * 4).toBeCloseTo(BREAKER_INDEX * depth, 12);
  });

  it('takes the largest height as twice the vertical bound (crest to trough)', () => {
    expect(windSeaHeightOf(1.7)).toBe(3.4);
  });

  it('negative control: a sea with no height is never scaled', () => {
    expect(windSeaFactor(0.1, 0)).toBe(1);
  });
});
