import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { oceanPicture } from './harness';
import { useHarness } from './useHarness';

/**
 * compare=seed,fft,gerstner on the beach, seen from its sand. A strip holds the pixels its model
 * draws alone, coast included: every strip's sea feels the same floor. The control: the same
 * strips compared with their models alone over the open sea (bathymetry=deep) differ.
 */
const VIEW = 'preset=beach&t=10';
const MODELS = ['seed', 'fft', 'gerstner'];
const harness = useHarness();

const picture = (query: string): Promise<PNG> => oceanPicture(harness, `${VIEW}&${query}`, 960, 540);

/** The mean difference, in levels per channel, over the middle half of third `strip` (clear of the dividers). */
function stripDifference(a: PNG, b: PNG, strip: number): number {
  let sum = 0;
  let count = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = Math.floor((a.width * (strip + 0.25)) / 3); x < (a.width * (strip + 0.75)) / 3; x++) {
      const i = (y * a.width + x) * 4;
      for (let c = 0; c < 3; c++) sum += Math.abs(a.data[i + c] - b.data[i + c]);
      count += 3;
    }
  }
  return sum / count;
}

/** The compared view, drawn once for both tests. */
let comparedView: Promise<PNG> | undefined;
const compared = (): Promise<PNG> => (comparedView ??= picture(`compare=${MODELS.join(',')}`));

describe('compared models on a coast', () => {
  it('each strip is its model drawn alone over the same beach', async () => {
    const view = await compared();
    const differences: number[] = [];
    for (const [strip, model] of MODELS.entries()) differences.push(stripDifference(view, await picture(`waves=${model}`), strip));
    console.log(`[oceano] each strip against its model alone, beach: ${differences.map((d) => d.toFixed(2)).join(', ')} levels`);
    for (const difference of differences) expect(difference).toBeLessThan(1);
  });

  it('negative control: the same strips against their models alone over the open sea differ', async () => {
    const fftAlone = stripDifference(await compared(), await picture('waves=fft&bathymetry=deep'), 1);
    console.log(`[oceano] the fft strip against fft alone over the open sea: ${fftAlone.toFixed(2)} levels`);
    expect(fftAlone).toBeGreaterThan(5);
  });
});
