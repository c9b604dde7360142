import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { foamWhiteFrom, solidFoamLevels } from './light/foamMeasure';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';
import { seaStatistics } from '../support/pictureStatistics';

/**
 * The spectral sea's picture: exact in time (t = 10⁶ s looks like t = 10 s, a frozen t draws
 * the same picture on every load), seeded, and foam where the crests fold.
 */
const harness = useHarness();
const WIDTH = 480;
const HEIGHT = 270;
/** The sea below the horizon of the default camera: rows 0.55 h to h. */
const SEA_FROM_ROW = 0.55;

/** Solid foam's levels under the default sun (18° high), from foam's measured reflectance. */
const SOLID_FOAM = solidFoamLevels(18);

/**
 * Share of white sea pixels (bright and grey, foam at least 70 % of the pixel: foamMeasure.ts) in
 * the left half of the frame below its middle: the sun (azimuth 20°) puts its glitter, white too, in the right half.
 */
function whiteShare(png: Buffer): number {
  const image = PNG.sync.read(png);
  const top = Math.round(image.height * 0.55);
  const right = Math.round(image.width / 2);
  const darkest: number[] = [];
  const spreads: number[] = [];
  for (let y = top; y < image.height; y++) {
    for (let x = 0; x < right; x++) {
      const i = 4 * (y * image.width + x);
      const [r, g, b] = [image.data[i], image.data[i + 1], image.data[i + 2]];
      darkest.push(Math.min(r, g, b));
      spreads.push(Math.max(r, g, b) - Math.min(r, g, b));
    }
  }
  const from = foamWhiteFrom(darkest.slice().sort((a, b) => a - b)[Math.floor(darkest.length / 2)], SOLID_FOAM);
  return darkest.filter((level, i) => level > from && spreads[i] < 40).length / darkest.length;
}

async function frameAt(page: Page, t: number): Promise<Buffer> {
  await page.evaluate((t) => {
    window.oceano.pause();
    window.oceano.setTime(t);
  }, t);
  return canvasPng(page);
}

function ratio(a: number, b: number): number {
  return Math.max(a, b) / Math.min(a, b);
}

/**
 * Two seas look alike when the mean, the spread and the high-frequency energy of their
 * luminance agree within these ratios. Measured (log lines, seed 2): t = 10 against t = 10⁶
 * differ by 6 % in mean, 10 % in spread and 26 % in high-frequency energy (two realisations
 * of one sea; 5 % and 18 % before the foam's edges were sharpened); the calm sea against the
 * fresh breeze (the negative control) by 2.5× in energy.
 */
const LIMITS = { mean: 1.1, std: 1.25, energy: 1.35 };
function alike(a: ReturnType<typeof seaStatistics>, b: ReturnType<typeof seaStatistics>): boolean {
  return ratio(a.mean, b.mean) < LIMITS.mean && ratio(a.std, b.std) < LIMITS.std && ratio(a.energy, b.energy) < LIMITS.energy;
}

describe('waves=fft picture', () => {
  // The same luminance statistics and fine detail.
  it('t = 10⁶ s looks as good as t = 10 s; a calm sea does not pass as the same', async () => {
    const { page } = await openOcean(harness, 'waves=fft&seed=2&t=10', WIDTH, HEIGHT);
    const early = seaStatistics(await frameAt(page, 10), SEA_FROM_ROW);
    const late = seaStatistics(await frameAt(page, 1_000_000), SEA_FROM_ROW);
    await page.evaluate(() => window.oceano.setParams({ windSpeed: 4 }));
    const calm = seaStatistics(await frameAt(page, 10), SEA_FROM_ROW);
    const show = (s: ReturnType<typeof seaStatistics>) => `mean ${s.mean.toFixed(1)}, std ${s.std.toFixed(1)}, HF ${s.energy.toFixed(1)}`;
    console.log(`[oceano] fft t=10: ${show(early)}; t=1e6: ${show(late)}; calm (negative control): ${show(calm)}`);
    expect(alike(early, late)).toBe(true);
    expect(alike(early, calm)).toBe(false);
    await page.close();
  });

  it('same seed, same picture on a fresh load; another seed another picture', async () => {
    const first = await openOcean(harness, 'waves=fft&seed=5&t=42.5', WIDTH, HEIGHT);
    const a = await canvasPng(first.page);
    await first.page.evaluate(() => window.oceano.setParams({ seed: 6 }));
    const otherSeed = await canvasPng(first.page);
    await first.page.close();
    const second = await openOcean(harness, 'waves=fft&seed=5&t=42.5', WIDTH, HEIGHT);
    const b = await canvasPng(second.page);
    await second.page.close();
    expect(diffPngs(a, b, 0).differentPixels).toBe(0);
    expect(diffPngs(a, otherSeed, 0).share).toBeGreaterThan(0.2);
  });

  it('foam is white in the default view at 15 m/s, and gone with foam=false', async () => {
    const { page } = await openOcean(harness, 'waves=fft&windSpeed=15&t=10', WIDTH, HEIGHT);
    // Whitecaps break in groups that travel (src/sim/waves/fft/foamBreakup.ts): the near sea of
    // one instant may hold none, so the white share is the mean of four instants 30 s apart.
    const meanWhite = async () => {
      let sum = 0;
      for (const t of [10, 40, 70, 100]) {
        await page.evaluate((time) => {
          window.oceano.pause();
          window.oceano.setTime(time);
        }, t);
        sum += whiteShare(await canvasPng(page)) / 4;
      }
      return sum;
    };
    const withFoam = await meanWhite();
    await page.evaluate(() => window.oceano.setParams({ foam: false }));
    const without = await meanWhite();
    // Negative control for the lower bound: thresholds biased 0.1 lower in J foam far less.
    await page.evaluate(() => window.oceano.setParams({ foam: true, foamThreshold: -0.1 }));
    const biased = await meanWhite();
    console.log(
      `[oceano] white share of the sea at 15 m/s: foam ${(withFoam * 100).toFixed(2)} %, foam=false ${(without * 100).toFixed(2)} %, threshold −0.1 ${(biased * 100).toFixed(2)} %`,
    );
    // Measured: 4.06 % of the left half's sea pixels white with foam (a group passes close at
    // t = 70 s), 0.09 % without (the glitter of a steep face reaching the left half at one
    // instant). This low camera sees the foam foreshortened, and far off as thin lace; seen from
    // 150 m above the same foam covers Monahan's share within 30 % (tests/browser/light/foam.test.ts).
    // The thresholds biased 0.1 lower, 0.58 %, are the planted fault the lower bound catches; the
    // upper one, 3× Monahan's 3.9 %, says that the sea has not turned white altogether.
    expect(withFoam).toBeGreaterThan(0.01);
    expect(withFoam).toBeLessThan(0.12);
    expect(without).toBeLessThan(0.005);
    expect(biased).toBeLessThan(0.01);
    await page.close();
  });
});
