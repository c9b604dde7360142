import { describe, expect, it } from 'vitest';
import { undoHorizontalDisplacement } from '../../../../src/sim/waves/waveModel';

// A single trochoid: D(p) = (−A sin(k p), A cos(k p)) along x. With k A = 0.7 the
// horizontal map's derivative is 1 − kA cos, so the fixed point contracts with rate ≤ 0.7.
const A = 1;
const K = 0.7;
const trochoid = (x: number): [number, number, number] => [-A * Math.sin(K * x), A * Math.cos(K * x), 0];

describe('undoHorizontalDisplacement', () => {
  it('finds the grid point whose displaced position is the query point (seeded points, seed 7)', () => {
    let s = 7;
    const rand = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
    for (let i = 0; i < 100; i++) {
      const q = (rand() - 0.5) * 200;
      const r = undoHorizontalDisplacement((x) => trochoid(x), q, 3, 40);
      expect(r.residual).toBeLessThan(1e-6);
      expect(r.x + trochoid(r.x)[0]).toBeCloseTo(q, 6);
      expect(r.z).toBe(3);
    }
  });

  it('reports a large residual when given too few steps for a steep wave (negative control)', () => {
    const steep = (x: number): [number, number, number] => [-Math.sin(0.95 * x), 0, 0];
    const worst = Math.max(...Array.from({ length: 50 }, (_, i) => undoHorizontalDisplacement((x) => steep(x), i * 0.37, 0, 0).residual));
    expect(worst).toBeGreaterThan(0.1);
  });
});
