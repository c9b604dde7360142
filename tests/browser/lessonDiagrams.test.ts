import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();

/** The open card's diagram: its accessible name, its ring labels, where it sits in the card and whether it fits. */
function diagramFacts(page: Page) {
  return page.evaluate(() => {
    const card = document.querySelector('.oceano-lesson-card') as HTMLElement;
    const figure = card.querySelector<HTMLElement>('.oceano-lesson-diagram');
    if (!figure) return null;
    const svg = figure.querySelector('svg')!;
    const order = Array.from(card.children, (child) => child.className);
    const box = figure.getBoundingClientRect();
    const cardBox = card.getBoundingClientRect();
    return {
      role: svg.getAttribute('role'),
      name: svg.getAttribute('aria-label'),
      texts: Array.from(svg.querySelectorAll('text'), (t) => t.textContent),
      afterMath: order.indexOf('oceano-lesson-diagram') === order.indexOf('oceano-lesson-math') + 1,
      fits: box.left >= cardBox.left - 0.5 && box.right <= cardBox.right + 0.5 && box.height > 60,
    };
  });
}

describe('lesson diagrams in the card', () => {
  // Control: a lesson without one has none.
  it('the LOD bands’ diagram appears after the equations and follows the L slider', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'lesson=lod-bands', 1366, 768);
    await page.waitForSelector('.oceano-lesson-diagram svg[aria-label]');
    const before = await diagramFacts(page);
    expect(before).toMatchObject({ role: 'img', afterMath: true, fits: true });
    expect(before!.name).toContain('first ring at 100 m');
    expect(before!.texts).toContain('1600');
    await page.evaluate(() => {
      const slider = document.querySelector<HTMLInputElement>('.oceano-lesson-card input[data-param="lodDistance"]')!;
      slider.value = '40';
      slider.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.waitForFunction(() => document.querySelector('.oceano-lesson-diagram svg')?.getAttribute('aria-label')?.includes('40 m'));
    const after = await diagramFacts(page);
    expect(after!.name).toContain('first ring at 40 m');
    expect(after!.texts).toContain('640');
    expect(after!.texts).not.toContain('1600');
    expect(await page.evaluate(() => window.oceano.getParams().lodDistance)).toBe(40);
    expect(await page.evaluate(() => window.oceano.setLesson('flat-plane'))).toBe(true);
    await page.waitForFunction(() => (document.querySelector('.oceano-lesson-card') as HTMLElement).dataset.lesson === 'flat-plane');
    expect(await diagramFacts(page)).toBeNull();
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('on a phone in Spanish the stone’s diagram counts the seconds since the stone fell', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'lesson=iwave-stone&lang=es', 390, 844);
    await page.waitForSelector('.oceano-lesson-diagram svg[aria-label]');
    const first = (await diagramFacts(page))!;
    expect(first.name).toMatch(/^Las crestas de la piedra.*t = \d+,\d s$/);
    expect(first.fits).toBe(true);
    // The clock runs: the name's age moves on, and so do the crests.
    await page.waitForFunction(
      (name) => document.querySelector('.oceano-lesson-diagram svg')?.getAttribute('aria-label') !== name,
      {},
      first.name,
    );
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
