import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import type { FrameCounts } from '../../src/render/diagnostics/frameCounter';

/**
 * What one frame asks of the GPU, counted from its WebGL calls (oceano.debug.frameCounts) at
 * 1280×720: the same on every machine, so the budgets are held here rather than timed.
 */
const harness = useHarness();

type Budget = Partial<Record<keyof FrameCounts, number>>;

/** The counts over their budget, by name: none when the frame keeps it. */
const breaches = (counts: FrameCounts, budget: Budget): string[] =>
  Object.entries(budget)
    .filter(([name, most]) => counts[name as keyof FrameCounts] > (most as number))
    .map(([name, most]) => `${name} ${counts[name as keyof FrameCounts]} > ${most}`);

/** One frame `seconds` on from the last, counted after three alike (programs compiled, the boat placed, a replay done). */
async function frameCounts(page: Page, options: { seconds?: number; plantedPass?: boolean } = {}): Promise<FrameCounts> {
  await page.evaluate(() => window.oceano.pause());
  const { plantedPass, ...warmUp } = options;
  for (let i = 0; i < 3; i++) await page.evaluate((o) => window.oceano.debug.frameCounts(o), warmUp);
  return page.evaluate((o) => window.oceano.debug.frameCounts(o), { ...warmUp, plantedPass });
}

async function countsOf(query: string, options: { seconds?: number; plantedPass?: boolean } = {}): Promise<FrameCounts> {
  const { page, consoleErrors } = await openOcean(harness, query, 1280, 720);
  const counts = await frameCounts(page, options);
  expect(consoleErrors).toEqual([]);
  await page.close();
  return counts;
}

describe('what a played frame asks of the GPU', () => {
  // The boat in one draw, the sky with the sun's disc in one, the sea's chunks: straight to the canvas.
  const DEFAULT_VIEW: Budget = { drawCalls: 10, passes: 1 };

  it('the default view: at most 10 draw calls, in one pass, uploading nothing', async () => {
    const counts = await countsOf('t=10');
    expect(breaches(counts, { ...DEFAULT_VIEW, bytesUploaded: 0 })).toEqual([]);
    expect(counts.drawCalls).toBeGreaterThan(0);
  });

  it('a render planted into a target of its own breaks the default view budget of passes', async () => {
    const counts = await countsOf('t=10', { plantedPass: true });
    expect(breaches(counts, DEFAULT_VIEW)).toContain(`passes ${counts.passes} > 1`);
  });

  // The spectral sea's cascades share one set of passes (src/render/waves/fft/gpuFft.ts): one evolve pass,
  // one per Stockham stage, the last stage once per cascade, then the foam; a frame that steps the foam's
  // lattice adds two. Counted on one frame in six of those, the budget must hold for both.
  const SPECTRAL_VIEW: Budget = { drawCalls: 30, passes: 20 };

  it.each(['t=10&waves=fft', 't=10&preset=gale'])(
    '%s: at most 20 passes and 30 draw calls in any of six frames',
    async (query) => {
      const { page, consoleErrors } = await openOcean(harness, query, 1280, 720);
      const frames: FrameCounts[] = [await frameCounts(page)];
      for (let i = 1; i < 6; i++) frames.push(await page.evaluate(() => window.oceano.debug.frameCounts({})));
      console.log(`[oceano] ${query}: passes ${frames.map((f) => f.passes).join(' ')}, draws ${frames.map((f) => f.drawCalls).join(' ')}`);
      expect(frames.flatMap((counts) => breaches(counts, SPECTRAL_VIEW))).toEqual([]);
      expect(consoleErrors).toEqual([]);
      await page.close();
    },
    300_000,
  );

  it('compare-models, three seas side by side: at most 60 draw calls', async () => {
    const counts = await countsOf('t=10&preset=compare-models');
    expect(breaches(counts, { drawCalls: 60 })).toEqual([]);
  }, 300_000);

  // The interactive waves carry nothing from the CPU: their field is stepped, disturbed and read on the GPU.
  it('a stone in the interactive waves, its guide off: no upload in a played frame', async () => {
    expect((await countsOf('t=1&preset=stone&iwaveGuide=0')).bytesUploaded).toBe(0);
  }, 300_000);

  it('a stone in the interactive waves once its guide rings have gone: no upload in a played frame', async () => {
    expect((await countsOf('t=70&preset=stone')).bytesUploaded).toBe(0);
  }, 300_000);

  it("the guide's rings upload only when they move: none drawing the same time again, some in a played frame", async () => {
    const { page } = await openOcean(harness, 't=1&preset=stone&iwaveEquation=non-dispersive', 1280, 720);
    expect((await frameCounts(page, { seconds: 0 })).bytesUploaded).toBe(0);
    // The control: the ring grows as time runs, and the counter sees it go up. (The wave equation's
    // one ring shows from the stone's first second; deep water's crests from its fourth, 240 steps on.)
    const played = await frameCounts(page);
    expect(played.bytesUploaded).toBeGreaterThan(0);
    expect(played.uploads).toBe(1);
    await page.close();
  }, 300_000);
});
