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
    const size = Math.sqrt(maps[0].length);
    // Where heightmapView.frag puts each map: two squares 0.9 of the height tall, side by
    // side about the centre, a 2 % gap at the seam, texture v upwards while screen y runs down.
    const gap = 0.02;
    const { width: w, height: h } = image;
    const check = (map: number[], second: boolean, transposed: boolean) => {
      let checked = 0;
      let within = 0;
      for (let py = 0; py < h; py += 3) {
        for (let px = 0; px < w; px += 3) {
          const uvx = (px + 0.5 - w / 2) / h / 0.9 + 1;
          const uvy = (0.5 - (py + 0.5) / h) / 0.9 + 0.5;
          if (uvy < 0 || uvy >= 1 || (second ? uvx < 1 + gap || uvx >= 2 : uvx < 0 || uvx >= 1 - gap)) continue;
          const s = second ? (uvx - 1 - gap) / (1 - gap) : uvx / (1 - gap);
          const fi = s * size;
          const fj = uvy * size;
          // Nearest filtering: skip pixels within a tenth of a texel of a texel edge, where rounding decides.
          if (Math.abs(fi - Math.round(fi)) < 0.1 || Math.abs(fj - Math.round(fj)) < 0.1) continue;
          const [i, j] = transposed ? [Math.floor(fj), Math.floor(fi)] : [Math.floor(fi), Math.floor(fj)];
          const expected = map[j * size + i] * 0.5 + 0.5;
          const o = (py * w + px) * 4;
          checked++;
          // One level of 8-bit rounding, and grey: R = G = B.
          if (Math.abs(image.data[o] / 255 - expected) <= 1.01 / 255 && image.data[o + 1] === image.data[o] && image.data[o + 2] === image.data[o]) within++;
        }
      }
      return { checked, within };
    };
    for (const [index, second] of [
      [0, false],
      [1, true],
    ] as const) {
      const straight = check(maps[index], second, false);
      expect(straight.checked).toBeGreaterThan(2000);
      expect(straight.within, `map ${index}`).toBe(straight.checked);
      // Negative control: the same check against a transposed upload fails nearly everywhere.
      const transposed = check(maps[index], second, true);
      expect(transposed.within / transposed.checked, `map ${index} transposed`).toBeLessThan(0.1);
    }
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
