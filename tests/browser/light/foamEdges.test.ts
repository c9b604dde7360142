import { describe, expect, it } from 'vitest';
import { openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { foamOwnLight } from './foamLight';

/**
 * A whitecap's edge feathers: outside its solid white the foam thins into lace and bubbles
 * before the water shows (shaders/foam/foamMaterial.glsl foamOver, and the band of thinning
 * foam around the breaking threshold in shaders/waves/fft.glsl), rather than ending on a line.
 * Seen from 15 m straight down at 15 m/s (640 × 360, 4.3 cm a pixel), the foam's own light (the frame
 * with foam less the same instant without) in a ring 13–39 cm outside the solid foam, against
 * the solid foam's own.
 * Control: foam cut hard at half its thickness (`featheredEdges: false`), where the ring holds
 * almost nothing.
 */
const harness = useHarness();
const W = 640;
const H = 360;
const TIMES = [10, 40, 70, 100];
const QUERY = 'waves=fft&windSpeed=15&windDirection=90&sunElevation=30&cam=0,15,0,0,0,-0.01';
// Solid foam: lighter by this many levels than the water under it.
const SOLID_LEVELS = 120;
// The ring, in pixels of chessboard distance from the solid foam.
const RING = [3, 9] as const;

/** Each pixel's chessboard distance to the nearest solid pixel, up to `max` (farther: max + 1). */
function distanceToSolid(solid: Uint8Array, max: number): Uint8Array {
  const distance = new Uint8Array(solid.length).fill(max + 1);
  let front: number[] = [];
  solid.forEach((s, i) => {
    if (!s) return;
    distance[i] = 0;
    front.push(i);
  });
  for (let d = 1; d <= max && front.length > 0; d++) {
    const next: number[] = [];
    for (const i of front) {
      const x = i % W;
      const y = (i - x) / W;
      for (let j = Math.max(0, y - 1); j <= Math.min(H - 1, y + 1); j++) {
        for (let k = Math.max(0, x - 1); k <= Math.min(W - 1, x + 1); k++) {
          const n = j * W + k;
          if (distance[n] <= d) continue;
          distance[n] = d;
          next.push(n);
        }
      }
    }
    front = next;
  }
  return distance;
}

async function feathering(feathered: boolean): Promise<{ ratio: number; solid: number; ring: number }> {
  const { page } = await openOcean(harness, QUERY, W, H);
  if (!feathered) await page.evaluate(() => window.oceano.debug.setShadingFixes({ featheredEdges: false }));
  let solidLight = 0;
  let solidPixels = 0;
  let ringLight = 0;
  let ringPixels = 0;
  for (const t of TIMES) {
    const light = await foamOwnLight(page, t);
    const solid = Uint8Array.from(light, (v) => (v >= SOLID_LEVELS ? 1 : 0));
    const distance = distanceToSolid(solid, RING[1]);
    light.forEach((v, i) => {
      if (solid[i]) {
        solidLight += v;
        solidPixels++;
      } else if (distance[i] >= RING[0] && distance[i] <= RING[1]) {
        ringLight += Math.max(v, 0);
        ringPixels++;
      }
    });
  }
  await page.close();
  return { ratio: ringLight / ringPixels / (solidLight / solidPixels), solid: solidPixels, ring: ringPixels };
}

// Measured: 0.091 feathered, 0.000 cut hard (the pictures are deterministic, so the bound sits between).
const LIMIT = 0.05;

describe('foam’s edges feather', () => {
  // Straight down. Control: foam cut hard at half its thickness.
  it('seen from 15 m at 15 m/s, the ring 13–39 cm outside solid foam keeps over 5 % of its light', { timeout: 240_000 }, async () => {
    const soft = await feathering(true);
    const hard = await feathering(false);
    const say = `ring/solid light ${soft.ratio.toFixed(3)} (solid ${soft.solid} px, ring ${soft.ring} px), control ${hard.ratio.toFixed(3)} (solid ${hard.solid} px, ring ${hard.ring} px)`;
    console.log(`[oceano] ${say}`);
    expect(soft.solid, say).toBeGreaterThan(10_000);
    expect(soft.ratio, say).toBeGreaterThan(LIMIT);
    expect(hard.ratio, say).toBeLessThan(LIMIT);
  });
});
