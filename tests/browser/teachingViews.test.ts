import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';
import { viewBoxes } from './layoutBoxes';
import { PerspectiveCamera, Vector3 } from 'three';
import { figurePictures, crossPlacement } from '../../src/sim/teaching/teachingFigures';
import { blendedStage, noiseStages, type StageImage } from '../../src/sim/noise/noiseStages';
import { HEIGHTMAP_SIZE, surfaceStateAt } from '../../src/sim/waves/seed/seedSurface';
import { crossPoint } from '../../src/sim/optics/cubeCross';
import type { Rect } from '../../src/sim/layout/rect';

const harness = useHarness();

/**
 * How many pixels of a picture drawn at `rect` (CSS px, v up the square, nearest texel) show
 * their field's value as grey (v · 0.5 + 0.5, R = G = B, within one 8-bit level), of those
 * checked: pixels within a tenth of a texel of a texel's edge, where rounding decides, are skipped.
 */
function pictureAgreement(image: PNG, rect: Rect, field: StageImage): { checked: number; within: number } {
  let checked = 0;
  let within = 0;
  for (let py = rect.y; py < rect.y + rect.height; py += 2) {
    for (let px = rect.x; px < rect.x + rect.width; px += 2) {
      const fi = ((px + 0.5 - rect.x) / rect.width) * field.size;
      const fj = (1 - (py + 0.5 - rect.y) / rect.height) * field.size;
      if (Math.abs(fi - Math.round(fi)) < 0.1 || Math.abs(fj - Math.round(fj)) < 0.1) continue;
      const expected = field.data[Math.floor(fj) * field.size + Math.floor(fi)] * 0.5 + 0.5;
      const o = (py * image.width + px) * 4;
      checked++;
      if (
        Math.abs(image.data[o] / 255 - expected) <= 1.01 / 255 &&
        image.data[o + 1] === image.data[o] &&
        image.data[o + 2] === image.data[o]
      )
        within++;
    }
  }
  return { checked, within };
}

/** The part `rect` of a PNG, as PNG bytes. */
function crop(png: Buffer, rect: Rect): Buffer {
  const source = PNG.sync.read(png);
  const out = new PNG({ width: rect.width, height: rect.height });
  PNG.bitblt(source, out, rect.x, rect.y, rect.width, rect.height, 0, 0);
  return PNG.sync.write(out);
}

/** The share of two pictures' pixels (the second scaled to the first's size) whose grey differs by more than 8 levels. */
function greyDifference(a: PNG, ra: Rect, b: PNG, rb: Rect): number {
  let differing = 0;
  let total = 0;
  for (let y = 0; y < ra.height; y += 2) {
    for (let x = 0; x < ra.width; x += 2) {
      const va = a.data[((ra.y + y) * a.width + ra.x + x) * 4];
      const vb = b.data[((rb.y + Math.floor((y * rb.height) / ra.height)) * b.width + rb.x + Math.floor((x * rb.width) / ra.width)) * 4];
      total++;
      if (Math.abs(va - vb) > 8) differing++;
    }
  }
  return differing / total;
}

describe('teaching views of the seed figures', () => {
  it("flat normals (the seed's wrong ones) lose the waves' shading that fabricated normals give", async () => {
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

  it('shows the two heightmaps themselves as greyscale images of their values, in the free part of the canvas', async () => {
    const { page } = await openOcean(harness, 'seed=4&view=heightmap');
    const image = PNG.sync.read(await canvasPng(page));
    const maps = await page.evaluate(async () => (await window.oceano.debug.heightmaps()).map((m) => Array.from(m.data)));
    const free = (await viewBoxes(page)).published;
    await page.close();
    const size = Math.sqrt(maps[0].length);
    for (const [index, { rect }] of figurePictures('heightmap', free).entries()) {
      const map = { size, data: Float32Array.from(maps[index]) };
      const straight = pictureAgreement(image, rect, map);
      expect(straight.checked).toBeGreaterThan(1000);
      expect(straight.within, `map ${index}`).toBe(straight.checked);
      // Negative control: the same check against a transposed upload fails nearly everywhere.
      const transposed = { size, data: map.data.map((_, k) => map.data[(k % size) * size + Math.floor(k / size)]) };
      const wrong = pictureAgreement(image, rect, transposed);
      expect(wrong.within / wrong.checked, `map ${index} transposed`).toBeLessThan(0.1);
    }
  });

  // And differs from the next (controls: a stage against the next one’s array; a picture against itself).
  it('shows the Perlin noise step by step: each stage’s picture is the CPU stage’s array', async () => {
    const seed = 4;
    const time = 10;
    const { page } = await openOcean(harness, `seed=${seed}&t=${time}&view=noise-hash`, 1366, 768);
    const stages = noiseStages(seed, HEIGHTMAP_SIZE);
    const params = await page.evaluate(() => window.oceano.getParams());
    const weight = surfaceStateAt(params, time).rippleBlend;
    const expected: Record<string, StageImage> = {
      ...stages,
      first: stages.octaves,
      blend: blendedStage(stages.octaves, stages.second, weight),
    };
    // Each stage cut from the first view that shows it, checked in every view that does.
    const shown = new Map<string, { image: PNG; rect: Rect }>();
    for (const view of ['noise-hash', 'noise-smoothing', 'noise-octaves', 'noise-blend'] as const) {
      await page.evaluate((v) => window.oceano.setParams({ view: v }), view);
      const image = PNG.sync.read(await canvasPng(page));
      const free = (await viewBoxes(page)).published;
      for (const { id, rect } of figurePictures(view, free)) {
        const agreement = pictureAgreement(image, rect, expected[id]);
        expect(agreement.checked, `${view} ${id}`).toBeGreaterThan(1000);
        expect(agreement.within, `${view} ${id}`).toBe(agreement.checked);
        if (!shown.has(id)) shown.set(id, { image, rect });
      }
    }
    const captions = await page.$$eval('.oceano-figure-caption', (els) => els.map((el) => el.textContent));
    expect(captions).toEqual(['Heightmap H₀', `(1 − b) H₀ + b H₁, now b = ${weight.toFixed(2)}`, 'Heightmap H₁']);
    await page.close();
    const order = ['hash', 'smoothed', 'interpolated', 'octaves', 'blend'];
    for (let i = 0; i + 1 < order.length; i++) {
      const a = shown.get(order[i])!;
      const b = shown.get(order[i + 1])!;
      const changed = greyDifference(a.image, a.rect, b.image, b.rect);
      console.log(
        `[oceano] Perlin stage ${order[i]} -> ${order[i + 1]}: ${(changed * 100).toFixed(1)} % of the picture's pixels differ by more than 8 levels`,
      );
      expect(changed, `${order[i]} -> ${order[i + 1]}`).toBeGreaterThan(0.3);
      const wrong = pictureAgreement(a.image, a.rect, expected[order[i + 1]]);
      expect(wrong.within / wrong.checked, `${order[i]} checked as ${order[i + 1]}`).toBeLessThan(0.2);
    }
    const same = shown.get('hash')!;
    expect(greyDifference(same.image, same.rect, same.image, same.rect)).toBe(0);
  });

  // Each texel in its direction (control: the cross read mirrored).
  it('unfolds the sky’s cube map into a cross whose texels are the sky drawn behind the sea', async () => {
    const pose = { position: [0, 3, 40] as [number, number, number], target: [0, 40, -40] as [number, number, number] };
    const width = 800;
    const height = 450;
    const { page } = await openOcean(harness, `t=10&cam=${[...pose.position, ...pose.target].join(',')}`, width, height);
    const sea = PNG.sync.read(await canvasPng(page));
    await page.evaluate(() => window.oceano.setParams({ view: 'sky-cube' }));
    const cross = PNG.sync.read(await canvasPng(page));
    const free = (await viewBoxes(page)).published;
    const faces = await page.$$eval('.oceano-figure-face', (els) => els.map((el) => el.textContent));
    await page.close();
    expect(faces).toEqual(['−x', '−z (ahead)', '+x', '+z (behind)', '+y (up)', '−y (down)']);
    const { box, cell } = crossPlacement(free);
    const camera = new PerspectiveCamera(55, width / height, 0.1, 1000);
    camera.position.fromArray(pose.position);
    camera.lookAt(...pose.target);
    camera.updateMatrixWorld();
    const meanDifference = (mirror: boolean) => {
      let sum = 0;
      let count = 0;
      // The upper half of the sea view is sky alone (the boat and the horizon lie below it).
      for (let y = 4; y < height * 0.5; y += 9) {
        for (let x = 4; x < width; x += 9) {
          const ray = new Vector3(((x + 0.5) / width) * 2 - 1, 1 - ((y + 0.5) / height) * 2, 0.5).unproject(camera).sub(camera.position);
          const [cx, cy] = crossPoint([mirror ? -ray.x : ray.x, ray.y, ray.z]);
          const a = (y * width + x) * 4;
          const b = (Math.floor(box.y + cy * cell) * width + Math.floor(box.x + cx * cell)) * 4;
          for (let c = 0; c < 3; c++) sum += Math.abs(sea.data[a + c] - cross.data[b + c]);
          count += 3;
        }
      }
      return sum / count;
    };
    const straight = meanDifference(false);
    const mirrored = meanDifference(true);
    console.log(
      `[oceano] the cube's cross against the sky behind the sea: mean difference ${straight.toFixed(2)} levels; read mirrored ${mirrored.toFixed(2)}`,
    );
    expect(cell).toBeGreaterThan(60);
    // Measured: 0.34 levels (the cross's texel centres are not the sea view's rays); mirrored, 12.9.
    expect(straight).toBeLessThan(1.5);
    expect(mirrored).toBeGreaterThan(5);
  });

  // Not blank, and not the seed's maps.
  it("under waves=fft shows the largest and smallest cascade's height fields, moving with time", async () => {
    // Grey spread (8-bit levels) inside the left picture: a blank view (what waves=fft drew
    // before, the negative control) has 0.
    let left: Rect = { x: 0, y: 0, width: 0, height: 0 };
    const spread = (png: Buffer) => {
      const image = PNG.sync.read(png);
      const values: number[] = [];
      for (let y = left.y; y < left.y + left.height; y += 2) {
        for (let x = left.x; x < left.x + left.width; x += 2) values.push(image.data[(y * image.width + x) * 4]);
      }
      const mean = values.reduce((a, b) => a + b, 0) / values.length;
      return Math.sqrt(values.reduce((a, b) => a + (b - mean) ** 2, 0) / values.length);
    };
    const fft = await openOcean(harness, 'seed=4&t=10&waves=fft&view=heightmap', 320, 180);
    const pictures = figurePictures('heightmap', (await viewBoxes(fft.page)).published);
    left = pictures[0].rect;
    // The two pictures' row, where the maps are: the grey round them is the same in every view.
    const row = { ...left, width: pictures[1].rect.x + pictures[1].rect.width - left.x };
    const at10 = await canvasPng(fft.page);
    await fft.page.evaluate(() => window.oceano.setTime(14));
    const at14 = await canvasPng(fft.page);
    await fft.page.close();
    const seed = await openOcean(harness, 'seed=4&t=10&view=heightmap', 320, 180);
    const seedMaps = await canvasPng(seed.page);
    await seed.page.close();
    const fromSeed = diffPngs(crop(at10, row), crop(seedMaps, row)).share;
    const fromLater = diffPngs(crop(at10, row), crop(at14, row)).share;
    console.log(
      `[oceano] heightmap view grey spread: fft ${spread(at10).toFixed(1)}, seed ${spread(seedMaps).toFixed(1)} levels; pixels changed against the seed's ${(fromSeed * 100).toFixed(1)} %, against t = 14 s ${(fromLater * 100).toFixed(1)} %`,
    );
    // Measured: the FFT's spread is 41 levels (each map's ±3σ spans black to white); within
    // the pictures' row 59 % of the pixels change against the seed's maps and 63 % four seconds
    // later (pixelmatch's 0.1 threshold ignores small grey steps).
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
