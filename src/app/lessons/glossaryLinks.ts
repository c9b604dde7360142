import type { Language } from '../language/i18n';
import type { GlossaryTerm } from './glossary';

/** Where a glossary term occurs in a text: [start, end) in UTF-16 units. */
export interface TermOccurrence {
  key: string;
  start: number;
  end: number;
}

const escaped = (form: string) => form.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** A form as a whole word (no letter or digit touching either end), in any case. */
function formPattern(form: string): RegExp {
  return new RegExp(`(?<![\\p{L}\\p{N}])${escaped(form)}(?![\\p{L}\\p{N}])`, 'giu');
}

/**
 * The first occurrence of each term in `text`, in reading order, none overlapping another:
 * where two forms start at one place the longer wins ("Kelvin wake" over "wake"), and a term
 * whose first occurrence sits inside a longer one's is linked at its next free occurrence.
 */
export function firstTermOccurrences(text: string, language: Language, glossary: Record<string, GlossaryTerm>): TermOccurrence[] {
  const all: TermOccurrence[] = [];
  for (const [key, term] of Object.entries(glossary)) {
    const elsewhere = (term.otherSenses?.[language] ?? []).flatMap((phrase) =>
      [...text.matchAll(formPattern(phrase))].map((m) => [m.index, m.index + m[0].length]),
    );
    for (const form of term.words[language]) {
      for (const match of text.matchAll(formPattern(form))) {
        const [start, end] = [match.index, match.index + match[0].length];
        if (!elsewhere.some(([from, to]) => start >= from && end <= to)) all.push({ key, start, end });
      }
    }
  }
  all.sort((a, b) => a.start - b.start || b.end - a.end);
  const linked = new Set<string>();
  const chosen: TermOccurrence[] = [];
  let free = 0;
  for (const occurrence of all) {
    if (linked.has(occurrence.key) || occurrence.start < free) continue;
    // A shorter match starting inside an accepted one is skipped; a longer one at the same start came first.
    chosen.push(occurrence);
    linked.add(occurrence.key);
    free = occurrence.end;
  }
  return chosen;
}

/** The terms that occur in none of `texts` (a glossary of the cards should have none). */
export function termsMissingFrom(texts: string[], language: Language, glossary: Record<string, GlossaryTerm>): string[] {
  const found = new Set(texts.flatMap((text) => firstTermOccurrences(text, language, glossary).map((o) => o.key)));
  return Object.keys(glossary).filter((key) => !found.has(key));
}

/** Word forms that two terms (or one term twice) claim in one language, ignoring case: a link could go to either. */
export function sharedWordForms(glossary: Record<string, GlossaryTerm>): string[] {
  const shared: string[] = [];
  for (const language of ['en', 'es'] as const) {
    const seen = new Set<string>();
    for (const term of Object.values(glossary)) {
      for (const form of term.words[language]) {
        const folded = form.toLocaleLowerCase(language);
        if (seen.has(folded)) shared.push(`${language}: ${form}`);
        seen.add(folded);
      }
    }
  }
  return shared;
}
