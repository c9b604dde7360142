/**
 * The LOD's figures for the closing note: the default view drawn by the chunk manager and
 * the same view drawn as a brute-force full-resolution grid of the same extent
 * (lodBruteForce=1): triangles, draw calls, median frame time, and the CPU time of one
 * LOD update. Prints figures; asserts nothing. Other processes share the CPU: repeat runs.
 * Usage: npx vite build && npx tsx scripts/bench/lodVsBruteForce.ts [query] [frames] [bruteFrames]
 */
import { median } from '../../src/sim/physics/sampleStatistics';
import { openOcean, startHarness } from '../../tests/browser/harness';

const query = process.argv[2] ?? 'seed=1&t=10';
const frames = Number(process.argv[3] ?? 15);
const bruteFrames = Number(process.argv[4] ?? 3);

async function measure(harness: Awaited<ReturnType<typeof startHarness>>, q: string, n: number) {
  const { page } = await openOcean(harness, q, 1280, 720);
  const result = await page.evaluate(async (count) => {
    const o = window.oceano;
    const times: number[] = [];
    for (let i = 0; i < count; i++) {
      const start = performance.now();
      o.renderFrame();
      times.push(performance.now() - start);
    }
    return { times, lodUpdateMs: await o.debug.lodUpdateMs(), stats: o.stats() };
  }, n);
  await page.close();
  return { frameMs: median(result.times), lodUpdateMs: result.lodUpdateMs, stats: result.stats };
}

const harness = await startHarness();
try {
  const lod = await measure(harness, query, frames);
  const brute = await measure(harness, `${query}&lodBruteForce=1`, bruteFrames);
  for (const [name, r] of [
    ['LOD', lod],
    ['brute force', brute],
  ] as const) {
    console.log(
      `${name.padEnd(12)} triangles ${String(r.stats.triangles).padStart(9)}  draw calls ${r.stats.drawCalls}  chunks ${r.stats.chunksVisible}/${r.stats.chunksTotal} [${r.stats.lodCounts.join(' ')}]  frame ${r.frameMs.toFixed(1)} ms  LOD update ${r.lodUpdateMs.toFixed(3)} ms`,
    );
  }
  console.log(
    `LOD submits ${((100 * lod.stats.triangles) / brute.stats.triangles).toFixed(2)}% of the brute-force triangles; frame time ratio ${(lod.frameMs / brute.frameMs).toFixed(3)}`,
  );
} finally {
  await harness.close();
}
