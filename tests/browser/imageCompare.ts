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

/**
 * Compares a screenshot with its committed reference (pixelmatch per-pixel threshold 0.1,
 * the same as three.js's screenshot suite). Writes the actual image and the diff to
 * __output__/ so a failure can be looked at.
 */
export function compareWithReference(name: string, png: Buffer): Comparison {
  const referencePath = join(REFERENCE_DIR, `${name}.png`);
  if (updatingReferences || !existsSync(referencePath)) {
    if (!updatingReferences) throw new Error(`No reference image ${referencePath}; run \`npm run references\` to create it.`);
    mkdirSync(REFERENCE_DIR, { recursive: true });
    writeFileSync(referencePath, png);
    return { differentPixels: 0, share: 0 };
  }
  mkdirSync(OUTPUT_DIR, { recursive: true });
  writeFileSync(join(OUTPUT_DIR, `${name}.actual.png`), png);
  return diffPngs(readFileSync(referencePath), png, 0.1, join(OUTPUT_DIR, `${name}.diff.png`));
}
