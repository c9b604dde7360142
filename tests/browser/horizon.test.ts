import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();
const FOV = 55;
type Vec3 = [number, number, number];

/**
 * Magenta pixels whose ray points below the horizon by more than one pixel's angle. For a
 * flat sea the horizon lies at the eye's height (the view ray's elevation is 0), so every
 * such pixel must be sea; one pixel of margin allows for the waves on the horizon line.
 */
function skyBelowHorizon(png: Buffer, position: Vec3, target: Vec3): { magenta: number; checked: number } {
  const { width, height, data } = PNG.sync.read(png);
  const back = position.map((p, k) => p - target[k]) as Vec3;
  const bl = Math.hypot(...back);
  const z = back.map((v) => v / bl) as Vec3;
  const xl = Math.hypot(z[2], z[0]);
  const x: Vec3 = [z[2] / xl, 0, -z[0] / xl];
  const y: Vec3 = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]];
  const t = Math.tan((FOV / 2) * (Math.PI / 180));
  const pixelAngle = (2 * t) / height;
  let magenta = 0;
  let checked = 0;
  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const cx = ((px + 0.5) / width) * 2 - 1;
      const cy = 1 - ((py + 0.5) / height) * 2;
      const dir = [0, 1, 2].map((k) => x[k] * cx * t * (width / height) + y[k] * cy * t - z[k]);
      if (-dir[1] / Math.hypot(dir[0], dir[2]) < pixelAngle) continue;
      checked++;
      const o = (py * width + px) * 4;
      if (data[o] > 200 && data[o + 1] < 80 && data[o + 2] > 200) magenta++;
    }
  }
  return { magenta, checked };
}

async function oceanOnMagenta(page: Page): Promise<void> {
  await page.evaluate(() => {
    const { scene, renderer } = window.oceano.three;
    // The sky mesh out of the scene: what the sea does not cover shows the clear colour.
    scene.getObjectByName('oceano-sky')!.removeFromParent();
    renderer.setClearColor(0xff00ff, 1);
  });
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

describe('the sea reaches the horizon', () => {
  it('leaves no row below the horizon without sea, from 2 m to 10 km up, looking level and 20° down', async () => {
    const { page, consoleErrors } = await openOcean(harness, 't=10', 480, 270);
    await oceanOnMagenta(page);
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
    await page.close();
  }, 240_000);

  it('finds the gap when the far rings and the skirt are hidden (the check can fail)', async () => {
    const { page } = await openOcean(harness, 't=10', 480, 270);
    await oceanOnMagenta(page);
    await page.evaluate(() => {
      window.oceano.three.scene.traverse((o) => {
        const mesh = o as unknown as { geometry?: { isInstancedBufferGeometry?: boolean; getAttribute?: (n: string) => { count: number } | undefined }; material?: { uniforms?: Record<string, unknown> }; visible: boolean };
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
    await page.close();
  });
});
