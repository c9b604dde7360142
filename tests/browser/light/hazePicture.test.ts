import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { pixelRay, type Vec3 } from '../viewRays';
import { hazeExtinction, hazeWeight } from '../../../src/sim/optics/haze';
import { pixelLuminance } from '../../support/luminance';
import { srgbToLinear } from '../../support/srgb';

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
    for (let y = y0; y < y1; y++) for (let x = 0; x < 213; x++) sum += pixelLuminance(png.data, y * 640 + x);
    return sum / ((y1 - y0) * 213);
  };
  return meanLuma(100, 130) - meanLuma(200, 360);
}

describe('the haze', () => {
  // Control: a 3.26 km visibility's haze.
  it('leaves the sea seen from 500 m darker than the horizon’s sky on every wave model', async () => {
    const measured: Record<string, number> = {};
    for (const waves of ['seed', 'fft', 'gerstner']) measured[waves] = await seaBelowSky(`waves=${waves}`);
    const control = await seaBelowSky('waves=seed&visibility=3.26');
    console.log(`[oceano] sky minus sea from 500 m: ${JSON.stringify(measured)}; 3.26 km haze ${control.toFixed(1)}`);
    for (const difference of Object.values(measured)) expect(difference).toBeGreaterThan(40);
    expect(control).toBeLessThan(40);
  });
});

/**
 * The shader's haze weight against the CPU's (src/sim/optics/haze.ts), without knowing the
 * sea's or the horizon's colour: each pixel is c(V) = (1 − w(V)) sea + w(V) horizon, so for
 * three visibilities (c₃ − c₁)/(c₂ − c₁) = (w₃ − w₁)/(w₂ − w₁) whatever the two colours. A
 * flat mirror sea (no swell, no ripples, no roughness, the sun behind the eye) seen from
 * 300 m up; each pixel's distance from where its ray meets the plane y = 0. Linear light
 * from the sRGB levels; only pixels below the highlights' knee (0.6) in all three pictures,
 * and with the colours at least 10 levels apart, so that one level's rounding moves the
 * ratio little.
 */

const PARITY_EYE: Vec3 = [0, 300, 0];
const PARITY_TARGET: Vec3 = [0, 0, -3000];
const PARITY_VISIBILITIES = [2, 6, 60] as const;
const PARITY_SIZE = { width: 320, height: 180 };
// Measured: median 0.0082 (95th percentile 0.0218) over 3966 pixels; the control 0.065 (0.108).
const PARITY_MEDIAN_LIMIT = 0.02;

async function hazeRatios(
  cpuWeight: (beta: number, distance: number) => number,
): Promise<{ median: number; worst: number; pixels: number }> {
  const { width, height } = PARITY_SIZE;
  const cam = [...PARITY_EYE, ...PARITY_TARGET].join(',');
  const { page } = await openOcean(
    harness,
    `waves=seed&swellAmplitude=0&rippleStrength=0&seaRoughness=false&subsurface=false&sunAzimuth=180&sunElevation=30&t=10&cam=${cam}`,
    width,
    height,
  );
  const pictures: PNG[] = [];
  for (const visibility of PARITY_VISIBILITIES) {
    await page.evaluate((v) => window.oceano.setParams({ visibility: v }), visibility);
    pictures.push(PNG.sync.read(await canvasPng(page)));
  }
  await page.close();
  const errors: number[] = [];
  for (let y = 0; y < height; y += 2) {
    for (let x = 0; x < width; x += 2) {
      const d = pixelRay(x, y, width, height, PARITY_EYE, PARITY_TARGET);
      if (d[1] > -0.02) continue;
      const distance = PARITY_EYE[1] / -d[1];
      const i = (y * width + x) * 4 + 1;
      const levels = pictures.map((p) => p.data[i]);
      if (Math.abs(levels[1] - levels[0]) < 10 || Math.abs(levels[2] - levels[0]) < 10) continue;
      const c = levels.map((level) => srgbToLinear(level / 255));
      if (c.some((v) => v > 0.55)) continue;
      const w = PARITY_VISIBILITIES.map((v) => cpuWeight(hazeExtinction(v * 1000), distance));
      errors.push((c[2] - c[0]) / (c[1] - c[0]) - (w[2] - w[0]) / (w[1] - w[0]));
    }
  }
  const sorted = errors.map(Math.abs).sort((a, b) => a - b);
  return { median: sorted[Math.floor(sorted.length / 2)], worst: sorted[Math.floor(sorted.length * 0.95)], pixels: sorted.length };
}

describe('the haze on the GPU', () => {
  // Control: the CPU without the thinning with height.
  it('weighs each pixel as the CPU does, from 300 m up at three visibilities', async () => {
    const exact = await hazeRatios((beta, distance) => hazeWeight(beta, PARITY_EYE[1], 0, distance));
    const flat = await hazeRatios((beta, distance) => hazeWeight(beta, 0, 0, distance));
    console.log(
      `[oceano] haze parity over ${exact.pixels} pixels: ratio error median ${exact.median.toFixed(4)}, 95th percentile ${exact.worst.toFixed(4)}; control ${flat.median.toFixed(4)}, ${flat.worst.toFixed(4)}`,
    );
    expect(exact.pixels).toBeGreaterThan(500);
    expect(exact.median).toBeLessThan(PARITY_MEDIAN_LIMIT);
    expect(flat.median).toBeGreaterThan(PARITY_MEDIAN_LIMIT);
  });
});
