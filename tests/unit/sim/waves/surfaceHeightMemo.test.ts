import { describe, expect, it } from 'vitest';
import { SurfaceHeightMemo } from '../../../../src/sim/waves/surfaceHeightMemo';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import { FftWaveModel } from '../../../../src/sim/waves/fft/fftWaveModel';
import { defaultParams } from '../../../../src/sim/params/params';
import type { LiveWaveModel } from '../../../../src/sim/waves/waveModel';

/** A model that counts its height questions (the seed model's answers). */
function counted(model: LiveWaveModel): { model: LiveWaveModel; calls: () => number } {
  let calls = 0;
  const wrapper = Object.create(model) as LiveWaveModel;
  wrapper.height = (x, z, t) => (calls++, model.height(x, z, t));
  return { model: wrapper, calls: () => calls };
}

describe('SurfaceHeightMemo: the height under the eye, kept while nothing it depends on changed', () => {
  // Also when the revision changes; it gives the model's own answer.
  it('answers a repeat without asking, and asks the model again when the point, time or model changes', () => {
    const seed = new SeedWaveModel(defaultParams());
    const { model, calls } = counted(seed);
    const memo = new SurfaceHeightMemo();
    expect(memo.height(model, 3, 4, 10)).toBe(seed.height(3, 4, 10));
    expect(memo.height(model, 3, 4, 10)).toBe(seed.height(3, 4, 10));
    expect(calls()).toBe(1);
    const changes: [number, number, number][] = [
      [3.001, 4, 10],
      [3.001, 4.2, 10],
      [3.001, 4.2, 10.5],
    ];
    for (const [x, z, t] of changes) {
      expect(memo.height(model, x, z, t)).toBe(seed.height(x, z, t));
    }
    expect(calls()).toBe(4);
    // New parameters at the same time and place: a new revision, a new surface.
    seed.setParams({ ...defaultParams(), swellAmplitude: 1.7 });
    expect(memo.height(model, 3.001, 4.2, 10.5)).toBe(seed.height(3.001, 4.2, 10.5));
    expect(calls()).toBe(5);
    // Another model (the waves switched) at the same time and place.
    const other = new SeedWaveModel({ ...defaultParams(), seed: 9 });
    expect(memo.height(other, 3.001, 4.2, 10.5)).toBe(other.height(3.001, 4.2, 10.5));
  });

  it('under waves=fft, fields delivered by the Worker at the same time are a new surface', () => {
    const params = { ...defaultParams(), waves: 'fft' as const, fftSize: '64' as const, windSpeed: 12 };
    const fft = new FftWaveModel(params);
    fft.attachSource({ request: () => {}, dispose: () => {} });
    const memo = new SurfaceHeightMemo();
    memo.height(fft, 5, 6, 10); // a jump: computed at 10
    memo.height(fft, 5, 6, 10.05); // playing: answered from the fields at 10
    const answered = fft.height(5, 6, 10.05);
    expect(memo.height(fft, 5, 6, 10.05)).toBe(answered);
    // The Worker's fields for 10.05 arrive: the same question now has the exact answer.
    const worker = new FftWaveModel(params);
    worker.ocean.setTime(10.05);
    fft.receive(
      fft.sea,
      10.05,
      worker.ocean.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })),
    );
    const exact = worker.height(5, 6, 10.05);
    expect(exact).not.toBe(answered);
    expect(memo.height(fft, 5, 6, 10.05)).toBe(exact);
  });
});
