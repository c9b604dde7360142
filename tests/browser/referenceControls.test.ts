import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { measureDifference, REFERENCE_DIR, withinTolerance, describeDifference } from './imageCompare';
import { REFERENCE_VIEWS } from './referenceViews';

/**
 * The reference comparison itself, on the committed files: it must pass a picture against
 * itself and fail the faults a blind comparison would let through. (The same controls on
 * freshly drawn pictures are in pageState.test.ts and surface.test.ts.)
 */
const read = (name: string) => readFileSync(join(REFERENCE_DIR, `${name}.png`));

/** The picture with every pixel below `fromRow` scaled by `factor`: the sea's colour changed, the sky kept. */
function scaleBelow(png: Buffer, fromRow: number, factor: number): Buffer {
  const image = PNG.sync.read(png);
  for (let y = fromRow; y < image.height; y++) {
    for (let x = 0; x < image.width; x++) {
      for (let c = 0; c < 3; c++) {
        const i = (y * image.width + x) * 4 + c;
        image.data[i] = Math.min(255, Math.round(image.data[i] * factor));
      }
    }
  }
  return PNG.sync.write(image);
}

describe('reference comparison: negative controls on the committed images', () => {
  it('passes each reference against itself', () => {
    for (const view of REFERENCE_VIEWS) {
      const png = read(view.name);
      // Once from the bytes, so the comparison decodes the file as it does in the suite.
      expect(withinTolerance(measureDifference(png, PNG.sync.read(png))), view.name).toBe(true);
    }
  });

  it('fails normals-wrong against normals-right', () => {
    const d = measureDifference(read('preset-normals-right'), read('preset-normals-wrong'));
    expect(withinTolerance(d), describeDifference(d)).toBe(false);
  });

  it('fails the default view with its sea (lower half) 3 % darker or 3 % brighter', () => {
    const original = read('surface-seed1-t10');
    for (const factor of [0.97, 1.03]) {
      const d = measureDifference(original, scaleBelow(original, 180, factor));
      expect(withinTolerance(d), `×${factor}: ${describeDifference(d)}`).toBe(false);
    }
  });

  it('fails every reference against every other of its size', () => {
    const pictures = REFERENCE_VIEWS.map((view) => ({
      name: view.name,
      png: PNG.sync.read(read(view.name)),
      size: `${view.width}×${view.height}`,
    }));
    for (const a of pictures) {
      for (const b of pictures) {
        if (a.name >= b.name || a.size !== b.size) continue;
        const d = measureDifference(a.png, b.png);
        expect(withinTolerance(d), `${a.name} vs ${b.name}: ${describeDifference(d)}`).toBe(false);
      }
    }
  });
});
