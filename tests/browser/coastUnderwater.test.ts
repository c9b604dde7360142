import { describe, expect, it } from 'vitest';
import { oceanPicture } from './harness';
import { useHarness } from './useHarness';

/**
 * Under the water over the beach's shallows (3 m of water), looking towards the shore: the
 * surface's underside, outside Snell's window, is a mirror (total internal reflection), and over
 * a sand bed 3 m down it mirrors the bright bed, not the dark open water. The same camera over
 * the open sea (bathymetry=deep) is the control: its underside mirrors only the water.
 */
const VIEW = 't=10&cam=250,-1.2,0,330,-2.5,20';
const harness = useHarness();

/** The mean green level of the picture's top fifth (the underside, above the bed's far edge). */
async function undersideGreen(query: string): Promise<number> {
  const png = await oceanPicture(harness, `${query}&${VIEW}`, 640, 360);
  let sum = 0;
  const rows = Math.floor(png.height / 5);
  for (let i = 0; i < rows * png.width * 4; i += 4) sum += png.data[i + 1];
  return sum / (rows * png.width);
}

describe('the shallows from under the water', () => {
  it('the underside mirrors the sand bed: brighter than over the open sea', async () => {
    const beach = await undersideGreen('preset=beach');
    const deep = await undersideGreen('preset=beach&bathymetry=deep');
    console.log(`[oceano] underside's green, beach shallows ${beach.toFixed(1)}, open sea ${deep.toFixed(1)}`);
    // Measured 105 against 58; with the mirror showing only the water, the shallows read about 52.
    expect(beach).toBeGreaterThan(1.5 * deep);
  });
});
