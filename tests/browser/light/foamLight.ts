import type { Page } from 'puppeteer-core';
import { canvasPng } from '../harness';
import { pngLuminances } from '../../support/luminance';

/**
 * The foam's own light at simulation time `time`: the frame with foam less the same instant
 * without it, luminance per pixel, so the water, the glint and the boat cancel.
 */
export async function foamOwnLight(page: Page, time: number): Promise<Float64Array> {
  const frame = async (foam: boolean) => {
    await page.evaluate(
      (t, on) => {
        window.oceano.setParams({ foam: on });
        window.oceano.pause();
        window.oceano.setTime(t);
      },
      time,
      foam,
    );
    return pngLuminances(await canvasPng(page));
  };
  const water = await frame(false);
  return (await frame(true)).map((value, i) => value - water[i]);
}
