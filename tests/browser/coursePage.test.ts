import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { useHarness } from './useHarness';
import { recordedPage } from './pages';
import { ensurePosters } from './distPosters';
import { lessonIds } from '../../src/app/lessons/lessonCatalog';
import { LESSON_TEXTS } from '../../src/app/lessons/lessonTexts';
import { readLessonQuotes } from '../../scripts/build/lessonQuotes';
import { BIBLIOGRAPHY } from '../../src/app/lessons/bibliography';
import { citation } from '../../src/app/lessons/referenceLists';
import { citedWorks, glossaryEntries } from '../../src/course/backMatter';
import {
  bannedSpanishWords,
  bibliographyFaults,
  shownLessonFaults,
  termLinkFaults,
  unresolvedLinks,
  type CardSource,
  type ListedEntry,
  type ShownLesson,
} from '../../src/course/coursePageChecks';

const harness = useHarness();
const quotes = readLessonQuotes(join(import.meta.dirname, '..', '..'));
const citations = (id: string) => (LESSON_TEXTS[id].references ?? []).map((key) => citation(BIBLIOGRAPHY[key]));
const cards = (language: 'es' | 'en'): CardSource => ({
  text: (id) => LESSON_TEXTS[id].text[language],
  code: (id) => quotes[id]?.text ?? null,
  references: citations,
});

/** Every figure and card as the page shows it, once its captions are written. */
async function shownLessons(page: Page): Promise<ShownLesson[]> {
  await page.waitForFunction(() => document.documentElement.dataset.captions === 'written');
  return page.evaluate(() =>
    Array.from(document.querySelectorAll<HTMLElement>('[data-lesson]'), (holder) => {
      const view = holder.querySelector('oceano-view');
      return {
        lesson: holder.dataset.lesson!,
        text: holder.querySelector('.lesson-text')?.textContent ?? '',
        code: holder.querySelector('.code-quote code')?.textContent ?? null,
        references: Array.from(holder.querySelectorAll('.lesson-references li'), (li) => li.textContent ?? ''),
        attributes: view
          ? view
              .getAttributeNames()
              .filter((n) => !['lang', 'poster', 'alt', 'class', 'style'].includes(n))
              .map((n): [string, string] => [n, view.getAttribute(n)!])
          : null,
      };
    }),
  );
}

/** The page's bibliography and glossary, and the captions' links into them. */
async function backMatter(page: Page) {
  return page.evaluate(() => {
    const entries = (selector: string) => Array.from(document.querySelectorAll(selector), (e) => ({ id: e.id, text: e.textContent ?? '' }));
    return {
      bibliography: entries('.bibliography li') as ListedEntry[],
      glossary: entries('.glossary dt') as ListedEntry[],
      definitions: Array.from(document.querySelectorAll('.glossary dd'), (dd) => dd.textContent),
      referenceLinks: Array.from(document.querySelectorAll('.lesson-references a'), (a) => a.getAttribute('href') ?? ''),
      termLinks: Array.from(document.querySelectorAll('.lesson-text a.glossary-term'), (a) => ({
        href: a.getAttribute('href') ?? '',
        text: a.textContent ?? '',
      })),
    };
  });
}

/** Every way the page's back matter and its links fail, in `language`. */
function backMatterFaults(matter: Awaited<ReturnType<typeof backMatter>>, language: 'es' | 'en'): string[] {
  const glossary = glossaryEntries(language);
  return [
    ...bibliographyFaults(matter.bibliography, citedWorks(LESSON_TEXTS)),
    ...unresolvedLinks(
      matter.referenceLinks,
      matter.bibliography.map((entry) => entry.id),
    ).map((href) => `${href}: no bibliography entry`),
    ...termLinkFaults(
      matter.termLinks,
      matter.glossary.map((entry) => entry.id),
      language,
    ),
    ...(JSON.stringify(matter.glossary.map((entry) => entry.text)) === JSON.stringify(glossary.map((entry) => entry.headword))
      ? []
      : ["the glossary's headwords are not the terms in the page's language"]),
    ...(JSON.stringify(matter.definitions) === JSON.stringify(glossary.map((entry) => entry.term.definition[language]))
      ? []
      : ["the glossary's definitions are not the terms' in the page's language"]),
  ];
}

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

/** Records every figure's error event from before the page's scripts run. */
async function recordFigureErrors(page: Page): Promise<void> {
  await page.evaluateOnNewDocument(() => {
    const errors: unknown[] = [];
    (window as unknown as { __figureErrors: unknown[] }).__figureErrors = errors;
    document.addEventListener(
      'error',
      (event) => {
        if ((event.target as Element).localName === 'oceano-view') errors.push((event as unknown as CustomEvent).detail);
      },
      true,
    );
  });
}

/** Waits until every figure on screen has started and drawn. */
async function visibleFiguresReady(page: Page): Promise<number> {
  const onScreen = `Array.from(document.querySelectorAll('oceano-view')).filter((view) => {
    const box = view.getBoundingClientRect();
    return box.bottom > 0 && box.top < innerHeight;
  })`;
  await page.waitForFunction(`${onScreen}.every((view) => view.oceano !== null)`);
  return page.evaluate(`Promise.all(${onScreen}.map((view) => view.oceano.ready)).then((all) => all.length)`) as Promise<number>;
}

describe('the course page (dist/course/)', () => {
  // Its figures point at the build's posters.
  beforeAll(() => ensurePosters(harness), 600_000);

  // The seed report made live: every figure starts as it is scrolled to.
  it('starts every figure as it is scrolled to, with no lost context, notice or page error', async () => {
    const { page, consoleErrors, violations } = await recordedPage(harness, 800, 700);
    // Figures open paused under reduced motion: the page is scrolled, not watched.
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
    await recordFigureErrors(page);
    await page.goto(`${harness.baseUrl}course/index.html?lang=es`, { waitUntil: 'load' });
    const outline = await page.evaluate(() => ({
      figures: document.querySelectorAll('oceano-view').length,
      sections: Array.from(document.querySelectorAll('main section h2 .es'), (h) => h.textContent),
      lang: document.documentElement.lang,
      figureLanguages: new Set(Array.from(document.querySelectorAll('oceano-view'), (v) => v.getAttribute('lang'))).size,
      englishShown: Array.from(document.querySelectorAll('.en')).some((e) => (e as HTMLElement).offsetParent !== null),
    }));
    expect(outline.figures).toBe(23);
    expect(outline.sections.slice(0, 10)).toEqual([
      'Superficie del agua',
      'Movimiento',
      'Ruido de valor (el «Perlin» del informe)',
      'Normales',
      'Environment map',
      'Óptica: Snell y Fresnel',
      'CPU shader: mover el barco',
      'Bajo el agua',
      'Optimización: niveles de detalle',
      'Frustum culling',
    ]);
    expect(outline.lang).toBe('es');
    expect(outline.figureLanguages).toBe(1);
    expect(outline.englishShown).toBe(false);

    // Every lesson of the catalog, as a figure or a card; each shows its own card's words and code, and a figure its lesson's view.
    const shown = await shownLessons(page);
    expect(shown.map((s) => s.lesson).sort()).toEqual([...lessonIds].sort());
    expect(shown.filter((s) => s.attributes).length).toBe(outline.figures);
    expect(shown.flatMap((s) => shownLessonFaults(s, cards('es')))).toEqual([]);
    // Control: each one read as if it named the next lesson is caught.
    for (let i = 0; i < shown.length; i++)
      expect(shownLessonFaults({ ...shown[i], lesson: shown[(i + 1) % shown.length].lesson }, cards('es'))).not.toEqual([]);
    // Every card's references in its caption (shownLessonFaults), every cited work in the bibliography, every link landing on an entry.
    const matter = await backMatter(page);
    expect(matter.referenceLinks.length).toBe(Object.values(LESSON_TEXTS).reduce((n, card) => n + (card.references?.length ?? 0), 0));
    expect(matter.termLinks.length).toBeGreaterThan(lessonIds.length);
    expect(backMatterFaults(matter, 'es')).toEqual([]);
    // One Spanish register, cards included.
    expect(bannedSpanishWords(await page.evaluate(() => document.body.innerText))).toEqual([]);
    const links = await page.evaluate(() => Array.from(document.querySelectorAll<HTMLAnchorElement>('a.open-in-app'), (a) => a.search));
    expect(links.length).toBe(lessonIds.length);
    expect(links.every((link) => /^\?lesson=[a-z-]+&lang=es$/.test(link))).toBe(true);

    // The figures far below, not started, show their posters: the build's picture of their preset.
    await page.waitForFunction(() =>
      Array.from(document.querySelectorAll<HTMLImageElement>('img.oceano-poster')).every((img) => img.complete),
    );
    const posters = await page.evaluate(() => ({
      withPoster: document.querySelectorAll('oceano-view[poster]').length,
      shown: Array.from(document.querySelectorAll<HTMLImageElement>('img.oceano-poster')).filter((img) => img.naturalWidth === 320).length,
      waiting: (Array.from(document.querySelectorAll('oceano-view[poster]')) as ViewElement[]).filter((view) => view.oceano === null)
        .length,
    }));
    expect(posters.withPoster).toBe(outline.figures);
    expect(posters.waiting).toBeGreaterThan(10);
    expect(posters.shown).toBeGreaterThanOrEqual(posters.waiting);

    // The physics panel's figure measures the sea (seconds of the page's one thread) only once it is seen, not while it
    // starts below: scrolled to just above it, it starts (figures start half a screen ahead) and measures nothing.
    await page.evaluate(() => {
      const box = document.querySelector('[data-lesson="physics-panel"] oceano-view')!.getBoundingClientRect();
      window.scrollTo(0, scrollY + box.top - innerHeight - 60);
    });
    await page.waitForFunction(() => (document.querySelector('[data-lesson="physics-panel"] oceano-view') as ViewElement).oceano !== null, {
      timeout: 120_000,
    });
    await new Promise((resolve) => setTimeout(resolve, 1500));
    expect(await page.evaluate(() => document.querySelectorAll('[data-lesson="physics-panel"] .oceano-physics .uplot').length)).toBe(0);
    await page.evaluate(() => window.scrollTo(0, 0));

    const started = new Set<number>();
    const panelStates: { live: boolean; onScreen: boolean; measured: number }[] = [];
    const bottom = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    for (let y = 0; ; y = Math.min(y + 700, bottom)) {
      await page.evaluate((top) => window.scrollTo(0, top), y);
      await visibleFiguresReady(page);
      const panel = await page.evaluate(() => {
        const view = document.querySelector('[data-lesson="physics-panel"] oceano-view') as ViewElement;
        const box = view.getBoundingClientRect();
        return {
          live: view.oceano !== null,
          onScreen: box.bottom > 0 && box.top < innerHeight,
          measured: view.querySelectorAll('.oceano-physics .uplot').length,
        };
      });
      if (panel.onScreen) {
        // Control: the same count sees the measurement once the figure is on screen.
        await page.waitForFunction(() => document.querySelectorAll('[data-lesson="physics-panel"] .oceano-physics .uplot').length === 2, {
          timeout: 120_000,
        });
      }
      panelStates.push(panel);
      const live = await page.evaluate(() =>
        (Array.from(document.querySelectorAll('oceano-view')) as ViewElement[]).flatMap((view, i) => (view.oceano ? [i] : [])),
      );
      for (const i of live) started.add(i);
      expect(await page.evaluate(() => document.querySelectorAll('oceano-view .oceano-notice').length)).toBe(0);
      if (y === bottom) break;
    }
    expect(started.size).toBe(outline.figures);
    // However far ahead it started, it had measured nothing before it was seen.
    const beforeSeen = panelStates.slice(
      0,
      panelStates.findIndex((state) => state.onScreen),
    );
    expect(beforeSeen.map((state) => state.measured)).toEqual(beforeSeen.map(() => 0));
    expect(await page.evaluate(() => (window as unknown as { __figureErrors: unknown[] }).__figureErrors)).toEqual([]);
    expect(consoleErrors).toEqual([]);
    expect(violations).toEqual([]);
    await page.close();
  }, 400_000);

  it("is linked from the app, after its lessons, in the reader's language", async () => {
    const { page, consoleErrors } = await recordedPage(harness, 1366, 768);
    await page.goto(`${harness.baseUrl}index.html?lang=es`, { waitUntil: 'load' });
    const link = await page.waitForSelector('a.oceano-lessons-course');
    // After every lesson of the list (the bibliography and glossary buttons may follow it).
    const { href, text, afterLessons } = await link!.evaluate((a) => ({
      href: (a as HTMLAnchorElement).href,
      text: a.textContent,
      afterLessons: Array.from(a.closest('ol')!.querySelectorAll('[data-lesson]')).every(
        (lesson) => lesson.compareDocumentPosition(a) & Node.DOCUMENT_POSITION_FOLLOWING,
      ),
    }));
    expect(afterLessons).toBe(true);
    expect(text).toMatch(/^La página del curso/);
    expect(href).toBe(`${harness.baseUrl}course/index.html?lang=es`);
    await Promise.all([page.waitForNavigation(), link!.click()]);
    expect(await page.evaluate(() => document.querySelectorAll('oceano-view').length)).toBe(23);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('speaks English when asked, figures included', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 800, 700);
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
    await page.goto(`${harness.baseUrl}course/index.html?lang=en`, { waitUntil: 'load' });
    // The first figure may lie just below the first screen, within starting distance.
    await page.waitForFunction(() => (document.querySelector('oceano-view') as ViewElement).oceano !== null);
    await page.evaluate(() => (document.querySelector('oceano-view') as ViewElement).oceano!.ready);
    const facts = await page.evaluate(() => ({
      title:
        (document.querySelector('h1 .en') as HTMLElement).offsetParent !== null &&
        (document.querySelector('h1 .es') as HTMLElement).offsetParent === null,
      label: document.querySelector('oceano-view canvas.oceano-canvas')!.getAttribute('aria-label'),
      link: (document.querySelector('a.open-in-app') as HTMLAnchorElement).search,
    }));
    expect(facts).toEqual({ title: true, label: 'A flat grid of vertices', link: '?lesson=flat-plane&lang=en' });
    // The captions are the cards' English words.
    const shown = await shownLessons(page);
    expect(shown.flatMap((s) => shownLessonFaults(s, cards('en')))).toEqual([]);
    // Control: held to the Spanish cards, every one fails.
    expect(shown.every((s) => shownLessonFaults(s, cards('es')).length > 0)).toBe(true);
    // The bibliography, the English glossary, and the captions' links into them.
    const matter = await backMatter(page);
    expect(matter.termLinks.length).toBeGreaterThan(lessonIds.length);
    expect(backMatterFaults(matter, 'en')).toEqual([]);
    // Controls: held to Spanish the glossary fails; an entry that loses its id strands the links to it.
    expect(backMatterFaults(matter, 'es')).not.toEqual([]);
    const [reference, term] = [matter.referenceLinks[0], matter.termLinks[0].href];
    await page.evaluate(
      (ids) => ids.forEach((id) => document.getElementById(id)!.removeAttribute('id')),
      [reference.slice(1), term.slice(1)],
    );
    const broken = backMatterFaults(await backMatter(page), 'en');
    expect(broken).toContain(`${reference}: no bibliography entry`);
    expect(broken).toContain(`${term}: no glossary entry`);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
