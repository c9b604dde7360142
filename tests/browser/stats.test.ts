import { describe, expect, it } from 'vitest';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';

const harness = useHarness();

/**
 * One t=10 page for both tests (a boot costs seconds of SwiftShader work), small: neither
 * figure depends on the canvas size (ttffMs is a time, cpuMs the update step before any
 * draw), and the second test draws 64 frames. The first test reads it as loaded.
 */
const shared = sharedPage(harness, 't=10', 160, 90);

describe('oceano.stats() start-up and CPU figures', () => {
  it('records the time to first frame once: after the script arrived, before ready, unchanged by later frames', async () => {
    const { page, consoleErrors } = await shared.opened();
    const atReady = await page.evaluate(() => {
      const script = performance.getEntriesByType('resource').find((entry) => /\/assets\/[^/]+\.js$/.test(entry.name)) as
        PerformanceResourceTiming | undefined;
      return { ttffMs: window.oceano.stats().ttffMs, scriptArrived: script?.responseEnd ?? null, now: performance.now() };
    });
    expect(atReady.scriptArrived).not.toBeNull();
    expect(atReady.ttffMs).not.toBeNull();
    expect(atReady.ttffMs as number).toBeGreaterThan(atReady.scriptArrived as number);
    expect(atReady.ttffMs as number).toBeLessThanOrEqual(atReady.now);
    // Frames from the loop and from the API must not move it.
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    await page.evaluate(() => window.oceano.renderFrame());
    expect(await page.evaluate(() => window.oceano.stats().ttffMs)).toBe(atReady.ttffMs);
    expect(consoleErrors).toEqual([]);
  });

  it('counts the update step in cpuMs: within frameMs, above boatMs, and 20 ms more when the update does 20 ms more', async () => {
    const figures = await shared.restoring((page) =>
      page.evaluate(() => {
        const o = window.oceano;
        // Enough frames to fill the 30-frame window the medians are taken over. The camera moves
        // a millimetre before each, as a user's would: an unmoved camera's matrices are not
        // remade (CullingView.sameCameraPose), which would skip the planted work below.
        const frames = () => {
          for (let i = 0; i < 32; i++) {
            o.three.camera.position.x += 1e-3;
            o.renderFrame();
          }
          const { cpuMs, frameMs, boatMs } = o.stats();
          return { cpuMs, frameMs, boatMs };
        };
        const plain = frames();
        // Planted work inside the update step: the view's update refreshes the camera's world
        // matrix, which refreshes its children; this child busy-waits 20 ms each time.
        const { camera } = o.three;
        const slow = camera.clone();
        slow.updateMatrixWorld = () => {
          const until = performance.now() + 20;
          while (performance.now() < until);
        };
        camera.add(slow);
        const loaded = frames();
        camera.remove(slow);
        return { plain, loaded };
      }),
    );
    console.log(
      `[oceano] stats: plain cpuMs ${figures.plain.cpuMs.toFixed(2)}, boatMs ${figures.plain.boatMs.toFixed(2)}, frameMs ${figures.plain.frameMs.toFixed(1)}; with 20 ms planted in the update: cpuMs ${figures.loaded.cpuMs.toFixed(2)}`,
    );
    for (const f of [figures.plain, figures.loaded]) {
      // Each frame's update is part of that frame and the boat part of the update, so their medians keep that order.
      expect(f.boatMs).toBeLessThanOrEqual(f.cpuMs);
      expect(f.cpuMs).toBeLessThanOrEqual(f.frameMs);
    }
    // Every loaded update holds the 20 ms; the difference of two medians can come out a little
    // under 20 when the plain run's median sits on a slow frame (measured 19.85).
    expect(figures.loaded.cpuMs).toBeGreaterThanOrEqual(20);
    expect(figures.loaded.cpuMs - figures.plain.cpuMs).toBeGreaterThan(15);
    // The planted work is in the update, not in the boat's share of it.
    expect(figures.loaded.boatMs).toBeLessThan(figures.plain.boatMs + 5);
  });
});
