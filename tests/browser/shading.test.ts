import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { pixelLuminance } from '../support/luminance';

const harness = useHarness();

// Measured at 640 × 360 under a 20 km visibility's haze: 4.29 with detail normals, 3.08 with
// vertex normals only; the bound lies between them, near their geometric mean. (Under the old
// 3.26 km haze, which dimmed this band's contrast: 2.22 and 1.54, bound 1.85; docs/light-sun-and-sky.md,
// "Measured: the 500 m view, and the haze".)
const MIN_FAR_ENERGY = 3.6;
// Measured: 3.05 / 3.07 = 0.99 with camera-relative positions, 5.79 / 3.07 = 1.89 with world
// coordinates (main). The two spots have different waves, so not 1 exactly.
const MAX_FAR_GLINT_RATIO = 1.3;
// Second-difference energy of the glint view at 640 × 360, 10⁶ m out over near the origin
// (spots 1.4 km and 10⁶ m out, different waves). Measured with normals at grid points
// relative to the render origin: Gerstner (5 m/s) 1.71 / 1.77 = 0.97, FFT 5.00 / 4.66 = 1.07;
// at absolute grid points: Gerstner 3.14 / 1.77 = 1.77, FFT 12.51 / 4.66 = 2.68. (Before the
// glint took Cox & Munk's roughness: Gerstner at 10 m/s 0.98 and 1.44, FFT 1.27 and 2.13.)
// FFT's spots may differ more (the glint's ridges fill more of the view 10⁶ m out), hence its bound.
const MAX_PIXEL_NORMAL_RATIO: Record<'gerstner' | 'fft', number> = { gerstner: 1.2, fft: 1.6 };
/** From 60 m up towards the glint point 60 / tan 18° = 184.7 m out at azimuth 20°. */
const GLINT_VIEW = '0,60,0,63.2,0,-173.6';

/** The picture's width and its luminance (0–255, Rec. 709 weights) at a pixel. */
function lumaOf(png: Buffer): { width: number; luma: (x: number, y: number) => number } {
  const { width, data } = PNG.sync.read(png);
  return {
    width,
    luma: (x, y) => pixelLuminance(data, y * width + x),
  };
}

/**
 * High-frequency energy of a band of rows: the mean absolute difference in luminance
 * (0–255) between each pixel and its right and lower neighbours. A flat, hazed sea scores
 * near 0; ripples add contrast from pixel to pixel.
 */
function rowBandEnergy(png: Buffer, y0: number, y1: number): number {
  const { width, luma } = lumaOf(png);
  let sum = 0;
  let count = 0;
  for (let y = y0; y < y1; y++) {
    for (let x = 0; x < width - 1; x++) {
      sum += Math.abs(luma(x, y) - luma(x + 1, y)) + Math.abs(luma(x, y) - luma(x, y + 1));
      count++;
    }
  }
  return sum / count;
}

/**
 * Mean absolute second difference in luminance along rows and columns over rows y0–y1: a
 * smooth glint scores low even where it is bright and steep; a glint made of 6 cm blocks
 * (a step at every block's edge) scores high.
 */
function blockEnergy(png: Buffer, y0: number, y1: number): number {
  const { width, luma } = lumaOf(png);
  let sum = 0;
  let count = 0;
  for (let y = y0 + 1; y < y1 - 1; y++) {
    for (let x = 1; x < width - 1; x++) {
      const c = 2 * luma(x, y);
      sum += Math.abs(luma(x - 1, y) - c + luma(x + 1, y)) + Math.abs(luma(x, y - 1) - c + luma(x, y + 1));
      count++;
    }
  }
  return sum / count;
}

async function redraw(page: Page): Promise<Buffer> {
  await page.evaluate(() => window.oceano.renderFrame());
  return canvasPng(page);
}

describe('shading far away', () => {
  it('keeps the ripples in the glint where the vertices are 24 m and more apart', async () => {
    // lodDistance=20 puts bands 4 and 5 (24 and 48 m between vertices) from 160 m out; from
    // 60 m up the sun's glint (elevation 18°, azimuth 20°) lies 185 m out, where a pixel at
    // 640 × 360 covers about 0.5 m across the view and 1.7 m along it. Rows 80–200 hold the
    // glint in those bands.
    const { page, consoleErrors } = await openOcean(harness, `t=10&lodDistance=20&cam=${GLINT_VIEW}`, 640, 360);
    await page.evaluate(() => window.oceano.pause());
    const detailed = rowBandEnergy(await redraw(page), 80, 200);
    // Negative control, and main's picture: the interpolated vertex normals alone.
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ detailNormals: false }));
    const flat = rowBandEnergy(await redraw(page), 80, 200);
    console.log(`[oceano] far-band energy: with detail normals ${detailed.toFixed(2)}, vertex normals only ${flat.toFixed(2)}`);
    expect(detailed).toBeGreaterThan(MIN_FAR_ENERGY);
    expect(flat).toBeLessThan(MIN_FAR_ENERGY);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  /** From 2 m up, 10 m back from the point (x, 0, x) looked at: the sun's glint, at any distance from the origin. */
  const glintView = (x: number) => ({
    position: [x, 2, x + 10] as [number, number, number],
    target: [x, 0, x] as [number, number, number],
  });

  it('draws the sun glint 10⁶ m out as smooth as near the origin', async () => {
    // From 2 m up, 10 m back from the point looked at: the glint fills rows 70–150 of rows 60–179 measured at
    // 320 × 180. The reference spot is 1.4 km from the origin, away from the boat.
    const { page, consoleErrors } = await openOcean(harness, 't=10', 320, 180);
    await page.evaluate(() => window.oceano.pause());
    const energyAt = async (x: number) => {
      await page.evaluate((pose) => window.oceano.setCamera(pose), glintView(x));
      return rowBandEnergy(await redraw(page), 60, 179);
    };
    const near = await energyAt(1000);
    const far = await energyAt(999000);
    // Negative control, and main's picture: world coordinates in float32 on the GPU.
    await page.evaluate(() => window.oceano.debug.setShadingFixes({ cameraRelative: false }));
    const absolute = await energyAt(999000);
    console.log(
      `[oceano] glint energy: near the origin ${near.toFixed(2)}, 10⁶ m out ${far.toFixed(2)}, world coordinates ${absolute.toFixed(2)}`,
    );
    expect(far).toBeLessThan(near * MAX_FAR_GLINT_RATIO);
    expect(absolute).toBeGreaterThan(near * MAX_FAR_GLINT_RATIO);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('shades Gerstner and FFT per pixel as smoothly 10⁶ m out as near the origin', async () => {
    // The same 2 m-high view of the glint at 640 × 360, where a pixel near the glint covers
    // about 1.5 cm: the 6 cm blocks of normals at absolute float32 grid points span 4 pixels.
    const { page, consoleErrors } = await openOcean(harness, 't=10&waves=gerstner', 640, 360);
    await page.evaluate(() => window.oceano.pause());
    const energyAt = async (x: number) => {
      await page.evaluate((pose) => window.oceano.setCamera(pose), glintView(x));
      return blockEnergy(await redraw(page), 120, 359);
    };
    for (const waves of ['gerstner', 'fft'] as const) {
      await page.evaluate(async (w) => {
        // Gerstner at 5 m/s: waves down to 3 m, which are summed per pixel (at 10 m/s every
        // wave is long enough for the 2 m vertices to carry its slope, shaders/waves/gerstner.glsl).
        window.oceano.setParams({ waves: w, windSpeed: w === 'gerstner' ? 5 : 10 });
        await window.oceano.debug.setShadingFixes({ relativePixelNormals: true });
      }, waves);
      const near = await energyAt(1000);
      const far = await energyAt(999000);
      // Negative control, and main's picture: normals and foam at absolute grid points.
      await page.evaluate(() => window.oceano.debug.setShadingFixes({ relativePixelNormals: false }));
      const absolute = await energyAt(999000);
      console.log(
        `[oceano] ${waves} glint block energy: near the origin ${near.toFixed(2)}, 10⁶ m out ${far.toFixed(2)}, absolute grid points ${absolute.toFixed(2)}`,
      );
      expect(far).toBeLessThan(near * MAX_PIXEL_NORMAL_RATIO[waves]);
      expect(absolute).toBeGreaterThan(near * MAX_PIXEL_NORMAL_RATIO[waves]);
    }
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
