import { afterAll, beforeAll, inject } from 'vitest';
import { startHarness, type Harness } from './harness';

/**
 * One harness (preview server + the suite's shared headless Chromium, see sharedBrowser.ts)
 * for the enclosing test file or describe block: started before its tests, closed after
 * them. The returned object is filled in by the time any test runs.
 */
export function useHarness(): Harness {
  const harness = {} as Harness;
  beforeAll(async () => {
    Object.assign(harness, await startHarness(undefined, inject('browserEndpoint')));
  });
  afterAll(async () => {
    await harness.close?.();
  });
  return harness;
}
