/**
 * Where a lesson's code quote lies in a source file: from the first line that contains
 * `from` (which must occur on exactly one line) through the first line at or after it that
 * contains `to`. Markers rather than line numbers, so a quote follows its code when lines
 * are added above it, and the build fails when the code itself is rewritten.
 */
export interface QuoteSource {
  /** Path from the repository root, e.g. shaders/waves/seed.glsl. */
  file: string;
  from: string;
  to: string;
}

/** A quote as the lesson card shows it: the file, its 1-based inclusive line range, and those lines. */
export interface Quote {
  file: string;
  firstLine: number;
  lastLine: number;
  text: string;
}

/** The longest quote a card shows: a few lines a student reads beside the picture. */
export const MAX_QUOTE_LINES = 15;
export const MIN_QUOTE_LINES = 3;

/** The quoted lines of `fileText`; throws, naming the file and marker, when they cannot be found unambiguously. */
export function extractQuote(fileText: string, source: QuoteSource): Quote {
  const lines = fileText.split(/\r?\n/);
  const starts = lines.flatMap((line, i) => (line.includes(source.from) ? [i] : []));
  if (starts.length !== 1)
    throw new Error(`${source.file}: the start marker "${source.from}" occurs on ${starts.length} lines, not exactly one.`);
  const first = starts[0];
  let last = first;
  while (last < lines.length && !lines[last].includes(source.to)) last++;
  if (last === lines.length) throw new Error(`${source.file}: no line after "${source.from}" contains the end marker "${source.to}".`);
  const count = last - first + 1;
  if (count < MIN_QUOTE_LINES || count > MAX_QUOTE_LINES) {
    throw new Error(
      `${source.file}: the quote from "${source.from}" to "${source.to}" has ${count} lines; a card shows ${MIN_QUOTE_LINES} to ${MAX_QUOTE_LINES}.`,
    );
  }
  return { file: source.file, firstLine: first + 1, lastLine: last + 1, text: lines.slice(first, last + 1).join('\n') };
}

/** Whether `quote` is, character for character, lines firstLine..lastLine of `fileText`. */
export function quoteMatchesFile(quote: Quote, fileText: string): boolean {
  const lines = fileText.split(/\r?\n/);
  if (quote.firstLine < 1 || quote.lastLine > lines.length || quote.firstLine > quote.lastLine) return false;
  return lines.slice(quote.firstLine - 1, quote.lastLine).join('\n') === quote.text;
}
