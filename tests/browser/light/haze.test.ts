import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';

/**
 * The sea seen from 500 m up is the sea, not a pale haze (src/sim/optics/haze.ts): away from
 * the glint it is darker than the sky just above the horizon. The measure is the difference
 * in mean luminance (0–255) between the sky's rows 100–129 and the sea's rows 200–359, both
 * on the left third of a 640×360 frame, where the glint is not. The haze of a 3.26 km
 * visibility at every height (the extinction 0.0012 m⁻¹ the sea had before) is the control:
 * it lays the horizon's colour over the sea.
 */
const harness = useHarness();
const VIEW = 't=10&cam=0,500,0,0,300,-2000';

async function seaBelowSky(extra: string): Promise<number> {
  const { page } = await openOcean(harness, `${VIEW}&${extra}`, 640, 360);
  const png = PNG.sync.read(await canvasPng(page));
  await page.close();
  const meanLuma = (y0: number, y1: number) => {
    let sum = 0;
    for (let y = y0; y < y1; y++) for (let x = 0; x < 213; x++) {
      const i = (y * 640 + x) * 4;
      sum += 0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2];
    }
    return sum / ((y1 - y0) * 213);
  };
  return meanLuma(100, 130) - meanLuma(200, 360);
}

describe('the haze', () => {
  it('leaves the sea seen from 500 m darker than the horizon’s sky on every wave model (control: the old 3.26 km haze)', async () => {
    const measured: Record<string, number> = {};
    for (const waves of ['seed', 'fft', 'gerstner']) measured[waves] = await seaBelowSky(`waves=${waves}`);
    const control = await seaBelowSky('waves=seed&visibility=3.26');
    console.log(`[oceano] sky minus sea from 500 m: ${JSON.stringify(measured)}; 3.26 km haze ${control.toFixed(1)}`);
    for (const difference of Object.values(measured)) expect(difference).toBeGreaterThan(40);
    expect(control).toBeLessThan(40);
  });
});
