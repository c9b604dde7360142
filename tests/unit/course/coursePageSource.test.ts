import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LESSONS, lessonIds } from '../../../src/app/lessons/lessonCatalog';
import { LESSON_TEXTS } from '../../../src/app/lessons/lessonTexts';
import { readLessonQuotes } from '../../../scripts/build/lessonQuotes';
import { lessonViewAttributes } from '../../../src/course/lessonFigure';
import { BIBLIOGRAPHY, firstSurname, type ReferenceKey } from '../../../src/app/lessons/bibliography';
import { GLOSSARY } from '../../../src/app/lessons/glossary';
import { firstTermOccurrences } from '../../../src/app/lessons/glossaryLinks';
import { citation } from '../../../src/app/lessons/referenceLists';
import { citedWorks, glossaryEntries, termAnchor, workAnchor } from '../../../src/course/backMatter';
import { bannedSpanishWords, bibliographyFaults, pageLessonIds, shownLessonFaults, termLinkFaults, type CardSource } from '../../../src/course/coursePageChecks';

const root = resolve(import.meta.dirname, '..', '..', '..');
const html = readFileSync(resolve(root, 'course/index.html'), 'utf8');
const quotes = readLessonQuotes(root);
const citations = (id: string) => (LESSON_TEXTS[id].references ?? []).map((key) => citation(BIBLIOGRAPHY[key]));
const cards = (language: 'es' | 'en'): CardSource => ({ text: (id) => LESSON_TEXTS[id].text[language], code: (id) => quotes[id]?.text ?? null, references: citations });
/** The page's own Spanish prose: its class="es" elements, tags and entities aside. */
const spanishProse = (page: string) => Array.from(page.matchAll(/<(\w+) class="es">([\s\S]*?)<\/\1>/g), (m) => m[2].replace(/<[^>]+>/g, ' ')).join('\n');

describe('the course page (course/index.html)', () => {
  it('names every lesson of the catalog once, and nothing else', () => {
    const ids = pageLessonIds(html);
    expect([...ids].sort()).toEqual([...lessonIds].sort());
    // Control: a page that drops a lesson, or names one twice, does not pass.
    const dropped = pageLessonIds(html.replace('data-lesson="iwave-boat"', 'data-lesson="iwave-stone"'));
    expect([...dropped].sort()).not.toEqual([...lessonIds].sort());
  });

  it('gives each figure its own lesson\'s view, and a figure pointed at another lesson fails the check', () => {
    for (const lesson of LESSONS) {
      const shown = { lesson: lesson.id, text: LESSON_TEXTS[lesson.id].text.es, code: quotes[lesson.id]?.text ?? null, references: citations(lesson.id), attributes: lessonViewAttributes(lesson) };
      expect(shownLessonFaults(shown, cards('es'))).toEqual([]);
      // Control: a caption that drops its last reference, or shows one the card does not cite, is caught.
      const fewer = shown.references.slice(0, -1);
      const more = [...shown.references, citation(BIBLIOGRAPHY.welch1967)];
      for (const references of shown.references.length ? [fewer, more] : [more]) {
        expect(shownLessonFaults({ ...shown, references }, cards('es'))).toEqual([`${lesson.id}: the caption's references are not the card's`]);
      }
    }
    // Control: every figure relabelled with the next lesson's id (its view, text and code left as they were) is caught.
    LESSONS.forEach((lesson, i) => {
      const other = LESSONS[(i + 1) % LESSONS.length];
      const shown = { lesson: other.id, text: LESSON_TEXTS[lesson.id].text.es, code: quotes[lesson.id]?.text ?? null, references: citations(lesson.id), attributes: lessonViewAttributes(lesson) };
      const faults = shownLessonFaults(shown, cards('es'));
      expect(faults.some((f) => f.includes('code') || f.includes('parameters') || f.includes('camera'))).toBe(true);
      expect(faults.some((f) => f.includes('text'))).toBe(true);
    });
  });

  it('writes its own Spanish in one register', () => {
    expect(bannedSpanishWords(spanishProse(html))).toEqual([]);
    // Control: each banned word is found in a sentence, and its right word is not.
    expect(bannedSpanishWords('La grilla del bote, el rolido y las perillas.')).toEqual(['grilla', 'bote', 'rolido', 'perillas']);
    expect(bannedSpanishWords('La malla del barco, el balanceo, los controles y un rebote.')).toEqual([]);
    // The report's own title, quoted, is a citation; the same words unquoted are not.
    expect(bannedSpanishWords('El “Quiero mover el bote” del informe.')).toEqual([]);
    expect(bannedSpanishWords('Quiero mover el bote.')).toEqual(['bote']);
  });

  it('lists in its bibliography every work a card cites, in full, and no other', () => {
    const cited = citedWorks(LESSON_TEXTS);
    for (const card of Object.values(LESSON_TEXTS)) for (const key of card.references ?? []) expect(cited).toContain(key);
    expect(new Set(cited).size).toBe(cited.length);
    // By first author's surname: "K. Hasselmann et al." files under H, not under "al.".
    const surnames = cited.map((key) => firstSurname(BIBLIOGRAPHY[key]));
    expect(surnames).toEqual([...surnames].sort((a, b) => a.localeCompare(b, 'en')));
    expect(firstSurname(BIBLIOGRAPHY.hasselmann1973)).toBe('Hasselmann');
    expect(firstSurname({ ...BIBLIOGRAPHY.hasselmann1973, authors: 'K. Hasselmann' })).toBe('Hasselmann');
    const entries = cited.map((key) => ({ id: workAnchor(key), text: citation(BIBLIOGRAPHY[key]) }));
    expect(bibliographyFaults(entries, cited)).toEqual([]);
    // Controls: a cited work left out, a work no card cites added, a citation cut short, an entry twice.
    expect(bibliographyFaults(entries.slice(1), cited)).toEqual([`${cited[0]}: cited but not in the bibliography`]);
    const uncited = (Object.keys(BIBLIOGRAPHY) as ReferenceKey[]).find((key) => !cited.includes(key));
    if (uncited) expect(bibliographyFaults([...entries, { id: workAnchor(uncited), text: citation(BIBLIOGRAPHY[uncited]) }], cited)).toEqual([`${workAnchor(uncited)}: listed but cited by no card`]);
    expect(bibliographyFaults([{ ...entries[0], text: BIBLIOGRAPHY[cited[0]].title }, ...entries.slice(1)], cited)).toEqual([`${cited[0]}: its entry is not its citation`]);
    expect(bibliographyFaults([...entries, entries[0]], cited)).toContain('an id is listed twice');
  });

  it('links each card text\'s glossary terms to an entry of its glossary, in both languages', () => {
    for (const language of ['es', 'en'] as const) {
      const ids = glossaryEntries(language).map(({ key }) => termAnchor(key));
      expect(new Set(ids).size).toBe(Object.keys(GLOSSARY).length);
      const links = Object.values(LESSON_TEXTS).flatMap((card) =>
        firstTermOccurrences(card.text[language], language, GLOSSARY).map(({ key, start, end }) => ({ href: `#${termAnchor(key)}`, text: card.text[language].slice(start, end) })),
      );
      expect(links.length).toBeGreaterThan(100);
      expect(termLinkFaults(links, ids, language)).toEqual([]);
      // Controls: a link to no entry, a link to another term's entry, and a glossary missing the entry linked to.
      expect(termLinkFaults([{ href: '#term-nonexistent', text: 'vertex' }], ids, language)).toContain('#term-nonexistent: no glossary entry');
      const [first, second] = links.filter((link, i) => links.findIndex((l) => l.href === link.href) === i);
      expect(termLinkFaults([{ href: second.href, text: first.text }], ids, language)).toEqual([`${second.href}: "${first.text}" is not that term`]);
      expect(termLinkFaults([first], ids.filter((id) => `#${id}` !== first.href), language)).toEqual([`${first.href}: no glossary entry`]);
    }
  });
});
