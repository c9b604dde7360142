import { describe, expect, it } from 'vitest';
import { gaussianKernel, halfResolutionSigma, ONE_PASS_TAIL, onePassBlurOffset } from '../../../../src/render/underwater/gaussianKernel';

/** What four bilinear taps at (±o, ±o), each weighing ¼, add up to over a 3×3 neighbourhood (index [y + 1][x + 1]). */
function fourTapKernel(o: number): number[][] {
  const k = [
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
  ];
  for (const sx of [-1, 1]) {
    for (const sy of [-1, 1]) {
      // A bilinear tap at (sx·o, sy·o) weighs texel 0 by (1 − o) and texel ±1 by o along each axis.
      for (const [x, wx] of [
        [0, 1 - o],
        [sx, o],
      ] as const) {
        for (const [y, wy] of [
          [0, 1 - o],
          [sy, o],
        ] as const)
          k[y + 1][x + 1] += 0.25 * wx * wy;
      }
    }
  }
  return k;
}

describe('the one-pass underwater blur (src/render/underwater/gaussianKernel.ts: onePassBlurOffset)', () => {
  it("reads exactly the radius-1 Gaussian's 3×3 product kernel, for every σ it accepts", () => {
    for (const sigma of [0.1, 0.3, 0.45, halfResolutionSigma(1.5)]) {
      const o = onePassBlurOffset(sigma);
      expect(o, `σ ${sigma}`).not.toBeNull();
      const g = gaussianKernel(sigma, 1);
      const oneD = [g[1], g[0], g[1]];
      const k = fourTapKernel(o as number);
      for (let y = 0; y < 3; y++) for (let x = 0; x < 3; x++) expect(k[y][x]).toBeCloseTo(oneD[y] * oneD[x], 6);
    }
  });

  it("differs from the two separable passes' kernel (radius 2) by at most the tail it leaves out", () => {
    const sigma = halfResolutionSigma(1.5);
    const wide = gaussianKernel(sigma, 2);
    const k = fourTapKernel(onePassBlurOffset(sigma) as number);
    const at = (x: number, y: number) => (Math.abs(x) <= 1 && Math.abs(y) <= 1 ? k[y + 1][x + 1] : 0);
    let total = 0;
    for (let y = -2; y <= 2; y++) for (let x = -2; x <= 2; x++) total += Math.abs(at(x, y) - wide[Math.abs(x)] * wide[Math.abs(y)]);
    // The ring past 1 texel holds about 4 tails of the mass; left out, the same goes back to the
    // 3×3 centre: twice that moved in all, so an edge moves by at most 4 tails of its contrast.
    expect(wide[2]).toBeGreaterThan(0);
    expect(total).toBeLessThan(8 * ONE_PASS_TAIL);
  });

  it('no blur is the four taps on the texel itself; a kernel reaching past 1 texel keeps the two passes', () => {
    expect(onePassBlurOffset(0)).toBe(0);
    expect(onePassBlurOffset(halfResolutionSigma(2))).toBeNull();
    expect(onePassBlurOffset(halfResolutionSigma(8))).toBeNull();
  });
});
