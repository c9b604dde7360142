import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { recordedPage, viewsReady } from './pages';
import { VIRTUAL_FRAMES, type Pumped } from './virtualFrames';

const harness = useHarness();

/**
 * The interactive waves through the app (dist/): its clock, the Step button, setTime, share
 * links, the boat, disturb's notices and the <oceano-view> attribute. A flat sea, so what
 * sampleSurface reports is the field alone.
 */
const FLAT = 'interactiveWaves=1&swellAmplitude=0&rippleStrength=0';
/** Texel centres (odd multiples of 0.25 m with the field centred on a whole metre) around the stones. */
const POINTS: [number, number][] = [
  [1.25, -2.25],
  [3.75, -0.25],
  [-0.75, -4.75],
  [5.25, -3.25],
  [2.25, 1.75],
];

/** sampleSurface at `points` once the field's read-back has caught up with a paused view (frames drawn until it has). */
async function fieldAt(page: Page, points: [number, number][] = POINTS): Promise<number[]> {
  return page.evaluate(async (p) => {
    for (let frame = 0; frame < 6; frame++) {
      window.oceano.renderFrame();
      await new Promise((r) => setTimeout(r, 100));
    }
    return p.map(([x, z]) => window.oceano.sampleSurface(x, z).height);
  }, points);
}

async function openVirtual(query: string): Promise<Page> {
  const page = await harness.browser.newPage();
  await page.evaluateOnNewDocument(VIRTUAL_FRAMES);
  await page.setViewport({ width: 320, height: 180, deviceScaleFactor: 1 });
  page.setDefaultTimeout(300_000);
  await page.goto(`${harness.baseUrl}?${query}`, { waitUntil: 'load' });
  await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
  await page.evaluate(() => window.oceano.ready);
  await page.evaluate(() => window.oceano.loaded());
  await page.evaluate(() => (window as unknown as Pumped).manualFrames());
  return page;
}

describe('the interactive waves in the app', () => {
  // Control: the stone a step later differs.
  it('hold the same field whether the clock plays, the Step button steps or setTime jumps', async () => {
    const N = 24;
    const stone = '1,3,-2,1,0.4';
    const query = (s: string) => `${FLAT}&t=1&timeScale=0.5&stones=${s}`;
    const played = await openVirtual(query(stone));
    // The loop's first frame measures no time: N + 1 frames advance N frames of 1/120 s.
    await played.evaluate((n) => {
      window.oceano.play();
      (window as unknown as Pumped).pumpFrames(n + 1);
      window.oceano.pause();
    }, N);
    const time = await played.evaluate(() => Number(new URL(window.oceano.shareUrl()).searchParams.get('t')));
    expect(time).toBeCloseTo(1 + N / 120, 9);
    const reference = await fieldAt(played);
    await played.close();
    console.log(`Field after ${N} frames at timeScale 0.5 (${time.toFixed(4)} s): ${reference.map((h) => h.toFixed(5)).join(', ')} m`);
    expect(Math.max(...reference.map(Math.abs))).toBeGreaterThan(1e-3);

    const stepped = await openVirtual(query(stone));
    await stepped.evaluate(async (n) => {
      const step = Array.from(document.querySelectorAll<HTMLButtonElement>('.lil-gui button')).find((b) =>
        b.textContent?.includes('Step one frame'),
      );
      if (!step) throw new Error('No Step button in the panel.');
      for (let i = 0; i < n; i++) {
        step.click();
        (window as unknown as Pumped).pumpFrames(1);
      }
    }, N);
    expect(await stepped.evaluate(() => Number(new URL(window.oceano.shareUrl()).searchParams.get('t')))).toBe(time);
    expect(await fieldAt(stepped)).toEqual(reference);
    await stepped.close();

    const jumped = await openVirtual(query(stone));
    await jumped.evaluate((t) => window.oceano.setTime(t), time);
    expect(await fieldAt(jumped)).toEqual(reference);
    // A jump forward and back again: the field restarts calm and replays the stone.
    await jumped.evaluate((t) => {
      window.oceano.setTime(t + 2);
      window.oceano.renderFrame();
      window.oceano.setTime(t);
    }, time);
    expect(await fieldAt(jumped)).toEqual(reference);
    await jumped.close();

    const later = await openVirtual(query(`${1 + 1 / 60},3,-2,1,0.4`));
    await later.evaluate((t) => window.oceano.setTime(t), time);
    expect(await fieldAt(later)).not.toEqual(reference);
    await later.close();
  }, 900_000);

  // The boat is read beside its hull; bad stones are a notice (controls: the link without its stones; the
  // field under the hull).
  it('carries its stones in a share link that reproduces the field, and the boat rides it', async () => {
    const { page } = await openOcean(harness, `${FLAT}&t=2`, 320, 180);
    await page.evaluate(() => window.oceano.loaded());
    const before = await fieldAt(page);
    expect(before.every((h) => h === 0)).toBe(true);

    // Bad input: a notice in the page, an error for the script, and nothing changes.
    const refused = await page.evaluate(() => {
      try {
        window.oceano.disturb(Number.NaN, 0);
        return null;
      } catch (error) {
        return String(error);
      }
    });
    expect(refused).toMatch(/x must be a finite number/);
    expect(await page.evaluate(() => window.oceano.notices())).toEqual([
      'disturb: x = NaN is not in [-1000000, 1000000] m; no stone dropped.',
    ]);
    expect(await fieldAt(page)).toEqual(before);

    // Two stones, the second with a radius under one texel (raised, and said), near the boat at (7, −5).
    const raised = await page.evaluate(() => {
      window.oceano.disturb(3, -2, { radius: 1.2, height: 0.5 });
      window.oceano.setTime(2.4);
      window.oceano.renderFrame();
      return window.oceano.disturb(4.5, -7, { radius: 0.2, height: -0.3 });
    });
    expect(raised).toEqual(['disturb: radius 0.2 m is under one texel; raised to 0.5 m.']);
    await page.evaluate(() => window.oceano.setTime(3));
    const field = await fieldAt(page);
    expect(Math.max(...field.map(Math.abs))).toBeGreaterThan(1e-3);

    // The boat's heave is the field beside its hull: the mean of the water 1 m off bow, stern and beam.
    const boat = await page.evaluate(() => {
      const { position, heading, target } = window.oceano.boat();
      const [x, , z] = position;
      const [fx, fz] = [Math.sin(heading), -Math.cos(heading)];
      const at = (u: number, v: number) => window.oceano.sampleSurface(x + u * fx - v * fz, z + u * fz + v * fx).height;
      return {
        heave: target.position[1],
        beside: 0.25 * (at(5, 0) + at(-5, 0) + at(0, 2.3) + at(0, -2.3)),
        under: window.oceano.sampleSurface(x, z).height,
      };
    });
    console.log(
      `Boat: target heave ${boat.heave.toFixed(5)} m, the water beside the hull ${boat.beside.toFixed(5)} m, under it ${boat.under} m`,
    );
    expect(Math.abs(boat.heave)).toBeGreaterThan(1e-4);
    expect(Math.abs(boat.heave - boat.beside)).toBeLessThan(1e-6);
    expect(boat.under).toBe(0);

    const url = await page.evaluate(() => window.oceano.shareUrl());
    expect(new URL(url).searchParams.get('stones')).toBe('2,3,-2,1.2,0.5;2.4,4.5,-7,0.5,-0.3');
    await page.close();
    const query = url.slice(url.indexOf('?') + 1);
    const reopened = await openOcean(harness, query, 320, 180);
    await reopened.page.evaluate(() => window.oceano.loaded());
    expect(await fieldAt(reopened.page)).toEqual(field);
    expect(await reopened.page.evaluate(() => window.oceano.notices())).toEqual([]);
    await reopened.page.close();
    const stripped = await openOcean(harness, query.replace(/stones=[^&]*/, 'stones='), 320, 180);
    await stripped.page.evaluate(() => window.oceano.loaded());
    expect(await fieldAt(stripped.page)).not.toEqual(field);
    await stripped.page.close();

    const bad = await openOcean(harness, `${FLAT}&t=2&stones=2,3,-2,1.2`, 320, 180);
    expect(await bad.page.evaluate(() => window.oceano.notices())).toEqual([
      '"stones=2,3,-2,1.2" is not a list of t,x,z,radius,height in range; no stones.',
    ]);
    await bad.page.close();
  }, 900_000);

  // Within 3e-5 m (planted fault: the GPU's hand-over 4 m farther out).
  it("blends the boat's waves from the field to the analytic wake with the same weights on GPU and CPU", async () => {
    // The boat at 6 m/s heading east (D = 2π·36/g = 23.1 m), its wake and its own near-field waves.
    const { page, consoleErrors } = await openOcean(harness, `${FLAT}&wake=1&boatSpeed=6&boatHeading=90&t=2&cam=7,30,20,-8,0,-5`, 320, 180);
    await page.evaluate(() => window.oceano.loaded());
    await fieldAt(page);
    // Behind the boat (7, −5), across the hand-over from 10 to 40 m, on and off its track.
    const points: [number, number][] = [];
    for (let d = 10; d <= 40; d += 1.5) for (const off of [-3, 0, 4]) points.push([7 - d, -5 + off]);
    const worst = (fault: boolean) =>
      page.evaluate(
        async (p, planted) => {
          const ocean = window.oceano.three.scene.getObjectByName('oceano-ocean') as unknown as {
            interactiveWaveUniforms: { uIWaveHandOver: { value: { z: number } } };
          };
          const handOver = ocean.interactiveWaveUniforms.uIWaveHandOver.value;
          if (planted) handOver.z += 4;
          const gpu = await window.oceano.probeGpu(p);
          if (planted) handOver.z -= 4;
          let difference = 0;
          let largest = 0;
          p.forEach(([x, z], i) => {
            const cpu = window.oceano.sampleSurface(x, z).height;
            difference = Math.max(difference, Math.abs(cpu - gpu[i].height));
            largest = Math.max(largest, Math.abs(cpu));
          });
          return { difference, largest, distance: handOver.z };
        },
        points,
        fault,
      );
    const ok = await worst(false);
    const control = await worst(true);
    console.log(
      `Hand-over at D = ${ok.distance.toFixed(2)} m: |GPU − CPU| ${ok.difference.toExponential(2)} m over ${points.length} points (largest height ${ok.largest.toFixed(3)} m); the GPU's hand-over 4 m out: ${control.difference.toExponential(2)} m`,
    );
    expect(ok.distance).toBeCloseTo((2 * Math.PI * 36) / 9.81, 4);
    expect(ok.largest).toBeGreaterThan(0.01);
    expect(ok.difference).toBeLessThan(3e-5);
    expect(control.difference).toBeGreaterThan(3e-5);
    expect(consoleErrors).toEqual([]);
    await page.close();
  }, 900_000);

  it('<oceano-view interactive-waves> turns them on, written bare and kebab-case (control: a misspelt name does not)', async () => {
    const { page, consoleErrors } = await recordedPage(harness, 400, 300);
    await page.goto(`${harness.baseUrl}fixtures/two-views.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const result = await page.evaluate(async () => {
      type View = HTMLElement & { oceano: (typeof window)['oceano'] | null };
      const make = async (attribute: string) => {
        const view = document.createElement('oceano-view') as View;
        view.setAttribute(attribute, '');
        view.setAttribute('t', '1');
        view.setAttribute('swellamplitude', '0');
        view.setAttribute('ripple-strength', '0');
        view.setAttribute('loading', 'eager');
        document.body.prepend(view);
        await new Promise<void>((resolve) => {
          const wait = () => (view.oceano ? resolve() : setTimeout(wait, 50));
          wait();
        });
        await view.oceano!.ready;
        await view.oceano!.loaded();
        return view;
      };
      const on = await make('interactive-waves');
      on.oceano!.disturb(0, 0, { radius: 1, height: 0.5 });
      on.oceano!.setTime(1.2);
      for (let frame = 0; frame < 6; frame++) {
        on.oceano!.renderFrame();
        await new Promise((r) => setTimeout(r, 100));
      }
      const seen = on.oceano!.sampleSurface(0.25, 0.25).height;
      const facts = { params: on.oceano!.getParams(), notices: on.oceano!.notices(), seen };
      on.remove();
      const misspelt = await make('interactive-wave');
      const control = { interactiveWaves: misspelt.oceano!.getParams().interactiveWaves, notices: misspelt.oceano!.notices() };
      misspelt.remove();
      return { ...facts, control };
    });
    expect(result.params).toMatchObject({ interactiveWaves: true, swellAmplitude: 0, rippleStrength: 0 });
    expect(result.notices).toEqual([]);
    expect(Math.abs(result.seen)).toBeGreaterThan(1e-3);
    expect(result.control.interactiveWaves).toBe(false);
    expect(result.control.notices).toEqual(['Unknown URL parameter "interactive-wave" was ignored.']);
    expect(consoleErrors.filter((e) => !e.includes('Content Security Policy'))).toEqual([]);
    await page.close();
  }, 600_000);
});
