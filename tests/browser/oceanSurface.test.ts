import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { fixtureBundle } from './fixtureBundle';
import { BROWSER_ARGS, findBrowser } from './harness';
import type { OceanSurfaceApi } from './fixtures/oceanSurface';

/**
 * What the library's Ocean promises a three.js user about its surface: position.y is the sea
 * level, for the CPU twin and for the picture; a transform it cannot honour and an option it
 * does not read throw, naming what; whenReady() covers a load started before it is called.
 * The page is a bundle of tests/browser/fixtures/oceanSurface.ts.
 */
let browser: Browser;
let page: Page;

beforeAll(async () => {
  const code = await fixtureBundle('oceanSurface', true);
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'oceanSurface' in window, { timeout: 60_000 }).catch((e: unknown) => errors.push(String(e)));
  expect(errors).toEqual([]);
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

type Api = { oceanSurface: OceanSurfaceApi };
const draw = (seaLevel: number, eyeHeight: number, fault = false): ReturnType<OceanSurfaceApi['draw']> =>
  page.evaluate((s, e, f) => (window as unknown as Api).oceanSurface.draw(s, e, f), seaLevel, eyeHeight, fault);

/** Pixels whose largest channel difference exceeds 2 levels. */
function differing(a: number[], b: number[]): number {
  let count = 0;
  for (let i = 0; i < a.length; i += 4)
    if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 2) count++;
  return count;
}

describe('the sea level: Ocean.position.y', () => {
  it('lowers sampleSurface by 1 m and the drawn sea with it: the sea and eye lowered together look the same', async () => {
    const level = await draw(0, 6);
    const lowered = await draw(-1, 5);
    expect(lowered.sampled - level.sampled).toBeCloseTo(-1, 9);
    // 160 × 160 pixels; the two pictures differ only by float rounding (measured: 0 pixels).
    expect(differing(level.pixels, lowered.pixels)).toBeLessThan(40);
  }, 120_000);

  it('control: the eye lowered alone, or the sea level kept from the shaders, changes the picture', async () => {
    const level = await draw(0, 6);
    const eyeOnly = await draw(0, 5);
    const unshaded = await draw(-1, 5, true);
    // Measured: about 8,900 of the 25,600 pixels each.
    expect(differing(level.pixels, eyeOnly.pixels)).toBeGreaterThan(1000);
    expect(differing(level.pixels, unshaded.pixels)).toBeGreaterThan(1000);
  }, 120_000);
});

describe('transforms and options the Ocean cannot honour', () => {
  const updateAfter = (change: Parameters<OceanSurfaceApi['updateAfter']>[0]) =>
    page.evaluate((c) => (window as unknown as Api).oceanSurface.updateAfter(c), change);
  const refused = (options: Record<string, unknown>, via: 'constructor' | 'setParams') =>
    page.evaluate((o, v) => (window as unknown as Api).oceanSurface.refused(o, v), options, via);

  it('throws at update on a rotation, a scale or a sideways move, naming it; a raised sea level is fine', async () => {
    expect(await updateAfter('rotation')).toMatch(/^Ocean: it \(or a parent\) is rotated/);
    expect(await updateAfter('scale')).toMatch(/is scaled/);
    expect(await updateAfter('sideways')).toMatch(/is moved sideways/);
    expect(await updateAfter('up')).toBe('');
  });

  it('throws on an app-only or unknown option, naming the key, and takes the keys it reads', async () => {
    expect(await refused({ boatSpeed: 2 }, 'constructor')).toMatch(/^new Ocean: "boatSpeed" is not an Ocean option but the app's/);
    expect(await refused({ compare: 'seed-fft' }, 'constructor')).toMatch(/"compare" is not an Ocean option/);
    expect(await refused({ windSpeeed: 12 }, 'constructor')).toMatch(
      /^new Ocean: "windSpeeed" is not an Ocean option\. Its options: waves, /,
    );
    expect(await refused({ exposure: 1 }, 'setParams')).toMatch(/^Ocean\.setParams: "exposure"/);
    expect(await refused({ sky: null }, 'setParams')).toMatch(/"sky" is not an Ocean option/);
    expect(await refused({ windSpeed: 12, waves: 'seed' }, 'constructor')).toBe('');
    expect(await refused({ windSpeed: 12 }, 'setParams')).toBe('');
  });
});

describe('whenReady()', () => {
  it('covers a model load started before the call; one taken before the load does not', async () => {
    const { afterEarlier, afterLater } = await page.evaluate(() => (window as unknown as Api).oceanSurface.laterLoad());
    expect(afterLater).toBe(true);
    // Control: a promise taken earlier settles before the later load has finished.
    expect(afterEarlier).toBe(false);
  }, 60_000);
});
