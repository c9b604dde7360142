import type { Page } from 'puppeteer';
import type { FrameCounts } from '../../src/render/diagnostics/frameCounter';
import type { SideBySideRatio } from './sideBySide';
import { COMPARISONS } from './scenarios';

/** The SwiftShader guard: the default view at most 0.6× three.js's ocean example without its bloom, side by side. */
const GUARD_LABEL = 'default / three.js example (Water + Sky, no bloom)';
const [, , , GUARD_TARGET] = COMPARISONS.find(([label]) => label === GUARD_LABEL) ?? [];

export interface Guard extends SideBySideRatio {
  target: number;
}

/** The guard's side-by-side ratio, or null where the run left out one of its two rows. */
export function guardRatio(sideBySide: readonly SideBySideRatio[]): Guard | null {
  const ratio = sideBySide.find((r) => r.label === GUARD_LABEL);
  if (!ratio || typeof GUARD_TARGET !== 'number') return null;
  return { ...ratio, target: GUARD_TARGET };
}

/**
 * One frame of an open, warmed-up page counted (oceano.debug.frameCounts), `seconds` after the
 * last as the scenario's timed frames step (0: the clock paused, the same time drawn again).
 */
export function countFrames(page: Page, seconds: number): Promise<FrameCounts> {
  return page.evaluate((s) => window.oceano.debug.frameCounts({ seconds: s }), seconds);
}

/** A row's counts as the results table prints them. */
export function formatCounts(counts: FrameCounts): string[] {
  const kb = counts.bytesUploaded / 1024;
  const bytes = counts.bytesUploaded === 0 ? '0' : `${kb.toFixed(1)} KB in ${counts.uploads}`;
  return [String(counts.drawCalls), String(counts.passes), String(counts.programSwitches), bytes];
}
