import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { answer, openLesson } from './lessonExerciseStudent';

/**
 * The physics-panel exercises on cards that had none: a scripted student opens each lesson,
 * ticks "Physics panel" in the controls (unless it is open already: it then measures the new
 * sea by itself), reads Hs in the "measured" column, types it and presses Check: "Within
 * tolerance"; twice it (crest to trough) and half it (the amplitude) are "Not yet".
 */
const harness = useHarness();

/** Ticks the "Physics panel" box if it is not ticked, waits for the table and reads Hs's measured and theory cells, and the heading. */
async function panelHs(page: Page): Promise<{ measured: string; theory: string; heading: string; wasOpen: boolean }> {
  const wasOpen = await page.evaluate(() => {
    const names = Array.from(document.querySelectorAll('.lil-gui .lil-name, .lil-gui .name'));
    const name = names.find((n) => /^Physics panel/.test(n.textContent ?? ''));
    if (!name) throw new Error(`no Physics panel box among: ${names.map((n) => n.textContent).join(' | ')}`);
    const box = name.parentElement!.querySelector<HTMLInputElement>('input[type="checkbox"]')!;
    const open = box.checked;
    if (!open) box.click();
    return open;
  });
  // The estimators run on the CPU twin: 16 points × 512 times, 10 to 40 s for an FFT sea on a loaded 2-core machine.
  await page.waitForSelector('.oceano-physics table', { timeout: 120_000 });
  return page.$eval(
    '.oceano-physics',
    (root, open) => {
      const row = Array.from(root.querySelectorAll('table tr')).find((tr) =>
        /^Hs = 4σ/.test((tr as HTMLTableRowElement).cells[0]?.textContent ?? ''),
      ) as HTMLTableRowElement;
      return {
        measured: row.cells[1].textContent ?? '',
        theory: row.cells[2].textContent ?? '',
        heading: root.querySelector('h2')?.textContent ?? '',
        wasOpen: open,
      };
    },
    wasOpen,
  );
}

describe('physics-panel exercises on more cards, done with the panel', () => {
  // airy-waves and gerstner-gentle (Gerstner), spectra-compared (Phillips), sun-glint (5 m/s), fft-transform (its own physics=1, the panel left open).
  it('four seas, five cards: the panel\'s Hs is within tolerance, twice or half it "Not yet"', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=100&lesson=airy-waves', 1366, 768);
    await page.waitForSelector('.lil-gui.lil-root');
    const cases: [string, RegExp][] = [
      ['airy-waves', /gerstner sea/],
      // The same sea as airy-waves, its answer held to the drawn waves' Σ Aᵢ²/2: the open panel keeps its figures.
      ['gerstner-gentle', /gerstner sea/],
      ['spectra-compared', /fft sea/],
      ['sun-glint', /fft sea/],
      // The lesson opens the panel itself, over sun-glint's open one: its figures must be this sea's.
      ['fft-transform', /fft sea/],
    ];
    const theories: string[] = [];
    for (const [lesson, model] of cases) {
      await openLesson(page, lesson);
      await page.evaluate(() => window.oceano.pause());
      const read = await panelHs(page);
      expect(read.heading).toMatch(model);
      theories.push(read.theory);
      const right = await answer(page, read.measured);
      console.log(
        `${lesson}: ${read.heading}; Hs ${read.measured} m (theory ${read.theory} m)${read.wasOpen ? ', panel already open' : ''}; ${right.text}`,
      );
      expect(right.verdict, `${lesson}: ${right.text}`).toBe('within');
      expect(right.text).toMatch(/^Within tolerance/);
      for (const slip of [2, 0.5]) {
        const wrong = await answer(page, (Number(read.measured) * slip).toFixed(2));
        expect(wrong.verdict, `${lesson} ×${slip}: ${wrong.text}`).toBe('not-yet');
        expect(wrong.text).toMatch(/^Not yet/);
      }
    }
    // Each sea's own theory was on show (1.61, 1.84, 0.56 and 2.25 m), never the sea before's; airy-waves and gerstner-gentle share one sea.
    expect(new Set(theories).size).toBe(cases.length - 1);
    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 600_000);
});
