import { describe, expect, it } from 'vitest';
import { FftWaveModel, INVERSION_STEPS, INVERSION_TOLERANCE, type FieldSource } from '../../../../src/sim/waves/fft/fftWaveModel';
import { FftOcean } from '../../../../src/sim/waves/fft/fftOcean';
import { GerstnerLiveModel } from '../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import {
  checkSampleOptions,
  checkSurfaceBatch,
  sampleSurfaces,
  SAMPLE_FLOATS,
  type SurfaceSamples,
} from '../../../../src/sim/waves/surfaceBatch';
import { undoHorizontalDisplacement, type LiveWaveModel, type SurfaceSample } from '../../../../src/sim/waves/waveModel';
import { defaultParams } from '../../../../src/sim/params/params';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

const gale = { ...defaultParams(), waves: 'fft' as const, windSpeed: 20, choppiness: 1.2 };

/** `count` world points, x, z pairs within ±1 km, from `seed`. */
function randomPoints(seed: number, count: number): Float64Array {
  const random = seededRandom(seed);
  return Float64Array.from({ length: 2 * count }, () => (random() - 0.5) * 2000);
}

/** How many points of `batch` differ from `sample` at the same point (every number compared as `round` stores it). */
function mismatches(
  batch: SurfaceSamples,
  points: ArrayLike<number>,
  sample: (x: number, z: number) => SurfaceSample,
  round = (v: number) => v,
): number {
  let count = 0;
  for (let i = 0; i < points.length / 2; i++) {
    const s = sample(points[2 * i], points[2 * i + 1]);
    const expected = [s.height, ...s.normal].map(round);
    if (expected.some((v, k) => v !== batch[SAMPLE_FLOATS * i + k])) count++;
  }
  return count;
}

describe('sampleSurfaces: many points, each what sampleSurface answers', () => {
  it('FFT gale, 500 random points (seed 29): float64 out bit for bit, float32 out as float32 rounds it', () => {
    const points = randomPoints(29, 500);
    const model = new FftWaveModel(gale);
    const reference = new FftWaveModel(gale);
    const wide = sampleSurfaces(model, points, 12.5, new Float64Array(2000));
    const narrow = sampleSurfaces(model, Float32Array.from(points), 12.5, checkSurfaceBatch(Float32Array.from(points), undefined));
    expect(narrow).toBeInstanceOf(Float32Array);
    expect(mismatches(wide, points, (x, z) => reference.sample(x, z, 12.5))).toBe(0);
    const narrowPoints = Float32Array.from(points);
    expect(mismatches(narrow, narrowPoints, (x, z) => reference.sample(x, z, 12.5), Math.fround)).toBe(0);
  });

  it('control (seed 29): the same comparison catches points read as z, x or at another time', () => {
    const points = randomPoints(29, 500);
    const model = new FftWaveModel(gale);
    const swapped = points.map((_, i) => points[i ^ 1]);
    const batch = sampleSurfaces(model, swapped, 12.5, new Float64Array(2000));
    expect(mismatches(batch, points, (x, z) => model.sample(x, z, 12.5))).toBeGreaterThan(490);
    const later = sampleSurfaces(model, points, 12.5 + 1e-3, new Float64Array(2000));
    expect(mismatches(later, points, (x, z) => model.sample(x, z, 12.5))).toBeGreaterThan(490);
  });

  it("the FFT sample is the seam's inversion, displacement and normal, bit for bit (random points, seed 31)", () => {
    const points = randomPoints(31, 300);
    for (const sea of [gale, { ...gale, windSpeed: 6, choppiness: 1 }]) {
      const model = new FftWaveModel(sea);
      const ocean = model.ocean;
      const composed = (x: number, z: number): SurfaceSample => {
        const p = undoHorizontalDisplacement((px, pz) => ocean.displacement(px, pz, 7), x, z, INVERSION_STEPS, INVERSION_TOLERANCE);
        return { height: ocean.displacement(p.x, p.z, 7)[1], normal: ocean.normalAt(p.x, p.z, 7) };
      };
      const batch = sampleSurfaces(model, points, 7, new Float64Array(1200));
      expect(mismatches(batch, points, composed)).toBe(0);
      // The frame loop's height question agrees too.
      for (let i = 0; i < 300; i++) expect(model.height(points[2 * i], points[2 * i + 1], 7)).toBe(batch[4 * i]);
    }
  });

  it('stopping the inversion once settled loses nothing against 12 full steps (gale, 1000 points, seed 37)', () => {
    const points = randomPoints(37, 1000);
    const ocean = new FftWaveModel(gale).ocean;
    const out = new Float64Array(4);
    const worstError = (steps: number, tolerance: number): number => {
      let worst = 0;
      for (let i = 0; i < 1000; i++) {
        const [x, z] = [points[2 * i], points[2 * i + 1]];
        ocean.sampleInto(x, z, 3, 40, 0, out, 0);
        const exact = out[0];
        ocean.sampleInto(x, z, 3, steps, tolerance, out, 0);
        worst = Math.max(worst, Math.abs(out[0] - exact));
      }
      return worst;
    };
    const fixed = worstError(INVERSION_STEPS, 0);
    expect(worstError(INVERSION_STEPS, INVERSION_TOLERANCE)).toBeLessThanOrEqual(fixed * 1.05);
    // Control: a loose tolerance (1 cm) does lose accuracy, so the comparison can fail.
    expect(worstError(INVERSION_STEPS, 1e-2)).toBeGreaterThan(fixed * 10);
  });

  it('seed and Gerstner seas, which have no batch of their own: one sample per point, equal (seed 43)', () => {
    const points = randomPoints(43, 100);
    const models: LiveWaveModel[] = [
      new SeedWaveModel(defaultParams()) as unknown as LiveWaveModel,
      new GerstnerLiveModel(defaultParams()),
    ];
    for (const model of models) {
      expect(model.sampleMany).toBeUndefined();
      const batch = sampleSurfaces(model, points, 4, new Float64Array(400));
      expect(mismatches(batch, points, (x, z) => model.sample(x, z, 4))).toBe(0);
    }
  });

  it('what the caller adds to each sample (the interactive waves) reaches every point, on the FFT sea too', () => {
    const points = randomPoints(47, 50);
    const model = new FftWaveModel(gale);
    const raise = (s: SurfaceSample, x: number): SurfaceSample => ({ height: s.height + x * 1e-3, normal: s.normal });
    const batch = sampleSurfaces(model, points, 2, new Float64Array(200), raise);
    expect(mismatches(batch, points, (x, z) => raise(model.sample(x, z, 2), x))).toBe(0);
    expect(mismatches(batch, points, (x, z) => model.sample(x, z, 2))).toBeGreaterThan(45);
  });
});

describe("sampleSurfaces for a frame: the frame's own data, or an exact time", () => {
  /** A playing FFT sea whose Worker has delivered the fields of 10 s, and been asked for the frame at 10.016 s. */
  function playing(): { model: FftWaveModel; requests: number[] } {
    const model = new FftWaveModel(gale);
    const requests: number[] = [];
    const source: FieldSource = { request: (_sea, t) => requests.push(t), dispose: () => {} };
    model.attachSource(source);
    const worker = new FftOcean(model.sea);
    worker.setTime(10);
    model.receive(model.sea, 10, worker.fields);
    model.height(0, 0, 10);
    model.height(0, 0, 10.016);
    return { model, requests };
  }

  it("playing: the frame's answer is the held fields' surface (10 s) with no FFT computed; an exact time is exact", () => {
    const points = randomPoints(53, 200);
    const { model, requests } = playing();
    const reference = new FftWaveModel(gale);
    const revision = model.surfaceRevision;
    const at = model.frameDataTime(10.016);
    expect(at).toBe(10);
    const frame = sampleSurfaces(model, points, at, new Float64Array(800));
    expect(model.surfaceRevision).toBe(revision); // the fields were read, not recomputed
    expect(requests.at(-1)).toBe(10.016); // the Worker is still asked for the frame
    expect(mismatches(frame, points, (x, z) => reference.sample(x, z, 10))).toBe(0);
    const exact = sampleSurfaces(model, points, 10.016, new Float64Array(800));
    expect(model.surfaceRevision).not.toBe(revision);
    expect(mismatches(exact, points, (x, z) => reference.sample(x, z, 10.016))).toBe(0);
  });

  it("control: the frame's answer really is another time's surface than the frame's exact one", () => {
    const points = randomPoints(53, 200);
    const { model } = playing();
    const reference = new FftWaveModel(gale);
    const frame = sampleSurfaces(model, points, model.frameDataTime(10.016), new Float64Array(800));
    expect(mismatches(frame, points, (x, z) => reference.sample(x, z, 10.016))).toBeGreaterThan(190);
  });

  it('without a Worker, or on a sea with no lagging data, the frame answer is the exact one at the time asked', () => {
    const model = new FftWaveModel(gale);
    expect(model.frameDataTime(10.016)).toBe(10.016);
    expect(model.frameDataTime(10.032)).toBe(10.032);
    expect((new GerstnerLiveModel(defaultParams()) as LiveWaveModel).frameDataTime).toBeUndefined();
  });

  it('options: time must be a finite number and is the only key (a TypeError otherwise); control: good ones pass', () => {
    expect(() => checkSampleOptions({ tme: 3 })).toThrow(
      new TypeError('sampleSurfaces has no option "tme"; its only option is time (seconds).'),
    );
    expect(() => checkSampleOptions({ time: Number.NaN })).toThrow(/finite number of seconds, got number NaN/);
    expect(() => checkSampleOptions({ time: '3' })).toThrow(/got string 3/);
    expect(() => checkSampleOptions(3)).toThrow(/as an object \({ time }\), got number 3/);
    expect(checkSampleOptions(undefined)).toEqual({});
    expect(checkSampleOptions({ time: 3 })).toEqual({ time: 3 });
    expect(checkSampleOptions({ time: undefined })).toEqual({ time: undefined });
  });
});

describe('sampleSurfaces: bad input is a TypeError that says what was wanted', () => {
  it('names the fault', () => {
    expect(() => checkSurfaceBatch('1,2', undefined)).toThrow(
      new TypeError('sampleSurfaces needs points as a Float32Array, Float64Array or array of x, z pairs (metres), got string 1,2.'),
    );
    expect(() => checkSurfaceBatch([1, 2, 3], undefined)).toThrow(/even number of coordinates, got 3/);
    expect(() => checkSurfaceBatch([1, 2, 3, Number.NaN], undefined)).toThrow(/point 1's z is NaN/);
    expect(() => checkSurfaceBatch([1, '2'], undefined)).toThrow(/point 0's z is 2/);
    expect(() => checkSurfaceBatch([1, 2], new Float32Array(3))).toThrow(/out of length 4 \(4 per point for 1 points\), got 3/);
    expect(() => checkSurfaceBatch([1, 2], [0, 0, 0, 0])).toThrow(/got Array/);
    for (const bad of [() => checkSurfaceBatch(null, undefined), () => checkSurfaceBatch(new Int32Array(2), undefined)])
      expect(bad).toThrow(TypeError);
  });

  it('control: good input passes, and gets a Float32Array of 4 per point when no out is given', () => {
    expect(checkSurfaceBatch(new Float32Array([1, 2, 3, 4]), undefined)).toEqual(new Float32Array(8));
    const out = new Float64Array(4);
    expect(checkSurfaceBatch([1, 2], out)).toBe(out);
    expect(checkSurfaceBatch([], undefined)).toHaveLength(0);
  });
});
