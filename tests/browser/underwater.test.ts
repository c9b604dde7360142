import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';
import { compareWithReference, describeDifference, diffPngs, measureDifference, withinTolerance } from './imageCompare';
import { DIVE_QUERY } from './referenceViews';
import { highFrequencyEnergy } from '../support/imageEnergy';

const harness = useHarness();

/**
 * The dive view loaded once for the tests that look at it through the API (each boot costs
 * seconds of SwiftShader work); what a test changes is put back (sharedPage.ts). The
 * reference test comes first, on the page as loaded.
 */
const dive = sharedPage(harness, DIVE_QUERY);

function energyOf(png: Buffer): number {
  const image = PNG.sync.read(png);
  return highFrequencyEnergy(image.data, image.width, image.height);
}

describe('under the water', () => {
  it('draws the dive view through the composer, matching the committed reference', async () => {
    const { page, consoleErrors } = await dive.opened();
    const png = await canvasPng(page);
    const stats = await page.evaluate(() => window.oceano.stats());
    expect(stats.underwater).toBe(true);
    expect(stats.submersion).toBe('below');
    expect(stats.composerPasses).toBe(6);
    const timings = await page.evaluate(() => window.oceano.debug.passTimings());
    // The god rays at a quarter of the resolution, the water and the blur at half (the default
    // σ's kernel within 1 texel: one pass, src/render/underwater/gaussianKernel.ts); the composite also
    // tone-maps, so no output pass.
    expect(timings.map((t) => t.name)).toEqual(['scene', 'shafts', 'rays', 'water', 'blur', 'composite']);
    const reference = compareWithReference('underwater-seed1-t10', png);
    expect(reference.matches, reference.summary).toBe(true);
    expect(consoleErrors).toEqual([]);
  });

  it('lowers the high-frequency energy of the same frame when the blur is on', async () => {
    const [sharp, blurred] = await dive.restoring(async (page) => {
      await page.evaluate(() => window.oceano.setParams({ blurStrength: 0 }));
      const blurOff = energyOf(await canvasPng(page));
      // Blur off: scene, shafts, god rays at half resolution, water at full resolution onto the canvas.
      expect(await page.evaluate(() => window.oceano.stats().composerPasses)).toBe(4);
      await page.evaluate(() => window.oceano.setParams({ blurStrength: 3 }));
      const blurOn = energyOf(await canvasPng(page));
      // σ = 3 px reaches past 1 texel at half resolution: the two separable passes.
      expect(await page.evaluate(() => window.oceano.stats().composerPasses)).toBe(7);
      return [blurOff, blurOn];
    });
    console.log(`[oceano] high-frequency energy: blur off ${sharp.toFixed(2)}, blur σ = 3 px ${blurred.toFixed(2)}`);
    expect(sharp).toBeGreaterThan(0);
    expect(blurred).toBeLessThan(sharp * 0.5);
  });

  it("draws the same shafts from the window generic wave models get as from the seed's repeating tile", async () => {
    const { consoleErrors } = await dive.opened();
    await dive.restoring(async (page) => {
      const tile = await canvasPng(page);
      await page.evaluate(async () => {
        await window.oceano.debug.forceShaftLightWindow(true);
        window.oceano.renderFrame();
      });
      const windowed = await canvasPng(page);
      // The window's corner is on the tile's texel lattice, so both bakes hold the lens at the
      // same points and the god rays read the same values (src/render/underwater/shaftLightTile.ts).
      const same = measureDifference(tile, windowed);
      console.log(`[oceano] shaft light, window vs tile: ${describeDifference(same)}`);
      expect(withinTolerance(same), describeDifference(same)).toBe(true);
      // Negative control: the same comparison sees the shafts' share of the picture, here made
      // 25 % brighter, which a window baked at the wrong place or with the wrong lens would move.
      await page.evaluate(() => window.oceano.setParams({ godRaysIntensity: 1.25 * window.oceano.getParams().godRaysIntensity }));
      const brighter = measureDifference(tile, await canvasPng(page));
      expect(withinTolerance(brighter), describeDifference(brighter)).toBe(false);
      await page.evaluate(() => window.oceano.debug.forceShaftLightWindow(false));
    });
    expect(consoleErrors).toEqual([]);
  });

  // The shortcuts: back faces only, no above-the-surface caustics test, nothing drawn past where the fog
  // hides it.
  it('draws the same pictures with the underwater shortcuts as without', async () => {
    // The dive view (the underside over the upper half, outside Snell's window; the sea bed and
    // its caustics below), then looking up into Snell's window (the bench's underwater camera).
    const { consoleErrors } = await dive.opened();
    await dive.restoring(async (page) => {
      const shortcutsAgainstFull = async (label: string) => {
        expect(await page.evaluate(() => window.oceano.stats().submersion)).toBe('below');
        const fast = await canvasPng(page);
        const culled = await page.evaluate(() => window.oceano.stats().chunksVisible);
        await page.evaluate(() => window.oceano.debug.setShadingFixes({ underwaterShortcuts: false }));
        const full = await canvasPng(page);
        const all = await page.evaluate(() => window.oceano.stats().chunksVisible);
        await page.evaluate(() => window.oceano.debug.setShadingFixes({ underwaterShortcuts: true }));
        // The far plane at the fog's reach leaves out most chunks (measured: 98 of 1,700 looking up),
        // so the comparison below is of a picture that lost them.
        console.log(`[oceano] chunks drawn under the water, ${label}: ${culled} with the far plane in, ${all} without`);
        expect(culled).toBeLessThan(all / 4);
        const same = measureDifference(fast, full);
        // Measured before the far plane came in: largest difference 0 levels in both views (the
        // left-out code changed no pixel); with it, see the log.
        console.log(`[oceano] underwater shortcuts on vs off, ${label}: ${describeDifference(same)}`);
        expect(withinTolerance(same), describeDifference(same)).toBe(true);
        return fast;
      };
      const divePicture = await shortcutsAgainstFull('dive view');
      // Negative control: the comparison sees the bed's caustics 25 % stronger.
      const params = await page.evaluate(() => window.oceano.getParams());
      await page.evaluate((p) => window.oceano.setParams({ causticsIntensity: 1.25 * p.causticsIntensity }), params);
      const strongerCaustics = measureDifference(divePicture, await canvasPng(page));
      console.log(`[oceano] control, caustics 25 % stronger: ${describeDifference(strongerCaustics)}`);
      expect(withinTolerance(strongerCaustics)).toBe(false);
      await page.evaluate((p) => window.oceano.setParams({ causticsIntensity: p.causticsIntensity }), params);

      await page.evaluate(() => window.oceano.setCamera({ position: [0, -8, 20], target: [0, 5, -20] }));
      const up = await shortcutsAgainstFull('looking up');
      // Negative control: the comparison sees the underside's shading change (its Fresnel
      // weights off: Snell's window then ends in a hard step instead of fading into the mirror).
      await page.evaluate(() => window.oceano.setParams({ fresnel: false }));
      const noFresnel = measureDifference(up, await canvasPng(page));
      console.log(`[oceano] control, underside without Fresnel: ${describeDifference(noFresnel)}`);
      expect(withinTolerance(noFresnel)).toBe(false);
    });
    expect(consoleErrors).toEqual([]);
  });

  it('flips underwater exactly at the CPU surface height under the camera', async () => {
    // The dive page's sea is seed=1&t=10's; the camera is placed here, then put back.
    const result = await dive.restoring((page) =>
      page.evaluate(() => {
        const o = window.oceano;
        const [x, z] = [12.5, -30.25];
        const h = o.sampleSurface(x, z).height;
        const at = (y: number) => {
          o.setCamera({ position: [x, y, z], target: [x + 10, h, z - 40] });
          o.renderFrame();
          return { y: o.getCamera().position[1], ...o.stats() };
        };
        return { h, above: at(h + 1e-3), below: at(h - 1e-3) };
      }),
    );
    expect(result.above.y).toBeCloseTo(result.h + 1e-3, 9);
    expect(result.below.y).toBeCloseTo(result.h - 1e-3, 9);
    expect(result.above.underwater).toBe(false);
    expect(result.below.underwater).toBe(true);
    // A millimetre from the surface the near plane crosses it: both frames decide per pixel.
    expect(result.above.submersion).toBe('straddling');
    expect(result.below.submersion).toBe('straddling');
  });

  it('shows air above and water below the waterline of a straddling camera', async () => {
    // The eye 7 cm under the surface there (1.62 m): the near plane's upper half is in the
    // air. (1.7 m, 8 cm above it, used to straddle with the fixed 0.5 m near plane; the near
    // plane fitted to the eye's clearance now keeps it above the water: src/render/ocean/nearPlane.ts.)
    const { page } = await openOcean(harness, 'seed=1&t=10&cam=0,1.55,40,0,1.5,-20&blurStrength=0');
    const png = PNG.sync.read(await canvasPng(page));
    expect(await page.evaluate(() => window.oceano.stats().submersion)).toBe('straddling');
    const mean = (y0: number, y1: number) => {
      const sum = [0, 0, 0];
      for (let y = y0; y < y1; y++)
        for (let x = 0; x < png.width; x++) for (let c = 0; c < 3; c++) sum[c] += png.data[(y * png.width + x) * 4 + c];
      return sum.map((s) => s / ((y1 - y0) * png.width));
    };
    const top = mean(0, 20);
    const bottom = mean(png.height - 20, png.height);
    // The sky at the top is bright and blue; the water at the bottom is dark blue-green.
    expect(top[2]).toBeGreaterThan(150);
    expect(bottom[0] + bottom[1] + bottom[2]).toBeLessThan((top[0] + top[1] + top[2]) * 0.6);
    expect(bottom[1]).toBeGreaterThan(bottom[0]);
    await page.close();
  });

  it('draws an above-water frame directly, with no composer pass', async () => {
    const { page } = await openOcean(harness, 'seed=1&t=10');
    await page.evaluate(() => window.oceano.renderFrame());
    const stats = await page.evaluate(() => window.oceano.stats());
    expect(stats.underwater).toBe(false);
    expect(stats.submersion).toBe('above');
    expect(stats.composerPasses).toBe(0);
    // Drawn once, directly: the same frame through the composer would draw the scene and five more passes.
    // The first frame below the surface fetches the underwater passes; until they arrive the canvas keeps its last frame.
    const viaComposer = await page.evaluate(async () => {
      window.oceano.setCamera({ position: [0, -6, 40], target: [0, -6, -20] });
      window.oceano.renderFrame();
      const whileLoading = window.oceano.stats().composerPasses;
      await window.oceano.loaded();
      return { ...window.oceano.stats(), whileLoading };
    });
    expect(viaComposer.whileLoading).toBe(0);
    expect(viaComposer.composerPasses).toBeGreaterThan(0);
    expect(stats.drawCalls).toBeLessThan(viaComposer.drawCalls);
    await page.evaluate(() => window.oceano.setCamera({ position: [0, 9, 40], target: [0, 0, -60] }));
    expect((await page.evaluate(() => window.oceano.debug.passTimings())).map((t) => t.name)).toEqual(['scene']);
    await page.close();
  });

  it("lights the wet side of the boat's hull with the same caustics, and nothing else in view", async () => {
    // Beside the hull, looking up at it; the sea bed pushed out of sight, blur and god rays off,
    // so only the hull can change with the caustics' intensity.
    const view = 'seed=1&t=10&cam=12,-1.2,-14,7,-0.2,-5&seaBedDepth=200&blurStrength=0&godRays=0';
    // One page, the intensity then turned down through the API (a second boot cost seconds).
    const lit = await openOcean(harness, `${view}&causticsIntensity=2`);
    expect(await lit.page.evaluate(() => window.oceano.boat().model)).toBe('loaded');
    const litPng = await canvasPng(lit.page);
    expect(lit.consoleErrors).toEqual([]);
    await lit.page.evaluate(() => window.oceano.setParams({ causticsIntensity: 0 }));
    const difference = diffPngs(litPng, await canvasPng(lit.page), 0);
    await lit.page.close();
    expect(difference.differentPixels).toBeGreaterThan(50);
    // The hull covers a small part of the frame: the rest (surface, fog) is the same.
    expect(difference.share).toBeLessThan(0.1);
  });
});
