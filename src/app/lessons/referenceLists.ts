import type { Translator } from '../language/i18n';
import { teachingWord } from '../language/teachingWords';
import { BIBLIOGRAPHY, bySurnameAndYear, type Reference, type ReferenceKey } from './bibliography';
import { GLOSSARY, type GlossaryTerm } from './glossary';

/** A work in full, as a reference list writes it: authors (year). Title. Where. */
export function citation(reference: Reference): string {
  return `${reference.authors} (${reference.year}). ${reference.title}. ${reference.where}.`;
}

function list(className: string, keys: readonly ReferenceKey[]): HTMLOListElement {
  const ol = document.createElement('ol');
  ol.className = className;
  for (const key of keys) {
    const li = document.createElement('li');
    li.textContent = citation(BIBLIOGRAPHY[key]);
    li.dataset.reference = key;
    ol.append(li);
  }
  return ol;
}

/** The card's References fold: folded at first, its works in full when opened. */
export function referencesFold(tr: Translator, keys: readonly ReferenceKey[]): HTMLDetailsElement {
  const details = document.createElement('details');
  details.className = 'oceano-lesson-references';
  const summary = document.createElement('summary');
  summary.textContent = teachingWord(tr, 'lessonReferences');
  details.append(summary, list('oceano-lesson-reference-list', keys));
  return details;
}

/** Every work the lessons cite, by first author's surname and year. */
export function bibliographyList(): HTMLOListElement {
  return list('oceano-bibliography-list', bySurnameAndYear(Object.keys(BIBLIOGRAPHY) as ReferenceKey[]));
}

/** Every glossary term with its definition, in the page's language and its alphabetical order. */
export function glossaryList(tr: Translator): HTMLDListElement {
  const language = tr.language;
  const headword = (term: GlossaryTerm) => term.words[language][0];
  const terms = (Object.entries(GLOSSARY) as [string, GlossaryTerm][]).sort(([, a], [, b]) =>
    headword(a).localeCompare(headword(b), language, { sensitivity: 'base' }),
  );
  const dl = document.createElement('dl');
  dl.className = 'oceano-glossary-list';
  for (const [key, term] of terms) {
    const dt = document.createElement('dt');
    dt.textContent = headword(term);
    dt.dataset.term = key;
    const dd = document.createElement('dd');
    dd.textContent = term.definition[language];
    dl.append(dt, dd);
  }
  return dl;
}
