import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';

const harness = useHarness();

describe('teaching views of the seed figures', () => {
  it('flat normals (the seed\'s wrong ones) lose the waves\' shading that fabricated normals give', async () => {
    // One page, the normals switched through the API: a second boot cost seconds of SwiftShader work.
    const { page } = await openOcean(harness, 't=10&shading=normals');
    const right = PNG.sync.read(await canvasPng(page));
    await page.evaluate(() => window.oceano.setParams({ normals: 'flat' }));
    const wrong = PNG.sync.read(await canvasPng(page));
    await page.close();
    // Flat normals are (0, 1, 0) everywhere: encoded as (128, 255, 128) on every sea pixel.
    const bottomRow = (image: PNG) => Array.from({ length: image.width }, (_, x) => image.data[((image.height - 1) * image.width + x) * 4]);
    expect(new Set(bottomRow(wrong))).toEqual(new Set([128]));
    expect(new Set(bottomRow(right)).size).toBeGreaterThan(10);
  });

  it('shows the two heightmaps themselves as greyscale images of their values', async () => {
    const { page } = await openOcean(harness, 'seed=4&view=heightmap');
    const image = PNG.sync.read(await canvasPng(page));
    const maps = await page.evaluate(async () => (await window.oceano.debug.heightmaps()).map((m) => Array.from(m.data)));
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

  it('under waves=fft shows the largest and smallest cascade\'s height fields: not blank, not the seed\'s maps, moving with time', async () => {
    // Grey spread (8-bit levels) inside the left square, a quarter of the frame's height in
    // from its edges: a blank view (what waves=fft drew before, the negative control) has 0.
    const spread = (png: Buffer) => {
      const image = PNG.sync.read(png);
      const values: number[] = [];
      for (let y = Math.round(image.height * 0.25); y < image.height * 0.75; y += 2) {
        for (let x = Math.round(image.width * 0.15); x < image.width * 0.45; x += 2) values.push(image.data[(y * image.width + x) * 4]);
      }
      const mean = values.reduce((a, b) => a + b, 0) / values.length;
      return Math.sqrt(values.reduce((a, b) => a + (b - mean) ** 2, 0) / values.length);
    };
    const fft = await openOcean(harness, 'seed=4&t=10&waves=fft&view=heightmap', 320, 180);
    const at10 = await canvasPng(fft.page);
    await fft.page.evaluate(() => window.oceano.setTime(14));
    const at14 = await canvasPng(fft.page);
    await fft.page.close();
    const seed = await openOcean(harness, 'seed=4&t=10&view=heightmap', 320, 180);
    const seedMaps = await canvasPng(seed.page);
    await seed.page.close();
    const fromSeed = diffPngs(at10, seedMaps).share;
    const fromLater = diffPngs(at10, at14).share;
    console.log(`[oceano] heightmap view grey spread: fft ${spread(at10).toFixed(1)}, seed ${spread(seedMaps).toFixed(1)} levels; pixels changed against the seed's ${(fromSeed * 100).toFixed(1)} %, against t = 14 s ${(fromLater * 100).toFixed(1)} %`);
    // Measured: the FFT's spread is 43 levels (each map's ±3σ spans black to white); 40 % of
    // the pixels change against the seed's maps and 44 % four seconds later (pixelmatch's
    // 0.1 threshold ignores small grey steps; the grey border is the same in all three).
    expect(spread(at10)).toBeGreaterThan(15);
    expect(fromSeed).toBeGreaterThan(0.2);
    expect(fromLater).toBeGreaterThan(0.2);
  });

  it('draws the Fresnel plot only when asked', async () => {
    const { page } = await openOcean(harness, 't=10');
    expect(await page.$('.oceano-fresnel-plot')).toBeNull();
    // The plot's code is fetched the first time it is asked for.
    await page.evaluate(async () => {
      window.oceano.setParams({ fresnelPlot: true });
      await window.oceano.loaded();
    });
    expect(await page.$eval('.oceano-fresnel-plot', (el) => (el as HTMLElement).offsetParent === null)).toBe(false);
    const withFresnel = await canvasPng(page);
    await page.evaluate(() => window.oceano.setParams({ fresnel: false }));
    expect(diffPngs(withFresnel, await canvasPng(page)).share).toBeGreaterThan(0.01);
  });
});
