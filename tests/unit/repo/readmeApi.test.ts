import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { createFailedApi } from '../../../src/app/api/automationApi';

const README = readFileSync(join(import.meta.dirname, '..', '..', '..', 'README.md'), 'utf8');

/** The README's section under `heading`, up to the next heading of the same level. */
function section(markdown: string, heading: string): string {
  const start = markdown.indexOf(`\n${heading}`);
  if (start < 0) throw new Error(`The README has no section "${heading}".`);
  const end = markdown.indexOf('\n## ', start + 1);
  return markdown.slice(start, end < 0 ? undefined : end);
}

/** The members of oceano and oceano.debug that a text never names as `oceano.x` / `oceano.debug.x`. */
function unnamedMembers(text: string): string[] {
  // The API of a failed start has every member and needs no DOM to build.
  const api = createFailedApi(new Error('not started'));
  return [
    ...Object.keys(api).filter((key) => key !== 'debug' && !new RegExp(`oceano\\.${key}\\b`).test(text)),
    ...Object.keys(api.debug).filter((key) => !new RegExp(`oceano\\.debug\\.${key}\\b`).test(text)),
  ];
}

describe('README automation list', () => {
  const automation = section(README, '## Automation');

  it('names every method of oceano and oceano.debug', () => {
    expect(unnamedMembers(automation)).toEqual([]);
  });

  it('notices a member the list leaves out (negative control)', () => {
    const withoutShareUrl = automation.replace(/^oceano\.shareUrl\(\);.*$/m, '');
    expect(withoutShareUrl).not.toBe(automation);
    expect(unnamedMembers(withoutShareUrl)).toEqual(['shareUrl']);
    const withoutPassTimings = automation.replace(/^await oceano\.debug\.passTimings\(\);.*$/m, '');
    expect(unnamedMembers(withoutPassTimings)).toEqual(['passTimings']);
  });

  it('reads only its own section, not the rest of the README', () => {
    expect(automation).not.toContain('## Tests');
    expect(section('# T\n## Automation\noceano.a\n## Next\noceano.b', '## Automation')).toBe('\n## Automation\noceano.a');
  });
});
