import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { compareStrips } from '../../src/sim/compare/compareLayout';
import { differingPixels } from '../support/pictureStatistics';

/**
 * The boat's wake in the side-by-side view: compare=seed,gerstner,fft with the wake on. The
 * wake's uniforms are shared by every model's ocean material, so each compared model's strip
 * must hold exactly the pixels of that model drawn alone with the wake on: the wake's heights,
 * and its per-pixel slope and foam too. The boat rides the first model (seed), so the camera
 * keeps it in the first strip, and the wake crosses the other two. The wake's bound grows
 * each compared model's culling bounds as it grows the first model's: the bands' geomorphing
 * reads the wave height they were chosen with, so a strip culled with the model's bounds alone
 * put its far vertices a little elsewhere (609 and 1,787 pixels differed).
 *
 * Negative control: the old fault, the compared models' pixels drawn without the wake (their
 * vertices still carry it): the fragment shader's wake block compiled out of every ocean
 * material of the split page, which must differ from the models alone across the wake. (The
 * code before the fix, wake switched on for the first model's material only, failed this test
 * with 6,964 pixels differing in the gerstner strip.)
 */
const harness = useHarness();

const WIDTH = 320;
const HEIGHT = 180;
const SHARED = 't=10&seed=1&wake=1&wakeGuide=0&boatSpeed=4&boatHeading=270&boatTurnRate=3&cam=25,12,30,25,0,-40';
const SPLIT = 0.35;
const SPLIT2 = 0.65;
const COMPARED = ['gerstner', 'fft'] as const;
/**
 * Measured 0 differing pixels in either strip (the same programs on the same data), so the
 * tolerance is 0. The control moved 4,395 (gerstner) and 7,101 (fft) pixels by more than 2
 * levels; it must move more than CONTROL_FLOOR.
 */
const STRIP_TOLERANCE = 0;
const CONTROL_FLOOR = 1000;

async function picture(page: Page): Promise<PNG> {
  return PNG.sync.read(await canvasPng(page));
}

describe('compare=seed,gerstner,fft with the boat wake on', () => {
  it('holds each compared model with its wake, pixel for pixel, on its own strip; the pixels without the wake fail', async () => {
    const split = await openOcean(
      harness,
      `${SHARED}&compare=seed,gerstner,fft&compareSplit=${SPLIT}&compareSplit2=${SPLIT2}`,
      WIDTH,
      HEIGHT,
    );
    const both = await picture(split.page);
    // The control: every ocean material's fragment shader without its wake block.
    const patched = await split.page.evaluate(() => {
      type Material = { fragmentShader?: string; uniforms?: Record<string, unknown>; needsUpdate: boolean };
      const materials = new Set<Material>();
      window.oceano.three.scene.traverse((object) => {
        const m = (object as unknown as { material?: Material }).material;
        if (m?.uniforms?.uWakeCount && m.uniforms.uFresnelTable) materials.add(m);
      });
      let count = 0;
      for (const m of materials) {
        const source = m.fragmentShader ?? '';
        const faulty = source.replace('#ifdef OCEAN_WAKE\n', '#ifdef OCEAN_WAKE_NOT_IN_PIXELS\n');
        if (faulty === source) continue;
        m.fragmentShader = faulty;
        m.needsUpdate = true;
        count++;
      }
      return count;
    });
    const faulty = await picture(split.page);
    expect(split.consoleErrors).toEqual([]);
    await split.page.close();
    // Three models, each a far and a near-band material.
    expect(patched).toBe(6);

    const strips = compareStrips(3, SPLIT, SPLIT2, WIDTH);
    const report: string[] = [];
    for (const [k, model] of COMPARED.entries()) {
      const { page, consoleErrors } = await openOcean(harness, `${SHARED}&waves=${model}`, WIDTH, HEIGHT);
      const alone = await picture(page);
      expect(consoleErrors).toEqual([]);
      await page.close();
      const { x0, x1 } = strips[k + 1];
      const own = differingPixels(both, alone, x0, x1);
      const control = differingPixels(faulty, alone, x0, x1, 2);
      report.push(
        `${model} [${x0}, ${x1}): ${own} px differ from ${model} alone with the wake; control (no wake in the pixels) ${control} px by more than 2 levels`,
      );
      expect(own, report.at(-1)).toBeLessThanOrEqual(STRIP_TOLERANCE);
      expect(control, report.at(-1)).toBeGreaterThan(CONTROL_FLOOR);
    }
    console.log(`[oceano] ${report.join('\n')}`);
  });
});
