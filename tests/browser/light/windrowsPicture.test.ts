import { describe, expect, it } from 'vitest';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { foamOwnLight } from './foamLight';
import { streakAnisotropy } from './streakMeasure';
import { seededRandom } from '../../../src/sim/noise/integerHash';
import { windrowCoordinates, windrowLattice, windrowShare, windrowStrength } from '../../../src/sim/waves/fft/windrows';

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
  // Looking down; anisotropy over 0.16. Control: the windrows off leave round patches.
  it('from 150 m at 20 m/s the foam left behind is drawn out along the wind', { timeout: 240_000 }, async () => {
    const streaks = await anisotropy(true);
    const patches = await anisotropy(false);
    const say = `anisotropy ${streaks.toFixed(3)} with windrows, ${patches.toFixed(3)} without`;
    console.log(`[oceano] ${say}`);
    expect(streaks, say).toBeGreaterThan(LIMIT);
    expect(patches, say).toBeLessThan(LIMIT);
  });
});

/**
 * The GPU's windrows against their CPU twin: the probe runs the real chunk
 * (shaders/foam/foamWindrows.glsl) at grid points up to 3 km out and late in time, and
 * windrowShare is asked the same on the lattice that windrowLattice places.
 * Control: the twin without the surface's drift.
 */
const PARITY = { seed: 5, windSpeed: 20, windDirection: 35, times: [0, 37.25, 4321.5], points: 64, extent: 3000 } as const;

function twinShare(x: number, z: number, t: number, drifting: boolean): number {
  const [u, v] = windrowCoordinates(windrowLattice(PARITY, 0, 0, drifting ? t : 0), x, z);
  return windrowShare(u, v, PARITY.seed, windrowStrength(PARITY.windSpeed), 0);
}

describe('windrows: the GPU against the CPU twin', () => {
  // Control: the twin without the drift is caught.
  it('agree within 1e-3 at seeded random grid points up to 3 km out and t up to 4,321 s', { timeout: 120_000 }, async () => {
    const random = seededRandom(20261127);
    const cases = PARITY.times.map((t) => ({
      t,
      points: Array.from(
        { length: PARITY.points },
        () => [Math.fround((random() * 2 - 1) * PARITY.extent), Math.fround((random() * 2 - 1) * PARITY.extent)] as [number, number],
      ),
    }));
    const { page } = await openOcean(
      harness,
      `waves=fft&seed=${PARITY.seed}&windSpeed=${PARITY.windSpeed}&windDirection=${PARITY.windDirection}&t=0`,
      320,
      180,
    );
    let worst = 0;
    let control = 0;
    for (const { t, points } of cases) {
      const gpu = await page.evaluate(async (p, time) => (await window.oceano.probeGpu(p, time)).map((s) => s.windrowShare), points, t);
      points.forEach(([x, z], i) => {
        worst = Math.max(worst, Math.abs(gpu[i] - twinShare(x, z, t, true)));
        if (t > 0) control = Math.max(control, Math.abs(gpu[i] - twinShare(x, z, t, false)));
      });
    }
    await page.close();
    const say = `windrows GPU–CPU: max |Δshare| ${worst.toExponential(2)}; control (no drift) ${control.toFixed(3)}`;
    console.log(`[oceano] ${say}`);
    expect(worst, say).toBeLessThan(1e-3);
    expect(control, say).toBeGreaterThan(0.1);
  });
});
