import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LESSON_QUOTE_SOURCES } from '../../../../src/app/lessons/lessonQuoteSources';
import { extractQuote, MAX_QUOTE_LINES, MIN_QUOTE_LINES, quoteMatchesFile, type Quote } from '../../../../src/app/lessons/quoteExtraction';
import { lessonQuotes, readLessonQuotes } from '../../../../scripts/build/lessonQuotes';

const root = resolve(import.meta.dirname, '..', '..', '..', '..');
const fileText = (file: string) => readFileSync(resolve(root, file), 'utf8');

describe('lesson code quotes', () => {
  const quotes = readLessonQuotes(root);

  it.each(Object.keys(LESSON_QUOTE_SOURCES))('%s quotes its file line for line', (id) => {
    const quote = quotes[id];
    const lines = quote.lastLine - quote.firstLine + 1;
    expect(lines).toBeGreaterThanOrEqual(MIN_QUOTE_LINES);
    expect(lines).toBeLessThanOrEqual(MAX_QUOTE_LINES);
    expect(quote.file).toBe(LESSON_QUOTE_SOURCES[id].file);
    expect(quoteMatchesFile(quote, fileText(quote.file))).toBe(true);
    // The markers are where the quote begins and ends.
    expect(quote.text.split('\n')[0]).toContain(LESSON_QUOTE_SOURCES[id].from);
    expect(quote.text.split('\n').at(-1)).toContain(LESSON_QUOTE_SOURCES[id].to);
  });

  it('the build plugin serves exactly these quotes', async () => {
    const plugin = lessonQuotes(root);
    const resolveId = plugin.resolveId as (id: string) => string | null;
    const load = plugin.load as (this: { addWatchFile(file: string): void }, id: string) => string | null;
    const id = resolveId('virtual:oceano-lesson-quotes')!;
    const watched: string[] = [];
    const code = load.call({ addWatchFile: (file) => watched.push(file) }, id)!;
    const served = JSON.parse(code.replace(/^export const LESSON_QUOTES = /, '').replace(/;$/, '')) as Record<string, Quote>;
    expect(served).toEqual(quotes);
    expect(new Set(watched)).toEqual(new Set(Object.values(LESSON_QUOTE_SOURCES).map((s) => resolve(root, s.file))));
  });

  // A bad marker: ambiguous or missing.
  it('negative controls: a changed character, a shifted range, a bad marker, an overlong quote all fail', () => {
    const quote = quotes.swell;
    const text = fileText(quote.file);
    expect(quoteMatchesFile({ ...quote, text: quote.text.replace('uSwellAmplitude', 'uSwellAmplitudes') }, text)).toBe(false);
    expect(quoteMatchesFile({ ...quote, firstLine: quote.firstLine + 1, lastLine: quote.lastLine + 1 }, text)).toBe(false);
    expect(quoteMatchesFile({ ...quote, lastLine: text.split('\n').length + 1 }, text)).toBe(false);
    expect(() => extractQuote(text, { file: quote.file, from: 'uniform float', to: ';' })).toThrow(/exactly one/);
    expect(() => extractQuote(text, { file: quote.file, from: 'float swellHeight(vec2 p) {', to: 'no such line' })).toThrow(/end marker/);
    expect(() =>
      extractQuote(text, { file: quote.file, from: 'float swellHeight(vec2 p) {', to: 'return swellHeight(p) + rippleHeight(p);' }),
    ).toThrow(/lines/);
  });
});
