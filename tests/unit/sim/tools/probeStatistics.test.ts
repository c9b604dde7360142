import { describe, expect, it } from 'vitest';
import {
  crestToTrough,
  meanUpCrossingPeriod,
  probeFigures,
  significantHeight,
  timeMean,
  upCrossings,
} from '../../../../src/sim/tools/probeStatistics';
import { PROBE_WINDOW, ProbeRecord } from '../../../../src/sim/tools/probeRecord';

/** a sin(2π t / T + φ) + offset sampled at `times`. */
function sine(times: number[], a: number, period: number, phase = 0.3, offset = 0) {
  return { times, heights: times.map((t) => offset + a * Math.sin((2 * Math.PI * t) / period + phase)) };
}
const every = (dt: number, duration: number, start = 0) => Array.from({ length: Math.floor(duration / dt) + 1 }, (_, i) => start + i * dt);

describe('the probe’s figures', () => {
  it('a sine’s period is exact, whatever the sampling, the phase or the offset', () => {
    // 30 s at 60 frames/s of a 6.283 s wave: not a whole number of waves in the record.
    expect(meanUpCrossingPeriod(sine(every(1 / 60, 30), 1.2, 2 * Math.PI))).toBeCloseTo(2 * Math.PI, 3);
    expect(meanUpCrossingPeriod(sine(every(0.1, 30, 7.3), 0.5, 4.49, 2.1, 0.8))).toBeCloseTo(4.49, 2);
    // Uneven frames: a record taken once per drawn frame.
    const uneven: number[] = [];
    for (let t = 0, i = 0; t < 30; i++) uneven.push((t += i % 3 === 0 ? 0.05 : 0.013));
    expect(meanUpCrossingPeriod(sine(uneven, 2, 3.7))).toBeCloseTo(3.7, 3);
  });

  it('Hs = 4σ is 2√2 a for a sine of amplitude a, and crest to trough is 2a', () => {
    const record = sine(every(1 / 120, 40), 1.5, 5);
    expect(significantHeight(record)).toBeCloseTo(4 * (1.5 / Math.SQRT2), 2);
    expect(crestToTrough(record)).toBeCloseTo(3, 3);
    expect(timeMean(sine(every(0.01, 50), 1, 5, 0, 0.7))).toBeCloseTo(0.7, 3);
  });

  it('counts the waves that cross the mean: a short wave riding a smaller long one crosses once per short period', () => {
    const times = every(0.01, 60);
    const record = { times, heights: times.map((t) => 0.8 * Math.sin((2 * Math.PI * t) / 6) + Math.sin((2 * Math.PI * t) / 1.5)) };
    // The short wave is the larger, so each of its waves takes the sum through zero: Tz = 1.5 s.
    // The long wave shifts each crossing a little, so the first and last stand off their places by a few ms.
    expect(Math.abs(meanUpCrossingPeriod(record) / 1.5 - 1)).toBeLessThan(0.01);
    expect(upCrossings(record)).toHaveLength(40);
  });

  it('negative controls: a record with times off by 5 % gives a period 5 % off; fewer than two waves give NaN', () => {
    const times = every(1 / 60, 30);
    const right = sine(times, 1, 4);
    const stretched = { times: times.map((t) => t * 1.05), heights: right.heights };
    expect(Math.abs(meanUpCrossingPeriod(stretched) / 4 - 1)).toBeGreaterThan(0.04);
    expect(meanUpCrossingPeriod(sine(every(0.1, 5), 1, 8))).toBeNaN();
    expect(probeFigures({ times: [], heights: [] }).crossings).toBe(0);
  });
});

describe('the probe’s record', () => {
  it('keeps the last 30 s of simulation time, one sample per new time; a jump back starts afresh', () => {
    const record = new ProbeRecord();
    for (let i = 0; i <= 40 * 60; i++) record.add(i / 60, Math.sin(i / 60));
    expect(record.add(40, 9)).toBe(false);
    const window = record.window();
    expect(window.times[0]).toBeCloseTo(40 - PROBE_WINDOW, 9);
    expect(window.times.at(-1)).toBe(40);
    expect(window.times).toHaveLength(30 * 60 + 1);
    record.add(12, 0.5);
    expect(record.window()).toEqual({ times: [12], heights: [0.5] });
  });
});
