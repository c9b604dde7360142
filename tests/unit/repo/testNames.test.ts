import { describe, expect, it } from 'vitest';
import { readRepoFile } from '../../support/docChecks';
import { issueCitations, MAX_TEST_NAME_LENGTH, overlongTestNames, testNames, testSourceFiles } from '../../support/testNames';

const SOURCES = Object.fromEntries(testSourceFiles().map((path) => [path, readRepoFile(path)]));

/**
 * Test files whose names other work is rewriting now (the lesson cards' claims and the course
 * page); this list is to be left empty.
 */
const KNOWN_FILES_WITH_LONG_NAMES: readonly string[] = [
  'tests/unit/app/lessons/lessonClaims/concepts.test.ts',
  'tests/unit/app/lessons/lessonClaims/fft.test.ts',
  'tests/unit/app/lessons/lessonClaims/light.test.ts',
  'tests/unit/app/lessons/lessonClaims/seed.test.ts',
];

describe("a test's name says what it shows, briefly", () => {
  it(`no test or suite name is longer than ${MAX_TEST_NAME_LENGTH} characters, but in the known files`, () => {
    const overlong = Object.entries(SOURCES)
      .filter(([path]) => !KNOWN_FILES_WITH_LONG_NAMES.includes(path))
      .flatMap(([path, text]) => overlongTestNames(text, path));
    expect(overlong).toEqual([]);
  });

  it('every known file still has a long name, so the list empties as they are renamed', () => {
    for (const path of KNOWN_FILES_WITH_LONG_NAMES) expect(overlongTestNames(SOURCES[path], path).length).toBeGreaterThan(0);
  });

  it('reads names from it, test, describe, their modifiers and .each, templates as written', () => {
    const source = [
      "describe('a suite', () => {",
      "  it('a test', () => {});",
      '  it.each([1, 2])(`case ${0}`, () => {});',
      "  test.skip('skipped', () => {});",
      "  describe.each([[1]])('rows %i', () => {});",
      "  notATest('ignored');",
      '});',
    ].join('\n');
    expect(testNames(source).map(({ name }) => name)).toEqual(['a suite', 'a test', 'case ${0}', 'skipped', 'rows %i']);
  });

  it('flags a name one character over the limit and passes one at it (negative control)', () => {
    const atLimit = 'a'.repeat(MAX_TEST_NAME_LENGTH);
    const source = `it('${atLimit}', () => {});\nit.each([1])('${atLimit}b', () => {});\n`;
    expect(overlongTestNames(source, 'planted.test.ts')).toEqual([`planted.test.ts:2 (${MAX_TEST_NAME_LENGTH + 1})`]);
  });
});

describe('test comments give the reason, not a tracker number', () => {
  it('no test source cites an issue by number', () => {
    const cited = Object.entries(SOURCES).flatMap(([path, text]) => issueCitations(text, path));
    expect(cited).toEqual([]);
  });

  it('reports planted citations in comments and names, and passes colours, counts and code (negative control)', () => {
    // Built from parts so that this file does not cite one itself.
    const issue = ['iss', 'ue'].join('');
    const hash = '#';
    const planted = [
      `// the pause froze the boat (${issue} 11.1)`,
      `/** ${issue.toUpperCase()}S 14 and ${hash}32 */`,
      "const colour = '#06283a', bad = '#06283'; // 14 issues remain; an issue's reason; the 2nd issue",
      `it('keeps the pose (${issue} 3)', () => {});`,
    ].join('\n');
    expect(issueCitations(planted, 'planted.ts')).toEqual([
      `planted.ts:1: ${issue} 11.1`,
      `planted.ts:2: ${issue.toUpperCase()}S 14`,
      `planted.ts:2: ${hash}32`,
      `planted.ts:4: ${issue} 3`,
    ]);
  });
});
