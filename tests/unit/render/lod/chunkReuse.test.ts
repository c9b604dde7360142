import { describe, expect, it } from 'vitest';
import { BufferAttribute, Mesh, PerspectiveCamera } from 'three';
import { OceanChunks, type LodSettings } from '../../../../src/render/lod/oceanChunks';
import type { OceanMaterial } from '../../../../src/render/ocean/oceanMaterial';
import type { DisplacementBounds } from '../../../../src/sim/waves/waveModel';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

/** OceanChunks only tells its material where the grid's centre is; the rest is three's scene graph. */
function chunks(): OceanChunks {
  return new OceanChunks({ setOceanCenter: () => undefined, setLodMorph: () => undefined } as unknown as OceanMaterial);
}

/** What a frame uploads: each drawn batch's chunk records, in order. */
function uploaded(ocean: OceanChunks): string {
  return ocean
    .drawnRecords()
    .map((records) => records.map((r) => r.join(',')).join('|'))
    .join('\n');
}

interface Step {
  position: [number, number, number];
  target: [number, number, number];
  fov: number;
  settings: LodSettings;
  bounds: DisplacementBounds;
}

function camera(step: Step): PerspectiveCamera {
  const c = new PerspectiveCamera(step.fov, 16 / 9, 0.1, 20000);
  c.position.set(...step.position);
  c.lookAt(...step.target);
  c.updateMatrixWorld();
  return c;
}

/** A seeded walk that often stands still and otherwise changes one thing the selection depends on. */
function walk(seed: number, length: number): Step[] {
  const random = seededRandom(seed);
  let step: Step = {
    position: [0, 9, 40],
    target: [0, 0, -60],
    fov: 50,
    settings: { lodDistance: 100, lodBands: 3, lodBruteForce: false, freezeCulling: false, lodMorph: true },
    bounds: { vertical: 2.5, horizontal: 0 },
  };
  const steps: Step[] = [];
  for (let n = 0; n < length; n++) {
    const change = Math.floor(random() * 7);
    const next: Step = {
      ...step,
      position: [...step.position],
      target: [...step.target],
      settings: { ...step.settings },
      bounds: { ...step.bounds },
    };
    if (change === 1) next.position[0] += (random() - 0.5) * 80;
    if (change === 2) next.position[1] = 2 + random() * 300;
    if (change === 3) next.target[0] += (random() - 0.5) * 200;
    if (change === 4) next.fov = 30 + random() * 50;
    if (change === 5) next.settings.lodDistance = 20 + random() * 300;
    if (change === 6) next.bounds.vertical = 0.5 + random() * 40;
    steps.push((step = next));
  }
  return steps;
}

/**
 * Runs `update` (which moves `reused` to the step) over the steps and checks that after each
 * one `reused` uploads exactly what a fresh OceanChunks selecting for that step does.
 * Returns how many steps changed the fresh selection (the check's power).
 */
function uploadsAsFresh(steps: Step[], update: (step: Step) => void, reused: OceanChunks): number {
  let changedFrames = 0;
  let previousFresh = '';
  for (const step of steps) {
    update(step);
    const fresh = chunks();
    fresh.update(camera(step), step.settings, step.bounds);
    const expected = uploaded(fresh);
    expect(uploaded(reused)).toBe(expected);
    if (expected !== previousFresh) changedFrames++;
    previousFresh = expected;
  }
  return changedFrames;
}

describe('a still camera reuses the last selection', () => {
  it('uploads exactly what a fresh selection would, over a seeded walk of still and moving frames (seed 14)', () => {
    const reused = chunks();
    const changedFrames = uploadsAsFresh(walk(14, 60), (step) => reused.update(camera(step), step.settings, step.bounds), reused);
    // Power of the check: most frames change the selection, so a reuse that missed one of
    // the inputs (position, height, aim, field of view, LOD distance, bounds) would upload a stale one.
    expect(changedFrames).toBeGreaterThan(30);
  });

  it('skips the selection when nothing changed, and selects again after forgetSelection (context restored)', () => {
    const ocean = chunks();
    const step = walk(3, 1)[0];
    ocean.update(camera(step), step.settings, step.bounds);
    const geometry = (ocean.group.children[0] as Mesh).geometry;
    const attribute = geometry.getAttribute('aChunk') as BufferAttribute;
    const version = attribute.version;
    ocean.update(camera(step), step.settings, step.bounds);
    expect(attribute.version).toBe(version);
    ocean.forgetSelection();
    ocean.update(camera(step), step.settings, step.bounds);
    expect(attribute.version).toBeGreaterThan(version);
  });
});

describe('a camera moved in place is captured again', () => {
  // No updateMatrixWorld by the caller (seed 12).
  it('one camera moved as OrbitCamera moves it uploads what a fresh selection would', () => {
    // The capture skips the camera's matrix update while its position, rotation, scale and
    // projection are those of the last capture. Negative control: a pose check that ignores
    // the rotation, or the position, uploads a stale selection here.
    const reused = chunks();
    const moved = new PerspectiveCamera(50, 16 / 9, 0.1, 20000);
    // Every third frame the eye and its target move together (the boat carrying a following
    // camera): a new position, the same rotation.
    const steps = walk(12, 60).map((walked, n) => {
      const shift = 40 * Math.floor(n / 3) * (n % 3 === 0 ? 1 : 0);
      return {
        ...walked,
        position: [walked.position[0] + shift, walked.position[1], walked.position[2]] as [number, number, number],
        target: [walked.target[0] + shift, walked.target[1], walked.target[2]] as [number, number, number],
      };
    });
    const changedFrames = uploadsAsFresh(
      steps,
      (step) => {
        moved.position.set(...step.position);
        moved.lookAt(...step.target); // three updates the world matrix first, with the old rotation
        if (moved.fov !== step.fov) {
          moved.fov = step.fov;
          moved.updateProjectionMatrix();
        }
        reused.update(moved, step.settings, step.bounds);
      },
      reused,
    );
    expect(changedFrames).toBeGreaterThan(30);
  });
});

describe('a compare strip draws the nearest band split as the model alone does', () => {
  // Control: no split in strips draws the 2 m grid.
  it("uploads the same split chunks as tiles or whole; the strip's tiles are only for unsplit bands", () => {
    const step: Step = {
      position: [0, 1.2, 10],
      target: [30, 0, -60],
      fov: 30,
      settings: { lodDistance: 100, lodBands: 3, lodBruteForce: false, freezeCulling: false, lodMorph: true },
      bounds: { vertical: 1.5, horizontal: 1 },
    };
    const alone = chunks();
    alone.update(camera(step), step.settings, step.bounds, false, 4);
    const strip = chunks();
    strip.update(camera(step), step.settings, step.bounds, true, 4);
    const refinedOf = (ocean: OceanChunks) =>
      (ocean as unknown as { refined: Map<number, { count: number; record(n: number): number[] }> }).refined.get(4);
    /** The split nearest band's records (its quads 2 m / 4), as the frame uploads them. */
    const records = (ocean: OceanChunks) => {
      const batch = refinedOf(ocean);
      return batch ? Array.from({ length: batch.count }, (_, n) => batch.record(n).join(',')).join('|') : '';
    };
    expect(records(alone).length).toBeGreaterThan(0);
    expect(records(strip)).toBe(records(alone));
    // The strip still tiles the coarser bands' straddling chunks: the tiling is not switched off wholesale.
    expect(uploaded(strip)).not.toBe(uploaded(alone));
    // Control: a strip drawn with no split (what strips did) has no split chunk at all.
    const unsplit = chunks();
    unsplit.update(camera(step), step.settings, step.bounds, true, 1);
    expect(records(unsplit)).not.toBe(records(alone));
  });
});
