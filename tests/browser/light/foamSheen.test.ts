import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { canvasPng, openOcean } from '../harness';
import { useHarness } from '../useHarness';
import { sunDirection, SUN_IRRADIANCE, SUN_LIGHT_COLOR } from '../../../src/sim/optics/sun';
import { HIGHLIGHT_KNEE, rollOffHighlight } from '../../../src/sim/optics/highlightRollOff';
import { linearToSrgb, srgbToLinear } from '../../support/srgb';

/**
 * Foam's wet sheen (shaders/foam/foamMaterial.glsl foamOver): besides its diffuse light, foam
 * reflects the sun in a rough lobe, Beckmann facets of mean-square slope 0.3 with water's
 * Fresnel at normal incidence, 0.02. Seen towards a sun 30° high from 10 m up, the camera
 * pitched 30° down (the mirror direction on the middle row), on a sea made solid foam for the
 * measurement (a shader edit of the test's own), the sheen is the picture with it less the
 * picture without it. Each band of 30 rows is compared with the lobe's light for flat foam along
 * that band's rays, added to the light each pixel has without it, through the tone curve:
 * measured 0.91–0.96 of it (the bubbles' relief tilts the facets away from the lobe's peak).
 * Control: a sheen twice as smooth (σ² 0.15) reads 1.43–1.69 of the lobe the material states.
 */
const harness = useHarness();
const WIDTH = 480;
const HEIGHT = 270;
const PITCH = -30;
const HALF_FIELD = 27.5;
const SUN_ELEVATION = 30;
const SHEEN_VARIANCE = 0.3;
const SHEEN_FRESNEL = 0.02;
const BAND = 30;
const RATIO_BOUNDS = [0.85, 1.1] as const;

const eye = [300, 10, 300];
const target = [eye[0], eye[1] + 100 * Math.sin((PITCH * Math.PI) / 180), eye[2] - 100 * Math.cos((PITCH * Math.PI) / 180)];
const sun = sunDirection(SUN_ELEVATION, 0);

/** The tone curve's inverse (src/sim/optics/highlightRollOff.ts): the light before the curve. */
function unrolled(y: number): number {
  if (y <= HIGHLIGHT_KNEE) return y;
  return HIGHLIGHT_KNEE - (1 - HIGHLIGHT_KNEE) * Math.log(1 - Math.min((y - HIGHLIGHT_KNEE) / (1 - HIGHLIGHT_KNEE), 0.9999));
}

/** The sheen's radiance per unit of the sun's irradiance, for flat foam seen along a ray `elevation` degrees from level, towards the sun's azimuth. */
function sheen(elevation: number): number {
  const e = (elevation * Math.PI) / 180;
  const toEye = [0, -Math.sin(e), Math.cos(e)];
  const h = sun.map((s, i) => s + toEye[i]);
  const cosH = Math.max(h[1] / Math.hypot(...h), 0.05);
  const tan2 = (1 - cosH * cosH) / (cosH * cosH);
  return (SHEEN_FRESNEL * Math.exp(-tan2 / SHEEN_VARIANCE)) / (Math.PI * SHEEN_VARIANCE * cosH ** 4 * 4 * Math.max(toEye[1], 0.05));
}

/** The picture with every sea pixel solid foam, with or without the sheen; `faults` are more edits of the shader. */
async function solidFoam(withSheen: boolean, faults: [string, string][] = []): Promise<PNG> {
  const cam = [...eye, ...target].map((c) => c.toFixed(3)).join(',');
  const { page } = await openOcean(
    harness,
    `waves=fft&windSpeed=3&sunElevation=${SUN_ELEVATION}&sunAzimuth=0&t=10&cam=${cam}`,
    WIDTH,
    HEIGHT,
  );
  const edits: [string, string][] = [['if (foam > 0.0) {', 'foam = 1.0;\n  if (foam > 0.0) {'], ...faults];
  if (!withSheen) edits.push(['uSunColor * SUN_IRRADIANCE * sheen * sunUp', '0.0 * sheen']);
  await page.evaluate((edits) => {
    const materials = new Set<{ fragmentShader: string; needsUpdate: boolean }>();
    window.oceano.three.scene.traverse((c) => {
      const material = (c as unknown as { material?: { uniforms?: Record<string, unknown>; fragmentShader: string; needsUpdate: boolean } })
        .material;
      if (material?.uniforms?.uEyeRelative) materials.add(material);
    });
    for (const material of materials) {
      for (const [find, replace] of edits) {
        if (!material.fragmentShader.includes(find)) throw new Error(`not in the ocean's shader: ${find}`);
        material.fragmentShader = material.fragmentShader.replace(find, replace);
      }
      material.needsUpdate = true;
    }
    window.oceano.pause();
    window.oceano.renderFrame();
  }, edits);
  const image = PNG.sync.read(await canvasPng(page));
  await page.close();
  return image;
}

/** Each band of rows: the sheen measured (with less without, levels) over the lobe's prediction, at the middle quarter's solid-foam pixels. */
function sheenRatios(withSheen: PNG, without: PNG): number[] {
  const ratios: number[] = [];
  for (let top = BAND; top < HEIGHT; top += BAND) {
    let measured = 0;
    let predicted = 0;
    for (let y = top; y < top + BAND; y++) {
      const ndc = 1 - (2 * (y + 0.5)) / HEIGHT;
      const elevation = PITCH + (Math.atan(ndc * Math.tan((HALF_FIELD * Math.PI) / 180)) * 180) / Math.PI;
      const lobe = SUN_IRRADIANCE * sheen(elevation);
      for (let x = (3 * WIDTH) / 8; x < (5 * WIDTH) / 8; x++) {
        const i = (y * WIDTH + x) * 4;
        // Solid foam only: the lace's holes show the water.
        if (Math.min(without.data[i], without.data[i + 1], without.data[i + 2]) < 150) continue;
        for (let c = 0; c < 3; c++) {
          const before = unrolled(srgbToLinear(without.data[i + c] / 255));
          predicted += 255 * linearToSrgb(rollOffHighlight(before + SUN_LIGHT_COLOR[c] * lobe)) - without.data[i + c];
          measured += withSheen.data[i + c] - without.data[i + c];
        }
      }
    }
    ratios.push(measured / predicted);
  }
  return ratios;
}

describe("foam's wet sheen", () => {
  // Control: a smoother sheen.
  it('is the rough Beckmann lobe the material states, in size and in its fall across the view', async () => {
    const without = await solidFoam(false);
    const ratios = sheenRatios(await solidFoam(true), without);
    const smoother = sheenRatios(
      await solidFoam(true, [['const float FOAM_SHEEN_VARIANCE = 0.3;', 'const float FOAM_SHEEN_VARIANCE = 0.15;']]),
      without,
    );
    const say = `measured over predicted, bands of ${BAND} rows from the horizon down: ${ratios.map((r) => r.toFixed(2)).join(', ')}; control (σ² 0.15): ${smoother.map((r) => r.toFixed(2)).join(', ')}`;
    console.log(`[oceano] foam sheen ${say}`);
    for (const ratio of ratios) {
      expect(ratio, say).toBeGreaterThan(RATIO_BOUNDS[0]);
      expect(ratio, say).toBeLessThan(RATIO_BOUNDS[1]);
    }
    expect(
      smoother.some((r) => r > RATIO_BOUNDS[1]),
      say,
    ).toBe(true);
  });
});
