import { readdirSync, readFileSync } from 'node:fs';
import { pageEntry, scriptSizes, staticImports } from '../../scripts/build/distScripts';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { describe, expect, it } from 'vitest';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';
import { recordedPage, viewsReady } from './pages';
import { diffPngs } from './imageCompare';

/** What issue 11's new user tripped over, each checked the way they met it. */
const harness = useHarness();

type ViewElement = HTMLElement & { oceano: (typeof window)['oceano'] | null };

describe('notices', () => {
  it('in a 400-px figure, every one of seven notices wraps inside its box and can be scrolled to', async () => {
    const { page } = await recordedPage(harness, 600, 400);
    await page.goto(`${harness.baseUrl}fixtures/notices-400.html`, { waitUntil: 'load' });
    await viewsReady(page);
    const facts = await page.evaluate(() => {
      const view = document.querySelector('#bad') as ViewElement;
      const list = view.querySelector('.oceano-notices') as HTMLElement;
      const box = view.getBoundingClientRect();
      const items = Array.from(list.querySelectorAll<HTMLElement>('.oceano-notice'));
      const overflowing = items.filter((item) => item.scrollWidth > item.clientWidth + 1 || item.getBoundingClientRect().right > box.right + 0.5);
      // Scroll each notice into the list's view: it must then lie inside the figure.
      const reachable = items.filter((item) => {
        item.scrollIntoView({ block: 'nearest' });
        const r = item.getBoundingClientRect();
        return r.top >= box.top - 0.5 && r.bottom <= box.bottom + 0.5;
      });
      return { count: view.oceano!.notices().length, items: items.length, overflowing: overflowing.length, reachable: reachable.length, listBottom: list.getBoundingClientRect().bottom, boxBottom: box.bottom, width: box.width };
    });
    expect(facts.width).toBe(400);
    expect(facts.count).toBe(7);
    expect(facts.items).toBe(7);
    expect(facts.overflowing).toBe(0);
    expect(facts.reachable).toBe(7);
    expect(facts.listBottom).toBeLessThanOrEqual(facts.boxBottom);
    await page.close();
  });

  it('shows a refused share link wrapped beside the panel, selectable in one click', async () => {
    const { page } = await openOcean(harness, 't=4&seed=5', 800, 450);
    await page.evaluate(() => {
      Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new DOMException('refused', 'NotAllowedError')) } });
    });
    const url = await page.evaluate(() => window.oceano.shareUrl());
    await page.evaluate(() => (Array.from(document.querySelectorAll<HTMLElement>('.lil-gui button')).find((b) => b.textContent?.includes('Share link')) as HTMLElement).click());
    await page.waitForFunction(() => window.oceano.notices().length > 0);
    const facts = await page.evaluate(() => {
      const notice = document.querySelector('.oceano-notice') as HTMLElement;
      const link = notice.querySelector('.oceano-notice-link') as HTMLElement;
      const panel = document.querySelector('.lil-gui') as HTMLElement;
      return {
        noticeRight: notice.getBoundingClientRect().right,
        panelLeft: panel.getBoundingClientRect().left,
        fits: notice.scrollWidth <= notice.clientWidth + 1,
        link: link.textContent,
        userSelect: getComputedStyle(link).userSelect,
        lines: Math.round(link.getBoundingClientRect().height / parseFloat(getComputedStyle(link).lineHeight)),
      };
    });
    expect(facts.link).toBe(url);
    expect(facts.fits).toBe(true);
    expect(facts.noticeRight).toBeLessThanOrEqual(facts.panelLeft);
    expect(facts.userSelect).toBe('all');
    expect(facts.lines).toBeGreaterThan(1);
    await page.close();
  });
});

describe('booting', () => {
  it('opened from disk, says in words to serve it over http(s), and oceano.ready rejects with that reason', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    await page.goto(pathToFileURL(join(import.meta.dirname, '..', '..', 'dist', 'index.html')).href, { waitUntil: 'load' });
    const facts = await page.evaluate(async () => {
      const api = (window as { oceano?: unknown }).oceano as { ready?: Promise<void> } | undefined;
      let rejection = 'did not reject';
      try {
        await api?.ready;
      } catch (error) {
        rejection = (error as Error).message;
      }
      const fatal = document.querySelector('.oceano-fatal') as HTMLElement | null;
      return { isElement: api instanceof Element, rejection, text: fatal?.innerText ?? '', visible: fatal !== null && fatal.getBoundingClientRect().height > 0 };
    });
    expect(facts.isElement).toBe(false);
    expect(facts.text).toMatch(/served over http\(s\)/);
    expect(facts.text).toContain('python3 -m http.server 8000');
    expect(facts.visible).toBe(true);
    expect(facts.rejection).toBe(facts.text);
    await page.close();
  });

  it('without WebGL2, oceano.ready rejects with the reason shown on the page', async () => {
    const page = await harness.browser.newPage();
    await page.evaluateOnNewDocument(() => {
      const original = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, kind: string, ...rest: unknown[]) {
        return kind === 'webgl2' ? null : (original as (k: string, ...r: unknown[]) => RenderingContext | null).call(this, kind, ...rest);
      } as typeof original;
    });
    await page.goto(harness.baseUrl, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined, { timeout: 10_000 });
    const rejection = await page.evaluate(() => window.oceano.ready.then(() => 'resolved', (error: Error) => error.message));
    expect(rejection).toMatch(/WebGL2/);
    expect(await page.$eval('.oceano-fatal', (el) => (el as HTMLElement).innerText)).toBe(rejection);
    await page.close();
  });
});

describe('Spanish page', () => {
  it('says a missing boat in Spanish only, and labels the Fresnel plot in Spanish', async () => {
    const { page } = await openOcean(harness, 'lang=es&t=2&fresnelPlot=1&boat=models/none.glb', 640, 360);
    const facts = await page.evaluate(() => ({ notices: window.oceano.notices(), plot: document.querySelector('.oceano-fresnel-plot')!.getAttribute('aria-label') }));
    // The preview server answers a missing file with its index page (boatWebPage) or a 404 (boatNotFound): either, all in Spanish.
    expect(facts.notices).toHaveLength(1);
    expect(facts.notices[0]).toMatch(/^(No se encontró el modelo del barco "models\/none\.glb" \(HTTP 404\)|Falta el modelo del barco "models\/none\.glb": el servidor envió una página web en su lugar)\. El océano sigue sin él\.$/);
    expect(facts.plot).toMatch(/^Gráfico de la reflectancia de Fresnel/);
    const plotPng = async () => Buffer.from(await (await page.$('.oceano-fresnel-plot'))!.screenshot({ type: 'png' }));
    const spanish = await plotPng();
    const english = await openOcean(harness, 'lang=en&t=2&fresnelPlot=1', 640, 360);
    const englishPlot = Buffer.from(await (await english.page.$('.oceano-fresnel-plot'))!.screenshot({ type: 'png' }));
    // Same curves, other words: the pictures differ only by their labels.
    expect(diffPngs(spanish, englishPlot, 0).differentPixels).toBeGreaterThan(200);
    await english.page.close();
    await page.close();
  });
});

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
      await session.send('Emulation.setEmulatedMedia', { features: [{ name: 'hover', value: 'none' }, { name: 'pointer', value: 'coarse' }] });
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

      const play = await page.$eval('.oceano-play', (b) => ({ pressed: b.getAttribute('aria-pressed'), label: b.getAttribute('aria-label') }));
      expect(play).toEqual({ pressed: null, label: 'Play' });
      await page.click('.oceano-play');
      expect(await page.$eval('.oceano-play', (b) => [b.getAttribute('aria-pressed'), b.getAttribute('aria-label')])).toEqual([null, 'Pause']);

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

describe('content security policy', () => {
  const STRICT = "default-src 'self'; style-src 'self' 'unsafe-inline'";

  it(`runs clean under "${STRICT}", the panel's icon font included`, async () => {
    const html = readFileSync(join(import.meta.dirname, '..', '..', 'dist', 'index.html'), 'utf8');
    const strict = html.replace(/<meta http-equiv="Content-Security-Policy" content="[^"]*"/, `<meta http-equiv="Content-Security-Policy" content="${STRICT}"`);
    expect(strict).toContain(STRICT);
    const page = await harness.browser.newPage();
    const violations: string[] = [];
    const errors: string[] = [];
    const requests: string[] = [];
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.exposeFunction('__violation', (text: string) => violations.push(text));
    await page.evaluateOnNewDocument(() => {
      document.addEventListener('securitypolicyviolation', (e) => (window as unknown as { __violation(t: string): void }).__violation(`${e.effectiveDirective} ${e.blockedURI}`));
    });
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      requests.push(request.url());
      if (request.url().split('?')[0] === harness.baseUrl) void request.respond({ status: 200, contentType: 'text/html', body: strict });
      else void request.continue();
    });
    await page.setViewport({ width: 800, height: 600, deviceScaleFactor: 1 });
    await page.goto(`${harness.baseUrl}?t=1`, { waitUntil: 'load' });
    await page.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
    await page.evaluate(() => window.oceano.ready);
    // A checked box draws its ✓ in lil-gui's icon font: make sure the font is wanted and loaded.
    await page.evaluate(() => document.querySelectorAll<HTMLElement>('.lil-gui .lil-title').forEach((t) => t.parentElement!.classList.contains('lil-closed') && t.click()));
    const fontLoaded = await page.evaluate(async () => {
      await document.fonts.ready;
      return document.fonts.check('12px "lil-gui"', '✓') && Array.from(document.fonts).some((f) => f.family.replaceAll('"', '') === 'lil-gui' && f.status === 'loaded');
    });
    expect(violations).toEqual([]);
    expect(errors).toEqual([]);
    expect(fontLoaded).toBe(true);
    expect(requests.some((url) => url.endsWith('fonts/lil-gui.woff2'))).toBe(true);
    await page.close();
  });
});

describe('packaging', () => {
  const dist = join(import.meta.dirname, '..', '..', 'dist');
  const scripts = [...readdirSync(join(dist, 'assets')).filter((f) => f.endsWith('.js')).map((f) => `assets/${f}`), 'oceano.js'];
  const text = (file: string) => readFileSync(join(dist, file), 'utf8');

  it('ships minified scripts, three.js once, imported by both the page and oceano.js', () => {
    for (const file of scripts) {
      const code = text(file);
      // Minified: no indented methods, no class keeping its source name (GLSL strings keep their lines, so line length says nothing).
      expect(code, file).not.toMatch(/\n\s+constructor\(/);
      expect(code, file).not.toMatch(/class (OceanApp|WebGLRenderer|OceanView)\b/);
    }
    const withThree = scripts.filter((file) => text(file).includes('THREE.WebGLRenderer'));
    expect(withThree).toHaveLength(1);
    const threeChunk = withThree[0].split('/').pop()!;
    const entry = pageEntry(dist);
    expect(text(entry)).toContain(threeChunk);
    expect(text('oceano.js')).toContain(threeChunk);
    // What a page loads before its first frame: its entry and what that imports statically
    // (scripts/build/distScripts.ts, which the bench's size figures use too). Chunks loaded only on
    // use (the physics panel's plots, the FFT twin's worker) are left out.
    const sizes = scriptSizes(dist);
    const loaded = new Set([...sizes.pageFiles, ...staticImports(dist, 'oceano.js')]);
    expect(loaded.size).toBeLessThan(scripts.length);
    // Fetched on first use, never before the first frame: the glTF loader (with the boat), the
    // underwater passes, the FFT and Gerstner models, the control panel (lil-gui, after the
    // first frame), the physics estimators, the GPU probe and the sky prefiltered for the seed's sea.
    for (const lazy of ['GLTFLoader', 'oceanUnderwater', 'fftModelCode', 'gerstnerModelCode', 'controlPanel', 'physicsReport', 'surfaceProbe', 'prefilteredSky']) {
      const chunk = scripts.find((file) => file.startsWith(`assets/${lazy}-`));
      expect(chunk, lazy).toBeDefined();
      expect(loaded.has(chunk!), lazy).toBe(false);
    }
    // Measured 195.8 KB for the page and 1.9 KB more for oceano.js (three.js's core alone
    // 142 KB); 194.3 KB before the near-bands program and the fitted near plane joined; 218.2 KB before the FFT and Gerstner models, lil-gui, the physics estimators
    // and the GPU probe became chunks fetched on use (issue 14's target: 200); 216.7 KB
    // before the latest joined; before the shaders' comments were left out of the build, 226.6 KB for the page;
    // 218 KB before the wake, the compare view and geomorphing joined; before the glTF loader
    // and the underwater passes moved out, 237 KB; before one shared build, 205 + 283 KB.
    // Issue 14's targets are 200 and 20.
    expect(sizes.pageKB).toBeLessThanOrEqual(200);
    expect(sizes.componentExtraKB).toBeLessThan(20);
    // The shaders arrive without their comments (scripts/build/glslMinify.ts) but with their code.
    const shaderCode = sizes.pageFiles.map(text).join('\n');
    expect(shaderCode).toContain('vec3 waveDisplacement(vec2 gridXZ)');
    expect(shaderCode).not.toContain('// The contract every model');
  });
});

describe('live LOD counts', () => {
  // Wireframe counts its triangles.
  it('the panel agrees with stats() after every change of a paused view, Dive included', async () => {
    const { page } = await openOcean(harness, 't=1', 800, 600);
    const agree = async () => {
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      return page.evaluate(() => {
        const value = (name: string) => {
          const row = Array.from(document.querySelectorAll('.lil-controller')).find((c) => c.querySelector('.lil-name')?.textContent === name);
          return (row?.querySelector('input') as HTMLInputElement | null)?.value ?? '';
        };
        const s = window.oceano.stats();
        return {
          panel: [value('Chunks visible / total'), value('Triangles'), value('Draw calls')],
          stats: [`${s.chunksVisible} / ${s.chunksTotal}`, s.triangles.toLocaleString('en-US'), String(s.drawCalls)],
        };
      });
    };
    await page.evaluate(() => window.oceano.setParams({ lodDistance: 400 }));
    await page.evaluate(() => window.oceano.setCamera({ position: [30, 12, 60], target: [0, 0, -80] }));
    let now = await agree();
    expect(now.panel).toEqual(now.stats);
    await page.evaluate(() => (Array.from(document.querySelectorAll<HTMLElement>('.lil-gui button')).find((b) => b.textContent?.includes('Dive')) as HTMLElement).click());
    await page.evaluate(() => window.oceano.loaded());
    now = await agree();
    expect(now.panel).toEqual(now.stats);
    const solid = await page.evaluate(() => window.oceano.stats().triangles);
    await page.evaluate(() => window.oceano.setParams({ wireframe: true }));
    now = await agree();
    expect(now.panel).toEqual(now.stats);
    const wire = await page.evaluate(() => window.oceano.stats().triangles);
    // The same chunks drawn as lines: the same triangles (the boat, solid either way, included).
    expect(wire).toBe(solid);
    await page.close();
  });
});

describe('share link and the boat', () => {
  const settle = (page: import('puppeteer').Page, ms: number) => page.evaluate((wait) => new Promise((r) => setTimeout(r, wait)), ms);

  for (const steered of [false, true]) {
    it(`reopens a ${steered ? 'steered' : 'free-running'} boat where it was, pixel for pixel`, async () => {
      const { page } = await openOcean(harness, 'seed=3', 640, 360);
      if (steered) {
        // Under SwiftShader a frame takes 0.1 s of simulated time at most (the clock clamps it),
        // so a second of keys moves the boat only metres: start at speed.
        await page.evaluate(() => window.oceano.setParams({ boatSpeed: 6 }));
        await page.keyboard.down('KeyW');
        await settle(page, 1500);
        await page.keyboard.up('KeyW');
        await page.keyboard.down('KeyD');
        await settle(page, 800);
        await page.keyboard.up('KeyD');
      } else {
        await settle(page, 2000);
      }
      await page.evaluate(() => window.oceano.pause());
      const original = await canvasPng(page);
      const boat = await page.evaluate(() => window.oceano.boat());
      const url = await page.evaluate(() => window.oceano.shareUrl());
      expect(url).toContain('boatState=');
      if (steered) expect(Math.hypot(boat.position[0] - 7, boat.position[2] + 5)).toBeGreaterThan(0.01);
      const shared = await harness.browser.newPage();
      await shared.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
      await shared.goto(url, { waitUntil: 'load' });
      await shared.waitForFunction(() => (window as { oceano?: unknown }).oceano !== undefined);
      await shared.evaluate(() => window.oceano.ready);
      const again = await shared.evaluate(() => window.oceano.boat());
      expect(again.position).toEqual(boat.position);
      expect([again.heading, again.pitch, again.roll]).toEqual([boat.heading, boat.pitch, boat.roll]);
      expect(diffPngs(original, await canvasPng(shared), 0).differentPixels).toBe(0);
      await shared.close();
      await page.close();
    });
  }
});

describe('loading', () => {
  /**
   * Every painted state of the indicator, recorded once per animation frame from before the
   * page's own scripts run: a state that never reaches a frame was never seen by anyone.
   */
  function recordPaintedLoadingStates(): void {
    const seen: string[] = [];
    (window as unknown as { __loadingSeen: string[] }).__loadingSeen = seen;
    const look = () => {
      const box = document.querySelector('.oceano-loading');
      const state = box ? Array.from(box.querySelectorAll('li')).map((li) => `${li.dataset.step}:${li.dataset.state}`).join(' ') || 'static' : 'none';
      if (seen[seen.length - 1] !== state) seen.push(state);
      requestAnimationFrame(look);
    };
    requestAnimationFrame(look);
  }

  // From the first paint: before the script runs.
  it('shows progress from the first paint, while the first frame is drawn, and while the boat loads', async () => {
    const page = await harness.browser.newPage();
    await page.setViewport({ width: 640, height: 360, deviceScaleFactor: 1 });
    page.setDefaultTimeout(120_000);
    await page.evaluateOnNewDocument(recordPaintedLoadingStates);
    const held = new Map<string, () => void>();
    await page.setRequestInterception(true);
    page.on('request', (request) => {
      const url = request.url();
      const which = /\/assets\/index-[^/]*\.js$/.test(url) ? 'script' : url.endsWith('models/boat.glb') ? 'boat' : null;
      if (which) held.set(which, () => void request.continue());
      else void request.continue();
    });
    const opened = page.goto(`${harness.baseUrl}?t=4`, { waitUntil: 'load' });
    await page.waitForFunction(() => document.querySelector('.oceano-loading') !== null);
    await new Promise((resolve) => setTimeout(resolve, 300));
    const beforeScript = await page.evaluate(() => {
      const box = document.querySelector('.oceano-loading') as HTMLElement;
      const r = box.getBoundingClientRect();
      return { api: typeof (window as { oceano?: unknown }).oceano, text: box.textContent, visible: r.width > 50 && r.height > 10 && getComputedStyle(box).visibility === 'visible' };
    });
    expect(held.has('script')).toBe(true);
    expect(beforeScript).toEqual({ api: 'undefined', text: 'Loading Oceano…', visible: true });
    held.get('script')!();
    await page.waitForFunction(() => document.querySelector('.oceano-loading li[data-step="boat"][data-state="active"]') !== null);
    const whileBoat = await page.evaluate(() => ({
      steps: Array.from(document.querySelectorAll('.oceano-loading li')).map((li) => `${(li as HTMLElement).dataset.step}:${(li as HTMLElement).dataset.state}`),
      role: document.querySelector('.oceano-loading')!.getAttribute('role'),
    }));
    expect(whileBoat).toEqual({ steps: ['sky:done', 'firstFrame:done', 'boat:active'], role: 'status' });
    for (let waited = 0; !held.has('boat') && waited < 10_000; waited += 50) await new Promise((resolve) => setTimeout(resolve, 50));
    expect(held.has('boat')).toBe(true);
    held.get('boat')!();
    await opened;
    await page.evaluate(() => window.oceano.ready);
    const painted = await page.evaluate(() => (window as unknown as { __loadingSeen: string[] }).__loadingSeen);
    // The first frame holds the main thread for seconds on a software GPU: its step must have been painted first.
    const firstFrameShown = painted.indexOf('sky:done firstFrame:active boat:pending');
    expect(firstFrameShown).toBeGreaterThan(painted.indexOf('static'));
    expect(painted.indexOf('static')).toBeGreaterThanOrEqual(0);
    expect(painted[painted.length - 1]).toBe('none');
    await page.close();
  });
});
