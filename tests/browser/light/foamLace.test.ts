import { describe, expect, it } from 'vitest';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { highPass } from '../../support/highPass';
import { foamOwnLight } from './foamLight';

/**
 * Foam seen from 30 m straight down (15 m/s, the wind towards +x) keeps its lace: a pixel there
 * covers about 12 texels of the detail texture, too many for its bubbles, but not for its
 * patches and streaks, which shaders/foam/foamMaterial.glsl keeps by shading the foam's share
 * with the density the mipmaps give there. The foam's own light is the picture with foam less
 * the same instant without it (the glint, the boat and the water cancel); inside the thin
 * patches of foam left behind, its detail finer than 0.35 m, relative to the patch's
 * brightness, is the lace.
 * Control: the share shaded by the thickness alone (the old far path) draws smooth grey patches.
 */
const harness = useHarness();
const VIEW = { width: 640, height: 360, altitude: 30, times: [10, 40, 70, 100] } as const;
const QUERY = `waves=fft&windSpeed=15&windDirection=90&sunElevation=30&cam=0,${VIEW.altitude},0,0,0,-0.01`;
const METRES_PER_PIXEL = (2 * VIEW.altitude * Math.tan((27.5 * Math.PI) / 180)) / VIEW.height;
// The lace's walls are a few pixels apart here: its detail is what a box 0.35 m wide leaves; a
// patch is the mean over a box 1.1 m wide, over which the patches' soft edges are straight.
const FINE_BOX = Math.round(0.17 / METRES_PER_PIXEL);
const PATCH_BOX = Math.round(0.55 / METRES_PER_PIXEL);
// The thin foam left behind: where the foam brightens the picture by this many levels,
// averaged over the box, and no more than THIN_LEVELS (the whitecaps breaking now, solid white).
const PATCH_LEVELS = 6;
const THIN_LEVELS = 40;

/** The lace: the foam's light finer than the box over its mean, inside the patches; and how many pixels those are. */
async function laceContrast(roundShare: boolean): Promise<{ contrast: number; pixels: number }> {
  const { page } = await openOcean(harness, QUERY, VIEW.width, VIEW.height);
  if (roundShare) await page.evaluate(() => window.oceano.debug.setShadingFixes({ farLace: false }));
  let fine = 0;
  let mean = 0;
  let pixels = 0;
  for (const t of VIEW.times) {
    const light = await foamOwnLight(page, t);
    const detail = light.slice();
    highPass(detail, VIEW.width, VIEW.height, FINE_BOX);
    const aroundPatch = light.slice();
    highPass(aroundPatch, VIEW.width, VIEW.height, PATCH_BOX);
    for (let i = 0; i < light.length; i++) {
      const patch = light[i] - aroundPatch[i];
      if (patch < PATCH_LEVELS || patch > THIN_LEVELS) continue;
      fine += detail[i] * detail[i];
      mean += patch;
      pixels++;
    }
  }
  await page.close();
  return { contrast: Math.sqrt(fine / pixels) / (mean / pixels), pixels };
}

// Measured: 0.359 with the lace's density, 0.294 with the thickness alone (the pictures are
// deterministic, so the bound sits between them).
const LIMIT = 0.33;

describe('far foam keeps its lace', () => {
  // Straight down. Control: the share shaded by thickness alone is under it.
  it('from 30 m the fine light inside thin foam patches is over 0.33 of their brightness', { timeout: 180_000 }, async () => {
    const lace = await laceContrast(false);
    const round = await laceContrast(true);
    const say = `lace contrast ${lace.contrast.toFixed(3)} (${lace.pixels} px), control ${round.contrast.toFixed(3)} (${round.pixels} px)`;
    console.log(`[oceano] ${say}`);
    expect(lace.pixels, say).toBeGreaterThan(5000);
    expect(lace.contrast, say).toBeGreaterThan(LIMIT);
    expect(round.contrast, say).toBeLessThan(LIMIT);
  });
});
