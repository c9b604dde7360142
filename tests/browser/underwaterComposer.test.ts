import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { PNG } from 'pngjs';
import { fixtureBundle } from './fixtureBundle';
import { BROWSER_ARGS, findBrowser } from './harness';
import { describeDifference, measureDifference } from './imageCompare';
import type { UnderwaterComposerApi } from './fixtures/underwaterComposer';

/**
 * OceanUnderwaterPass in a user's own EffectComposer (RenderPass, the pass, three's
 * UnrealBloomPass, OutputPass) against OceanUnderwater, the short way, on a page of
 * tests/browser/fixtures/underwaterComposer.ts: the frame that straddles the surface, with a
 * lamp in the air above it for the bloom to spread.
 */
let browser: Browser;
let page: Page;
const errors: string[] = [];

beforeAll(async () => {
  const code = await fixtureBundle('underwaterComposer', true);
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(message.text());
  });
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'underwaterComposer' in window, { timeout: 120_000 });
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

/** The eye 5 cm above the surface under it, the near plane across the water: the waterline crosses the frame. */
const STRADDLING = 0.05;
/**
 * Mean |Δ| in levels per channel the two ways may differ by: the short way writes the blurred
 * water to the canvas through 8 bits, the composer keeps half floats until OutputPass. The
 * same tolerance as the encoded and linear scene targets (underwaterScene.test.ts).
 */
const SAME_PICTURE_MEAN = 1.0;

type Drawn = { png: PNG; submersion: string; lamp: [number, number] };

async function draw(way: 'short' | 'composer' | 'plain', options: Parameters<UnderwaterComposerApi['draw']>[1]): Promise<Drawn> {
  const seen = await page.evaluate(
    (w, o) => (window as unknown as { underwaterComposer: UnderwaterComposerApi }).underwaterComposer.draw(w, o),
    way,
    options,
  );
  return { ...seen, png: PNG.sync.read(Buffer.from(seen.png.split(',')[1], 'base64')) };
}

/** Rows [from, to) of a picture, as a picture of their own. */
function rows(png: PNG, from: number, to: number): PNG {
  const part = new PNG({ width: png.width, height: to - from });
  png.data.copy(part.data, 0, from * png.width * 4, to * png.width * 4);
  return part;
}

/** The water's rows: the bottom 40 % of the frame, well below the waterline and the lamp. */
const waterRows = (png: PNG): PNG => rows(png, Math.round(png.height * 0.6), png.height);

/** Mean brightness (levels) of the pixels between 8 and 20 pixels from the lamp's centre: where its bloom spreads. */
function aroundLamp({ png, lamp }: Drawn): number {
  let sum = 0;
  let n = 0;
  for (let y = 0; y < png.height; y++) {
    for (let x = 0; x < png.width; x++) {
      const r = Math.hypot(x + 0.5 - lamp[0], y + 0.5 - lamp[1]);
      if (r < 8 || r > 20) continue;
      const i = (y * png.width + x) * 4;
      sum += (png.data[i] + png.data[i + 1] + png.data[i + 2]) / 3;
      n++;
    }
  }
  return sum / n;
}

describe("OceanUnderwaterPass in the user's composer, beside UnrealBloomPass", () => {
  it('draws the straddling frame with the underwater look of OceanUnderwater, the lamp bloomed, and no error', async () => {
    const short = await draw('short', { aboveSurface: STRADDLING });
    const bloomed = await draw('composer', { aboveSurface: STRADDLING });
    const plain = await draw('composer', { aboveSurface: STRADDLING, bloom: false });
    const bloomNoPass = await draw('composer', { aboveSurface: STRADDLING, pass: false });
    expect(bloomed.submersion).toBe('straddling');
    const whole = measureDifference(plain.png, short.png);
    console.log(`[oceano] composer without bloom vs OceanUnderwater: ${describeDifference(whole)}`);
    for (const channel of whole.meanAbsError) expect(channel).toBeLessThan(SAME_PICTURE_MEAN);
    // With the bloom on, the pass still draws the underwater look: its water rows are far from those of the same composer without the pass.
    const lookKept = measureDifference(waterRows(bloomed.png), waterRows(bloomNoPass.png));
    console.log(`[oceano] water rows with bloom, with vs without the pass: ${describeDifference(lookKept)}`);
    expect(Math.max(...lookKept.meanAbsError)).toBeGreaterThan(5 * SAME_PICTURE_MEAN);
    const spread = aroundLamp(bloomed) - aroundLamp(plain);
    console.log(`[oceano] around the lamp: ${aroundLamp(plain).toFixed(1)} levels without bloom, ${aroundLamp(bloomed).toFixed(1)} with`);
    expect(spread).toBeGreaterThan(10);
    expect(errors).toEqual([]);
  });

  it('control: with the pass disabled the underwater look is absent from the water rows', async () => {
    const short = await draw('short', { aboveSurface: STRADDLING });
    const without = await draw('composer', { aboveSurface: STRADDLING, bloom: false, pass: false });
    const d = measureDifference(waterRows(without.png), waterRows(short.png));
    console.log(`[oceano] composer without the pass vs OceanUnderwater, water rows: ${describeDifference(d)}`);
    expect(Math.max(...d.meanAbsError)).toBeGreaterThan(5 * SAME_PICTURE_MEAN);
  });

  it('passes the picture through unchanged above the water', async () => {
    const on = await draw('composer', { aboveSurface: 6 });
    const off = await draw('composer', { aboveSurface: 6, pass: false });
    expect(on.submersion).toBe('above');
    expect(measureDifference(on.png, off.png).maxLevels).toBe(0);
  });
});

describe('OceanUnderwaterPass in a plain new EffectComposer(renderer), whose buffers have no depth texture', () => {
  // One test, in order: the plain composer's first frame is the control, its second the case.
  it('attaches the depth it reads on its first frame (which passes through) and then draws as OceanUnderwater', async () => {
    const short = await draw('short', { aboveSurface: STRADDLING });
    const first = await draw('plain', { aboveSurface: STRADDLING });
    const second = await draw('plain', { aboveSurface: STRADDLING });
    expect(second.submersion).toBe('straddling');
    // Control: the first frame, before any depth texture, lacks the underwater look the comparison looks for.
    const before = measureDifference(waterRows(first.png), waterRows(short.png));
    console.log(`[oceano] plain composer, first frame vs OceanUnderwater, water rows: ${describeDifference(before)}`);
    expect(Math.max(...before.meanAbsError)).toBeGreaterThan(5 * SAME_PICTURE_MEAN);
    const after = measureDifference(second.png, short.png);
    console.log(`[oceano] plain composer, second frame vs OceanUnderwater: ${describeDifference(after)}`);
    for (const channel of after.meanAbsError) expect(channel).toBeLessThan(SAME_PICTURE_MEAN);
    expect(errors).toEqual([]);
  });
});
