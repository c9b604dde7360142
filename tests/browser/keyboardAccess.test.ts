import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { sharedPage } from './sharedPage';
import { useHarness } from './useHarness';

/** The page by keyboard, on a phone and with assistive technology. */
const harness = useHarness();

describe('keyboard and accessibility', () => {
  /**
   * One t=1 page at 640×360 for the three tests below (each boot costs seconds of SwiftShader
   * work); each puts back the camera, parameters and paused clock it changed (sharedPage.ts).
   */
  const desk = sharedPage(harness, 't=1', 640, 360);

  it('moves the camera with J/L/I/K/U/O while the arrows steer the boat and leave the camera alone', async () => {
    await desk.restoring(async (page) => {
      const camera = () => page.evaluate(() => window.oceano.getCamera());
      const distance = (c: { position: number[]; target: number[] }) => Math.hypot(...c.position.map((p, i) => p - c.target[i]));
      const start = await camera();
      await page.keyboard.press('ArrowLeft');
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      expect(await camera()).toEqual(start);
      await page.keyboard.press('KeyL');
      const orbited = await camera();
      expect(orbited.target).toEqual(start.target);
      expect(distance(orbited)).toBeCloseTo(distance(start), 6);
      expect(Math.hypot(orbited.position[0] - start.position[0], orbited.position[2] - start.position[2])).toBeGreaterThan(1);
      await page.keyboard.press('KeyI');
      expect((await camera()).position[1]).toBeGreaterThan(orbited.position[1]);
      const before = distance(await camera());
      await page.keyboard.press('KeyU');
      expect(distance(await camera()) / before).toBeCloseTo(0.9, 6);
    });
  });

  // ▶ is labelled by its action only; the canvas is named by its view.
  it('shows a focus ring on lil-gui controls without hover, and names ▶ and the canvas by what they do', async () => {
    await desk.restoring(async (page) => {
      const session = await page.createCDPSession();
      await session.send('Emulation.setEmulatedMedia', {
        features: [
          { name: 'hover', value: 'none' },
          { name: 'pointer', value: 'coarse' },
        ],
      });
      expect(await page.evaluate(() => matchMedia('(hover: hover)').matches)).toBe(false);
      const rings: string[] = [];
      for (let i = 0; i < 12; i++) {
        await page.keyboard.press('Tab');
        const ring = await page.evaluate(() => {
          const el = document.activeElement as HTMLElement | null;
          if (!el || !el.closest('.lil-gui, .oceano-lessons')) return null;
          const style = getComputedStyle(el);
          return `${el.tagName}:${style.outlineStyle}:${style.outlineWidth}`;
        });
        if (ring) rings.push(ring);
      }
      expect(rings.length).toBeGreaterThan(3);
      for (const ring of rings) expect(ring).toMatch(/:solid:2px$/);

      const play = await page.$eval('.oceano-play', (b) => ({
        pressed: b.getAttribute('aria-pressed'),
        label: b.getAttribute('aria-label'),
      }));
      expect(play).toEqual({ pressed: null, label: 'Play' });
      await page.click('.oceano-play');
      expect(await page.$eval('.oceano-play', (b) => [b.getAttribute('aria-pressed'), b.getAttribute('aria-label')])).toEqual([
        null,
        'Pause',
      ]);

      const label = () => page.$eval('.oceano-canvas', (c) => c.getAttribute('aria-label'));
      expect(await label()).toBe('Animated 3D ocean under a sky');
      await page.evaluate(() => window.oceano.setParams({ view: 'heightmap' }));
      expect(await label()).toMatch(/heightmaps/);
      await page.evaluate(() => window.oceano.setParams({ view: 'ocean' }));
      expect(await label()).toBe('Animated 3D ocean under a sky');
      await session.send('Emulation.setEmulatedMedia', { features: [] });
      await session.detach();
    });
  });

  it('starts with the panel folded on a 375×667 phone, open on a 640-px window', async () => {
    const phone = await openOcean(harness, 't=1', 375, 667);
    const folded = await phone.page.evaluate(() => {
      const gui = document.querySelector('.lil-gui.lil-root') as HTMLElement;
      return { closed: gui.classList.contains('lil-closed'), height: gui.getBoundingClientRect().height };
    });
    expect(folded.closed).toBe(true);
    expect(folded.height).toBeLessThan(667 / 10);
    await phone.page.close();
    expect(await (await desk.page()).$eval('.lil-gui.lil-root', (g) => g.classList.contains('lil-closed'))).toBe(false);
  });
});
