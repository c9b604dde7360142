import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { FOV, pixelRay, type Vec3 } from '../viewRays';
import { SkyPainter } from '../../../src/sim/optics/skyPainter';
import { sunDirection } from '../../../src/sim/optics/sun';
import { rollOffHighlight } from '../../../src/sim/optics/highlightRollOff';
import { SUN_DISC_SOLID_ANGLE } from '../../../src/sim/optics/sunDisc';
import { linearToSrgb, srgbToLinear } from '../../support/srgb';

/**
 * The whole frame goes through one tone curve (src/render/tone/wholeFrameToneCurve.ts), the sky
 * as well as the sea, and the sun's disc is drawn in its full brightness before it.
 *
 * The sky, GPU against CPU: looking towards a 25° sun from 30 m up, each sky pixel against the
 * sky painter's colour for its ray (src/sim/optics/skyPainter.ts, which the GPU's sky cube
 * paints too) put through the curve (src/sim/optics/highlightRollOff.ts) and encoded as sRGB.
 * Only the bright sky counts, where a channel is over 0.8 in linear light (the curve's work
 * starts at 0.6, and takes 0.8 down by 4 levels); the disc itself is left out.
 * Control: the renderer with no tone curve (a planted fault): the sky clips at white as before,
 * and stands several levels off the curve.
 *
 * The sun: the disc's pixels white (every channel 250 or more), about as many as its solid
 * angle covers. Control: the disc only as bright as the 8-bit cube holds it (white, 1), which
 * the curve shows as 0.85 (239 levels): no white pixel.
 *
 * The disc's edge: a pixel it crosses shows its share of the disc's white and the rest of the
 * sky's colour after the curve, not white whatever its share. Control: the edge stepping by whole
 * pixels, as the sky alone draws it.
 *
 * The exposure: the `exposure` parameter multiplies the light by 2^exposure before the curve, so
 * the same sky pixels match the painter's colour at half and at twice its light. Control: the
 * picture drawn at exposure 0, which a view that ignored the parameter would draw, against half.
 */
const harness = useHarness();
const W = 640;
const H = 360;
const ELEVATION = 25;
const AZIMUTH = 20;
const SUN = sunDirection(ELEVATION, AZIMUTH);
const POSITION: Vec3 = [0, 30, 0];
// 8° to the right of the sun and 5° below it, so the glow around it fills the upper half.
const LOOK = sunDirection(ELEVATION - 5, AZIMUTH + 8);
const TARGET = POSITION.map((p, k) => p + LOOK[k] * 1000) as Vec3;
const QUERY = `t=10&sunElevation=${ELEVATION}&sunAzimuth=${AZIMUTH}&cam=${[...POSITION, ...TARGET].map((v) => v.toFixed(3)).join(',')}`;

const srgbLevel = (linear: number): number => 255 * linearToSrgb(linear);

interface SkyFit {
  /** Median over the bright sky pixels of the largest channel's difference from the curve's colour, in levels. */
  offCurve: number;
  pixels: number;
  /** Pixels of the disc seen white (every channel 250 or more). */
  whiteDisc: number;
}

/**
 * Pixels of the disc's rim shown between the sky beside it and white (darkest channel 232–249),
 * within 1.2° of the sun's centre: where the disc covers part of a pixel. A hard edge has none:
 * any share of the disc is white, the sky outside it below 232.
 */
function discRim(png: PNG): number {
  let rim = 0;
  for (let py = 0; py < H; py++) {
    for (let px = 0; px < W; px++) {
      const ray = pixelRay(px, py, W, H, POSITION, TARGET);
      const fromSun = Math.acos(Math.min(1, ray[0] * SUN[0] + ray[1] * SUN[1] + ray[2] * SUN[2]));
      if (fromSun > (1.2 * Math.PI) / 180) continue;
      const o = (py * W + px) * 4;
      const darkest = Math.min(png.data[o], png.data[o + 1], png.data[o + 2]);
      if (darkest >= 232 && darkest < 250) rim++;
    }
  }
  return rim;
}

/** The sky against the painter's colour times `gain` (the exposure's 2^EV) through the curve. */
function fitSky(png: PNG, gain = 1): SkyFit {
  const painter = new SkyPainter(SUN);
  const differences: number[] = [];
  let whiteDisc = 0;
  for (let py = 0; py < H; py++) {
    for (let px = 0; px < W; px++) {
      const ray = pixelRay(px, py, W, H, POSITION, TARGET);
      if (ray[1] < 0.03) continue;
      const o = (py * W + px) * 4;
      const fromSun = Math.acos(Math.min(1, ray[0] * SUN[0] + ray[1] * SUN[1] + ray[2] * SUN[2]));
      if (fromSun < 0.03) {
        if (Math.min(png.data[o], png.data[o + 1], png.data[o + 2]) >= 250) whiteDisc++;
        continue;
      }
      const linear = painter.color(ray).map(srgbToLinear);
      if (Math.max(...linear) < BRIGHT) continue;
      differences.push(Math.max(...[0, 1, 2].map((c) => Math.abs(png.data[o + c] - srgbLevel(rollOffHighlight(gain * linear[c]))))));
    }
  }
  differences.sort((a, b) => a - b);
  return { offCurve: differences[Math.floor(differences.length / 2)] ?? Infinity, pixels: differences.length, whiteDisc };
}

// Measured: 0.41 levels through the curve, 7.69 with no curve (656 bright pixels); the disc 90 pixels white of 86.
const MAX_OFF_CURVE = 2.5;
/** Linear light above which a channel counts as bright sky. */
const BRIGHT = 0.8;
/** The disc's pixels: its solid angle over one pixel's at the picture's centre. */
const DISC_PIXELS = SUN_DISC_SOLID_ANGLE / ((2 * Math.tan((FOV / 2) * (Math.PI / 180))) / H) ** 2;
/** The length of its edge, px: the circumference of a circle of DISC_PIXELS. */
const RIM_PIXELS = 2 * Math.sqrt(Math.PI * DISC_PIXELS);

describe('the whole frame through one tone curve', () => {
  // Controls: no curve, a disc no brighter than the cube.
  it("draws the bright sky as the sky painter's colour through the curve, and the sun's disc white", { timeout: 180_000 }, async () => {
    const { page, consoleErrors } = await openOcean(harness, QUERY, W, H);
    await page.evaluate(() => window.oceano.pause());
    const shot = async () => fitSky(PNG.sync.read(await canvasPng(page)));
    const curve = await shot();
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ wholeFrameToneCurve: false }));
    const clipped = await shot();
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ wholeFrameToneCurve: true, sunInFullBrightness: false }));
    const dimSun = await shot();
    const say = `bright sky ${curve.pixels} px off the curve by ${curve.offCurve.toFixed(2)} levels (no curve: ${clipped.offCurve.toFixed(2)}); the disc ${curve.whiteDisc} px white of ${DISC_PIXELS.toFixed(0)} (no brighter than the cube: ${dimSun.whiteDisc})`;
    console.log(`[oceano] ${say}`);
    expect(curve.pixels, say).toBeGreaterThan(300);
    expect(curve.offCurve, say).toBeLessThan(MAX_OFF_CURVE);
    expect(clipped.offCurve, say).toBeGreaterThan(MAX_OFF_CURVE);
    expect(curve.whiteDisc, say).toBeGreaterThan(0.7 * DISC_PIXELS);
    expect(dimSun.whiteDisc, say).toBe(0);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  // Control: the picture at 0 stops is off half the light.
  it('multiplies the light by 2^exposure before the curve, at −1 and +1 stop', { timeout: 180_000 }, async () => {
    const { page, consoleErrors } = await openOcean(harness, QUERY, W, H);
    await page.evaluate(() => window.oceano.pause());
    const shotAt = async (exposure: number) => {
      await page.evaluate((ev) => window.oceano.setParams({ exposure: ev }), exposure);
      return PNG.sync.read(await canvasPng(page));
    };
    const darker = fitSky(await shotAt(-1), 0.5);
    const brighter = fitSky(await shotAt(1), 2);
    const ignored = fitSky(await shotAt(0), 0.5);
    const say = `exposure −1: ${darker.offCurve.toFixed(2)} levels off (${darker.pixels} px), +1: ${brighter.offCurve.toFixed(2)}; the picture at 0 against half the light: ${ignored.offCurve.toFixed(2)}`;
    console.log(`[oceano] ${say}`);
    expect(darker.pixels, say).toBeGreaterThan(300);
    expect(darker.offCurve, say).toBeLessThan(MAX_OFF_CURVE);
    expect(brighter.offCurve, say).toBeLessThan(MAX_OFF_CURVE);
    expect(ignored.offCurve, say).toBeGreaterThan(MAX_OFF_CURVE);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  // Control: the edge stepping by whole pixels.
  it("draws the disc's edge antialiased after the curve: its rim pixels between the sky and white", { timeout: 120_000 }, async () => {
    const { page, consoleErrors } = await openOcean(harness, QUERY, W, H);
    await page.evaluate(() => window.oceano.pause());
    const smooth = discRim(PNG.sync.read(await canvasPng(page)));
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ sunDiscEdge: false }));
    const stepped = discRim(PNG.sync.read(await canvasPng(page)));
    const say = `the disc's rim: ${smooth} px between the sky and white (its edge ${RIM_PIXELS.toFixed(0)} px round); stepping by whole pixels: ${stepped}`;
    console.log(`[oceano] ${say}`);
    expect(smooth, say).toBeGreaterThan(0.3 * RIM_PIXELS);
    expect(stepped, say).toBe(0);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
