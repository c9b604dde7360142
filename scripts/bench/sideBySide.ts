import type { Browser, Page } from 'puppeteer';
import { median } from '../../src/sim/physics/sampleStatistics';
import { openOcean, type Harness } from '../../tests/browser/harness';
import { timeFloorFrames, timeOceanFrames, timeThreejsExampleFrames } from './pageMeasures';
import { COMPARISONS, type BenchScenario } from './scenarios';
import { openThreejsOceanExample } from './threejsOceanServer';

/** One target ratio measured with its two rows interleaved: the median of the rounds' ratios and their range. */
export interface SideBySideRatio {
  label: string;
  ratio: number;
  min: number;
  max: number;
  target: number | null;
}

export interface SideBySideOptions {
  width: number;
  height: number;
  rounds: number;
  framesPerBlock: number;
  pageTimeoutMs: number;
}

/**
 * The ratios the targets are stated in, with every row they name drawn in one browser at once:
 * one page per row stays open, and each round times a block of frames on each page in turn, so a
 * load that drifts between minutes (two runs 10 minutes apart read the default view at 187 and
 * 333 ms) moves both rows of a ratio alike. Each round gives each ratio from its two blocks'
 * medians; the figure is the median over the rounds. The sequential rows above stay as they
 * were (their absolute times, p95, passes, twin and start-up figures).
 */
export async function sideBySideRatios(
  browser: Browser,
  harness: Harness,
  exampleBaseUrl: string,
  scenarios: readonly BenchScenario[],
  options: SideBySideOptions,
): Promise<SideBySideRatio[]> {
  const comparisons = COMPARISONS.filter(([, a, b]) => [a, b].every((name) => name === 'floor' || scenarios.some((s) => s.name === name)));
  const names = [...new Set(comparisons.flatMap(([, a, b]) => [a, b]))];
  const pages = new Map<string, { page: Page; time: () => Promise<number[]> }>();
  const { width, height, framesPerBlock } = options;
  try {
    for (const name of names) {
      if (name === 'floor') continue;
      const scenario = scenarios.find((s) => s.name === name) as BenchScenario;
      if (scenario.page === 'threejs-ocean') {
        const { page } = await openThreejsOceanExample(browser, exampleBaseUrl, scenario.query, width, height, options.pageTimeoutMs);
        pages.set(name, { page, time: async () => (await page.evaluate(timeThreejsExampleFrames, framesPerBlock, 1)).frameTimes });
      } else {
        const { page } = await openOcean(harness, scenario.query, width, height, '', options.pageTimeoutMs);
        await scenario.setup?.(page);
        const startTime = Number(new URLSearchParams(scenario.query).get('t') ?? 0);
        pages.set(name, {
          page,
          time: async () => (await page.evaluate(timeOceanFrames, framesPerBlock, 1, scenario.stepSeconds ?? 0, startTime)).frameTimes,
        });
      }
    }
    // The floor draws in a context of its own, made in the first page and lost after each block;
    // its frames are short, so it takes four times the block and three warm-up frames.
    const floorPage = [...pages.values()][0].page;
    const timeFloor = async () => (await floorPage.evaluate(timeFloorFrames, width, height, 4 * framesPerBlock, 3)).frameTimes;
    const perRound: Record<string, number[]> = Object.fromEntries(comparisons.map(([label]) => [label, []]));
    for (let round = 0; round < options.rounds; round++) {
      const blockMedian = new Map<string, number>();
      for (const name of names)
        blockMedian.set(
          name,
          median(name === 'floor' ? await timeFloor() : await (pages.get(name) as { time: () => Promise<number[]> }).time()),
        );
      for (const [label, a, b] of comparisons) perRound[label].push((blockMedian.get(a) as number) / (blockMedian.get(b) as number));
    }
    return comparisons.map(([label, , , target]) => {
      const ratios = perRound[label];
      return { label, ratio: median(ratios), min: Math.min(...ratios), max: Math.max(...ratios), target };
    });
  } finally {
    for (const { page } of pages.values()) await page.close();
  }
}
