import { describe, expect, it } from 'vitest';
import { LESSONS } from '../../../src/app/lessons/lessonCatalog';
import { PRESETS } from '../../../src/app/url/presets';
import {
  docFiles,
  historyMarks,
  lineCount,
  MAX_DOC_LINES,
  missingPaths,
  overlongDocs,
  readRepoFile,
  statedCounts,
} from '../../support/docChecks';
import { readingPathMarkdown, READING_PATH_DOC } from '../../../scripts/build/readingPath';

const DOCS = Object.fromEntries(docFiles().map((path) => [path, readRepoFile(path)]));
const README = DOCS['README.md'];

/** Docs allowed past MAX_DOC_LINES, each with the reason: none; a doc that grows past it is split by concept. */
const KNOWN_OVERLONG_DOCS: readonly string[] = [];

/** Paths cited by docs that other work is rewriting now; this list is to be left empty. */
const KNOWN_MISSING_PATHS: readonly string[] = [];

describe('docs cite files that exist', () => {
  it('every path cited in README.md and docs/ is in the tree', () => {
    const missing = Object.entries(DOCS).flatMap(([path, text]) => missingPaths(text, path));
    expect(missing.filter((entry) => !KNOWN_MISSING_PATHS.includes(entry))).toEqual([]);
  });

  it('reports a planted missing path, a bad relative link and an unmatched glob (negative control)', () => {
    const planted =
      'See `src/sim/optics/waterColour.ts`, [the tools](tool.md) and `shaders/nothing*.glsl`; `src/sim/optics/waterColor.ts` exists.';
    expect(missingPaths(planted, 'docs/planted.md')).toEqual([
      'docs/planted.md: src/sim/optics/waterColour.ts',
      'docs/planted.md: shaders/nothing*.glsl',
      'docs/planted.md: tool.md',
    ]);
  });
});

describe('docs stay short enough to read', () => {
  it(`no doc is longer than ${MAX_DOC_LINES} lines, but for the known exceptions`, () => {
    const overlong = overlongDocs(DOCS).map((entry) => entry.slice(0, entry.indexOf(':')));
    expect(overlong.filter((path) => !KNOWN_OVERLONG_DOCS.includes(path))).toEqual([]);
  });

  it('every known exception is still over the limit, so the list empties as docs are split', () => {
    for (const path of KNOWN_OVERLONG_DOCS) expect(lineCount(DOCS[path])).toBeGreaterThan(MAX_DOC_LINES);
  });

  it('flags a doc one line over the limit (negative control)', () => {
    const long = 'line\n'.repeat(MAX_DOC_LINES + 1);
    expect(overlongDocs({ 'docs/long.md': long, 'docs/short.md': 'line\n'.repeat(MAX_DOC_LINES) })).toEqual([
      `docs/long.md: ${MAX_DOC_LINES + 1}`,
    ]);
  });
});

/** The one commit a doc may name: the baseline the FFT view's cost budget is defined against. */
const BASELINE_COMMIT = '65d506c';

/** Docs that still carry history, each to be cleaned by the work that owns it; this list is to be left empty. */
const KNOWN_DOCS_WITH_HISTORY: readonly string[] = [];

describe('docs carry no history', () => {
  it(`no doc names a commit other than the baseline ${BASELINE_COMMIT}, or a date`, () => {
    const marks = Object.entries(DOCS)
      .filter(([path]) => !KNOWN_DOCS_WITH_HISTORY.includes(path))
      .flatMap(([path, text]) => historyMarks(text, path, [BASELINE_COMMIT]));
    expect(marks).toEqual([]);
  });

  it('every doc allowed history still has some, so the list empties as docs are cleaned', () => {
    for (const path of KNOWN_DOCS_WITH_HISTORY) expect(historyMarks(DOCS[path], path, [BASELINE_COMMIT]).length).toBeGreaterThan(0);
  });

  it('reports a planted commit and dates, and passes the baseline, numbers and words (negative control)', () => {
    const planted = `Measured at b5bed51 on 2026-11-27 and again on 26 Nov 2026 against ${BASELINE_COMMIT}; seed 2147483647, a decade, #06283a.`;
    expect(historyMarks(planted, 'docs/planted.md', [BASELINE_COMMIT])).toEqual([
      'docs/planted.md: b5bed51',
      'docs/planted.md: 2026-11-27',
      'docs/planted.md: 26 Nov 2026',
    ]);
    expect(historyMarks(planted, 'docs/planted.md', [])).toContain(`docs/planted.md: ${BASELINE_COMMIT}`);
  });
});

describe("the README's counts are the code's", () => {
  const courseFigures = (readRepoFile('course/index.html').match(/<figure data-lesson=/g) ?? []).length;
  const presetRows = (text: string) => (text.match(/^\| `[a-z-]+` \|.*<img /gm) ?? []).length;
  const exampleLines = lineCount(readRepoFile('examples/threejs-scene.html'));

  it('the lessons, presets, course figures and the example page are counted as they are', () => {
    expect(statedCounts(README, 'lessons').length).toBeGreaterThan(0);
    expect(new Set(statedCounts(README, 'lessons'))).toEqual(new Set([LESSONS.length]));
    expect(statedCounts(README, 'presets')).toEqual([Object.keys(PRESETS).length]);
    expect(presetRows(README)).toBe(Object.keys(PRESETS).length);
    expect(statedCounts(README, 'figures')).toEqual([courseFigures]);
    expect(statedCounts(README, 'lines with')).toEqual([exampleLines]);
  });

  it('a stale count is caught (negative control)', () => {
    const stale = README.replace(`${LESSONS.length} lessons in`, `${LESSONS.length - 5} lessons in`);
    expect(stale).not.toBe(README);
    expect(new Set(statedCounts(stale, 'lessons'))).not.toEqual(new Set([LESSONS.length]));
    const rowDropped = README.replace(/^\| `gale` \|.*\n/m, '');
    expect(presetRows(rowDropped)).toBe(Object.keys(PRESETS).length - 1);
  });
});

describe('the reading path', () => {
  it(`${READING_PATH_DOC} is what scripts/build/readingPath.ts writes from the lessons' quote sources`, () => {
    expect(DOCS[READING_PATH_DOC]).toBe(readingPathMarkdown());
  });

  it('a hand edit of the reading path is caught (negative control)', () => {
    expect(readingPathMarkdown().replace('shaders/ocean.vert', 'shaders/ocean.frag')).not.toBe(readingPathMarkdown());
  });
});
