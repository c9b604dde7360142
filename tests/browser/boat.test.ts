import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import type { HTTPRequest } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';
import { diffPngs } from './imageCompare';
import { PARITY_HEIGHT_LIMIT } from './parity';
import { ANGLE_BAND, HEAVE_BAND } from '../../src/sim/boat/boatMotion';

const harness = useHarness();

/**
 * The default view, and the same view whose boat model is missing, each loaded once for the
 * tests that only read them (each boot costs seconds of SwiftShader work). The sailing test,
 * which moves the boat for good, loads its own.
 */
const withBoat = sharedPage(harness, 'seed=1&t=10');
const withoutBoat = sharedPage(harness, 'seed=1&t=10&boat=models/missing.glb');

describe('the boat', () => {
  it('is loaded by oceano.ready and sits on the CPU surface at its centre, which the GPU draws', async () => {
    const { page, consoleErrors } = await withBoat.opened();
    const result = await page.evaluate(async () => {
      const boat = window.oceano.boat();
      const [x, , z] = boat.position;
      const cpu = window.oceano.sampleSurface(x, z).height;
      const [gpu] = await window.oceano.probeGpu([[x, z]]);
      return {
        boat,
        cpu,
        gpu: gpu.height,
        notices: window.oceano.notices(),
        indicator: document.querySelector('.oceano-loading') !== null,
      };
    });
    const boatMs = await page.evaluate(() => {
      for (let i = 0; i < 12; i++) window.oceano.renderFrame();
      return window.oceano.stats().boatMs;
    });
    console.log(`[oceano] boat update per frame (median over frames, 0.1 ms timer resolution): ${boatMs.toFixed(2)} ms`);
    expect(result.boat.model).toBe('loaded');
    expect(result.indicator).toBe(false);
    expect(result.notices).toEqual([]);
    // Time is frozen, so the damped pose is the surface's own.
    expect(result.boat.position[1]).toBe(result.cpu);
    expect(Math.abs(result.boat.position[1] - result.gpu)).toBeLessThan(PARITY_HEIGHT_LIMIT);
    expect(result.boat.heading).toBeCloseTo((290 * Math.PI) / 180, 12);
    expect(consoleErrors).toEqual([]);
  });

  it('floats within its band of the surface while time runs, through an abrupt swell change', async () => {
    const { page } = await openOcean(harness, 'seed=2');
    const worst = await page.evaluate(async () => {
      const o = window.oceano;
      const nextFrame = () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
      let heave = 0;
      let angle = 0;
      let moved = 0;
      const first = o.boat().position[1];
      for (let i = 0; i < 24; i++) {
        if (i === 8) o.setParams({ swellAmplitude: 4, rippleStrength: 2 });
        if (i === 16) o.setParams({ swellAmplitude: 0, rippleStrength: 0 });
        await nextFrame();
        const boat = o.boat();
        heave = Math.max(heave, Math.abs(boat.position[1] - boat.target.position[1]));
        angle = Math.max(angle, Math.abs(boat.pitch - boat.target.pitch), Math.abs(boat.roll - boat.target.roll));
        moved = Math.max(moved, Math.abs(boat.position[1] - first));
        // The target is the CPU surface at the boat's centre, at the time of the frame drawn.
        const surface = o.sampleSurface(boat.position[0], boat.position[2]).height;
        if (Math.abs(surface - boat.target.position[1]) > 1e-12)
          throw new Error(`target ${boat.target.position[1]} is not the surface ${surface}`);
      }
      return { heave, angle, moved };
    });
    expect(worst.heave).toBeLessThanOrEqual(HEAVE_BAND + 1e-9);
    expect(worst.angle).toBeLessThanOrEqual(ANGLE_BAND + 1e-9);
    expect(worst.moved).toBeGreaterThan(0);
    await page.close();
  });

  it('sails along its heading, turns with the keyboard, and carries the camera when following', async () => {
    const { page } = await openOcean(harness, 'seed=1&t=10');
    const start = await page.evaluate(() => {
      window.oceano.setParams({ boatHeading: 90, boatSpeed: 6, boatFollow: true });
      // A frame with the clock standing still turns the boat to its new heading at once.
      window.oceano.renderFrame();
      return { boat: window.oceano.boat(), camera: window.oceano.getCamera() };
    });
    // Following starts by aiming the camera at the boat.
    expect(start.camera.target[0]).toBeCloseTo(start.boat.position[0], 9);
    expect(start.camera.target[2]).toBeCloseTo(start.boat.position[2], 9);
    expect(start.boat.heading).toBeCloseTo(Math.PI / 2, 12);
    await page.evaluate(() => window.oceano.play());
    await new Promise((r) => setTimeout(r, 1500));
    const sailed = await page.evaluate(() => ({ boat: window.oceano.boat(), camera: window.oceano.getCamera() }));
    expect(sailed.boat.position[0] - start.boat.position[0]).toBeGreaterThan(0.5);
    expect(sailed.boat.position[2]).toBeCloseTo(start.boat.position[2], 9);
    expect(sailed.camera.target[0]).toBeCloseTo(sailed.boat.position[0], 9);
    expect(sailed.camera.position[0] - sailed.camera.target[0]).toBeCloseTo(start.camera.position[0] - start.camera.target[0], 9);

    // Frames take a second or more on a busy software rasterizer: hold each key until a frame has applied it.
    await page.keyboard.down('KeyD');
    await page.waitForFunction(() => window.oceano.getParams().boatHeading > 90, { timeout: 30_000 });
    await page.keyboard.up('KeyD');
    await page.keyboard.down('ArrowDown');
    await page.waitForFunction(() => window.oceano.getParams().boatSpeed < 6, { timeout: 30_000 });
    await page.keyboard.up('ArrowDown');
    const steered = await page.evaluate(() => window.oceano.getParams());
    // Turning to starboard raises the heading; D did nothing to the speed, ↓ nothing to the heading.
    expect(steered.boatHeading).toBeGreaterThan(90);
    expect(steered.boatHeading).toBeLessThanOrEqual(90 + 45 * 0.1 * 40);
    expect(steered.boatSpeed).toBeLessThan(6);
    // A tap shorter than a frame still counts for one frame.
    const before = await page.evaluate(() => window.oceano.getParams().boatHeading);
    await page.keyboard.press('KeyA');
    await page.waitForFunction((h) => window.oceano.getParams().boatHeading < h, { timeout: 30_000 }, before);
    await page.close();
  });

  it('is visible in the default view: the picture without the boat differs around it', async () => {
    const a = await canvasPng(await withBoat.page());
    // The notice about the missing model lies over the canvas; canvasPng hides the notices
    // while it takes the picture (the next test reads that notice, so it is not dismissed).
    const b = await canvasPng(await withoutBoat.page());
    const diff = diffPngs(a, b);
    // At 640×360 the boat covers about 1400 pixels; nothing else in the frame changes.
    expect(diff.differentPixels).toBeGreaterThan(800);
    expect(diff.differentPixels).toBeLessThan(4000);
  });
});

describe('bad boat models', () => {
  it('a missing model leaves the ocean running with a notice', async () => {
    const page = await withoutBoat.page();
    const state = await page.evaluate(() => ({
      notices: window.oceano.notices(),
      boat: window.oceano.boat(),
      stats: window.oceano.stats(),
    }));
    expect(state.notices.join('\n')).toMatch(/boat model "models\/missing\.glb" (is missing|was not found).*runs without the boat/);
    expect(state.boat.model).toBe('failed');
    expect(state.stats.triangles).toBeGreaterThan(10_000);
  });

  it('a file that is not a glTF leaves the ocean running with a notice', async () => {
    const { page } = await openOcean(harness, 'seed=1&t=10&boat=sky/px.png');
    const notices = await page.evaluate(() => window.oceano.notices());
    expect(notices.join('\n')).toMatch(/boat model "sky\/px\.png" is not a valid glTF model.*runs without the boat/);
    await page.close();
  });

  it('a model path off this site is refused with a notice', async () => {
    const { page } = await openOcean(harness, 'seed=1&t=10&boat=https://example.com/boat.glb');
    const state = await page.evaluate(() => ({ notices: window.oceano.notices(), boat: window.oceano.boat() }));
    expect(state.notices.join('\n')).toMatch(/"boat=https:\/\/example\.com\/boat\.glb" is not a path on this site/);
    expect(state.boat.model).toBe('loaded');
    await page.close();
  });

  it('a truncated GLB leaves the ocean running with a notice', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    await page.setRequestInterception(true);
    const truncated = readFileSync(new URL('../../public/models/boat.glb', import.meta.url)).subarray(0, 600);
    page.on('request', (request) => {
      if (request.url().endsWith('.glb')) void request.respond({ status: 200, contentType: 'model/gltf-binary', body: truncated });
      else void request.continue();
    });
    const warnings: string[] = [];
    page.on('console', (m) => m.type() === 'warn' && warnings.push(m.text()));
    await page.goto(`${harness.baseUrl}?seed=1&t=10`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const state = await page.evaluate(() => ({
      notices: window.oceano.notices(),
      model: window.oceano.boat().model,
      triangles: window.oceano.stats().triangles,
    }));
    expect(state.model).toBe('failed');
    expect(state.triangles).toBeGreaterThan(10_000);
    // The notice names the file in the page's words; the loader's English reason goes to the console,
    // so a Spanish page never shows an English sentence.
    expect(state.notices.join('\n')).toMatch(
      /boat model "models\/boat\.glb" is not a valid glTF model: .+\. The ocean runs without the boat\.$/,
    );
    expect(warnings.join('\n')).toMatch(/boat model "models\/boat\.glb" could not be parsed: .+/);
    await page.close();
  });

  it('shows a loading indicator over the running sea until the model arrives, and a notice when the request fails', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    await page.setRequestInterception(true);
    const held: HTTPRequest[] = [];
    page.on('request', (request) => {
      if (request.url().endsWith('.glb')) held.push(request);
      else void request.continue();
    });
    await page.goto(`${harness.baseUrl}?seed=1&t=10`, { waitUntil: 'load' });
    await page.waitForFunction(() => document.querySelector('.oceano-loading') !== null && (window.oceano?.stats().triangles ?? 0) > 0);
    expect(await page.$eval('.oceano-loading li[data-state="active"]', (el) => (el as HTMLElement).innerText)).toBe('boat');
    expect(held).toHaveLength(1);
    await held[0].abort('failed');
    await page.evaluate(() => window.oceano.ready);
    const state = await page.evaluate(() => ({
      notices: window.oceano.notices(),
      model: window.oceano.boat().model,
      indicator: document.querySelector('.oceano-loading') !== null,
    }));
    expect(state.model).toBe('failed');
    expect(state.indicator).toBe(false);
    expect(state.notices.join('\n')).toMatch(/boat model "models\/boat\.glb" could not be fetched.*runs without the boat/);
    await page.close();
  });
});
