import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';

/**
 * The beach seen from 300 m up, its shoreline (x = 400 m) down the middle of the picture: sand
 * on the right, the surf's foam just left of the shore, turquoise shallows farther left. The
 * same camera over the open sea (bathymetry=deep) is the negative control: none of the three.
 */
const CAMERA = 'cam=400,300,150,400,0,0&t=10';
const harness = useHarness();

interface Region {
  r: number;
  g: number;
  b: number;
  /** Share of the region's pixels that are foam: bright, and no warmer than white (sand is warmer). */
  foam: number;
}

/** Mean colour and foam share of the columns between fractions `from` and `to` of the width (rows 20–80 %). */
function region(png: PNG, from: number, to: number): Region {
  let r = 0;
  let g = 0;
  let b = 0;
  let n = 0;
  let foam = 0;
  for (let y = Math.floor(png.height * 0.2); y < png.height * 0.8; y++) {
    for (let x = Math.floor(png.width * from); x < png.width * to; x++) {
      const i = (y * png.width + x) * 4;
      const [pr, pg, pb] = [png.data[i], png.data[i + 1], png.data[i + 2]];
      r += pr;
      g += pg;
      b += pb;
      n++;
      if (Math.min(pr, pg, pb) > 175 && pb >= pr) foam++;
    }
  }
  return { r: r / n, g: g / n, b: b / n, foam: foam / n };
}

async function picture(query: string): Promise<{ sand: Region; surf: Region; shallows: Region }> {
  const { page, consoleErrors } = await openOcean(harness, query);
  expect(consoleErrors).toEqual([]);
  const png = PNG.sync.read(await canvasPng(page));
  await page.close();
  return { sand: region(png, 0.6, 0.95), surf: region(png, 0.25, 0.5), shallows: region(png, 0.02, 0.2) };
}

const isSand = (c: Region) => c.r > c.b + 8 && (c.r + c.g + c.b) / 3 > 140;
const isTurquoise = (c: Region) => c.g > 1.5 * c.r && c.b > 1.5 * c.r && c.g > 90;

describe('the beach', () => {
  it('draws sand above the shore, surf foam at it and turquoise shallows off it', async () => {
    const { sand, surf, shallows } = await picture(`preset=beach&${CAMERA}`);
    console.log(
      `[oceano] beach from 300 m: sand ${JSON.stringify(sand)}, surf ${JSON.stringify(surf)}, shallows ${JSON.stringify(shallows)}`,
    );
    expect(isSand(sand)).toBe(true);
    expect(surf.foam).toBeGreaterThan(0.02);
    expect(isTurquoise(shallows)).toBe(true);
  });

  it('negative control: the open sea under the same camera has none of them', async () => {
    const { sand, surf, shallows } = await picture(`preset=beach&bathymetry=deep&${CAMERA}`);
    console.log(
      `[oceano] open sea from 300 m: sand ${JSON.stringify(sand)}, surf ${JSON.stringify(surf)}, shallows ${JSON.stringify(shallows)}`,
    );
    expect(isSand(sand)).toBe(false);
    expect(surf.foam).toBeLessThan(0.005);
    expect(isTurquoise(shallows)).toBe(false);
  });
});
