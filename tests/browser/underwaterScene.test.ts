import { describe, expect, it } from 'vitest';
import { canvasPng } from './harness';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';
import { describeDifference, measureDifference } from './imageCompare';

const harness = useHarness();

/**
 * The page opens above the water, so no underwater pass has run yet; each picture is then
 * taken from a straddling camera: sky, waterline, the water and the boat's hull below it,
 * so the scene target carries every kind of colour and a material that is not Oceano's.
 */
const ABOVE_QUERY = 'seed=1&t=10';
const STRADDLE = { position: [0, 0.05, 30], target: [0, 0, -20] } as const;

/**
 * The two ways the scene reaches the underwater passes (src/render/underwater/underwaterPost.ts):
 * the library's default, a half-float target with every material as it is, and the app's,
 * an RGBA8 target holding an encoding that every material is patched to write. They draw the
 * same picture but for the encoding's rounding.
 */
const page = sharedPage(harness, ABOVE_QUERY);
/** Mean |Δ| in levels the encoding's rounding may leave, per channel; measured 0.2 to 0.4 here. */
const SAME_PICTURE_MEAN = 1.0;

async function drawWith(mode: 'linear' | 'every-material'): Promise<Buffer> {
  const { page: p } = await page.opened();
  await p.evaluate(
    async (m, pose) => {
      await window.oceano.debug.underwaterScene(m);
      window.oceano.setCamera({ position: [...pose.position], target: [...pose.target] });
      window.oceano.renderFrame();
      await window.oceano.loaded();
    },
    mode,
    STRADDLE,
  );
  return canvasPng(p);
}

/** Whether any material in the scene that is not Oceano's has been patched to write the encoding. */
function othersPatched(): Promise<boolean> {
  return page.opened().then(({ page: p }) =>
    p.evaluate(() => {
      let patched = false;
      window.oceano.three.scene.traverse((object) => {
        const material = (object as { material?: { userData: Record<string, unknown>; customProgramCacheKey(): string } }).material;
        if (material && !material.userData.oceanoMaterial && material.customProgramCacheKey().includes('oceano-scene-encode'))
          patched = true;
      });
      return patched;
    }),
  );
}

describe("the underwater passes' scene target", () => {
  // Without touching other materials.
  it('draws the same picture through a half-float target as through the encoded one', async () => {
    const linear = await drawWith('linear');
    expect(await othersPatched()).toBe(false);
    const encoded = await drawWith('every-material');
    expect(await othersPatched()).toBe(true);
    const d = measureDifference(linear, encoded);
    console.log(`[oceano] half-float vs encoded scene target: ${describeDifference(d)}`);
    for (const channel of d.meanAbsError) expect(channel).toBeLessThan(SAME_PICTURE_MEAN);
  });

  it('would see a different sea (negative control: the fog 20 % denser through the half-float target)', async () => {
    const encoded = await drawWith('every-material');
    const { page: p } = await page.opened();
    const fog = await p.evaluate(() => window.oceano.getParams().fogDensity);
    await p.evaluate((f) => window.oceano.setParams({ fogDensity: f * 1.2 }), fog);
    const denser = await drawWith('linear');
    await p.evaluate((f) => window.oceano.setParams({ fogDensity: f }), fog);
    const d = measureDifference(denser, encoded);
    console.log(`[oceano] half-float, fog +20 %, vs encoded: ${describeDifference(d)}`);
    expect(Math.max(...d.meanAbsError)).toBeGreaterThan(SAME_PICTURE_MEAN);
  });
});
