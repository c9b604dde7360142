import type { Plugin } from 'vite';
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { LESSON_QUOTE_SOURCES } from '../../src/app/lessons/lessonQuoteSources';
import { extractQuote, type Quote } from '../../src/app/lessons/quoteExtraction';

/** What the lesson cards import their code quotes from (src/app/lessons/lessonQuotes.d.ts types it). */
export const LESSON_QUOTES_MODULE = 'virtual:oceano-lesson-quotes';
const RESOLVED = `\0${LESSON_QUOTES_MODULE}`;

/** Every lesson's quote, read now from the files under `root`; throws on a marker that no longer fits its file. */
export function readLessonQuotes(root: string): Record<string, Quote> {
  const quotes: Record<string, Quote> = {};
  for (const [id, source] of Object.entries(LESSON_QUOTE_SOURCES))
    quotes[id] = extractQuote(readFileSync(resolve(root, source.file), 'utf8'), source);
  return quotes;
}

/**
 * The lesson cards' code, extracted from the source files when the bundle is built (and on
 * every dev-server load, watching those files), so what a card quotes is what runs.
 */
export function lessonQuotes(root = process.cwd()): Plugin {
  return {
    name: 'oceano-lesson-quotes',
    resolveId: (id) => (id === LESSON_QUOTES_MODULE ? RESOLVED : null),
    load(id) {
      if (id !== RESOLVED) return null;
      for (const source of Object.values(LESSON_QUOTE_SOURCES)) this.addWatchFile(resolve(root, source.file));
      return `export const LESSON_QUOTES = ${JSON.stringify(readLessonQuotes(root))};`;
    },
  };
}
