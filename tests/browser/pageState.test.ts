import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { compareWithOtherReference, compareWithReference, diffPngs } from './imageCompare';
import { presetView, viewPng } from './referenceViews';
import { presetNames } from '../../src/app/url/presets';
import { recordedPage } from './pages';

const harness = useHarness();

const surfaceHeight = (page: Page) => page.evaluate(() => window.oceano.sampleSurface(3, -7).height);
const pause = (ms: number) => new Promise((r) => setTimeout(r, ms));

describe('shareable URL state', () => {
  it('reopens a shared link with the same parameters, camera and time, pixel for pixel', async () => {
    const { page } = await openOcean(harness, 't=3', 320, 180);
    await page.evaluate(() => {
      window.oceano.setParams({
        swellAmplitude: 2.37,
        swellFrequency: 0.0731,
        seed: 42,
        sunElevation: 33.3,
        sunAzimuth: 141,
        waterColor: '#113355',
        fresnel: false,
        rippleStrength: 0.91,
      });
      window.oceano.setCamera({ position: [12.5 + 1 / 3, 14.25, 31], target: [-5, 1, -70.1] });
      window.oceano.setTime(123.456789);
    });
    const original = await canvasPng(page);
    const state = await page.evaluate(() => ({
      url: window.oceano.shareUrl(),
      params: window.oceano.getParams(),
      camera: window.oceano.getCamera(),
    }));
    expect(state.url.startsWith(harness.baseUrl)).toBe(true);
    expect(state.url).toMatch(/[?&]cam=/);
    expect(state.url).toMatch(/[?&]t=123\.456789(&|$)/);
    await page.close();

    const reopened = await openOcean(harness, state.url.slice(state.url.indexOf('?') + 1), 320, 180);
    expect(await reopened.page.evaluate(() => window.oceano.getParams())).toEqual(state.params);
    expect(await reopened.page.evaluate(() => window.oceano.getCamera())).toEqual(state.camera);
    expect(await reopened.page.evaluate(() => window.oceano.notices())).toEqual([]);
    expect(diffPngs(original, await canvasPng(reopened.page), 0).differentPixels).toBe(0);
    await reopened.page.close();
  });

  it('copies the link with the share button, and shows it in a notice where the clipboard is refused', async () => {
    const context = harness.browser.defaultBrowserContext();
    await context.overridePermissions(new URL(harness.baseUrl).origin, ['clipboard-read', 'clipboard-write', 'clipboard-sanitized-write']);
    const { page } = await openOcean(harness, 't=4&seed=5', 640, 360);
    const shareButton = async () => {
      const buttons = await page.$$('.lil-gui button');
      for (const button of buttons) if ((await button.evaluate((b) => b.textContent ?? '')).includes('Share link')) return button;
      throw new Error('No share button in the panel.');
    };
    await (await shareButton()).click();
    await page.waitForFunction(() => window.oceano.notices().length > 0);
    const url = await page.evaluate(() => window.oceano.shareUrl());
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(url);
    expect(await page.evaluate(() => window.oceano.notices())).toEqual(['Link to this view copied to the clipboard.']);

    await page.evaluate(() => {
      navigator.clipboard.writeText = () => Promise.reject(new DOMException('refused', 'NotAllowedError'));
    });
    // From the keyboard this time: the share control is a focusable button.
    await (await shareButton()).focus();
    await page.keyboard.press('Enter');
    await page.waitForFunction(() => window.oceano.notices().length > 1);
    expect((await page.evaluate(() => window.oceano.notices()))[1]).toBe(`Copy this link to share the view: ${url}`);
    await context.clearPermissionOverrides();
    await page.close();
  });
});

describe('language', () => {
  const pageWords = (page: Page) =>
    page.evaluate(() => ({
      lang: document.documentElement.lang,
      canvas: document.querySelector('canvas')!.getAttribute('aria-label'),
      // Every label, in folded folders too (the panel starts with its folders folded).
      panel: Array.from(document.querySelectorAll('.lil-gui .lil-name, .lil-gui .lil-title'), (el) => el.textContent).join('\n'),
      play: document.querySelector('.oceano-play')!.getAttribute('aria-label'),
      notices: window.oceano.notices(),
    }));

  it('speaks Spanish with lang=es: labels, folders, buttons, canvas label and notices', async () => {
    const { page } = await openOcean(harness, 'lang=es&t=1&swellAmplitude=9', 640, 360);
    const words = await pageWords(page);
    expect(words.lang).toBe('es');
    expect(words.canvas).toBe('Océano 3D animado bajo un cielo');
    expect(words.panel).toContain('Amplitud del oleaje (m)');
    expect(words.panel).toContain('Oleaje');
    expect(words.panel).toContain('Compartir enlace');
    expect(words.play).toBe('Reproducir');
    expect(words.notices).toEqual(['"swellAmplitude=9" está fuera de [0, 4] m; se limita a 4.']);
    await page.close();
  });

  it('speaks English with lang=en', async () => {
    const { page } = await openOcean(harness, 'lang=en&t=1&swellAmplitude=9', 640, 360);
    const words = await pageWords(page);
    expect(words.lang).toBe('en');
    expect(words.canvas).toBe('Animated 3D ocean under a sky');
    expect(words.panel).toContain('Swell amplitude (m)');
    expect(words.panel).toContain('Share link');
    expect(words.play).toBe('Play');
    expect(words.notices).toEqual(['"swellAmplitude=9" is outside [0, 4] m; clamped to 4.']);
    await page.close();
  });

  it('follows the browser language when the URL names none', async () => {
    const { page } = await recordedPage(harness, 640, 360);
    await page.evaluateOnNewDocument(() => {
      Object.defineProperty(navigator, 'languages', { get: () => ['es-MX', 'es'] });
    });
    await page.goto(`${harness.baseUrl}?t=1`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    expect(await page.evaluate(() => document.documentElement.lang)).toBe('es');
    await page.close();
  });
});

describe('embedding and accessibility', () => {
  it('embed=1 shows no panel, fills the frame and keeps a small play/pause button', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'embed=1&t=2', 480, 270);
    const layout = await page.evaluate(() => {
      const canvas = document.querySelector('canvas')!.getBoundingClientRect();
      const play = document.querySelector('.oceano-play')!.getBoundingClientRect();
      return {
        panels: document.querySelectorAll('.lil-gui').length,
        canvas: [canvas.left, canvas.top, canvas.width, canvas.height],
        scroll: [document.documentElement.scrollWidth, document.documentElement.scrollHeight],
        playArea: play.width * play.height,
      };
    });
    expect(layout.panels).toBe(0);
    expect(layout.canvas).toEqual([0, 0, 480, 270]);
    expect(layout.scroll).toEqual([480, 270]);
    expect(layout.playArea).toBeGreaterThan(0);
    expect(layout.playArea).toBeLessThan(48 * 48);
    expect(consoleErrors).toEqual([]);
    await page.close();
  });

  it('starts paused under prefers-reduced-motion, with a play button reachable by Tab that starts it', async () => {
    const { page } = await recordedPage(harness, 480, 270);
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'reduce' }]);
    await page.goto(`${harness.baseUrl}?seed=3`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const h0 = await surfaceHeight(page);
    await pause(600);
    expect(await surfaceHeight(page)).toBe(h0);
    expect(await page.evaluate(() => window.oceano.activity().looping)).toBe(false);
    await page.keyboard.press('Tab');
    const focused = await page.evaluate(() => ({
      className: document.activeElement?.className,
      label: document.activeElement?.getAttribute('aria-label'),
    }));
    expect(focused).toEqual({ className: 'oceano-play', label: 'Play' });
    await page.keyboard.press('Enter');
    await page.waitForFunction((h) => window.oceano.sampleSurface(3, -7).height !== h, {}, h0);
    expect(await page.evaluate(() => document.querySelector('.oceano-play')!.getAttribute('aria-label'))).toBe('Pause');
    await page.close();
  });

  it('runs from the start without reduced motion', async () => {
    const { page } = await recordedPage(harness, 480, 270);
    await page.emulateMediaFeatures([{ name: 'prefers-reduced-motion', value: 'no-preference' }]);
    await page.goto(`${harness.baseUrl}?seed=3`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    const h0 = await surfaceHeight(page);
    await page.waitForFunction((h) => window.oceano.sampleSurface(3, -7).height !== h, {}, h0);
    expect(await page.evaluate(() => window.oceano.activity().looping)).toBe(true);
    await page.close();
  });
});

describe('presets', () => {
  const presetViews = presetNames.map(presetView);
  for (const view of presetViews) {
    // The preset named in view.query, against references/{view.name}.png.
    it(`${view.name}: matches its reference and no other preset's`, async () => {
      const { page } = await openOcean(harness, view.query, view.width, view.height);
      expect(await page.evaluate(() => window.oceano.notices())).toEqual([]);
      if (view.wholePage) {
        // The Fresnel plot is the subject: page content over the canvas, so the whole page is compared.
        expect(await page.$eval('.oceano-fresnel-plot', (el) => (el as HTMLElement).offsetParent !== null)).toBe(true);
      }
      const png = await viewPng(page, view);
      await page.close();
      const own = compareWithReference(view.name, png);
      expect(own.matches, own.summary).toBe(true);
      // Negative control: the comparison tells this figure from every other one (normals-wrong
      // from normals-right above all: telling those apart is what that pair teaches).
      const decoded = PNG.sync.read(png);
      for (const other of presetViews.filter((v) => v.name !== view.name)) {
        const confused = compareWithOtherReference(other.name, decoded);
        expect(confused.matches, `preset ${view.name} passed ${confused.summary}`).toBe(false);
      }
    });
  }

  it('an unknown preset gives a notice and exactly the default view', async () => {
    const unknown = await openOcean(harness, 'preset=nope&t=10', 320, 180);
    expect((await unknown.page.evaluate(() => window.oceano.notices()))[0]).toMatch(/"nope"/);
    const withUnknown = await canvasPng(unknown.page);
    await unknown.page.close();
    const plain = await openOcean(harness, 't=10', 320, 180);
    expect(diffPngs(withUnknown, await canvasPng(plain.page), 0).differentPixels).toBe(0);
    await plain.page.close();
  });
});
