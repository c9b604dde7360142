import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';

/**
 * Gerstner's long waves are summed per vertex and their derivatives interpolated, the short
 * ones per pixel (shaders/waves/gerstner.glsl). Where that shows, the normal must stay the
 * closed form's: the normals view of the steepness lesson (its 3.9 m crests per pixel) against
 * the same frame with every wave summed per pixel. Control: every wave per vertex.
 */
const harness = useHarness();
const VIEW = { query: 'preset=gerstner-steepness&shading=normals&t=10', width: 640, height: 360, seaRows: [180, 360] } as const;

/** The frame with the ocean's vertex shaders' split bound set to `bound` (0: every wave per pixel; huge: every wave per vertex). */
async function withSplit(page: Page, bound: string): Promise<Buffer> {
  await page.evaluate((value) => {
    const o = window.oceano;
    o.pause();
    o.three.scene.traverse((object) => {
      const material = (
        object as {
          material?: { uniforms?: Record<string, unknown>; vertexShader: string; needsUpdate: boolean; userData: Record<string, unknown> };
        }
      ).material;
      if (!material?.uniforms?.uEyeRelative) return;
      material.userData.shipped ??= material.vertexShader;
      const shipped = material.userData.shipped as string;
      const line = 'const float GERSTNER_VERTEX_SLOPE_ERROR = 0.02;';
      if (!shipped.includes(line)) throw new Error("The ocean's vertex shader has no split bound to set.");
      material.vertexShader = shipped.split(line).join(`const float GERSTNER_VERTEX_SLOPE_ERROR = ${value};`);
      material.needsUpdate = true;
    });
    o.renderFrame();
  }, bound);
  return canvasPng(page);
}

/** Mean absolute difference per channel, levels, over the rows of the sea below the horizon. */
function meanDifference(a: Buffer, b: Buffer): number {
  const [A, B] = [PNG.sync.read(a), PNG.sync.read(b)];
  let sum = 0;
  let count = 0;
  for (let y = VIEW.seaRows[0]; y < VIEW.seaRows[1]; y++) {
    for (let x = 0; x < A.width; x++) {
      for (let c = 0; c < 3; c++) {
        const i = 4 * (y * A.width + x) + c;
        sum += Math.abs(A.data[i] - B.data[i]);
        count++;
      }
    }
  }
  return sum / count;
}

describe("Gerstner's normal: long waves per vertex, short ones per pixel", () => {
  // Control: every wave per vertex differs by over 0.5.
  it('draws the closed-form normal within 0.1 level of every wave per pixel', { timeout: 120_000 }, async () => {
    const { page } = await openOcean(harness, VIEW.query, VIEW.width, VIEW.height);
    const shipped = await withSplit(page, '0.02');
    const perPixel = await withSplit(page, '0.0');
    const perVertex = await withSplit(page, '1e9');
    await page.close();
    // Measured: 0.01 and 1.3 levels.
    expect(meanDifference(shipped, perPixel)).toBeLessThan(0.1);
    expect(meanDifference(perVertex, perPixel)).toBeGreaterThan(0.5);
  });
});
