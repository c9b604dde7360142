import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { diffPngs } from './imageCompare';
import { recordedPage } from './pages';
import { DIVE_QUERY } from './referenceViews';
import { seaStatistics } from '../support/pictureStatistics';

const harness = useHarness();

const relative = (a: number, b: number) => Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b));

describe('WebGL context loss', () => {
  it('shows a notice while lost, then rebuilds and draws the same picture with the same parameters', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10&seed=4&swellAmplitude=2', 320, 180);
    const before = await canvasPng(page);
    const paramsBefore = await page.evaluate(() => window.oceano.getParams());
    await page.evaluate(() => {
      const gl = window.oceano.three.renderer.getContext();
      const extension = gl.getExtension('WEBGL_lose_context')!;
      (window as unknown as { loseContext: WEBGL_lose_context }).loseContext = extension;
      extension.loseContext();
    });
    await page.waitForFunction(() => window.oceano.notices().some((n) => n.includes('graphics context was lost')));
    expect(await page.evaluate(() => window.oceano.activity().looping)).toBe(false);
    // Drawing while lost is a no-op, not an exception.
    await page.evaluate(() => window.oceano.renderFrame());

    const framesBefore = await page.evaluate(() => window.oceano.activity().framesDrawn);
    await page.evaluate(() => (window as unknown as { loseContext: WEBGL_lose_context }).loseContext.restoreContext());
    await page.waitForFunction(() => window.oceano.notices().length === 0);
    await page.waitForFunction((n) => window.oceano.activity().framesDrawn > n, {}, framesBefore);
    expect(await page.evaluate(() => window.oceano.getParams())).toEqual(paramsBefore);
    expect(diffPngs(before, await canvasPng(page), 0).differentPixels).toBe(0);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('under the water too: after a restore the composer passes and their targets draw the same picture', async () => {
    const { page, consoleErrors } = await openOcean(harness, DIVE_QUERY, 320, 180);
    const before = await canvasPng(page);
    expect(await page.evaluate(() => window.oceano.stats().composerPasses)).toBe(6);
    const framesBefore = await page.evaluate(() => window.oceano.activity().framesDrawn);
    await page.evaluate(() => {
      const extension = window.oceano.three.renderer.getContext().getExtension('WEBGL_lose_context')!;
      extension.loseContext();
      setTimeout(() => extension.restoreContext(), 200);
    });
    await page.waitForFunction(() => window.oceano.notices().length === 1);
    await page.waitForFunction(() => window.oceano.notices().length === 0);
    await page.waitForFunction((n) => window.oceano.activity().framesDrawn > n, {}, framesBefore);
    expect(diffPngs(before, await canvasPng(page), 0).differentPixels).toBe(0);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('every wave model, the comparison and the wake draw the same picture after a restore, with the same draw calls', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10&seed=4', 240, 135);
    const modes: { name: string; params: object; moving?: boolean }[] = [
      { name: 'seed', params: { waves: 'seed' } },
      { name: 'fft', params: { waves: 'fft' } },
      { name: 'gerstner', params: { waves: 'gerstner' } },
      { name: 'compare seed,gerstner,fft', params: { waves: 'seed', compare: 'seed,gerstner,fft' } },
      { name: 'fft at 20 m/s', params: { compare: 'off', waves: 'fft', windSpeed: 20 } },
      {
        name: 'the wake behind a boat turning at 6 m/s',
        params: { waves: 'seed', windSpeed: 10, wake: true, boatSpeed: 6, boatTurnRate: 12 },
        moving: true,
      },
    ];
    // What the last frame drew, and what three.js holds on the GPU (it counts again from zero on a restored context).
    const drawn = () =>
      page.evaluate(() => {
        const { drawCalls, triangles } = window.oceano.stats();
        const info = window.oceano.three.renderer.info;
        return {
          drawCalls,
          triangles,
          memory: { geometries: info.memory.geometries, textures: info.memory.textures, programs: info.programs?.length ?? 0 },
        };
      });
    const report: string[] = [];
    for (const [index, mode] of modes.entries()) {
      await page.evaluate(async (params) => {
        window.oceano.setParams(params);
        await window.oceano.loaded();
      }, mode.params);
      if (mode.moving) {
        // The boat sails for 10 s, two frames a second, so that a wake trails it; then the clock stays.
        await page.evaluate(() => {
          for (let i = 1; i <= 20; i++) {
            window.oceano.setTime(10 + i / 2);
            window.oceano.renderFrame();
          }
        });
      }
      const before = await canvasPng(page);
      const drawnBefore = await drawn();
      const framesBefore = await page.evaluate(() => window.oceano.activity().framesDrawn);
      await page.evaluate(() => {
        const extension = window.oceano.three.renderer.getContext().getExtension('WEBGL_lose_context')!;
        extension.loseContext();
        setTimeout(() => extension.restoreContext(), 200);
      });
      await page.waitForFunction(() => window.oceano.notices().length === 1);
      await page.waitForFunction(() => window.oceano.notices().length === 0);
      await page.waitForFunction((n) => window.oceano.activity().framesDrawn > n, {}, framesBefore);
      const after = await canvasPng(page);
      const drawnAfter = await drawn();
      report.push(`${mode.name}: before ${JSON.stringify(drawnBefore)}, after ${JSON.stringify(drawnAfter)}`);
      expect(diffPngs(before, after, 0).differentPixels, mode.name).toBe(0);
      expect([drawnAfter.drawCalls, drawnAfter.triangles], mode.name).toEqual([drawnBefore.drawCalls, drawnBefore.triangles]);
      // The first mode is all the page has drawn: the restored context holds exactly the
      // geometries and textures it held, and no program more. Before the loss it also held the
      // ocean's two programs for the frames drawn before the prefiltered sky's code arrived
      // (src/render/sky/prefilteredSky.ts), and the sky's for the frames before its sun disc's
      // square arrived (src/render/sky/sunDiscSquare.ts), which three.js keeps for reuse. Later modes held
      // before the loss also what earlier modes left for reuse (the strips' tile batches, each
      // material's programs for other wave models), which a restored context uploads and
      // compiles only when they are drawn again.
      if (index === 0) {
        expect([drawnAfter.memory.geometries, drawnAfter.memory.textures], mode.name).toEqual([
          drawnBefore.memory.geometries,
          drawnBefore.memory.textures,
        ]);
        expect(drawnBefore.memory.programs - drawnAfter.memory.programs, mode.name).toBeLessThanOrEqual(3);
      }
      for (const kind of ['geometries', 'textures', 'programs'] as const)
        expect(drawnAfter.memory[kind], `${mode.name}: ${kind}`).toBeLessThanOrEqual(drawnBefore.memory[kind]);
    }
    console.log(`[oceano] drawn and held around a restore:\n${report.join('\n')}`);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('keeps animating after a restore when it was running', async () => {
    const { page } = await openOcean(harness, 'seed=2', 160, 90);
    await page.evaluate(() => {
      const extension = window.oceano.three.renderer.getContext().getExtension('WEBGL_lose_context')!;
      extension.loseContext();
      setTimeout(() => extension.restoreContext(), 300);
    });
    await page.waitForFunction(() => window.oceano.notices().length === 1);
    await page.waitForFunction(() => window.oceano.notices().length === 0 && window.oceano.activity().looping);
    const h = await page.evaluate(() => window.oceano.sampleSurface(1, 1).height);
    await page.waitForFunction((h0) => window.oceano.sampleSurface(1, 1).height !== h0, {}, h);
    await page.close();
  });
});

describe('resizing', () => {
  // The half- and quarter-resolution targets follow the size.
  it('under the water, a resized view draws what a view opened at that size draws', async () => {
    const { page: resized, consoleErrors } = await openOcean(harness, DIVE_QUERY, 320, 180);
    await resized.setViewport({ width: 400, height: 224, deviceScaleFactor: 1 });
    await resized.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await resized.evaluate(() => window.oceano.renderFrame());
    expect(await resized.evaluate(() => [document.querySelector('canvas')!.width, document.querySelector('canvas')!.height])).toEqual([
      400, 224,
    ]);
    // Screenshot before the next page opens: a page behind another draws no screenshots.
    const after = await canvasPng(resized);
    expect(consoleErrors).toEqual([]);
    await resized.close();
    const { page: fresh } = await openOcean(harness, DIVE_QUERY, 400, 224);
    expect(diffPngs(await canvasPng(fresh), after, 0).differentPixels).toBe(0);
    await fresh.close();
  });

  it('survives repeated resizes, including the container at 0×0, and ends at the right size', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=5', 320, 180);
    for (const [w, h] of [
      [800, 200],
      [1, 1],
      [200, 700],
      [33, 17],
      [640, 360],
    ]) {
      await page.setViewport({ width: w, height: h, deviceScaleFactor: 1 });
      await page.evaluate(() => window.oceano.renderFrame());
    }
    for (let i = 0; i < 4; i++) {
      await page.evaluate(
        (zero) => {
          const container = document.getElementById('oceano-page')!;
          container.style.width = zero ? '0px' : '';
          container.style.height = zero ? '0px' : '';
        },
        i % 2 === 0,
      );
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      await page.evaluate(() => window.oceano.renderFrame());
    }
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const size = await page.evaluate(() => {
      const canvas = document.querySelector('canvas')!;
      const camera = window.oceano.three.camera;
      return { buffer: [canvas.width, canvas.height], aspect: camera.aspect };
    });
    expect(size.buffer).toEqual([640, 360]);
    expect(size.aspect).toBeCloseTo(640 / 360, 12);
    expect(consoleErrors).toEqual([]);
    // The picture after all that equals a fresh load at the final size.
    const after = await canvasPng(page);
    await page.close();
    const fresh = await openOcean(harness, 't=5', 640, 360);
    expect(diffPngs(after, await canvasPng(fresh.page), 0).differentPixels).toBe(0);
    await fresh.page.close();
  });
});

describe('long runs', () => {
  it('draws the sea at t = 1e6 s as detailed as at t = 10 s (phases kept in range)', async () => {
    // The sea as a mirror (seaRoughness off): the sun's glitter, as wide as Cox & Munk's 10 m/s
    // sea makes it, would fill much of the view, its place set by the swell at each instant, and
    // the sky's reflection, blurred by that roughness, would show the ripples' detail less.
    const { page } = await openOcean(harness, 'cam=0,30,60,0,0,-100&t=10&seaRoughness=false', 480, 270);
    // Single frames vary with the ripple layers' blend weight: average instants spread evenly
    // over one blend period, so both times see the same mix of the two heightmaps.
    const blendPeriod = (2 * Math.PI) / (await page.evaluate(() => window.oceano.getParams().rippleBlendSpeed));
    const averaged = async (t0: number, samples = 8) => {
      const all: ReturnType<typeof seaStatistics>[] = [];
      for (let i = 0; i < samples; i++) {
        await page.evaluate((t) => window.oceano.setTime(t), t0 + (i * blendPeriod) / samples);
        all.push(seaStatistics(await canvasPng(page), 0.45));
      }
      const mean = (f: (s: ReturnType<typeof seaStatistics>) => number) => all.reduce((sum, s) => sum + f(s), 0) / all.length;
      return { mean: mean((s) => s.mean), std: mean((s) => s.std), detail: mean((s) => s.detail) };
    };
    const early = await averaged(10);
    const late = await averaged(1e6);
    await page.evaluate(() => window.oceano.setParams({ rippleStrength: 0 }));
    const smooth = await averaged(10, 2);
    console.log(
      `[oceano] sea statistics t≈10: ${JSON.stringify(early)}, t≈1e6: ${JSON.stringify(late)}, no ripples: ${JSON.stringify(smooth)}`,
    );
    expect(relative(early.mean, late.mean)).toBeLessThan(0.03);
    expect(relative(early.std, late.std)).toBeLessThan(0.05);
    expect(relative(early.detail, late.detail)).toBeLessThan(0.05);
    // The measure tells a degraded sea apart: without ripples the fine detail drops well past the tolerance.
    expect(relative(early.detail, smooth.detail)).toBeGreaterThan(0.2);
    await page.close();
  });
});

describe('missing assets', () => {
  it("a page's own sky with a missing face gives a notice and the painted sky, and the sea is still drawn", async () => {
    const { page, consoleErrors } = await recordedPage(harness, 320, 180, ['sky/nz.png']);
    await page.goto(`${harness.baseUrl}?t=10&sky=sky`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    expect(await page.evaluate(() => window.oceano.notices())).toEqual([
      'The sky images under "sky" could not be loaded. Showing the sky painted from the sun instead.',
    ]);
    const png = await canvasPng(page);
    const sky = seaStatistics(png, 0);
    const sea = seaStatistics(png, 0.7);
    expect(sky.std).toBeGreaterThan(5);
    expect(sea.std).toBeGreaterThan(2);
    expect(sea.detail).toBeGreaterThan(0.1);
    expect(consoleErrors.filter((e) => !e.includes('404'))).toEqual([]);
    await page.close();
  });
});

describe('security', () => {
  it('the built page carries a strict CSP, has no inline script, and requests nothing from another origin', async () => {
    const html = readFileSync(join(import.meta.dirname, '..', '..', 'dist', 'index.html'), 'utf8');
    const csp = /<meta http-equiv="Content-Security-Policy" content="([^"]*)"/.exec(html)?.[1].replaceAll('&#39;', "'") ?? '';
    expect(csp).toContain("script-src 'self'");
    expect(csp).not.toMatch(/unsafe-eval|script-src[^;]*unsafe-inline/);
    for (const script of html.match(/<script\b[^>]*>/g) ?? []) expect(script).toMatch(/\bsrc=/);

    const { page, consoleErrors, requests, violations } = await recordedPage(harness, 640, 360);
    // sky=sky: the default sky is painted and fetches nothing, so the shipped faces are asked
    // for to have every kind of asset the page can load (page, script, style, six images, boat).
    await page.goto(`${harness.baseUrl}?t=1&seed=2&sky=sky`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    await page.evaluate(() => window.oceano.renderFrame());
    const origin = new URL(harness.baseUrl).origin;
    const network = requests.filter((url) => !url.startsWith('data:'));
    expect(network.length).toBeGreaterThan(6);
    expect(network.filter((url) => new URL(url).origin !== origin)).toEqual([]);
    expect(violations).toEqual([]);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });
});
