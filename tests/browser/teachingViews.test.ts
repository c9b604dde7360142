import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';

const harness = useHarness();

describe('teaching views of the seed figures', () => {
  it('flat normals (the seed\'s wrong ones) lose the waves\' shading that fabricated normals give', async () => {
    const right = PNG.sync.read(await canvasPng((await openOcean(harness, 't=10&shading=normals')).page));
    const wrong = PNG.sync.read(await canvasPng((await openOcean(harness, 't=10&shading=normals&normals=flat')).page));
    // Flat normals are (0, 1, 0) everywhere: encoded as (128, 255, 128) on every sea pixel.
    const bottomRow = (image: PNG) => Array.from({ length: image.width }, (_, x) => image.data[((image.height - 1) * image.width + x) * 4]);
    expect(new Set(bottomRow(wrong))).toEqual(new Set([128]));
    expect(new Set(bottomRow(right)).size).toBeGreaterThan(10);
  });

  it('shows the two heightmaps themselves as greyscale images of their values', async () => {
    const { page } = await openOcean(harness, 'seed=4&view=heightmap');
    const image = PNG.sync.read(await canvasPng(page));
    const maps = await page.evaluate(() => window.oceano.debug.heightmaps().map((m) => Array.from(m.data)));
    // Centre of the left square is texel (64, 64) of the first map; the screen's y runs down, the texture's up.
    const cx = Math.round(image.width / 2 - 0.45 * image.height);
    const cy = Math.round(image.height / 2);
    const pixel = image.data[(cy * image.width + cx) * 4];
    const expected = maps[0][64 * 128 + 64] * 0.5 + 0.5;
    expect(Math.abs(pixel / 255 - expected)).toBeLessThan(0.06);
    expect(image.data[(cy * image.width + cx) * 4 + 1]).toBe(pixel);
  });

  it('draws the Fresnel plot only when asked', async () => {
    const { page } = await openOcean(harness, 't=10');
    expect(await page.$('.oceano-fresnel-plot')).toBeNull();
    await page.evaluate(() => window.oceano.setParams({ fresnelPlot: true }));
    expect(await page.$eval('.oceano-fresnel-plot', (el) => (el as HTMLElement).offsetParent === null)).toBe(false);
    const withFresnel = await canvasPng(page);
    await page.evaluate(() => window.oceano.setParams({ fresnel: false }));
    expect(diffPngs(withFresnel, await canvasPng(page)).share).toBeGreaterThan(0.01);
  });
});
