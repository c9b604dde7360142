import type { Page } from 'puppeteer';
import { canvasPng, openOcean, type Harness } from './harness';
import { PRESETS, presetNames, type PresetName } from '../../src/app/url/presets';

type Vec3 = [number, number, number];

/** How one committed reference image is drawn: the page, its size, and an optional camera set after load. */
export interface ReferenceView {
  name: string;
  query: string;
  width: number;
  height: number;
  pose?: { position: Vec3; target: Vec3 };
  /** The whole page (panel and overlays included) rather than the canvas alone. */
  wholePage?: boolean;
}

/** Six metres down, looking level across the sea bed towards the sun's side. */
export const DIVE_QUERY = 'seed=1&t=10&cam=0,-6,40,0,-6,-20';

/**
 * The LOD debug views: tinted bands from the default camera and from above. (The frozen
 * selection seen from outside is the frustum-culling preset's reference: the two were the
 * same picture, byte for byte, so only the preset keeps one.)
 */
export const LOD_COLOUR_VIEWS: ReferenceView[] = [
  { name: 'lod-colors-default', query: 'seed=1&t=10&lodColors=1', width: 640, height: 360 },
  {
    name: 'lod-colors-above',
    query: 'seed=1&t=10&lodColors=1&lodDistance=40',
    width: 640,
    height: 360,
    pose: { position: [0, 120, 150], target: [0, 0, -150] },
  },
];

/**
 * The preset's reference. The Fresnel preset's subject is the plot, which is page content
 * over the canvas, so its reference is the whole page; a canvas-only shot of it would be the
 * default view again.
 */
export function presetView(name: string): ReferenceView {
  // The interactive waves run every step since their first stone (or 10 s of the boat) before
  // the first frame: 3 s of them, 180 steps, take about a minute on SwiftShader, 10 s minutes,
  // past the page's waits.
  const t = (PRESETS[name as PresetName]?.params as { interactiveWaves?: boolean } | undefined)?.interactiveWaves ? 3 : 10;
  return name === 'fresnel'
    ? { name: 'preset-fresnel-page', query: 'preset=fresnel&t=10', width: 640, height: 360, wholePage: true }
    : { name: `preset-${name}`, query: `preset=${name}&t=${t}`, width: 640, height: 360 };
}

/** Every committed reference image, each once. */
export const REFERENCE_VIEWS: ReferenceView[] = [
  { name: 'surface-seed1-t10', query: 'seed=1&t=10', width: 640, height: 360 },
  { name: 'readme-default-1280x720', query: 'seed=1&t=10', width: 1280, height: 720 },
  { name: 'underwater-seed1-t10', query: DIVE_QUERY, width: 640, height: 360 },
  ...LOD_COLOUR_VIEWS,
  ...presetNames.map(presetView),
];

/** The picture a reference view is compared on, from an opened page. */
export async function viewPng(page: Page, view: ReferenceView): Promise<Buffer> {
  if (view.pose) await page.evaluate((pose) => window.oceano.setCamera(pose), view.pose);
  if (!view.wholePage) return canvasPng(page);
  await page.evaluate(() => window.oceano.renderFrame());
  return Buffer.from(await page.screenshot({ type: 'png' }));
}

/** Opens a fresh page for the view, draws it, closes the page. */
export async function drawView(harness: Harness, view: ReferenceView): Promise<Buffer> {
  const { page } = await openOcean(harness, view.query, view.width, view.height);
  try {
    return await viewPng(page, view);
  } finally {
    await page.close();
  }
}
