import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { useHarness } from './useHarness';

/**
 * The page's JavaScript before its first frame stays small, so a first visit draws the sea soon. The FFT and Gerstner models, the
 * control panel (lil-gui), the physics estimators and the GPU probe are chunks fetched on
 * use. These tests load the page as a user does and check that each arrives when asked for,
 * and that a chunk the network refuses gives a notice and keeps the ocean running.
 */
const harness = useHarness();

interface Opened {
  page: Page;
  /** Script URLs requested, in order. */
  scripts: string[];
  /** Console errors and uncaught exceptions, without the browser's own line for a refused request. */
  errors: string[];
  /** The chunks refused; empty it to let them through from then on. */
  refuse: string[];
}

/** Opens the page; `refuse` names chunks (by file-name start) whose requests fail as a dropped connection would. */
async function open(query: string, refused: string[] = []): Promise<Opened> {
  const refuse = [...refused];
  const page = await harness.browser.newPage();
  page.setDefaultTimeout(120_000);
  await page.setViewport({ width: 320, height: 180, deviceScaleFactor: 1 });
  const scripts: string[] = [];
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error' && !m.text().startsWith('Failed to load resource')) errors.push(m.text());
  });
  page.on('pageerror', (error) => errors.push(String(error)));
  await page.setRequestInterception(true);
  page.on('request', (request) => {
    const url = request.url();
    if (url.endsWith('.js')) scripts.push(url.slice(url.lastIndexOf('/') + 1));
    if (refuse.some((name) => url.includes(`/assets/${name}-`))) void request.abort('connectionfailed');
    else void request.continue();
  });
  await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  return { page, scripts, errors, refuse };
}

const fetched = (scripts: string[], name: string) => scripts.some((file) => file.startsWith(`${name}-`));

/** The CPU twin's height and the GPU chunk's at one grid point (a model switch must change both, together). */
const surfaceAt = (page: Page) =>
  page.evaluate(async () => {
    const cpu = window.oceano.sampleSurface(10, -20).height;
    const [gpu] = await window.oceano.probeGpu([[10, -20]]);
    return { cpu, gpu: gpu.height };
  });

describe('parts fetched on use', () => {
  // Gerstner's CPU twin and shader arrive together.
  it("the default view fetches only the seed's wave model; gerstner arrives on setParams", async () => {
    const { page, scripts, errors } = await open('t=10');
    expect(fetched(scripts, 'gerstnerModelCode')).toBe(false);
    expect(fetched(scripts, 'fftModelCode')).toBe(false);
    // The panel came after the first frame, and `ready` waited for it.
    expect(fetched(scripts, 'controlPanel')).toBe(true);
    expect(await page.$$('.lil-gui.lil-root')).toHaveLength(1);
    const seed = await surfaceAt(page);
    await page.evaluate(() => window.oceano.setParams({ waves: 'gerstner' }));
    await page.evaluate(() => window.oceano.loaded());
    expect(fetched(scripts, 'gerstnerModelCode')).toBe(true);
    const gerstner = await surfaceAt(page);
    expect(await page.evaluate(() => window.oceano.getParams().waves)).toBe('gerstner');
    // A different sea for the CPU twin and for the shader alike (Gerstner's moves grid points
    // sideways too, so its grid point's height is not the height above that world point:
    // gerstnerApp.test.ts checks that parity).
    expect(Math.abs(gerstner.cpu - seed.cpu)).toBeGreaterThan(0.01);
    expect(Math.abs(gerstner.gpu - seed.gpu)).toBeGreaterThan(0.01);
    // The seed's sines move no grid point sideways: there both agree.
    expect(Math.abs(seed.gpu - seed.cpu)).toBeLessThan(1e-3);
    expect(await page.evaluate(() => window.oceano.notices())).toEqual([]);
    expect(errors).toEqual([]);
    await page.close();
  });

  it('a wave model whose code cannot be fetched: a notice, the current sea kept, and choosing it again later works', async () => {
    const { page, errors, refuse } = await open('t=10', ['gerstnerModelCode']);
    const before = await surfaceAt(page);
    await page.evaluate(() => window.oceano.setParams({ waves: 'gerstner', swellAmplitude: 2 }));
    await page.evaluate(() => window.oceano.loaded());
    const params = await page.evaluate(() => window.oceano.getParams());
    // The other change is kept; the model goes back to the one on screen.
    expect([params.waves, params.swellAmplitude]).toEqual(['seed', 2]);
    const notices = await page.evaluate(() => window.oceano.notices());
    expect(notices).toHaveLength(1);
    expect(notices[0]).toMatch(/"gerstner" waves could not be downloaded; still showing "seed"/);
    // The seed's sea, with the new swell: GPU and CPU agree, and it moved.
    const after = await surfaceAt(page);
    expect(Math.abs(after.gpu - after.cpu)).toBeLessThan(1e-3);
    expect(after.cpu).not.toBeCloseTo(before.cpu, 3);
    expect(await page.$eval('.lil-gui', (gui) => (gui.querySelector('select') as HTMLSelectElement).value)).toBe('seed');
    // The network is back: the same choice fetches the code again and shows the model.
    refuse.length = 0;
    await page.evaluate(() => window.oceano.setParams({ waves: 'gerstner' }));
    await page.evaluate(() => window.oceano.loaded());
    expect(await page.evaluate(() => window.oceano.getParams().waves)).toBe('gerstner');
    expect(Math.abs((await surfaceAt(page)).gpu - after.gpu)).toBeGreaterThan(0.01);
    expect(errors).toEqual([]);
    await page.close();
  });

  // waves=fft whose code the network refuses.
  it("at start: refused FFT code draws the seed's sea with a notice; a refused panel leaves the sea running", async () => {
    const { page, errors } = await open('t=10&waves=fft&lang=es', ['fftModelCode', 'controlPanel']);
    const state = await page.evaluate(() => ({
      waves: window.oceano.getParams().waves,
      notices: window.oceano.notices(),
      frames: window.oceano.activity().framesDrawn,
    }));
    expect(state.waves).toBe('seed');
    expect(state.frames).toBeGreaterThan(0);
    expect(state.notices).toHaveLength(2);
    expect(state.notices.join('\n')).toMatch(/No se pudo descargar el código de las olas "fft"; se sigue mostrando "seed"/);
    expect(state.notices.join('\n')).toMatch(/No se pudo descargar el panel de controles/);
    expect(await page.$$('.lil-gui.lil-root')).toHaveLength(0);
    // The sea on screen is the seed's, GPU and CPU alike.
    const surface = await surfaceAt(page);
    expect(Math.abs(surface.gpu - surface.cpu)).toBeLessThan(1e-3);
    expect(errors).toEqual([]);
    await page.close();
  });

  // Not the last frame above.
  it('a dive whose underwater passes are refused: a notice, and the sea drawn from below without them', async () => {
    const { page, errors } = await open('t=10', ['oceanUnderwater']);
    const above = await page.evaluate(() => window.oceano.stats().underwater);
    await page.evaluate(() => window.oceano.setCamera({ position: [0, -8, 20], target: [0, 5, -20] }));
    // The first frame under the water asks for the passes (until they settle the canvas keeps
    // its last frame); drawn here, not left to the loop, so loaded() always has a fetch to wait
    // for (in a slow full-suite run the loop had drawn no frame yet, and the check saw 0 triangles).
    await page.evaluate(() => window.oceano.renderFrame());
    await page.evaluate(() => window.oceano.loaded());
    await page.evaluate(() => window.oceano.renderFrame());
    const state = await page.evaluate(() => ({ stats: window.oceano.stats(), notices: window.oceano.notices() }));
    expect(above).toBe(false);
    expect(state.stats.underwater).toBe(true);
    expect(state.stats.composerPasses).toBe(0);
    // Drawn this frame: the surface from below, so draw calls and triangles were submitted.
    expect(state.stats.triangles).toBeGreaterThan(1000);
    expect(state.notices).toHaveLength(1);
    expect(state.notices[0]).toMatch(/underwater effects .* could not be downloaded/);
    expect(errors).toEqual([]);
    await page.close();
  });
});
