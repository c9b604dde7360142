import { describe, expect, it } from 'vitest';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { highPass } from '../../support/highPass';
import { foamOwnLight } from './foamLight';

/**
 * Foam is lit on its own bumpy normal (shaders/foam/foamMaterial.glsl foamOver: bubbles a few
 * centimetres high, the sun and the sky on that normal, a wet sheen), not flat paint. Seen from
 * 10 m straight down at 15 m/s (1.4 cm a pixel), inside the solid foam (lighter than the water
 * by 120 levels or more, and the whole box around the pixel solid), the foam's own light finer
 * than 7 cm, relative to its mean.
 * Control: foam as paint (`foamTexture=0`, the lesson's switch), one flat colour.
 */
const harness = useHarness();
const W = 640;
const H = 360;
const TIMES = [10, 40, 70, 100];
const QUERY = 'waves=fft&windSpeed=15&windDirection=90&sunElevation=30&cam=0,10,0,0,0,-0.01';
const SOLID_LEVELS = 120;
const BOX = 2;

async function relief(foamTexture: boolean): Promise<{ contrast: number; pixels: number }> {
  const { page } = await openOcean(harness, `${QUERY}&foamTexture=${foamTexture ? 1 : 0}`, W, H);
  let fine = 0;
  let mean = 0;
  let pixels = 0;
  for (const t of TIMES) {
    const light = await foamOwnLight(page, t);
    const detail = light.slice();
    highPass(detail, W, H, BOX);
    for (let y = BOX; y < H - BOX; y++) {
      for (let x = BOX; x < W - BOX; x++) {
        let solid = true;
        for (let j = -BOX; j <= BOX && solid; j++)
          for (let i = -BOX; i <= BOX && solid; i++) solid = light[(y + j) * W + x + i] >= SOLID_LEVELS;
        if (!solid) continue;
        const k = y * W + x;
        fine += detail[k] * detail[k];
        mean += light[k];
        pixels++;
      }
    }
  }
  await page.close();
  return { contrast: Math.sqrt(fine / pixels) / (mean / pixels), pixels };
}

// Measured: 0.030 lit on its relief, 0.010 as paint (the pictures are deterministic, so the bound sits between).
const LIMIT = 0.02;

describe('foam lit on its own relief', () => {
  // Straight down. Control: foam as paint is flat.
  it('from 10 m at 15 m/s solid foam’s light varies finer than 7 cm by over 2 % of its mean', { timeout: 240_000 }, async () => {
    const lit = await relief(true);
    const paint = await relief(false);
    const say = `solid foam's fine light ${lit.contrast.toFixed(4)} of its mean (${lit.pixels} px), as paint ${paint.contrast.toFixed(4)} (${paint.pixels} px)`;
    console.log(`[oceano] ${say}`);
    expect(lit.pixels, say).toBeGreaterThan(5000);
    expect(lit.contrast, say).toBeGreaterThan(LIMIT);
    expect(paint.contrast, say).toBeLessThan(LIMIT);
  });
});
