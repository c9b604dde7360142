import { describe, expect, it } from 'vitest';
import { FOAM_FADE_SECONDS, foamRemaining } from '../../../../../src/sim/waves/fft/whitecaps';

describe('foam decay (Callaghan et al. 2012: e-folding τ of 0.5–8 s)', () => {
  it('leaves e⁻¹ of the foam after τ, for τ across the published range; control: a half-life τ leaves ½ and fails', () => {
    for (const tau of [0.5, FOAM_FADE_SECONDS, 8]) expect(foamRemaining(tau, tau)).toBeCloseTo(Math.exp(-1), 12);
    expect(FOAM_FADE_SECONDS).toBeGreaterThanOrEqual(0.5);
    expect(FOAM_FADE_SECONDS).toBeLessThanOrEqual(8);
    const halfLife = (t: number, tau: number) => Math.pow(0.5, t / tau);
    expect(halfLife(2.5, 2.5)).not.toBeCloseTo(Math.exp(-1), 2);
  });

  // Control: a fixed fade per frame does not.
  it('depends on time only: 60 steps of 1/60 s leave what one step of 1 s leaves', () => {
    let stepped = 1;
    for (let i = 0; i < 60; i++) stepped *= foamRemaining(1 / 60);
    expect(stepped).toBeCloseTo(foamRemaining(1), 12);
    let perFrame = 1;
    for (let i = 0; i < 60; i++) perFrame *= 0.98;
    expect(Math.abs(perFrame - 0.98)).toBeGreaterThan(0.1);
  });
});
