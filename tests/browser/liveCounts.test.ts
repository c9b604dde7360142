import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

/** The panel's live LOD counts agree with what is drawn. */
const harness = useHarness();

describe('live LOD counts', () => {
  // Wireframe counts its triangles.
  it('the panel agrees with stats() after every change of a paused view, Dive included', async () => {
    const { page } = await openOcean(harness, 't=1', 800, 600);
    const agree = async () => {
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      return page.evaluate(() => {
        const value = (name: string) => {
          const row = Array.from(document.querySelectorAll('.lil-controller')).find(
            (c) => c.querySelector('.lil-name')?.textContent === name,
          );
          return (row?.querySelector('input') as HTMLInputElement | null)?.value ?? '';
        };
        const s = window.oceano.stats();
        return {
          panel: [value('Chunks visible / total'), value('Triangles'), value('Draw calls')],
          stats: [`${s.chunksVisible} / ${s.chunksTotal}`, s.triangles.toLocaleString('en-US'), String(s.drawCalls)],
        };
      });
    };
    await page.evaluate(() => window.oceano.setParams({ lodDistance: 400 }));
    await page.evaluate(() => window.oceano.setCamera({ position: [30, 12, 60], target: [0, 0, -80] }));
    let now = await agree();
    expect(now.panel).toEqual(now.stats);
    await page.evaluate(() =>
      (
        Array.from(document.querySelectorAll<HTMLElement>('.lil-gui button')).find((b) => b.textContent?.includes('Dive')) as HTMLElement
      ).click(),
    );
    await page.evaluate(() => window.oceano.loaded());
    now = await agree();
    expect(now.panel).toEqual(now.stats);
    const solid = await page.evaluate(() => window.oceano.stats().triangles);
    await page.evaluate(() => window.oceano.setParams({ wireframe: true }));
    now = await agree();
    expect(now.panel).toEqual(now.stats);
    const wire = await page.evaluate(() => window.oceano.stats().triangles);
    // The same chunks drawn as lines: the same triangles (the boat, solid either way, included).
    expect(wire).toBe(solid);
    await page.close();
  });
});
