import { PNG } from 'pngjs';
import type { Page } from 'puppeteer';

/** The app's vertical field of view, degrees (src/render/ocean/oceanView.ts). */
export const FOV = 55;
export type Vec3 = [number, number, number];

/** World direction of the ray through pixel (px, py) of a camera at `position` looking at `target`. */
export function pixelRay(px: number, py: number, width: number, height: number, position: Vec3, target: Vec3): Vec3 {
  const back = position.map((p, k) => p - target[k]) as Vec3;
  const bl = Math.hypot(...back);
  const z = back.map((v) => v / bl) as Vec3;
  const xl = Math.hypot(z[2], z[0]);
  const x: Vec3 = [z[2] / xl, 0, -z[0] / xl];
  const y: Vec3 = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]];
  const t = Math.tan((FOV / 2) * (Math.PI / 180));
  const cx = ((px + 0.5) / width) * 2 - 1;
  const cy = 1 - ((py + 0.5) / height) * 2;
  const d = [0, 1, 2].map((k) => x[k] * cx * t * (width / height) + y[k] * cy * t - z[k]) as Vec3;
  const l = Math.hypot(...d);
  return d.map((v) => v / l) as Vec3;
}

/** One pixel's angle at the picture's centre, radians: the finest step a ray's dip can take. */
export function pixelAngle(height: number): number {
  return (2 * Math.tan((FOV / 2) * (Math.PI / 180))) / height;
}

/**
 * Takes the sky out of the scene and clears to magenta, so every pixel the sea does not
 * cover shows as magenta.
 */
export async function showMagentaBehindTheSea(page: Page): Promise<void> {
  await page.evaluate(() => {
    const { scene, renderer } = window.oceano.three;
    scene.getObjectByName('oceano-sky')!.removeFromParent();
    renderer.setClearColor(0xff00ff, 1);
  });
}

/**
 * Magenta pixels among those whose view ray dips below the horizontal by at least
 * `minSlope(height)` (tan of the dip), and how many such pixels there were.
 */
export function magentaBelowSlope(
  png: Buffer,
  position: Vec3,
  target: Vec3,
  minSlope: (height: number) => number,
): { magenta: number; checked: number } {
  const { width, height, data } = PNG.sync.read(png);
  const slope = minSlope(height);
  let magenta = 0;
  let checked = 0;
  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const dir = pixelRay(px, py, width, height, position, target);
      if (-dir[1] / Math.hypot(dir[0], dir[2]) < slope) continue;
      checked++;
      const o = (py * width + px) * 4;
      if (data[o] > 200 && data[o + 1] < 80 && data[o + 2] > 200) magenta++;
    }
  }
  return { magenta, checked };
}
