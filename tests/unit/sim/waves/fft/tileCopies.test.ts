import { describe, expect, it } from 'vitest';
import { breakupOctaves, breakupOther, BREAKUP_CELLS_PER_PEAK_WAVELENGTH } from '../../../../../src/sim/waves/fft/foamBreakup';
import { cascadeLayout } from '../../../../../src/sim/waves/fft/cascades';
import { tileCopyRepeat, tileCopyWeights } from '../../../../../src/sim/waves/fft/tileCopies';

const SEED = 7;

/** The field at pairs of points one tile apart (along x and along z), for the two shorter tiles, in lattice cells. */
function pairsOneTileApart(): [number, number][] {
  const peakWavelength = 1;
  const cell = peakWavelength / BREAKUP_CELLS_PER_PEAK_WAVELENGTH;
  const field = (u: number, v: number) => breakupOther(breakupOctaves(u, v, SEED));
  const pairs: [number, number][] = [];
  for (const { size } of cascadeLayout(peakWavelength, 256).slice(1)) {
    const lag = size / cell;
    for (let v = 0; v < 200; v += 0.61) {
      for (let u = 0; u < 200; u += 0.61) {
        const here = field(u, v);
        pairs.push([here, field(u + lag, v)], [here, field(u, v + lag)]);
      }
    }
  }
  return pairs;
}

describe('the far tiles’ copies (src/sim/waves/fft/tileCopies.ts)', () => {
  const pairs = pairsOneTileApart();

  it('keep the slopes’ variance: the weights’ squares add to one at every angle', () => {
    for (const field of [-1, -0.3, 0, 0.12, 0.5, 1]) {
      for (const far of [0, 0.4, 1]) {
        const [own, copy] = tileCopyWeights(field, far);
        expect(own * own + copy * copy).toBeCloseTo(1, 12);
      }
    }
    expect(tileCopyWeights(0.8, 0)).toEqual([1, 0]);
  });

  it('leave under 1 % of a tile’s repeat; control: one copy or the other (weights ≥ 0) leaves over 40 %', () => {
    const turned = tileCopyRepeat(pairs, (field) => tileCopyWeights(field, 1));
    // The blend before the turn: the copy's share a steep step of the field, the weights normalised.
    const oneOrOther = tileCopyRepeat(pairs, (field) => {
      const share = Math.min(1, Math.max(0, (field + 0.05) / 0.1));
      const norm = Math.hypot(1 - share, share);
      return [(1 - share) / norm, share / norm];
    });
    console.log(
      `[oceano] repeat left by the copies: turned ${turned.toFixed(4)}, one or the other ${oneOrOther.toFixed(3)} (${pairs.length} pairs)`,
    );
    expect(Math.abs(turned)).toBeLessThan(0.01);
    expect(oneOrOther).toBeGreaterThan(0.4);
  });

  it('turn fast enough: a third of the turn leaves over 20 % of the repeat', () => {
    const slow = tileCopyRepeat(pairs, (field) => tileCopyWeights(field / 3, 1));
    expect(slow).toBeGreaterThan(0.2);
  });
});
