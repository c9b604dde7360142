import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { fixtureBundle } from './fixtureBundle';
import puppeteer, { type Browser, type Page } from 'puppeteer';
import { BROWSER_ARGS, findBrowser } from './harness';
import { playOnCpu, type IWaveScript } from './iwaveScript';
import type { MovingHull } from '../../src/sim/iwave/movingHull';
import type { IWaveParityApi } from './fixtures/iwaveParity';

/**
 * The GPU iWave (render targets, float32, shaders/iwave*.frag) against the CPU reference
 * (src/sim/iwave/iwaveGrid.ts, float64): stones, steps, a scroll and an obstacle, on the
 * 256² grid of 0.5 m the app uses. The page is a bundle of tests/browser/fixtures/iwaveParity.ts.
 */
let browser: Browser;
let page: Page;

beforeAll(async () => {
  const code = await fixtureBundle('iwaveParity');
  browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  page = await browser.newPage();
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent('<!doctype html><html><body></body></html>');
  await page.addScriptTag({ content: code, type: 'module' });
  await page.waitForFunction(() => 'iwaveParity' in window, { timeout: 60_000 });
  expect(errors).toEqual([]);
}, 300_000);

afterAll(async () => {
  await browser?.close();
});

const gpu = <K extends keyof IWaveParityApi>(name: K, ...args: Parameters<IWaveParityApi[K]>): Promise<ReturnType<IWaveParityApi[K]>> =>
  page.evaluate(
    (n, a) => (window as unknown as { iwaveParity: Record<string, (...x: unknown[]) => unknown> }).iwaveParity[n](...a),
    name,
    args as unknown[],
  ) as Promise<ReturnType<IWaveParityApi[K]>>;

function worstDifference(got: ArrayLike<number>, want: ArrayLike<number>): { absolute: number; relative: number } {
  let diff = 0;
  let scale = 0;
  for (let i = 0; i < want.length; i++) {
    diff = Math.max(diff, Math.abs(got[i] - want[i]));
    scale = Math.max(scale, Math.abs(want[i]));
  }
  return { absolute: diff, relative: diff / scale };
}

const n = 256;
/** A breakwater: a solid block 3 m × 12 m east of the first stone. */
function breakwater(): number[] {
  const mask = new Array<number>(n * n).fill(1);
  for (let j = 116; j < 140; j++) for (let i = 150; i < 156; i++) mask[j * n + i] = 0;
  return mask;
}

const script: IWaveScript = {
  n,
  spacing: 0.5,
  dt: 1 / 60,
  damping: 0.05,
  obstacle: breakwater(),
  actions: [
    { kind: 'disturb', disturbance: { x: 3.2, z: -1.1, radius: 1.5, height: 0.3 } },
    { kind: 'step', count: 40 },
    { kind: 'recentre', x: 2.3, z: -1.7 },
    { kind: 'disturb', disturbance: { x: -20.4, z: 14.9, radius: 0.8, height: -0.15 } },
    { kind: 'step', count: 80 },
  ],
};

describe('GPU iWave against the CPU reference', () => {
  // Within 3e-4 of the largest height (planted fault: the scroll the other way fails).
  it('matches after 120 steps with two stones, a scroll and an obstacle', async () => {
    const { heights, centre } = await gpu('run', script);
    const cpu = playOnCpu(script);
    expect(centre).toEqual([cpu.centerX, cpu.centerZ]);
    const error = worstDifference(heights, cpu.height);
    const largest = Math.max(...Array.from(cpu.height, Math.abs));
    console.log(
      `iWave parity, 256², 120 steps: worst |GPU − CPU| ${error.absolute.toExponential(2)} m, ${error.relative.toExponential(2)} of the largest height ${largest.toFixed(4)} m`,
    );
    // float32 against float64: measured 1.0e-4 of the largest height after these 120 steps.
    expect(error.relative).toBeLessThan(3e-4);
    const wrongWay = playOnCpu({ ...script, actions: script.actions.map((a) => (a.kind === 'recentre' ? { ...a, x: -a.x, z: -a.z } : a)) });
    const control = worstDifference(heights, wrongWay.height).relative;
    console.log(`Control (scrolled the other way on the CPU): ${control.toExponential(2)} of the largest height`);
    expect(control).toBeGreaterThan(1e-2);
    // Measured, not asserted (timings are noisy): the step's cost here, for docs/iwave.md.
    console.log(`iWave step, 256², this renderer: ${(await gpu('cost', 256, 20)).toFixed(1)} ms`);
  }, 300_000);

  // The hull: its footprint solid, its bow and stern sources (planted fault: the hull a texel off fails).
  it('matches with a moving hull and the wave equation beside iWave, within 3e-4', async () => {
    // A boat at 4 m/s heading 70°, moved every other step, with a stone meeting it; the right
    // half of the grid runs the wave equation.
    const hullAt = (step: number, offset = 0): MovingHull => ({
      x: -12 + offset + (4 * Math.sin(1.22) * step) / 60,
      z: 3 - (4 * Math.cos(1.22) * step) / 60,
      heading: 1.22,
      speed: 4,
      length: 8,
      beam: 2.6,
      strength: 1,
    });
    const moving = (offset: number): IWaveScript['actions'] => [
      { kind: 'disturb', disturbance: { x: -4, z: 8, radius: 1.2, height: 0.3 } },
      { kind: 'disturb', disturbance: { x: 20, z: -6, radius: 1, height: 0.25 } },
      ...Array.from({ length: 45 }, (_, k): IWaveScript['actions'] => [
        { kind: 'hull', hull: hullAt(2 * k, offset) },
        { kind: 'step', count: 2 },
      ]).flat(),
    ];
    const sideBySide: IWaveScript = { n, spacing: 0.5, dt: 1 / 60, damping: 0.02, equation: 'side-by-side', actions: moving(0) };
    const { heights } = await gpu('run', sideBySide);
    const cpu = playOnCpu(sideBySide);
    const error = worstDifference(heights, cpu.height);
    const largest = Math.max(...Array.from(cpu.height, Math.abs));
    console.log(
      `iWave parity with a moving hull, side by side, 90 steps: worst |GPU − CPU| ${error.absolute.toExponential(2)} m, ${error.relative.toExponential(2)} of the largest height ${largest.toFixed(4)} m`,
    );
    expect(error.relative).toBeLessThan(3e-4);
    const control = worstDifference(heights, playOnCpu({ ...sideBySide, actions: moving(0.5) }).height).relative;
    console.log(`Control (the hull half a metre off on the CPU): ${control.toExponential(2)} of the largest height`);
    expect(control).toBeGreaterThan(1e-2);
  }, 300_000);
});
