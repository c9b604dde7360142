import { describe, expect, it } from 'vitest';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { foamOwnLight } from './foamLight';
import { streakAnisotropy } from './streakMeasure';

/**
 * In a gale the foam left behind lies in streaks along the wind (the Beaufort scale from force 7;
 * src/sim/waves/fft/windrows.ts). Seen from 150 m straight down at 20 m/s, the wind along the
 * picture's x, the foam's own light (the frame with foam less the same instant without) is
 * measured by the anisotropy of its gradients once the lace's detail is averaged away
 * (streakMeasure.ts).
 * Control: the windrows parameter off, where the foam lies in its wave groups' round patches.
 */
const harness = useHarness();
const W = 640;
const H = 360;
const TIMES = [20, 50, 80];
const BOX = 4;
const QUERY = 'waves=fft&windSpeed=20&windDirection=90&sunElevation=30&cam=0,150,0,0,0,-0.01';
// Measured: 0.219 (instants 0.18–0.26) with the windrows, 0.114 (0.10–0.13) without; the
// pictures are deterministic, so the bound sits between them.
const LIMIT = 0.16;

async function anisotropy(windrows: boolean): Promise<number> {
  const { page } = await openOcean(harness, `${QUERY}&windrows=${windrows ? 1 : 0}`, W, H);
  let sum = 0;
  for (const t of TIMES) {
    sum += streakAnisotropy(await foamOwnLight(page, t), W, H, BOX);
  }
  await page.close();
  return sum / TIMES.length;
}

describe('windrows: a gale’s foam in streaks along the wind', () => {
  it('from 150 m down at 20 m/s the foam left behind is drawn out along the wind (anisotropy over 0.16); control: the windrows off leave round patches', { timeout: 240_000 }, async () => {
    const streaks = await anisotropy(true);
    const patches = await anisotropy(false);
    const say = `anisotropy ${streaks.toFixed(3)} with windrows, ${patches.toFixed(3)} without`;
    console.log(`[oceano] ${say}`);
    expect(streaks, say).toBeGreaterThan(LIMIT);
    expect(patches, say).toBeLessThan(LIMIT);
  });
});
