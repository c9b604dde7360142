import { describe, expect, it } from 'vitest';
import { FftOcean } from '../../src/sim/fftOcean';
import { FftWaveModel, type FieldSource } from '../../src/sim/fftWaveModel';
import { defaultParams } from '../../src/sim/params';

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
    model.receive(model.sea, 10.016, worker.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })));
    expect(model.height(1, 2, 10.016)).toBe(reference.height(1, 2, 10.016));
    // Negative control of the lag: the lagged answer really is another time's surface.
    expect(Math.abs(lagged - reference.height(1, 2, 10.016))).toBeGreaterThan(1e-4);
    // A jump (seek) is computed at once.
    expect(model.height(1, 2, 500)).toBe(reference.height(1, 2, 500));
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
