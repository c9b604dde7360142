import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { fixtureBundle } from './fixtureBundle';
import { BROWSER_ARGS, findBrowser } from './harness';
import type { OceanCamerasApi } from './fixtures/oceanCameras';

/**
 * One library Ocean (autoUpdate) seen by many cameras in one frame: each camera draws the
 * chunks and bands chosen for it. Two viewports of one canvas, each the picture that camera
 * draws alone; a CubeCamera's six faces, each seeing the sea below its horizon. The page is a
 * bundle of tests/browser/fixtures/oceanCameras.ts.
 */
let browser: Browser;
let page: Page;

const VIEW = 160;
/** The same tolerance as oceanSurface.test.ts's: pixels off by more than 2 levels, fewer than 40 of a 160 × 160 view. */
const SAME_PICTURE = 40;

beforeAll(async () => {
  const code = await fixtureBundle('oceanCameras', true);
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'oceanCameras' in window, { timeout: 60_000 }).catch((e: unknown) => errors.push(String(e)));
  await page.evaluate(() => (window as unknown as Api).oceanCameras.ready());
  expect(errors).toEqual([]);
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

type Api = { oceanCameras: OceanCamerasApi };
type Side = 'east' | 'west';
const draw = (sides: Side[], by: 'auto' | 'east') => page.evaluate((s, b) => (window as unknown as Api).oceanCameras.draw(s, b), sides, by);
const cube = (by: 'auto' | 'east') => page.evaluate((b) => (window as unknown as Api).oceanCameras.cube(b), by);

/** Pixels of the view at column `x0` (VIEW wide) whose largest channel difference exceeds 2 levels. */
function differingInView(a: number[], b: number[], x0: number): number {
  let count = 0;
  for (let y = 0; y < VIEW; y++) {
    for (let x = x0; x < x0 + VIEW; x++) {
      const i = (y * 2 * VIEW + x) * 4;
      if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 2) count++;
    }
  }
  return count;
}

/** Share of the view's pixels in the clear colour (magenta): where no sea was drawn. */
function clearShare(pixels: number[], x0: number): number {
  let clear = 0;
  for (let y = 0; y < VIEW; y++)
    for (let x = x0; x < x0 + VIEW; x++) {
      const i = (y * 2 * VIEW + x) * 4;
      if (pixels[i] > 200 && pixels[i + 1] < 60 && pixels[i + 2] > 200) clear++;
    }
  return clear / (VIEW * VIEW);
}

describe('two viewports, two cameras, one self-updating Ocean', () => {
  it('draws each viewport as the ocean drawn alone from that camera', async () => {
    const split = await draw(['east', 'west'], 'auto');
    const east = await draw(['east'], 'auto');
    const west = await draw(['west'], 'auto');
    const off = [differingInView(split, east, 0), differingInView(split, west, VIEW)];
    console.log(`[oceano] split views against each camera alone: ${off.join(' and ')} pixels differ`);
    expect(off[0]).toBeLessThan(SAME_PICTURE);
    expect(off[1]).toBeLessThan(SAME_PICTURE);
    // Both views show sea: the lower half of each is not the clear colour.
    expect(clearShare(split, 0)).toBeLessThan(0.5);
    expect(clearShare(split, VIEW)).toBeLessThan(0.5);
  }, 120_000);

  it("control: the west viewport drawn with the east camera's chunks differs from the west camera alone", async () => {
    const handDriven = await draw(['east', 'west'], 'east');
    const west = await draw(['west'], 'auto');
    const off = differingInView(handDriven, west, VIEW);
    console.log(`[oceano] west view with the east camera's chunks: ${off} of ${VIEW * VIEW} pixels differ`);
    expect(off).toBeGreaterThan(20 * SAME_PICTURE);
    // The east view, whose chunks they are, is still its own picture.
    expect(differingInView(handDriven, await draw(['east'], 'auto'), 0)).toBeLessThan(SAME_PICTURE);
  }, 120_000);
});

describe("a CubeCamera in the user's scene", () => {
  it('sees the sea below the horizon on every face, and the clear colour above it', async () => {
    const faces = await cube('auto');
    console.log(`[oceano] cube faces, clear-colour share below/above the horizon: ${JSON.stringify(faces)}`);
    for (const face of faces) {
      if (face.below !== null) expect(face.below).toBeLessThan(0.01);
      // No sky in the scene: above the horizon, nothing is drawn (the faces are read the right way up).
      if (face.above !== null) expect(face.above).toBeGreaterThan(0.95);
    }
  }, 120_000);

  it('control: with the chunks chosen for one camera looking east, the faces looking elsewhere miss the sea', async () => {
    const faces = await cube('east');
    console.log(`[oceano] cube faces with the east camera's chunks: ${JSON.stringify(faces)}`);
    const missing = faces.filter((face) => (face.below ?? 0) > 0.3).length;
    expect(missing).toBeGreaterThanOrEqual(2);
  }, 120_000);
});
