import { describe, expect, it } from 'vitest';
import { BIBLIOGRAPHY, bySurnameAndYear, firstSurname, type Reference, type ReferenceKey } from '../../../../src/app/lessons/bibliography';
import { LESSON_TEXTS, type LessonText } from '../../../../src/app/lessons/lessonTexts';
import { citation } from '../../../../src/app/lessons/referenceLists';

/** The keys the cards cite that the bibliography lacks, as "lesson: key". */
function unknownReferences(texts: Record<string, Pick<LessonText, 'references'>>, bibliography: Record<string, Reference>): string[] {
  return Object.entries(texts).flatMap(([id, card]) =>
    (card.references ?? []).filter((key) => !(key in bibliography)).map((key) => `${id}: ${key}`),
  );
}

/** The entries that miss a field, or give a year no printed work could have. */
function incompleteEntries(bibliography: Record<string, Reference>): string[] {
  const thisYear = new Date().getFullYear();
  return Object.entries(bibliography)
    .filter(
      ([, r]) =>
        [r.authors, r.title, r.where].some((field) => typeof field !== 'string' || field.trim().length < 2) ||
        !Number.isInteger(r.year) ||
        r.year < 1600 ||
        r.year > thisYear,
    )
    .map(([key]) => key);
}

describe('the bibliography', () => {
  it('has every work a card cites (control: a card citing an unknown key is reported)', () => {
    expect(unknownReferences(LESSON_TEXTS, BIBLIOGRAPHY)).toEqual([]);
    const planted = { ...LESSON_TEXTS, planted: { references: ['tessendorf2001', 'nobody1999'] } } as Record<
      string,
      Pick<LessonText, 'references'>
    >;
    expect(unknownReferences(planted, BIBLIOGRAPHY)).toEqual(['planted: nobody1999']);
  });

  // Control: an entry without a title, one with no year.
  it('gives every entry its authors, year, title and where it appeared', () => {
    expect(incompleteEntries(BIBLIOGRAPHY)).toEqual([]);
    const planted: Record<string, Reference> = {
      ...BIBLIOGRAPHY,
      untitled: { ...BIBLIOGRAPHY.tessendorf2001, title: '' },
      undated: { ...BIBLIOGRAPHY.tessendorf2001, year: Number.NaN },
    };
    expect(incompleteEntries(planted)).toEqual(['untitled', 'undated']);
  });

  it('cites a work in full: authors, year, title, where', () => {
    expect(citation(BIBLIOGRAPHY.coxMunk1954)).toBe(
      'C. Cox, W. Munk (1954). Measurement of the roughness of the sea surface from photographs of the sun’s glitter. Journal of the Optical Society of America 44(11), 838–850.',
    );
    for (const reference of Object.values(BIBLIOGRAPHY)) {
      const text = citation(reference);
      for (const part of [reference.authors, String(reference.year), reference.title, reference.where]) expect(text).toContain(part);
    }
  });

  // The drawer's bibliography and the course page's both list in this order.
  it('lists works by first author\'s surname, "et al." aside, then by year', () => {
    const all = Object.keys(BIBLIOGRAPHY) as ReferenceKey[];
    const ordered = bySurnameAndYear(all);
    expect([...ordered].sort()).toEqual([...all].sort());
    const surnames = ordered.map((key) => firstSurname(BIBLIOGRAPHY[key]));
    expect(surnames).toEqual([...surnames].sort((a, b) => a.localeCompare(b, 'en')));
    // "K. Hasselmann et al." (1973) files under H, just before D. E. Hasselmann (1980), not under "al.".
    expect(firstSurname(BIBLIOGRAPHY.hasselmann1973)).toBe('Hasselmann');
    expect(ordered.indexOf('hasselmann1980') - ordered.indexOf('hasselmann1973')).toBe(1);
    expect(firstSurname({ ...BIBLIOGRAPHY.hasselmann1973, authors: 'K. Hasselmann' })).toBe('Hasselmann');
    // Control: the last word of the first name, as the drawer once read it, gives "al." and files the work near the top.
    const lastWord = (reference: Reference) => reference.authors.split(',')[0].split(' ').at(-1);
    expect(lastWord(BIBLIOGRAPHY.hasselmann1973)).toBe('al.');
    const byLastWord = [...all].sort(
      (a, b) => lastWord(BIBLIOGRAPHY[a])!.localeCompare(lastWord(BIBLIOGRAPHY[b])!, 'en') || BIBLIOGRAPHY[a].year - BIBLIOGRAPHY[b].year,
    );
    expect(byLastWord.indexOf('hasselmann1973')).toBeLessThan(ordered.indexOf('hasselmann1973') - 5);
    // Control: a list with that work moved to its "al." place is not in surname order.
    const misfiled: ReferenceKey[] = ordered.filter((key) => key !== 'hasselmann1973');
    misfiled.splice(byLastWord.indexOf('hasselmann1973'), 0, 'hasselmann1973');
    const misfiledSurnames = misfiled.map((key) => firstSurname(BIBLIOGRAPHY[key]));
    expect(misfiledSurnames).not.toEqual([...misfiledSurnames].sort((a, b) => a.localeCompare(b, 'en')));
  });
});
