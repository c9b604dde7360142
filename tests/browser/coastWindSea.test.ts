import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { oceanPicture } from './harness';
import { useHarness } from './useHarness';

/**
 * The beach from 300 m up, where the far bands' detail normals (ocean.frag) fill most of the sea.
 * With the wind sea off, what is drawn must be the swell alone: the same picture as a sea whose
 * wave model has no waves at all. The detail normals once ignored the switch (and the shallows'
 * calming), so the far bands kept their ripples and a step showed where the near bands end.
 * The control: with the wind sea on, the two pictures differ.
 */
const VIEW = 'preset=beach&t=10&cam=150,300,250,400,0,0';
const NO_WIND_WAVES = 'swellAmplitude=0&rippleStrength=0';
const harness = useHarness();

const picture = (query: string): Promise<PNG> => oceanPicture(harness, `${VIEW}&${query}`, 1280, 720);

/** The mean difference of two pictures, in levels (0–255) per channel. */
function meanDifference(a: PNG, b: PNG): number {
  let sum = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    for (let c = 0; c < 3; c++) sum += Math.abs(a.data[i + c] - b.data[i + c]);
  }
  return sum / ((a.data.length / 4) * 3);
}

describe('the wind sea at the coast', () => {
  it('switched off, draws nothing of its own in any band: the picture is that of a sea with no wind waves', async () => {
    const difference = meanDifference(await picture('windSea=0'), await picture(`windSea=0&${NO_WIND_WAVES}`));
    console.log(`[oceano] wind sea off, with and without the model's waves: ${difference.toFixed(3)} levels`);
    // Measured 0.09 (render noise); with the far bands' ripples left in, 0.61.
    expect(difference).toBeLessThan(0.3);
  });

  it('negative control: switched on, its waves change the picture', async () => {
    const difference = meanDifference(await picture('windSea=1'), await picture(`windSea=1&${NO_WIND_WAVES}`));
    console.log(`[oceano] wind sea on, with and without the model's waves: ${difference.toFixed(3)} levels`);
    expect(difference).toBeGreaterThan(0.5);
  });
});
