import type { Page } from 'puppeteer';

/**
 * What the benchmark measures: each scenario is one row of the results, drawn in a page
 * of its own. To add a row (brute-force grid against LOD, the underwater passes, the boat),
 * add one entry here: a URL query that fixes `t` so every run draws the same picture, and,
 * when the URL is not enough, a setup step run after `oceano.ready` and before the timing.
 * The first scenario is the headline: its figures are the top-level ones in the JSON, and
 * its ttffMs is the app's first load (empty caches); later rows load with warm caches.
 */
export interface BenchScenario {
  name: string;
  query: string;
  setup?: (page: Page) => Promise<void>;
}

export const SCENARIOS: readonly BenchScenario[] = [{ name: 'default view', query: 't=10' }];
