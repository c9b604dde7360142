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
  /** Timed frames when the default count would take too long (the brute-force grid). */
  frames?: number;
  /** Also time each render pass separately (oceano.debug.passTimings). */
  passes?: boolean;
}

export const SCENARIOS: readonly BenchScenario[] = [
  { name: 'default view', query: 't=10' },
  // The LOD's reference: every chunk of the same 4 km extent at full resolution, no culling.
  { name: 'brute-force grid, same extent', query: 't=10&lodBruteForce=1', frames: 3 },
  { name: 'underwater (Snell window, god rays, blur)', query: 't=10&preset=underwater', passes: true },
];
