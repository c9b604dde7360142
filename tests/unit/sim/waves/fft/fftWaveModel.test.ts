import { describe, expect, it } from 'vitest';
import { FftOcean, type CascadeFields } from '../../../../../src/sim/waves/fft/fftOcean';
import { FftWaveModel, type FieldSource } from '../../../../../src/sim/waves/fft/fftWaveModel';
import { defaultParams } from '../../../../../src/sim/params/params';
import { SimulationClock } from '../../../../../src/app/time/simulationClock';
import { copyFields, fieldBuffers, packedFields } from '../../../../../src/render/waves/fft/fftFieldsMessages';
import { seededRandom } from '../../../../../src/sim/noise/integerHash';

const params = { ...defaultParams(), waves: 'fft' as const, fftSize: '64' as const, windSpeed: 12 };

function withSource() {
  const model = new FftWaveModel(params);
  const requests: number[] = [];
  const source: FieldSource = { request: (_sea, t) => requests.push(t), dispose: () => {} };
  model.attachSource(source);
  return { model, requests };
}

describe('FftWaveModel: when the twin is exact', () => {
  it('sampleSurface (sample) is exact at any time, with or without a Worker', () => {
    const { model } = withSource();
    const reference = new FftWaveModel(params);
    model.height(3, 4, 10);
    model.height(3, 4, 10.016);
    // Without the Worker's reply, sample at a playing time is still computed exactly.
    expect(model.sample(3, 4, 10.033).height).toBe(reference.sample(3, 4, 10.033).height);
  });

  it('while playing, height answers from the newest delivered fields and asks the Worker for now; a jump is exact', () => {
    const { model, requests } = withSource();
    const reference = new FftWaveModel(params);
    const h10 = model.height(1, 2, 10);
    expect(h10).toBe(reference.height(1, 2, 10));
    const lagged = model.height(1, 2, 10.016);
    expect(lagged).toBe(h10);
    expect(requests).toEqual([10.016]);
    // The Worker's reply arrives: the fields of an FftOcean of the same sea at that time.
    const worker = new FftOcean(model.sea);
    worker.setTime(10.016);
    model.receive(
      model.sea,
      10.016,
      worker.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })),
    );
    expect(model.height(1, 2, 10.016)).toBe(reference.height(1, 2, 10.016));
    // Negative control of the lag: the lagged answer really is another time's surface.
    expect(Math.abs(lagged - reference.height(1, 2, 10.016))).toBeGreaterThan(1e-4);
    // A jump (seek) is computed at once.
    expect(model.height(1, 2, 500)).toBe(reference.height(1, 2, 500));
  });

  it('a slow loop, whose frames the clock clamps to 0.1 s each, still asks the Worker on every frame', () => {
    // Under SwiftShader every frame is longer than 0.1 s, so the clock steps by its clamp, and
    // float64 sums of 0.1 exceed 0.1 by an ulp on most frames: with a playing threshold of
    // exactly 0.1 s those frames counted as jumps and computed every cascade's FFTs on the main
    // thread (stats().twinMs several ms). Negative control: MAX_FRAME_STEP = 0.1 fails here
    // (at frame 0).
    const { model, requests } = withSource();
    const worker = new FftOcean(model.sea);
    // From t = 16 s (between 16 and 32 a float64 ulp is 3.6e-15): most steps come out over 0.1.
    const clock = new SimulationClock(16, true);
    model.height(1, 2, clock.time); // the first frame: a jump, computed at once
    for (let frame = 0; frame < 12; frame++) {
      clock.advance(0.4); // a 400-ms frame
      const held = model.ocean.fieldsTime;
      model.height(1, 2, clock.time);
      // Not computed here (that would hold this frame's time): the Worker was asked.
      expect(model.ocean.fieldsTime, `frame ${frame}`).toBe(held);
      expect(requests.at(-1), `frame ${frame}`).toBe(clock.time);
      // The Worker answers before the next frame.
      worker.setTime(clock.time);
      model.receive(
        model.sea,
        clock.time,
        worker.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })),
      );
    }
  });

  it('ignores fields for another sea or older than those held', () => {
    const { model } = withSource();
    model.height(0, 0, 20);
    const other = new FftOcean({ ...model.sea, seed: 99 });
    other.setTime(25);
    model.receive(other.setup.sea, 25, other.fields);
    expect(model.ocean.fieldsTime).toBe(20);
    model.receive(model.sea, 5, other.fields);
    expect(model.ocean.fieldsTime).toBe(20);
  });
});

describe('FftWaveModel: the Worker refills the arrays the model hands back', () => {
  const copy = (fields: readonly CascadeFields[]) =>
    fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() }));

  it('hands back only arrays it no longer reads: the replaced fields, or a refused reply', () => {
    const model = new FftWaveModel(params);
    const recycled: CascadeFields[][] = [];
    model.attachSource({ request: () => {}, recycle: (fields) => recycled.push(fields), dispose: () => {} });
    const reference = new FftWaveModel(params);
    const worker = new FftOcean(model.sea);
    model.height(1, 2, 10); // computed at once: the model's own arrays
    const own = model.ocean.fields.slice();
    for (const t of [10.016, 10.033, 10.05]) {
      worker.setTime(t);
      model.receive(model.sea, t, copy(worker.fields));
      // The Worker overwrites what it got back (here with garbage) while the model reads on.
      for (const f of recycled.at(-1) ?? []) {
        f.displacement.fill(Number.NaN);
        f.derivatives.fill(Number.NaN);
      }
      expect(model.sample(1, 2, t).height).toBe(reference.sample(1, 2, t).height);
    }
    expect(recycled).toHaveLength(3);
    expect(recycled[0]).toEqual(own.map(() => expect.anything()));
    own.forEach((f, c) => expect(recycled[0][c]).toBe(f));
    // A refused reply (older than the fields held) goes straight back.
    worker.setTime(5);
    const stale = copy(worker.fields);
    model.receive(model.sea, 5, stale);
    expect(recycled.at(-1)).toBe(stale);
    expect(model.ocean.fieldsTime).toBe(10.05);
  });

  it('reports its twin: the fields it adopted (refused ones not counted) and their time', () => {
    const model = new FftWaveModel(params);
    expect(model.twinStatus()).toEqual({ fieldsReceived: 0, fieldsTime: Number.NaN });
    model.attachSource({ request: () => {}, dispose: () => {} });
    const worker = new FftOcean(model.sea);
    for (const t of [10.016, 10.033, 5]) {
      worker.setTime(t);
      model.receive(model.sea, t, copy(worker.fields));
    }
    expect(model.twinStatus()).toEqual({ fieldsReceived: 2, fieldsTime: 10.033 });
    // A new source starts counting afresh.
    model.attachSource({ request: () => {}, dispose: () => {} });
    expect(model.twinStatus()).toMatchObject({ fieldsReceived: 0 });
  });

  it('the Worker writes into the arrays it got back where they fit, and into new ones where they do not', () => {
    const { ocean } = new FftWaveModel(params);
    ocean.setTime(12);
    const spare = packedFields(ocean.fields);
    const filled = copyFields(ocean.fields, spare);
    expect(filled).toBe(spare);
    // One buffer carries every cascade's fields: a reply transfers one, not six.
    expect(fieldBuffers(filled)).toHaveLength(1);
    // Element by element (toEqual on 65 536 floats takes seconds).
    const same = (a: Float64Array, b: Float64Array) => a !== b && a.length === b.length && a.every((v, i) => v === b[i]);
    filled.forEach((f, c) => {
      expect(same(f.displacement, ocean.fields[c].displacement)).toBe(true);
      expect(same(f.derivatives, ocean.fields[c].derivatives)).toBe(true);
    });
    // Arrays of another size (the sea's fftSize changed meanwhile) are not used.
    const small = [{ displacement: new Float64Array(4), derivatives: new Float64Array(4) }, ...spare.slice(1)];
    const fresh = copyFields(ocean.fields, small);
    expect(fresh === small).toBe(false); // not .not.toBe: its message would print both sets of arrays
    expect(same(fresh[0].displacement, ocean.fields[0].displacement)).toBe(true);
    expect(same(copyFields(ocean.fields, null)[2].derivatives, ocean.fields[2].derivatives)).toBe(true);
    // Arrays of the right sizes but in separate buffers (the main thread's first fields, computed
    // by its own FftOcean) are not reused: the reply would carry six buffers again, for good.
    const separate = ocean.fields.map((f) => ({
      displacement: new Float64Array(f.displacement.length),
      derivatives: new Float64Array(f.derivatives.length),
    }));
    const repacked = copyFields(ocean.fields, separate);
    expect(repacked === separate).toBe(false);
    expect(fieldBuffers(repacked)).toHaveLength(1);
    expect(fieldBuffers(separate)).toHaveLength(6);
    expect(same(repacked[1].derivatives, ocean.fields[1].derivatives)).toBe(true);
  });
});

describe("FftWaveModel: the frame loop's height question", () => {
  it("is the inversion's height bit for bit, reading only the channels it uses (FftOcean.heightAt)", () => {
    // A choppy gale (the inversion's slowest convergence) and a calm sea, at t = 10 and 10⁶.
    const random = seededRandom(41);
    for (const sea of [
      { ...params, windSpeed: 20, choppiness: 1.2 },
      { ...params, windSpeed: 5 },
    ]) {
      const model = new FftWaveModel(sea);
      for (const t of [10, 1e6 + 0.37]) {
        for (let i = 0; i < 200; i++) {
          const x = (random() - 0.5) * 2000;
          const z = (random() - 0.5) * 2000;
          expect(model.height(x, z, t)).toBe(model.invert(x, z, t).height);
        }
      }
    }
  });
});

describe('FftWaveModel: the main thread time it reports (stats().twinMs)', () => {
  it('counts each surface question, each Worker request and each reported reply once, and starts afresh when taken', () => {
    // A clock that moves 1 ms at every reading: each timed section reads it twice, so counts 1 ms.
    let clock = 0;
    const model = new FftWaveModel(params, () => clock++);
    const requests: number[] = [];
    model.attachSource({ request: (_sea, t) => requests.push(t), dispose: () => {} });
    expect(model.takeMainThreadMs()).toBe(0);
    model.height(1, 2, 10);
    model.sample(1, 2, 10);
    model.displacement(1, 2, 10);
    model.prefetch(10.016);
    model.addMainThreadMs(0.25); // a Worker reply, timed by the FieldSource
    expect(requests).toEqual([10.016]);
    expect(model.takeMainThreadMs()).toBe(4.25);
    expect(model.takeMainThreadMs()).toBe(0);
    // Negative control: with a clock that stands still nothing is counted, so the 4 above
    // came from the clock readings around the work, not from a fixed charge per call.
    const still = new FftWaveModel(params, () => 7);
    still.height(1, 2, 10);
    still.sample(1, 2, 10);
    expect(still.takeMainThreadMs()).toBe(0);
  });

  it('measures real work with the default clock: a jump computes the fields on the calling thread (milliseconds)', () => {
    const model = new FftWaveModel(params);
    model.height(1, 2, 123.4);
    expect(model.takeMainThreadMs()).toBeGreaterThan(0);
  });
});
