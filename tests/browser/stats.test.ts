import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();

describe('oceano.stats() start-up and CPU figures', () => {
  it('records the time to first frame once: after the script arrived, before ready, unchanged by later frames', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10');
    const atReady = await page.evaluate(() => {
      const script = performance
        .getEntriesByType('resource')
        .find((entry) => /\/assets\/[^/]+\.js$/.test(entry.name)) as PerformanceResourceTiming | undefined;
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
    const { cpuMs } = await page.evaluate(() => window.oceano.stats());
    expect(Number.isFinite(cpuMs)).toBe(true);
    expect(cpuMs).toBeGreaterThanOrEqual(0);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
