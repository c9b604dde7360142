import { existsSync } from 'node:fs';
import { join } from 'node:path';
import type { Harness } from './harness';
import { buildPosters, posterJobs } from '../../scripts/build/posters';

const DIST = join(import.meta.dirname, '..', '..', 'dist');

/**
 * dist/posters as `npm run build` makes them. A plain `vite build` (what the test scripts run)
 * makes none and empties dist/, so they are made here by the same code when any is missing.
 */
export async function ensurePosters(harness: Harness): Promise<void> {
  const files = posterJobs().flatMap((job) => job.files);
  if (files.every((file) => existsSync(join(DIST, file)))) return;
  console.log(await buildPosters(harness.browser, harness.baseUrl, DIST));
}
