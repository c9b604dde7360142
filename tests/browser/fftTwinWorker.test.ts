import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { serveUnderSubPath } from './staticServer';
import { FftWaveModel } from '../../src/sim/waves/fft/fftWaveModel';
import { seededRandom } from '../../src/sim/noise/integerHash';
import type { OceanParams } from '../../src/sim/params/params';
import type { TwinStatus } from '../../src/sim/waves/fft/twinStatus';

/**
 * waves=fft with the clock playing: the CPU twin's fields come from its Worker, not from the
 * main thread, by messages, which need nothing of the host: on the app's own server (which
 * sends cross-origin isolation headers, for the bench's fine timers: vite.config.ts) and on a
 * static course site that sends none. On both they are the CPU FFT of the time they claim.
 * The page's twin is asked for heights at the time of the fields it holds, and node's
 * FftWaveModel computes the same heights itself: the same float64 code, so they agree to
 * rounding (measured: 6e-16 and 1.1e-15 m).
 * Negative control, run by hand: the Worker replying with the time of the request plus one
 * frame, 1/60 s (|Δheight| 2.5 cm).
 */
const QUERY = 'waves=fft&fftSize=64&windSpeed=12&seed=5&t=10&foam=false';
const FRAMES_WITH_FIELDS = 4;
const HEIGHT_TOLERANCE = 1e-9;

const harness = useHarness();

interface PlayedTwin {
  isolated: boolean;
  twin: TwinStatus;
  params: OceanParams;
  heights: number[];
}

/** Plays until the twin has adopted a few Worker deliveries, pauses, and samples the surface at their time. */
async function playAndSample(page: Page, points: [number, number][]): Promise<PlayedTwin> {
  await page.evaluate(() => window.oceano.play());
  await page.waitForFunction((n) => (window.oceano.stats().twin?.fieldsReceived ?? 0) >= n, { polling: 100 }, FRAMES_WITH_FIELDS);
  return page.evaluate((points) => {
    const o = window.oceano;
    o.pause();
    const twin = o.stats().twin!;
    // At the held fields' own time the twin answers from them, computing nothing itself.
    o.setTime(twin.fieldsTime);
    const heights = points.map(([x, z]) => o.sampleSurface(x, z).height);
    const after = o.stats().twin!;
    if (after.fieldsTime !== twin.fieldsTime)
      throw new Error(`The fields moved on while sampling: ${twin.fieldsTime} -> ${after.fieldsTime}`);
    return { isolated: window.crossOriginIsolated, twin, params: o.getParams(), heights };
  }, points);
}

function expectCpuFft(played: PlayedTwin, points: [number, number][]) {
  const model = new FftWaveModel(played.params);
  const worst = Math.max(...points.map(([x, z], i) => Math.abs(model.sample(x, z, played.twin.fieldsTime).height - played.heights[i])));
  expect(worst).toBeLessThanOrEqual(HEIGHT_TOLERANCE);
}

describe('the FFT twin fed by its Worker while the clock plays', () => {
  const random = seededRandom(20261122);
  const points: [number, number][] = Array.from({ length: 12 }, () => [(random() - 0.5) * 400, (random() - 0.5) * 400]);

  it("on the app's own server: fields from the Worker, of the time they claim", async () => {
    const { page, consoleErrors } = await openOcean(harness, QUERY, 320, 180);
    try {
      const played = await playAndSample(page, points);
      expect(played.isolated).toBe(true);
      expect(played.twin.fieldsReceived).toBeGreaterThanOrEqual(FRAMES_WITH_FIELDS);
      expect(played.twin.fieldsTime).toBeGreaterThan(10);
      expectCpuFft(played, points);
      expect(consoleErrors).toEqual([]);
    } finally {
      await page.close();
    }
  });

  it('on a host without isolation headers (a course site): the same, by the same transport', async () => {
    const { server, url } = await serveUnderSubPath();
    const page = await harness.browser.newPage();
    try {
      await page.setViewport({ width: 320, height: 180 });
      await page.goto(`${url}?${QUERY}`, { waitUntil: 'load' });
      await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await page.evaluate(() => window.oceano.ready);
      const played = await playAndSample(page, points);
      expect(played.isolated).toBe(false);
      expect(played.twin.fieldsReceived).toBeGreaterThanOrEqual(FRAMES_WITH_FIELDS);
      expect(played.twin.fieldsTime).toBeGreaterThan(10);
      expectCpuFft(played, points);
    } finally {
      await page.close();
      server.close();
    }
  });
});
