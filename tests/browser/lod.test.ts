import { describe, expect, it } from 'vitest';
import { canvasPng, openOcean } from './harness';
import { useHarness } from './useHarness';
import { sharedPage } from './sharedPage';
import { magentaBelowSlope, showMagentaBehindTheSea, type Vec3 } from './viewRays';
import { compareWithReference } from './imageCompare';
import { LOD_COLOUR_VIEWS, viewPng } from './referenceViews';
import { OCEAN_EXTENT } from '../../src/sim/lod/chunkSelection';
import { CHUNK_SIZE } from '../../src/sim/lod/lodBands';
import { maxDisplacement } from '../../src/sim/waves/seed/seedSurface';
import { defaultParams } from '../../src/sim/params/params';

const harness = useHarness();

/**
 * The default view loaded once for the tests that only read its counts or move its camera
 * (each boot costs seconds of SwiftShader work); what they change is put back (sharedPage.ts).
 */
const shared = sharedPage(harness, 'seed=1&t=10');

/**
 * Pixels showing the magenta clear colour where the view ray dips steeply enough that it
 * must meet the sea inside the ocean's extent: any such pixel is a hole in the surface.
 */
function holesBelowHorizon(png: Buffer, position: Vec3, target: Vec3): { holes: number; checked: number } {
  // Nearest edge of the extent, allowing for the camera-following snap; margin ×2 for waves.
  const reach = OCEAN_EXTENT / 2 - CHUNK_SIZE;
  const minSlope = (2 * (position[1] + maxDisplacement(defaultParams()))) / reach;
  const { magenta, checked } = magentaBelowSlope(png, position, target, () => minSlope);
  return { holes: magenta, checked };
}

describe('LOD and culling in the browser', () => {
  it('reports chunk counts in stats(), and the brute-force flag draws every chunk at full resolution', async () => {
    const { page, consoleErrors } = await shared.opened();
    const stats = await page.evaluate(() => window.oceano.stats());
    expect(stats.chunksTotal).toBe(84 * 84);
    expect(stats.chunksVisible).toBeGreaterThan(100);
    expect(stats.chunksVisible).toBeLessThan(stats.chunksTotal / 2);
    expect(stats.lodCounts).toHaveLength(6);
    expect(stats.lodCounts.reduce((a, b) => a + b, 0)).toBe(stats.chunksVisible);
    expect(stats.lodCounts[0]).toBeGreaterThan(0);
    expect(stats.triangles).toBeLessThan(60_000);
    // One draw per non-empty band (three still culls the boat's parts itself, so the total
    // also holds the sky and whichever of those are in view): instanced for the bands of large
    // chunks, one plain draw of the repeated grid for the small ones (src/render/lod/chunkBatch.ts).
    const seaDraws = await page.evaluate(() => {
      let count = 0;
      const sea = window.oceano.three.scene.getObjectByName('oceano-ocean');
      sea?.traverseVisible((o) => {
        const geometry = (
          o as {
            geometry?: {
              attributes: Record<string, unknown>;
              isInstancedBufferGeometry?: boolean;
              instanceCount?: number;
              drawRange: { count: number };
            };
          }
        ).geometry;
        if (!geometry?.attributes.aChunk) return;
        const drawn = geometry.isInstancedBufferGeometry ? (geometry.instanceCount ?? 0) : geometry.drawRange.count;
        // The skirt (a plain mesh drawn whole, count Infinity) is not a chunk batch.
        if (drawn > 0 && Number.isFinite(drawn)) count++;
      });
      return count;
    });
    const bandsInUse = stats.lodCounts.filter((n) => n > 0).length;
    // ...and one for all the far rings' cells.
    expect(stats.farCellsVisible).toBeGreaterThan(0);
    expect(seaDraws).toBe(bandsInUse + 1);
    expect(stats.drawCalls).toBeGreaterThanOrEqual(bandsInUse + 1);
    const brute = await page.evaluate(() => {
      window.oceano.setParams({ lodBruteForce: true });
      window.oceano.renderFrame();
      const s = window.oceano.stats();
      window.oceano.setParams({ lodBruteForce: false });
      return s;
    });
    expect(brute.chunksVisible).toBe(brute.chunksTotal);
    expect(brute.lodCounts).toEqual([brute.chunksTotal]);
    // Every chunk's full grid and the sky box, plus at most the boat's triangles (three culls those itself).
    const boatTriangles = await page.evaluate(() => {
      let triangles = 0;
      window.oceano.three.scene.traverseVisible((o) => {
        const geometry = (o as { isMesh?: boolean; geometry?: { isInstancedBufferGeometry?: boolean; index: { count: number } | null } })
          .geometry;
        if ((o as { isMesh?: boolean }).isMesh && geometry && !geometry.isInstancedBufferGeometry && geometry.index)
          triangles += geometry.index.count / 3;
      });
      return triangles;
    });
    // The far rings' cells are 6 × 6 quads; the skirt (64 triangles) is counted with the boat's non-instanced meshes.
    const oceanAndSky = brute.chunksTotal * 24 * 24 * 2 + brute.farCellsVisible * 72 + 12 + 64;
    expect(brute.triangles).toBeGreaterThanOrEqual(oceanAndSky);
    expect(brute.triangles).toBeLessThanOrEqual(oceanAndSky + boatTriangles);
    expect(stats.triangles).toBeLessThan(brute.triangles / 10);
    expect(consoleErrors).toEqual([]);
  });

  it('draws no ocean chunk when the camera looks straight up', async () => {
    const stats = await shared.restoring((page) =>
      page.evaluate(() => {
        const { camera } = window.oceano.three;
        camera.position.set(0, 10, 0);
        camera.lookAt(0, 1000, 0);
        window.oceano.renderFrame();
        return window.oceano.stats();
      }),
    );
    expect(stats.chunksVisible).toBe(0);
    expect(stats.lodCounts.every((n) => n === 0)).toBe(true);
    // Only the sky is drawn, with the sun's disc in the same draw.
    expect(stats.drawCalls).toBe(1);
  });

  const crackViews: { name: string; query: string; position: Vec3; target: Vec3; size: [number, number] }[] = [
    { name: 'grazing, default bands', query: 'seed=1&t=10', position: [0, 1.5, 0], target: [70, 0.4, -100], size: [1280, 720] },
    {
      name: 'grazing, L = 10 m (neighbours several bands apart)',
      query: 'seed=2&t=3&lodDistance=10',
      position: [5, 2, 11],
      target: [-90, 0.2, -120],
      size: [960, 540],
    },
    {
      name: 'from 60 m, L = 30 m',
      query: 'seed=3&t=7&lodDistance=30&swellAmplitude=3',
      position: [13, 60, 7],
      target: [200, 0, -300],
      size: [960, 540],
    },
    // The nearest band's quads split to 0.5 m (steep Gerstner waves) beside the 4 m band past it.
    {
      name: 'Gerstner, the nearest band split (gerstner-steepness)',
      query: 'preset=gerstner-steepness&t=10',
      position: [-30, 4, 4],
      target: [40, 0.3, -100],
      size: [960, 540],
    },
  ];
  for (const view of crackViews) {
    it(`shows no background through the sea (crack test: ${view.name})`, async () => {
      const { page } = await openOcean(harness, view.query, ...view.size);
      await page.evaluate((pose) => window.oceano.setCamera(pose), { position: view.position, target: view.target });
      await showMagentaBehindTheSea(page);
      const png = await canvasPng(page);
      const stats = await page.evaluate(() => window.oceano.stats());
      // Several bands meet in this view, so there are seams to crack.
      expect(stats.lodCounts.filter((n) => n > 0).length).toBeGreaterThanOrEqual(3);
      const { holes, checked } = holesBelowHorizon(png, view.position, view.target);
      expect(checked).toBeGreaterThan(view.size[0] * view.size[1] * 0.2);
      expect(holes).toBe(0);
      await page.close();
    });
  }

  it('finds holes when there are some: the crack check itself can fail', async () => {
    const { page } = await openOcean(harness, 'seed=1&t=10', 960, 540);
    const position: Vec3 = [0, 1.5, 0];
    const target: Vec3 = [70, 0.4, -100];
    await page.evaluate((pose) => window.oceano.setCamera(pose), { position, target });
    await showMagentaBehindTheSea(page);
    // Wireframe leaves the inside of every triangle open.
    await page.evaluate(() => window.oceano.setParams({ wireframe: true }));
    const { holes } = holesBelowHorizon(await canvasPng(page), position, target);
    expect(holes).toBeGreaterThan(1000);
    await page.close();
  });

  for (const view of LOD_COLOUR_VIEWS) {
    it(`draws the LOD debug view "${view.name}" as its reference`, async () => {
      const { page, consoleErrors } = await openOcean(harness, view.query, view.width, view.height);
      const reference = compareWithReference(view.name, await viewPng(page, view));
      expect(reference.matches, reference.summary).toBe(true);
      expect(consoleErrors).toEqual([]);
      await page.close();
    });
  }

  it('keeps the frozen selection while the camera orbits away', async () => {
    // The selection frozen from the loaded camera (as freezeCulling=1 in the URL freezes it;
    // the frustum-culling preset's reference covers that path).
    const result = await shared.restoring((page) =>
      page.evaluate(() => {
        window.oceano.setParams({ freezeCulling: true });
        window.oceano.renderFrame();
        const before = window.oceano.stats();
        window.oceano.setCamera({ position: [-900, 1400, 1300], target: [0, 0, -500] });
        window.oceano.renderFrame();
        const frozen = window.oceano.stats();
        window.oceano.setParams({ freezeCulling: false });
        window.oceano.renderFrame();
        return { before, frozen, live: window.oceano.stats() };
      }),
    );
    expect(result.frozen.chunksVisible).toBe(result.before.chunksVisible);
    expect(result.frozen.lodCounts).toEqual(result.before.lodCounts);
    expect(result.live.lodCounts).not.toEqual(result.before.lodCounts);
  });
});
