import type { Page } from 'puppeteer';
import { NATIVE_SIN_TURNS, SIN_TURNS_HEADER } from '../support/nativeSine';
import type { Harness } from './harness';

/**
 * How far the CPU twin (src/sim/waves/seed/seedSurface.ts) and the displacement shader may disagree, just
 * above what surfaceParity.test.ts measures on SwiftShader (1280 seeded points out to 3 km,
 * t up to 1e6 s; the figures are deterministic from run to run):
 * - default parameters: max |Δheight| 2.08e-5 m, max |Δnormal| 2.45e-5;
 * - the steepest, shortest swell the parameters allow (amplitude 4 m, frequency 0.2,
 *   ripples ×2): 2.39e-4 m and 2.67e-4.
 * The driver's own `sin` in place of the shader's Taylor series (the negative control) gives
 * 6.15e-4 m and 1.59e-4 with the defaults: 20 and 4 times the default limits. The old
 * single limit of 1e-3 let it through.
 */
export const PARITY_LIMITS = {
  defaults: { height: 3e-5, normal: 4e-5 },
  steepest: { height: 3e-4, normal: 3.5e-4 },
} as const;

/** The limits for pages at the default wave parameters (every test but the steep parity case). */
export const PARITY_HEIGHT_LIMIT = PARITY_LIMITS.defaults.height;
export const PARITY_NORMAL_LIMIT = PARITY_LIMITS.defaults.normal;

/**
 * A page whose shaders compute sinTurns with the driver's `sin` (tests/support/nativeSine.ts),
 * so the swell uses it (shaders/waves/seed.glsl): the fault the parity limits must catch. The
 * replacement is made as the page hands each shader's source to WebGL.
 */
export async function openWithNativeSin(harness: Harness, query: string): Promise<Page> {
  const page = await harness.browser.newPage();
  await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
  await page.evaluateOnNewDocument(
    (header: string, native: string) => {
      const original = WebGL2RenderingContext.prototype.shaderSource;
      WebGL2RenderingContext.prototype.shaderSource = function (shader: WebGLShader, source: string) {
        original.call(this, shader, source.replace(header, native));
      };
    },
    SIN_TURNS_HEADER,
    NATIVE_SIN_TURNS,
  );
  await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  return page;
}
