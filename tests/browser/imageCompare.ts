import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import pixelmatch from 'pixelmatch';
import { PNG } from 'pngjs';

export const REFERENCE_DIR = join(import.meta.dirname, 'references');
const OUTPUT_DIR = join(import.meta.dirname, '__output__');

/** Set UPDATE_REFERENCES=1 (npm run references) to rewrite the committed reference images on purpose. */
export const updatingReferences = process.env.UPDATE_REFERENCES === '1';

export interface Comparison {
  differentPixels: number;
  share: number;
}

/**
 * Perceptual count of changed pixels (pixelmatch). For "did anything move" checks between
 * two pictures drawn in the same test (threshold 0: any change at all); reference images
 * are compared with {@link measureDifference} instead, which sees shading.
 */
export function diffPngs(a: Buffer, b: Buffer, threshold = 0.1, diffPath?: string): Comparison {
  const left = PNG.sync.read(a);
  const right = PNG.sync.read(b);
  if (left.width !== right.width || left.height !== right.height) {
    throw new Error(`Image sizes differ: ${left.width}×${left.height} vs ${right.width}×${right.height}.`);
  }
  const diff = new PNG({ width: left.width, height: left.height });
  const differentPixels = pixelmatch(left.data, right.data, diff.data, left.width, left.height, { threshold });
  if (diffPath && differentPixels > 0) {
    mkdirSync(dirname(diffPath), { recursive: true });
    writeFileSync(diffPath, PNG.sync.write(diff));
  }
  return { differentPixels, share: differentPixels / (left.width * left.height) };
}

/** How far apart two pictures are, channel by channel, in 8-bit levels. */
export interface ImageDifference {
  /** Mean over all pixels of |a − b| for R, G and B. */
  meanAbsError: [number, number, number];
  /** Share of pixels where some channel differs by more than REFERENCE_TOLERANCE.levels. */
  shareOverLevels: number;
  /** The largest difference of any channel at any pixel. */
  maxLevels: number;
}

/**
 * The one tolerance for reference images. What a correct picture may differ by:
 *
 * Measured with `npx tsx tests/browser/measureReferenceNoise.ts` (each of the 20 reference
 * views drawn 2 or 3 times, each on a freshly loaded page, same build, headless Chromium
 * 156 + SwiftShader on a loaded 2-core machine, 2026-11-21): every draw was bit-identical
 * to the other draws and to the committed file — mean |Δ| 0 in every channel, no pixel off
 * by even one level. The noise is 0; the limits sit just above it, leaving room for a few
 * pixels of rounding drift after a Chromium or SwiftShader update:
 * - mean |Δ| ≤ 0.05 levels in each of R, G, B, and
 * - at most 0.1 % of pixels off by more than 2 levels in some channel.
 *
 * What they catch (negative controls in referenceControls.test.ts, surface.test.ts and
 * pageState.test.ts): the deep-water colour made 3 % brighter (#06283a → #06293c) moves the
 * default view by mean |Δ| 0.12 (G) and 0.30 (B) levels, 2.4 and 6 times the limit; every
 * pair of different references differs by 3 levels or more of mean |Δ| in some channel.
 */
export const REFERENCE_TOLERANCE = { meanAbsError: 0.05, levels: 2, shareOverLevels: 0.001 } as const;

/** PNG bytes, or an image already decoded (to compare one picture with many without decoding it each time). */
export type Picture = Buffer | PNG;

function readPng(picture: Picture): PNG {
  return Buffer.isBuffer(picture) ? PNG.sync.read(picture) : picture;
}

/** Channel-by-channel difference of two pictures of one size (alpha is ignored: the canvas is opaque). */
export function measureDifference(a: Picture, b: Picture, diffPath?: string): ImageDifference {
  const left = readPng(a);
  const right = readPng(b);
  if (left.width !== right.width || left.height !== right.height) {
    throw new Error(`Image sizes differ: ${left.width}×${left.height} vs ${right.width}×${right.height}.`);
  }
  const pixels = left.width * left.height;
  const sums = [0, 0, 0];
  let over = 0;
  let maxLevels = 0;
  const diff = diffPath ? new PNG({ width: left.width, height: left.height }) : null;
  const l = left.data;
  const r = right.data;
  for (let i = 0; i < pixels; i++) {
    // The three channels unrolled (the same sums as a loop over c; this runs once per pixel
    // of every picture the preset controls compare, about 10⁸ times in the suite).
    const p = i * 4;
    const d0 = Math.abs(l[p] - r[p]);
    const d1 = Math.abs(l[p + 1] - r[p + 1]);
    const d2 = Math.abs(l[p + 2] - r[p + 2]);
    sums[0] += d0;
    sums[1] += d1;
    sums[2] += d2;
    const worst = Math.max(d0, d1, d2);
    if (worst > REFERENCE_TOLERANCE.levels) over++;
    if (worst > maxLevels) maxLevels = worst;
    if (diff) {
      // Differences in red, scaled ×8 so a few levels show; unchanged pixels grey.
      const v = Math.min(255, worst * 8);
      diff.data.set(worst === 0 ? [64, 64, 64, 255] : [Math.max(v, 96), 0, 0, 255], i * 4);
    }
  }
  if (diff && diffPath && maxLevels > 0) {
    mkdirSync(dirname(diffPath), { recursive: true });
    writeFileSync(diffPath, PNG.sync.write(diff));
  }
  return { meanAbsError: sums.map((s) => s / pixels) as [number, number, number], shareOverLevels: over / pixels, maxLevels };
}

/** Whether a difference is within {@link REFERENCE_TOLERANCE}. */
export function withinTolerance(d: ImageDifference): boolean {
  return d.meanAbsError.every((m) => m <= REFERENCE_TOLERANCE.meanAbsError) && d.shareOverLevels <= REFERENCE_TOLERANCE.shareOverLevels;
}

export function describeDifference(d: ImageDifference): string {
  const mae = d.meanAbsError.map((m) => m.toFixed(3)).join('/');
  return `mean |Δ| R/G/B = ${mae} levels (limit ${REFERENCE_TOLERANCE.meanAbsError}), ${(d.shareOverLevels * 100).toFixed(3)} % of pixels off by more than ${REFERENCE_TOLERANCE.levels} levels (limit ${REFERENCE_TOLERANCE.shareOverLevels * 100} %), largest ${d.maxLevels}`;
}

export interface ReferenceComparison extends ImageDifference {
  matches: boolean;
  /** A readable line for the assertion message. */
  summary: string;
}

function reference(name: string): Buffer {
  const referencePath = join(REFERENCE_DIR, `${name}.png`);
  if (!existsSync(referencePath)) throw new Error(`No reference image ${referencePath}; run \`npm run references\` to create it.`);
  return readFileSync(referencePath);
}

/**
 * References decoded once per test file: each preset's control compares its picture with
 * every other preset's reference, and decoding those files again for each of the 22
 * presets cost about a second per test (2026-11-22, load 6). Dropped when a reference is
 * rewritten (UPDATE_REFERENCES=1), so a control never compares with the file's old picture.
 */
const decodedReferences = new Map<string, PNG>();

function decodedReference(name: string): PNG {
  let png = decodedReferences.get(name);
  if (!png) decodedReferences.set(name, (png = PNG.sync.read(reference(name))));
  return png;
}

/**
 * Compares a picture with a committed reference without writing anything: for negative
 * controls. Pass the picture decoded (PNG.sync.read) when comparing it with many references.
 */
export function compareWithOtherReference(name: string, png: Picture): ReferenceComparison {
  const d = measureDifference(decodedReference(name), png);
  return { ...d, matches: withinTolerance(d), summary: `against ${name}.png: ${describeDifference(d)}` };
}

/**
 * Compares a screenshot with its committed reference under {@link REFERENCE_TOLERANCE}.
 * Writes the actual image and a diff to __output__/ so a failure can be looked at. With
 * UPDATE_REFERENCES=1 it writes the reference instead.
 */
export function compareWithReference(name: string, png: Buffer): ReferenceComparison {
  if (updatingReferences) {
    mkdirSync(REFERENCE_DIR, { recursive: true });
    writeFileSync(join(REFERENCE_DIR, `${name}.png`), png);
    decodedReferences.delete(name);
  }
  const expected = reference(name);
  mkdirSync(OUTPUT_DIR, { recursive: true });
  writeFileSync(join(OUTPUT_DIR, `${name}.actual.png`), png);
  const d = measureDifference(expected, png, join(OUTPUT_DIR, `${name}.diff.png`));
  return { ...d, matches: withinTolerance(d), summary: `${name}: ${describeDifference(d)}` };
}
