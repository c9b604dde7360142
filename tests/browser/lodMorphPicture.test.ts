import { describe, expect, it } from 'vitest';
import type { Page } from 'puppeteer';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();
const SIZE = 128;
/**
 * Largest mean change of a step, 8-bit levels (each pixel's largest channel difference,
 * averaged). Measured with morphing: 0.26 to 0.29 per 0.25 m step, the parallax of the
 * camera's own rise (the same on steps far from any band change); without it the band
 * change steps measured 0.49, 1.97 and 1.25. The bound sits just above the first.
 */
const MAX_STEP_CHANGE = 0.35;

/**
 * The camera looks steeply down from heights `heights` in turn (time frozen); after each
 * frame the canvas is read back and compared with the previous one. Returns each step's
 * mean over the pixels of the largest channel difference, in 8-bit levels.
 */
async function stepChanges(page: Page, heights: number[], lodMorph: boolean): Promise<number[]> {
  return page.evaluate(
    (heights, lodMorph) => {
      const o = window.oceano;
      o.setParams({ lodMorph });
      const gl = o.three.renderer.getContext();
      const { drawingBufferWidth: w, drawingBufferHeight: h } = gl;
      let previous: Uint8Array | null = null;
      const changes: number[] = [];
      for (const y of heights) {
        o.setCamera({ position: [300, y, 300], target: [300, 0, 280] });
        o.renderFrame();
        // Read in the same task as the draw, before the browser presents (and clears) the buffer.
        const pixels = new Uint8Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
        if (previous) {
          let sum = 0;
          for (let k = 0; k < pixels.length; k += 4) {
            sum += Math.max(
              Math.abs(pixels[k] - previous[k]),
              Math.abs(pixels[k + 1] - previous[k + 1]),
              Math.abs(pixels[k + 2] - previous[k + 2]),
            );
          }
          changes.push(sum / (w * h));
        }
        previous = pixels;
      }
      return changes;
    },
    heights,
    lodMorph,
  );
}

describe('geomorphing in the browser', () => {
  it('the picture changes little per step while the camera rises through a band change, and pops without morphing', async () => {
    const { page, consoleErrors } = await openOcean(harness, 'seed=1&t=10&sunElevation=80', SIZE, SIZE);
    // A high sun puts its glint below the camera, where the per-vertex normals show any pop.
    // Nearly straight below, the chunk passes from band 0 to band 1 where the camera is L = 100 m
    // above the waves' top (about 102 m): 0.25 m steps from 96 m to 108 m cross it.
    const heights = Array.from({ length: 49 }, (_, k) => 96 + k * 0.25);
    const morphing = await stepChanges(page, heights, true);
    const popping = await stepChanges(page, heights, false);
    expect(Math.max(...morphing)).toBeLessThan(MAX_STEP_CHANGE);
    // Negative control: lodMorph=false, the same steps, must break the bound.
    expect(Math.max(...popping)).toBeGreaterThan(MAX_STEP_CHANGE);
    expect(consoleErrors).toEqual([]);
  }, 300_000);
});
