import FFT from 'fft.js';
import { describe, expect, it } from 'vitest';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import type { OceanParams } from '../../../../../src/sim/params/params';
import { butterflyDiagram } from '../../../../../src/sim/teaching/diagrams/butterflyDiagram';
import { FftOcean } from '../../../../../src/sim/waves/fft/fftOcean';
import { liveRowStages, type RadixStage } from '../../../../../src/sim/waves/fft/rowStages';
import { stockhamRadixStage } from '../../../../../src/sim/waves/fft/stockhamFft';
import { seaStateFromParams } from '../../../../../src/sim/waves/spectra/seaState';

const TIME = 37.25;

function params(change: Partial<OceanParams> = {}): OceanParams {
  const lesson = findLesson('fft-normals');
  if (!lesson) throw new Error('no lesson fft-normals');
  return { ...lessonView(lesson).params, ...change };
}

/** Largest |a − b| over the largest |b|: the relative error of a whole row. */
function relativeError(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let diff = 0;
  let size = 0;
  for (let i = 0; i < b.length; i++) {
    diff = Math.max(diff, Math.abs(a[i] - b[i]));
    size = Math.max(size, Math.abs(b[i]));
  }
  return diff / size;
}

/** The CPU's own FFT (fft.js, as InverseFft2d runs it) on the same row, unnormalised. */
function cpuInverse(row: Float64Array, n: number): number[] {
  const fft = new FFT(n);
  const out = fft.createComplexArray() as number[];
  fft.inverseTransform(out, Array.from(row));
  return out.map((v) => v * n);
}

/** A planted fault: the Stockham stage with the twiddle of output 1 in its last stage conjugated. */
function conjugatingOneTwiddle(n: number): RadixStage {
  let calls = 0;
  const stages = Math.log2(n) % 2 === 1 ? 1 + (Math.log2(n) - 1) / 2 : Math.log2(n) / 2;
  return (input, size, halfSize, radix) => {
    const out = stockhamRadixStage(input, size, halfSize, radix);
    if (++calls < stages) return out;
    // Redo output o = 1 (k = 1 when halfSize > 1) with e^{−iθ} for its m = 1 term.
    const o = 1;
    const k = o % halfSize;
    const j = Math.floor(o / (radix * halfSize)) * halfSize + k;
    const r = Math.floor(o / halfSize) % radix;
    let re = 0;
    let im = 0;
    for (let m = 0; m < radix; m++) {
      let angle = (2 * Math.PI * m * k) / (radix * halfSize) + (2 * Math.PI * m * r) / radix;
      if (m === 1) angle = -(2 * Math.PI * m * k) / (radix * halfSize) + (2 * Math.PI * m * r) / radix;
      const ar = input[2 * (j + (m * size) / radix)];
      const ai = input[2 * (j + (m * size) / radix) + 1];
      re += Math.cos(angle) * ar - Math.sin(angle) * ai;
      im += Math.cos(angle) * ai + Math.sin(angle) * ar;
    }
    out[2 * o] = re;
    out[2 * o + 1] = im;
    return out;
  };
}

describe('the live row through the FFT’s stages', () => {
  const sea = seaStateFromParams(params());
  const live = liveRowStages(sea, TIME);
  const n = sea.fftSize;
  const last = live.stages[live.stages.length - 1];

  it('runs the GPU’s radices and ends on the CPU FFT’s row and the CPU twin’s heights along z = 0 (1e-6 relative)', () => {
    expect(live.stages).toHaveLength(live.radices.length + 1);
    expect(live.radices.reduce((a, b) => a * b, 1)).toBe(n);
    expect(relativeError(last, cpuInverse(live.stages[0], n))).toBeLessThan(1e-6);
    const ocean = new FftOcean(sea);
    ocean.setTime(TIME);
    const heights = Array.from({ length: n }, (_, p) => ocean.fields[0].displacement[4 * p + 1]);
    const drawn = Array.from({ length: n }, (_, p) => last[2 * p]);
    expect(relativeError(drawn, heights)).toBeLessThan(1e-6);
    // Real heights: the imaginary part is rounding.
    expect(Math.max(...Array.from({ length: n }, (_, p) => Math.abs(last[2 * p + 1])))).toBeLessThan(
      1e-9 * Math.max(...heights.map(Math.abs)),
    );
    // And the intermediate stages are not yet the heights.
    const middle = live.stages[live.stages.length - 2];
    expect(
      relativeError(
        Array.from({ length: n }, (_, p) => middle[2 * p]),
        heights,
      ),
    ).toBeGreaterThan(1e-2);
  });

  it('control: one twiddle conjugated in the last stage no longer gives the heights', () => {
    const faulty = liveRowStages(sea, TIME, conjugatingOneTwiddle(n));
    const faultyLast = faulty.stages[faulty.stages.length - 1];
    expect(relativeError(faultyLast, cpuInverse(faulty.stages[0], n))).toBeGreaterThan(1e-3);
  });

  it('control: another time gives another row (the diagram is the live sea, not a fixed picture)', () => {
    const later = liveRowStages(sea, TIME + 2).stages;
    expect(relativeError(later[later.length - 1], last)).toBeGreaterThan(1e-2);
  });
});

describe('the butterflies diagram draws the live row', () => {
  const strips = (d: ReturnType<typeof butterflyDiagram>) => d.lines.filter((l) => l.points.length > 2);

  it('draws a strip per stage plus the spectrum, the last the heights the sea draws', () => {
    const p = params();
    const sea = seaStateFromParams(p);
    const d = butterflyDiagram(p, TIME);
    const live = liveRowStages(sea, TIME);
    expect(strips(d)).toHaveLength(live.stages.length);
    const heights = strips(d)[live.stages.length - 1];
    expect(heights.role).toBe('main');
    const last = live.stages[live.stages.length - 1];
    const largest = Math.max(...Array.from({ length: sea.fftSize }, (_, q) => Math.abs(last[2 * q])));
    expect(d.marks.find((m) => m.id === 'heights')?.value).toBe(largest);
    // The drawn curve is the heights, scaled: its highest point is the highest height's texel.
    const top = heights.points.reduce((best, pt, i) => (pt[1] > heights.points[best][1] ? i : best), 0);
    const highest = Array.from({ length: sea.fftSize }, (_, q) => last[2 * q]).reduce((best, h, i, all) => (h > all[best] ? i : best), 0);
    expect(top).toBe(highest);
  });

  it('follows a changed wind (control: the same wind draws the same strips)', () => {
    const p = params();
    const d = butterflyDiagram(p, TIME);
    const same = butterflyDiagram({ ...p }, TIME);
    expect(strips(same).map((l) => l.points)).toEqual(strips(d).map((l) => l.points));
    const turned = butterflyDiagram({ ...p, windDirection: p.windDirection + 60 }, TIME);
    expect(strips(turned).map((l) => l.points)).not.toEqual(strips(d).map((l) => l.points));
    const stronger = butterflyDiagram({ ...p, windSpeed: p.windSpeed * 1.5 }, TIME);
    expect(stronger.marks.find((m) => m.id === 'heights')?.value).not.toBeCloseTo(d.marks.find((m) => m.id === 'heights')?.value ?? 0, 3);
  });
});
