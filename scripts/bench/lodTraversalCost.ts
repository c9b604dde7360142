/**
 * CPU cost of the chunk manager per frame, in node: quadtree culling plus band and edge
 * selection for the default view and for seeded random views. Prints figures; asserts nothing.
 * Usage: npx tsx scripts/bench/lodTraversalCost.ts
 */
import { median } from '../../src/sim/physics/sampleStatistics';
import { Matrix4, PerspectiveCamera } from 'three';
import { ChunkSelector, oceanOrigin, type SelectionInput } from '../../src/sim/lod/chunkSelection';
import { planesFromMatrix } from '../../src/sim/lod/frustumMath';
import { seededRandom } from '../../src/sim/noise/integerHash';
import { bandTriangles, CHUNK_QUADS } from '../../src/sim/lod/lodBands';
import { defaultParams } from '../../src/sim/params/params';
import { maxDisplacement } from '../../src/sim/waves/seed/seedSurface';

const params = defaultParams();
const selector = new ChunkSelector();

/** The app's camera (55°, 16:9, near 0.5 m, far 20 km) at a pose: its view-projection matrix, by three. */
function viewProjection(camera: [number, number, number], target: [number, number, number]): number[] {
  const view = new PerspectiveCamera(55, 16 / 9, 0.5, 20000);
  view.position.fromArray(camera);
  view.lookAt(...target);
  view.updateMatrixWorld();
  return new Matrix4().multiplyMatrices(view.projectionMatrix, view.matrixWorldInverse).elements;
}

function input(camera: [number, number, number], target: [number, number, number]): SelectionInput {
  const [originX, originZ] = oceanOrigin(camera[0], camera[2]);
  return {
    planes: planesFromMatrix(viewProjection(camera, target)),
    camera,
    originX,
    originZ,
    maxDisplacement: maxDisplacement(params),
    lodDistance: params.lodDistance,
    lodBands: params.lodBands,
  };
}

/**
 * Median wall time of one selection, and the mean CPU time of the process per selection
 * (the CPU figure is steadier when other processes share the cores).
 */
function cpuMs(frame: SelectionInput, frames = 2000): number {
  const start = process.cpuUsage();
  for (let k = 0; k < frames; k++) selector.select(frame);
  const used = process.cpuUsage(start);
  return (used.user + used.system) / 1000 / frames;
}

function medianMs(frame: SelectionInput, frames = 2000): number {
  for (let k = 0; k < 200; k++) selector.select(frame);
  const times: number[] = [];
  for (let k = 0; k < frames; k++) {
    const start = performance.now();
    selector.select(frame);
    times.push(performance.now() - start);
  }
  return median(times);
}

const defaultView = input([0, 9, 40], [0, 0, -60]);
const ms = medianMs(defaultView);
const cpu = cpuMs(defaultView);
let triangles = 0;
for (let n = 0; n < selector.count; n++) triangles += bandTriangles(selector.bands[n]);
console.log(
  `default view: ${selector.count}/${selector.total} chunks, per band ${selector.lodCounts.join(' ')}, ${triangles} triangles (brute force ${selector.total * 2 * CHUNK_QUADS ** 2}), selection median ${ms.toFixed(4)} ms wall, ${cpu.toFixed(4)} ms CPU`,
);

const random = seededRandom(7);
const medians: number[] = [];
for (let n = 0; n < 20; n++) {
  const camera: [number, number, number] = [(random() - 0.5) * 2000, 1 + random() * 200, (random() - 0.5) * 2000];
  const yaw = random() * 2 * Math.PI;
  const pitch = -0.6 + random() * 0.7;
  medians.push(medianMs(input(camera, [camera[0] + Math.cos(yaw), camera[1] + Math.sin(pitch), camera[2] + Math.sin(yaw)]), 300));
}
console.log(`20 seeded random views (seed 7): median ${median(medians).toFixed(4)} ms, worst ${Math.max(...medians).toFixed(4)} ms`);
