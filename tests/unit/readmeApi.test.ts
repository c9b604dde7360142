import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { createFailedApi } from '../../src/app/api/automationApi';

/** Issue 11.11: the README's automation section names every member of the API. */
describe('README automation list', () => {
  it('names every method of oceano and oceano.debug', () => {
    const readme = readFileSync(join(import.meta.dirname, '..', '..', 'README.md'), 'utf8');
    const section = readme.slice(readme.indexOf('## Automation'), readme.indexOf('## Tests'));
    // The API of a failed start has every member and needs no DOM to build.
    const api = createFailedApi(new Error('not started'));
    const missing = [
      ...Object.keys(api).filter((key) => key !== 'debug' && !new RegExp(`oceano\\.${key}\\b`).test(section)),
      ...Object.keys(api.debug).filter((key) => !new RegExp(`oceano\\.debug\\.${key}\\b`).test(section)),
    ];
    expect(missing).toEqual([]);
  });
});
