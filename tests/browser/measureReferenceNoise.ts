// SwiftShader's run-to-run noise on the committed references, the figure REFERENCE_TOLERANCE
// in imageCompare.ts sits above. Needs a build (`npx vite build`). Run:
//   npx tsx tests/browser/measureReferenceNoise.ts [runs = 3] [name,name,...]
// Draws each reference view `runs` times, each on a freshly loaded page, and prints the
// difference of every run from the first run and from the committed file.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { startHarness } from './harness';
import { measureDifference, REFERENCE_DIR, REFERENCE_TOLERANCE, type ImageDifference } from './imageCompare';
import { drawView, REFERENCE_VIEWS } from './referenceViews';

const runs = Number(process.argv[2] ?? 3);
const filters = (process.argv[3] ?? '').split(',');

const line = (label: string, d: ImageDifference) =>
  `${label.padEnd(40)} mean|Δ| ${d.meanAbsError.map((m) => m.toFixed(4)).join(' ')}  >${REFERENCE_TOLERANCE.levels} lv ${(d.shareOverLevels * 100).toFixed(4)} %  max ${d.maxLevels}`;

const harness = await startHarness();
let worstMae = 0;
let worstShare = 0;
try {
  for (const view of REFERENCE_VIEWS.filter((v) => filters.some((f) => v.name.includes(f)))) {
    const committed = readFileSync(join(REFERENCE_DIR, `${view.name}.png`));
    const pictures: Buffer[] = [];
    for (let i = 0; i < runs; i++) pictures.push(await drawView(harness, view));
    pictures.forEach((png, i) => {
      const differences = [measureDifference(committed, png), ...(i > 0 ? [measureDifference(pictures[0], png)] : [])];
      console.log(line(`${view.name} run ${i} vs committed`, differences[0]));
      if (i > 0) console.log(line(`${view.name} run ${i} vs run 0`, differences[1]));
      for (const d of differences) {
        worstMae = Math.max(worstMae, ...d.meanAbsError);
        worstShare = Math.max(worstShare, d.shareOverLevels);
      }
    });
  }
  console.log(
    `worst over all: mean|Δ| ${worstMae.toFixed(4)} levels, share > ${REFERENCE_TOLERANCE.levels} levels ${(worstShare * 100).toFixed(4)} %`,
  );
} finally {
  await harness.close();
}
