import { afterAll, describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean, type OpenedPage } from './harness';
import { useHarness } from './useHarness';
import { magentaBelowSlope, pixelAngle, showMagentaBehindTheSea, type Vec3 } from './viewRays';

const harness = useHarness();

/**
 * Magenta pixels whose ray points below the horizon by more than one pixel's angle. For a
 * flat sea the horizon lies at the eye's height (the view ray's elevation is 0), so every
 * such pixel must be sea; one pixel of margin allows for the waves on the horizon line.
 */
function skyBelowHorizon(png: Buffer, position: Vec3, target: Vec3): { magenta: number; checked: number } {
  return magentaBelowSlope(png, position, target, pixelAngle);
}

async function lookFrom(page: Page, position: Vec3, target: Vec3): Promise<Buffer> {
  await page.evaluate((pose) => window.oceano.setCamera(pose), { position, target });
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  return canvasPng(page);
}

const HEIGHTS = [2, 100, 500, 2000, 10_000];
const PITCHES = [0, -20];

function pose(height: number, pitch: number): { position: Vec3; target: Vec3 } {
  const position: Vec3 = [130, height, -70];
  const p = (pitch * Math.PI) / 180;
  const target: Vec3 = [position[0] + 1000 * Math.cos(p) * 0.6, height + 1000 * Math.sin(p), position[2] - 1000 * Math.cos(p) * 0.8];
  return { position, target };
}

/**
 * One t=10 page at 480×270 with the sky taken out, for both tests (each boot costs seconds of
 * SwiftShader work). The control, which hides the far rings and the skirt for good, comes
 * last in the file; run alone (-t) it opens the page itself.
 */
let magentaPage: Promise<OpenedPage> | undefined;
const openMagentaPage = () =>
  (magentaPage ??= openOcean(harness, 't=10', 480, 270).then(async (opened) => {
    await showMagentaBehindTheSea(opened.page);
    return opened;
  }));
afterAll(async () => {
  if (magentaPage) await (await magentaPage).page.close();
});

describe('the sea reaches the horizon', () => {
  it('leaves no row below the horizon without sea, from 2 m to 10 km up, looking level and 20° down', async () => {
    const { page, consoleErrors } = await openMagentaPage();
    const found: string[] = [];
    for (const height of HEIGHTS) {
      for (const pitch of PITCHES) {
        const { position, target } = pose(height, pitch);
        const { magenta, checked } = skyBelowHorizon(await lookFrom(page, position, target), position, target);
        expect(checked).toBeGreaterThan(1000);
        if (magenta > 0) found.push(`${height} m, pitch ${pitch}°: ${magenta} of ${checked} pixels`);
      }
    }
    expect(found).toEqual([]);
    expect(consoleErrors).toEqual([]);
  }, 240_000);

  it('finds the gap when the far rings and the skirt are hidden (the check can fail)', async () => {
    const { page } = await openMagentaPage();
    await page.evaluate(() => {
      window.oceano.three.scene.traverse((o) => {
        const mesh = o as unknown as {
          geometry?: { isInstancedBufferGeometry?: boolean; getAttribute?: (n: string) => { count: number } | undefined };
          material?: { uniforms?: Record<string, unknown> };
          visible: boolean;
        };
        if (!mesh.geometry?.getAttribute || !mesh.material?.uniforms?.uFarFade) return;
        const vertices = mesh.geometry.getAttribute('position')?.count ?? 0;
        // The skirt (not instanced) and the ring cells' grid (7 × 7 vertices).
        if (!mesh.geometry.isInstancedBufferGeometry || vertices === 49) {
          mesh.visible = false;
          Object.defineProperty(mesh, 'visible', { get: () => false, set: () => undefined });
        }
      });
    });
    const { position, target } = pose(500, 0);
    const { magenta } = skyBelowHorizon(await lookFrom(page, position, target), position, target);
    expect(magenta).toBeGreaterThan(1000);
  });
});
