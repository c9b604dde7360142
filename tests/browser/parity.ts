import type { Page } from 'puppeteer';
import type { Harness } from './harness';

/**
 * How far the CPU twin (src/sim/surface.ts) and the displacement shader may disagree.
 * Measured (tests/browser/surfaceParity.test.ts, SwiftShader, 1280 points to |x|, |z| ≤ 3000 m
 * and t ≤ 1e6 s): max |Δheight| MEASURED_H m, max |Δnormal| MEASURED_N. The driver's own `sin`
 * instead of the shader's Taylor series (the negative control) gives NATIVE_H m and NATIVE_N.
 */
export const PARITY_HEIGHT_LIMIT = 1e-3;
export const PARITY_NORMAL_LIMIT = 1e-3;

/**
 * A page whose shaders are compiled with OCEANO_NATIVE_SIN defined, so the swell uses the
 * driver's `sin` (shaders/displacement.glsl): the fault the parity limits must catch. The
 * define is put after each shader's #version line as the page hands the source to WebGL.
 */
export async function openWithNativeSin(harness: Harness, query: string): Promise<Page> {
  const page = await harness.browser.newPage();
  await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
  await page.evaluateOnNewDocument(() => {
    const original = WebGL2RenderingContext.prototype.shaderSource;
    WebGL2RenderingContext.prototype.shaderSource = function (shader: WebGLShader, source: string) {
      const patched = source.replace(/^(#version[^\n]*\n)/, '$1#define OCEANO_NATIVE_SIN\n');
      if (patched === source) throw new Error('A shader without a #version line: the native-sin control cannot define itself.');
      original.call(this, shader, patched);
    };
  });
  await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  return page;
}
