import type { Page } from 'puppeteer';
import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';
import { defaultParams } from '../../src/sim/params/params';
import { meanUpCrossingPeriod } from '../../src/sim/tools/probeStatistics';
import { probeTheory, swellRecord } from '../../src/sim/tools/probeTheory';

const harness = useHarness();

/** The view the pointer tests look from: 12 m up, 30 m back from the origin, over a flat sea. */
const POSE = { position: [0, 12, 30] as [number, number, number], target: [0, 0, 0] as [number, number, number] };
/** OceanView's vertical field of view, degrees. */
const FOV = 55;
const FLAT = 'swellAmplitude=0&rippleStrength=0&t=4';

/**
 * Where the ray through a pixel meets the flat sea y = 0, from the pose alone (pinhole camera,
 * written out here rather than taken from three): what the ruler and the stones must find.
 */
function seaUnderPixel(px: number, py: number, width: number, height: number): { x: number; z: number } {
  const [ex, ey, ez] = POSE.position;
  const f = POSE.target.map((t, i) => t - POSE.position[i]);
  const fl = Math.hypot(...f);
  const forward = f.map((c) => c / fl);
  // right = forward × up, up' = right × forward (up = +y).
  const r = [-forward[2], 0, forward[0]];
  const rl = Math.hypot(...r);
  const right = r.map((c) => c / rl);
  const up = [
    right[1] * forward[2] - right[2] * forward[1],
    right[2] * forward[0] - right[0] * forward[2],
    right[0] * forward[1] - right[1] * forward[0],
  ];
  const tan = Math.tan(((FOV / 2) * Math.PI) / 180);
  const nx = (px / width) * 2 - 1;
  const ny = 1 - (py / height) * 2;
  const d = forward.map((c, i) => c + nx * tan * (width / height) * right[i] + ny * tan * up[i]);
  const s = -ey / d[1];
  return { x: ex + s * d[0], z: ez + s * d[2] };
}

/** Opens the sea tools from the panel's button, as a user does, and chooses `tool`. */
async function chooseTool(page: Page, tool: 'none' | 'probe' | 'ruler' | 'disturb'): Promise<void> {
  await page.waitForSelector('.lil-gui.lil-root');
  if (!(await page.$('.oceano-sea-tools:not([hidden])'))) {
    await page.evaluate(() =>
      Array.from(document.querySelectorAll<HTMLButtonElement>('.lil-gui button'))
        .find((b) => /Sea tools/.test(b.textContent ?? ''))!
        .click(),
    );
    await page.waitForSelector('.oceano-sea-tools:not([hidden])');
  }
  await page.click(`.oceano-sea-tools input[value="${tool}"]`);
  await page.waitForFunction(
    (name) => document.querySelector<HTMLInputElement>(`.oceano-sea-tools input[value="${name}"]`)!.checked,
    {},
    tool,
  );
}

/** Draws `n` frames `dt` seconds of simulation time apart, from the current time (the clock stays paused). */
async function runFrames(page: Page, n: number, dt: number): Promise<void> {
  await page.evaluate(
    (count, step) => {
      const start = Number(new URL(window.oceano.shareUrl()).searchParams.get('t'));
      for (let i = 1; i <= count; i++) {
        window.oceano.setTime(start + i * step);
        window.oceano.renderFrame();
      }
    },
    n,
    dt,
  );
}

describe('the probe', () => {
  // Controls: times 5 % off, ω 5 % off.
  it('measures the seed swell’s period as its formula (ω = √(g k)) gives it, within 2 %', async () => {
    const k = 0.2;
    const [x, z] = [13.7, -4.2];
    const { page, consoleErrors } = await openOcean(harness, `t=20&rippleStrength=0&swellFrequency=${k}&probe=${x},${z}`, 480, 270);
    await page.evaluate(() => window.oceano.loaded());
    // 30.5 s of simulation time in frames 0.1 s apart, the clock paused and set frame by frame.
    await runFrames(page, 305, 0.1);
    const reading = (await page.evaluate(() => window.oceano.probe()))!;
    expect(reading.x).toBe(x);
    expect(reading.z).toBe(z);
    expect(reading.times.length).toBeGreaterThanOrEqual(300);
    expect(reading.times.at(-1)! - reading.times[0]).toBeCloseTo(30, 6);

    // The probe recorded the swell at its point and times: the formula there, to float precision.
    const params = { ...defaultParams(), rippleStrength: 0, swellFrequency: k };
    const formula = swellRecord(params, x, z, reading.times);
    reading.heights.forEach((h, i) => expect(Math.abs(h - formula.heights[i])).toBeLessThan(1e-6));

    const theory = probeTheory(params, x, z, reading.times);
    expect(theory.kind).toBe('swell');
    if (theory.kind !== 'swell' || reading.theory.kind !== 'swell') return;
    expect(reading.theory.period).toBeCloseTo(theory.period, 9);
    expect(theory.swellPeriod).toBeCloseTo((2 * Math.PI) / Math.sqrt(9.81 * k), 9);
    const error = reading.measured.period / theory.period - 1;
    console.log(
      `probe at (${x}, ${z}), k = ${k} rad/m: Tz measured ${reading.measured.period.toFixed(4)} s, swell formula ${theory.period.toFixed(4)} s (${(100 * error).toFixed(3)} %), ` +
        `2π/ω = ${theory.swellPeriod.toFixed(4)} s (Tz / (2π/ω) = ${(reading.measured.period / theory.swellPeriod).toFixed(3)}); crest to trough ${reading.measured.crestToTrough.toFixed(3)} m against ${theory.height.toFixed(3)} m`,
    );
    expect(Math.abs(error)).toBeLessThan(0.02);
    expect(Math.abs(reading.measured.crestToTrough / theory.height - 1)).toBeLessThan(0.02);

    // Planted fault 1: a record whose times are 5 % off (a clock read at the wrong scale).
    const stretched = meanUpCrossingPeriod({ times: reading.times.map((t) => 20 + (t - 20) * 1.05), heights: reading.heights });
    expect(Math.abs(stretched / theory.period - 1)).toBeGreaterThan(0.02);
    // Planted fault 2: a theory with ω 5 % too high (k 10.25 % too high, as ω = √(g k)).
    const wrong = probeTheory({ ...params, swellFrequency: k * 1.05 ** 2 }, x, z, reading.times);
    expect(Math.abs(reading.measured.period / wrong.period - 1)).toBeGreaterThan(0.02);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('records one sample per Step, 1/60 s apart; a share link carries it; probe(null) removes it; bad input says so', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=3&lang=es', 480, 270);
    const placed = (await page.evaluate(() => window.oceano.probe(2.5, -7)))!;
    expect([placed.x, placed.z]).toEqual([2.5, -7]);
    await page.evaluate(() => window.oceano.renderFrame());
    // Step asks for a frame; drawn here at once, so the test waits for no animation frame. The frame Step asked for
    // comes later at the same time, and adds nothing.
    for (let i = 0; i < 3; i++) await page.evaluate(() => (window.oceano.step(), window.oceano.renderFrame()));
    await new Promise((resolve) => setTimeout(resolve, 200));
    const stepped = (await page.evaluate(() => window.oceano.probe()))!;
    expect(stepped.times).toHaveLength(4);
    stepped.times.slice(1).forEach((t, i) => expect(t - stepped.times[i]).toBeCloseTo(1 / 60, 9));
    // A change of the sea starts the record afresh: it never mixes two seas.
    await page.evaluate(() => (window.oceano.setParams({ swellAmplitude: 2 }), window.oceano.step(), window.oceano.renderFrame()));
    expect((await page.evaluate(() => window.oceano.probe()))!.times).toHaveLength(1);
    expect(new URL(await page.evaluate(() => window.oceano.shareUrl())).searchParams.get('probe')).toBe('2.5,-7');
    expect(await page.evaluate(() => window.oceano.probe(null))).toBeNull();
    expect(new URL(await page.evaluate(() => window.oceano.shareUrl())).searchParams.get('probe')).toBeNull();
    const error = await page.evaluate(() =>
      window.oceano.probe(Number.NaN, 1).then(
        () => 'placed',
        (e: Error) => `${e.name}: ${e.message}`,
      ),
    );
    expect(error).toMatch(/^TypeError: probe needs \(x, z\)/);
    await page.close();

    const bad = await openOcean(harness, 't=3&lang=es&probe=1,oops', 480, 270);
    await bad.page.evaluate(() => window.oceano.loaded());
    const notices = await bad.page.evaluate(() => window.oceano.notices());
    expect(notices).toEqual([expect.stringMatching(/^"probe=1,oops" no son dos números finitos/)]);
    expect(await bad.page.evaluate(() => window.oceano.probe())).toBeNull();
    expect([...consoleErrors, ...bad.consoleErrors]).toEqual([]);
    await bad.page.close();
  });
});

/** The tools card's box, and the boxes it must not cover: the lessons drawer, the panel, the play button. */
function layout(page: Page) {
  return page.evaluate(() => {
    const box = (selector: string) => {
      const el = document.querySelector<HTMLElement>(selector);
      if (!el || el.offsetParent === null) return null;
      const r = el.getBoundingClientRect();
      return { left: r.left, right: r.right, top: r.top, bottom: r.bottom };
    };
    return {
      card: box('.oceano-sea-tools')!,
      canvas: box('canvas')!,
      others: ['.oceano-lessons', '.lil-gui.lil-root', '.oceano-play'].map(box).filter((b) => b !== null),
    };
  });
}
type Box = { left: number; right: number; top: number; bottom: number };
const overlaps = (a: Box, b: Box) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

describe('the tools card', () => {
  // Laptop: beside them; phone: above the sea (control: moved left, it covers the drawer).
  it('lies where the drawer, the panel and the play button leave the view free, on laptop and phone', async () => {
    const laptop = await openOcean(harness, 't=5&probe=0,-20', 1366, 768);
    await laptop.page.waitForSelector('.lil-gui.lil-root');
    await laptop.page.waitForSelector('.oceano-lessons');
    await laptop.page.evaluate(() => window.oceano.renderFrame());
    let box = await layout(laptop.page);
    expect(box.others).toHaveLength(3);
    for (const other of box.others) expect(overlaps(box.card, other), JSON.stringify({ card: box.card, other })).toBe(false);
    expect(box.card.bottom).toBeLessThanOrEqual(box.canvas.bottom);
    // The sea between the drawer and the panel keeps most of its width above the card.
    expect((box.card.right - box.card.left) / box.canvas.right).toBeLessThan(0.26);
    await laptop.page.addStyleTag({ content: '#oceano-page .oceano-sea-tools { left: 100px !important; }' });
    box = await layout(laptop.page);
    expect(box.others.some((other) => overlaps(box.card, other))).toBe(true);
    await laptop.page.close();

    const phone = await openOcean(harness, 't=5&lang=es&probe=0,-20', 390, 844);
    await phone.page.waitForSelector('.lil-gui.lil-root');
    await phone.page.waitForSelector('.oceano-lessons');
    await phone.page.evaluate(() => window.oceano.renderFrame());
    box = await layout(phone.page);
    for (const other of box.others) expect(overlaps(box.card, other), JSON.stringify({ card: box.card, other })).toBe(false);
    // Between the card and the lessons' bottom sheet, at least a third of the view is sea.
    const sheet = box.others.find((other) => other.bottom === box.canvas.bottom)!;
    expect((sheet.top - box.card.bottom) / box.canvas.bottom).toBeGreaterThan(1 / 3);
    expect(await phone.page.$eval('.oceano-sea-tools h2', (el) => el.textContent)).toBe('Herramientas del mar');
    expect([...laptop.consoleErrors, ...phone.consoleErrors]).toEqual([]);
    await phone.page.close();
  });
});

describe('the ruler and the stones', () => {
  const [W, H] = [960, 540];
  /** Pixels on the sea that neither the folded drawer, the panel nor the tools card cover. */
  const A = [430, 290] as const;
  const B = [660, 420] as const;

  async function openFlat(query = FLAT): Promise<Page> {
    const { page } = await openOcean(harness, query, W, H);
    await page.evaluate((pose) => window.oceano.setCamera(pose), POSE);
    // Under 1000 px the lessons drawer starts folded to its header: the middle of the view is the sea's.
    await page.waitForSelector('.oceano-lessons-collapsed');
    await page.evaluate(() => window.oceano.renderFrame());
    return page;
  }

  // Control: with no tool, a drag turns the camera.
  it('a drag measures the horizontal distance between where it began and ended', async () => {
    const page = await openFlat();
    await chooseTool(page, 'none');
    await page.mouse.move(...A);
    await page.mouse.down();
    await page.mouse.move(...B, { steps: 4 });
    await page.mouse.up();
    const turned = await page.evaluate(() => window.oceano.getCamera());
    expect(turned.position).not.toEqual(POSE.position);
    expect(await page.$eval('.oceano-ruler-label', (el) => (el as HTMLElement).hidden)).toBe(true);

    await page.evaluate((pose) => window.oceano.setCamera(pose), POSE);
    await page.evaluate(() => window.oceano.renderFrame());
    await chooseTool(page, 'ruler');
    await page.mouse.move(...A);
    await page.mouse.down();
    await page.mouse.move(...B, { steps: 4 });
    await page.mouse.up();
    await page.evaluate(() => window.oceano.renderFrame());
    const a = seaUnderPixel(...A, W, H);
    const b = seaUnderPixel(...B, W, H);
    const expected = Math.hypot(b.x - a.x, b.z - a.z);
    const label = await page.$eval('.oceano-ruler-label', (el) => ({ text: el.textContent ?? '', hidden: (el as HTMLElement).hidden }));
    console.log(`ruler: label "${label.text}", from the pose alone ${expected.toFixed(3)} m`);
    expect(label.hidden).toBe(false);
    expect(await page.evaluate(() => window.oceano.getCamera())).toEqual(POSE);
    // The label is rounded to centimetres.
    expect(Math.abs(Number.parseFloat(label.text) - expected)).toBeLessThan(0.0051);

    // Keyboard: focus the keys button, Enter fixes the first end at the view's centre, five ↑ then Enter fix the second 5 m farther.
    await page.focus('.oceano-tool-keys');
    await page.keyboard.press('Enter');
    for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowUp');
    await page.keyboard.press('Enter');
    await page.evaluate(() => window.oceano.renderFrame());
    expect(await page.$eval('.oceano-ruler-distance', (el) => el.textContent)).toBe('Distance seen from above: 5.00 m');
    // The arrows moved the point, not the boat.
    expect(await page.evaluate(() => window.oceano.getParams().boatSpeed)).toBe(0);
    await page.close();
  });

  // Control: a click with no tool leaves the water still.
  it('a click drops a stone into the interactive waves where it lands', async () => {
    // From t = 0: a field switched on later first runs every step since 0 (calm ones too), minutes on SwiftShader.
    const page = await openFlat('swellAmplitude=0&rippleStrength=0&t=0&interactiveWaves=1');
    await page.evaluate(() => window.oceano.loaded());
    const hit = seaUnderPixel(...A, W, H);
    const far = seaUnderPixel(...B, W, H);
    const heights = () =>
      page.evaluate((p, q) => [window.oceano.sampleSurface(p.x, p.z).height, window.oceano.sampleSurface(q.x, q.z).height], hit, far);
    const settle = async () => {
      // The field steps with simulation time; sampleSurface sees it through a read-back a frame or two old.
      await runFrames(page, 6, 1 / 60);
      await new Promise((resolve) => setTimeout(resolve, 300));
      await page.evaluate(() => window.oceano.renderFrame());
    };
    await chooseTool(page, 'none');
    await page.mouse.click(...A);
    await settle();
    expect((await heights()).map(Math.abs).every((h) => h < 1e-6)).toBe(true);

    await chooseTool(page, 'disturb');
    await page.mouse.click(...A);
    await page.waitForFunction(() => document.querySelector('.oceano-tool-disturb .oceano-tool-note')?.textContent === 'Stones dropped: 1');
    await settle();
    const [atStone, away] = await heights();
    console.log(
      `stone at (${hit.x.toFixed(2)}, ${hit.z.toFixed(2)}): height there ${atStone.toFixed(4)} m, ${Math.hypot(far.x - hit.x, far.z - hit.z).toFixed(1)} m away ${away.toFixed(6)} m`,
    );
    expect(atStone).toBeGreaterThan(0.05);
    expect(Math.abs(away)).toBeLessThan(0.01);

    // For keyboard users: the card's button drops one at the point the camera orbits (the origin here).
    const before = await page.evaluate(() => window.oceano.sampleSurface(0, 0).height);
    await page.focus('.oceano-tool-disturb .oceano-tool-button');
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => document.querySelector('.oceano-tool-disturb .oceano-tool-note')?.textContent === 'Stones dropped: 2');
    await settle();
    const centre = await page.evaluate(() => window.oceano.sampleSurface(0, 0).height);
    console.log(`stone at the centre: height there ${before.toFixed(4)} → ${centre.toFixed(4)} m`);
    expect(centre - before).toBeGreaterThan(0.05);
    await page.close();
  });
});
