import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { recordedPage } from './pages';
import { PNG } from 'pngjs';
import { POSTER_SIZE, posterJobs } from '../../scripts/build/posters';
import { ensurePosters } from './distPosters';

const harness = useHarness();

/**
 * How far a poster may be from the figure's own picture, in luma (Rec. 601), 8-bit levels. WebP
 * keeps luma at full resolution but halves chroma both ways, so thin coloured lines (the frozen
 * frustum's) smear by up to 200 levels in one channel while the picture is the same; luma
 * moves by about 1 level on average (0.6-1.8 over the samples, docs/course-pages.md).
 * The same figure half a second later (the control) is off by more in both measures.
 */
const POSTER_TOLERANCE = { meanLevels: 2.5, over32: 0.01 };

interface LumaDifference {
  /** Mean |Δ luma| in levels. */
  mean: number;
  /** Share of pixels whose luma differs by more than 32 levels. */
  over32: number;
}

function lumaDifference(a: Buffer, b: Buffer): LumaDifference {
  const [left, right] = [PNG.sync.read(a), PNG.sync.read(b)];
  const pixels = left.width * left.height;
  const luma = (d: Buffer, p: number) => 0.299 * d[p] + 0.587 * d[p + 1] + 0.114 * d[p + 2];
  let sum = 0;
  let over = 0;
  for (let p = 0; p < pixels * 4; p += 4) {
    const d = Math.abs(luma(left.data, p) - luma(right.data, p));
    sum += d;
    if (d > 32) over++;
  }
  return { mean: sum / pixels, over32: over / pixels };
}

const within = (d: LumaDifference) => d.mean <= POSTER_TOLERANCE.meanLevels && d.over32 <= POSTER_TOLERANCE.over32;
const describeLuma = (d: LumaDifference) =>
  `luma mean |Δ| ${d.mean.toFixed(2)} levels (limit ${POSTER_TOLERANCE.meanLevels}), ${(d.over32 * 100).toFixed(2)} % of pixels off by more than 32 (limit ${POSTER_TOLERANCE.over32 * 100} %)`;

/** Presets and a lesson whose picture needs more than a first frame: the boat, a culling camera, code fetched late, the wake, the comparison. */
const SAMPLES = [
  'presets/boat-pitch',
  'presets/frustum-culling',
  'presets/perlin-heightmap',
  'presets/underwater',
  'presets/kelvin-wake',
  'presets/compare-models',
  'lessons/horizon',
];

/** A fresh figure of the poster's size with `attribute`, frozen at `time`: its picture once complete, as PNG. */
async function livePicture(page: Page, attribute: string, value: string, time: number): Promise<Buffer> {
  const dataUrl = await page.evaluate(
    async (name, text, t, width) => {
      const view = document.createElement('oceano-view') as HTMLElement & { oceano: (typeof window)['oceano'] | null };
      view.setAttribute(name, text);
      view.setAttribute('t', String(t));
      view.setAttribute('loading', 'eager');
      view.style.width = `${width}px`;
      document.body.append(view);
      while (!view.oceano) await new Promise((resolve) => setTimeout(resolve, 50));
      await view.oceano.ready;
      view.oceano.renderFrame();
      const picture = (view.querySelector('canvas.oceano-canvas') as HTMLCanvasElement).toDataURL('image/png');
      view.remove();
      return picture;
    },
    attribute,
    value,
    time,
    POSTER_SIZE.width,
  );
  return Buffer.from(dataUrl.split(',')[1], 'base64');
}

/** A poster from dist/posters, decoded by the browser, as PNG. */
async function posterPicture(page: Page, file: string): Promise<Buffer> {
  const dataUrl = await page.evaluate(async (url) => {
    const bitmap = await createImageBitmap(await (await fetch(url)).blob());
    const canvas = document.createElement('canvas');
    [canvas.width, canvas.height] = [bitmap.width, bitmap.height];
    canvas.getContext('2d')!.drawImage(bitmap, 0, 0);
    return canvas.toDataURL('image/png');
  }, `${harness.baseUrl}${file}`);
  return Buffer.from(dataUrl.split(',')[1], 'base64');
}

describe('posters (npm run build: dist/posters/)', () => {
  it('has one for every preset and lesson, 320×180', async () => {
    await ensurePosters(harness);
    const { page } = await recordedPage(harness, 400, 300);
    await page.goto(`${harness.baseUrl}fixtures/one-figure.html`, { waitUntil: 'load' });
    const files = posterJobs().flatMap((job) => job.files);
    const sizes = await page.evaluate(
      (base, paths) =>
        Promise.all(
          paths.map(async (path) =>
            createImageBitmap(await (await fetch(base + path)).blob()).then(
              (b) => `${b.width}×${b.height}`,
              () => 'unreadable',
            ),
          ),
        ),
      harness.baseUrl,
      files,
    );
    expect(files.length).toBeGreaterThanOrEqual(58);
    expect(new Set(sizes)).toEqual(new Set([`${POSTER_SIZE.width}×${POSTER_SIZE.height}`]));
    await page.close();
  }, 600_000);

  // Control: the same figure a moment later does not match.
  it('shows what a fresh figure with its attribute draws once complete, within the tolerance', async () => {
    await ensurePosters(harness);
    const { page, consoleErrors } = await recordedPage(harness, 400, 300);
    await page.goto(`${harness.baseUrl}fixtures/one-figure.html`, { waitUntil: 'load' });
    await page.waitForFunction(() => customElements.get('oceano-view') !== undefined);
    const rows: string[] = [];
    for (const sample of SAMPLES) {
      const [folder, value] = sample.split('/');
      const poster = await posterPicture(page, `posters/${sample}.webp`);
      const picture = await livePicture(page, folder === 'presets' ? 'preset' : 'lesson', value, 0);
      const live = lumaDifference(poster, picture);
      rows.push(`${sample}: ${describeLuma(live)}`);
      expect.soft(within(live), `${sample}: ${describeLuma(live)}`).toBe(true);
    }
    // Control: the boat pitching half a second later is another picture.
    const later = lumaDifference(
      await posterPicture(page, 'posters/presets/boat-pitch.webp'),
      await livePicture(page, 'preset', 'boat-pitch', 0.5),
    );
    rows.push(`control, boat-pitch at t = 0.5 s: ${describeLuma(later)}`);
    console.log(`posters against fresh figures:\n${rows.join('\n')}`);
    expect(within(later)).toBe(false);
    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 600_000);
});
