import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { meanChange } from './glintMeasure';
import { pixelLuminance } from '../../support/luminance';

/**
 * The lesson's switch for the sky's blur (skyBlur, shaders/skyCube.glsl skyCubeColorRough):
 * off, the sea reflects the sky as a mirror would, while the slopes below the pixels stay
 * rough. Seen from the default camera at 640×360, the far sea (rows 150–200, left of the
 * glint) changes with the switch, and the blurred reflection has less detail from pixel to
 * pixel than the sharp one: the mean luminance step between horizontal neighbours there.
 * The sky may be made of images (`sky=sky`, the shipped faces): they are given mip levels too
 * (src/render/sky/skyCube.ts). Without them the switch changed nothing there (0.00 levels on
 * the seed and FFT seas, measured): a rough sea mirrored the images sharply.
 */
const harness = useHarness();
const FAR_ROWS = [150, 200] as const;
const LEFT_OF_GLINT = 300;

function farDetail(png: Buffer): number {
  const image = PNG.sync.read(png);
  const luma = (x: number, y: number) => pixelLuminance(image.data, y * image.width + x);
  let sum = 0;
  let count = 0;
  for (let y = FAR_ROWS[0]; y < FAR_ROWS[1]; y++)
    for (let x = 0; x + 1 < LEFT_OF_GLINT; x++, count++) sum += Math.abs(luma(x + 1, y) - luma(x, y));
  return sum / count;
}

async function shot(query: string): Promise<Buffer> {
  const { page } = await openOcean(harness, query, 640, 360);
  const png = await canvasPng(page);
  await page.close();
  return png;
}

describe('the sky blurred by the roughness', () => {
  // On the seed and FFT seas, and under a sky of images.
  it('the switch reaches the far sea, where the blurred sky has less detail than the sharp one', async () => {
    for (const view of ['waves=seed', 'waves=fft', 'waves=seed&sky=sky']) {
      const blurred = await shot(`t=10&${view}`);
      const sharp = await shot(`t=10&${view}&skyBlur=0`);
      const change = meanChange(blurred, sharp, FAR_ROWS[0], FAR_ROWS[1]);
      const say = `${view}: far sea changes by ${change.toFixed(1)} levels; detail blurred ${farDetail(blurred).toFixed(2)}, sharp ${farDetail(sharp).toFixed(2)}`;
      console.log(`[oceano] skyBlur ${say}`);
      expect(change, say).toBeGreaterThan(5);
      expect(farDetail(blurred), say).toBeLessThan(farDetail(sharp));
    }
  });
});
