import { afterEach, describe, expect, it, vi } from 'vitest';
import { SharedFieldSource } from '../../src/render/waves/fft/sharedFieldSource';
import { FftWaveModel } from '../../src/sim/waves/fft/fftWaveModel';
import { defaultParams } from '../../src/sim/params/params';
import { chooseWriteSlot, controlViews, publish, readRequest, type ChannelMessage } from '../../src/render/waves/fft/sharedFieldsProtocol';

/** A stand-in for the page's Worker: records what the source posts (the channel, once per sea). */
class FakeWorker {
  static last: FakeWorker | null = null;
  posted: ChannelMessage[] = [];
  onerror: (() => void) | null = null;
  constructor() {
    FakeWorker.last = this;
  }
  postMessage(message: ChannelMessage): void {
    this.posted.push(message);
  }
  terminate(): void {}
}

describe('SharedFieldSource: per frame no message; the newest publication adopted as views, refused ones released', () => {
  afterEach(() => vi.unstubAllGlobals());

  it('opens one channel per sea, writes requests, delivers the newest publication once, releases a refused one', () => {
    vi.stubGlobal('Worker', FakeWorker);
    const model = new FftWaveModel({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });
    const delivered: number[] = [];
    const source = new SharedFieldSource((sea, time, fields) => {
      delivered.push(time);
      return model.receive(sea, time, fields);
    });
    model.attachSource(source);
    const worker = FakeWorker.last;
    if (!worker) throw new Error('No Worker made.');

    source.request(model.sea, 1);
    source.request(model.sea, 1.016);
    expect(worker.posted).toHaveLength(1);
    const { control, slots, generation } = worker.posted[0];
    const c = controlViews(control);
    expect(readRequest(c, 0)?.time).toBe(1.016);

    // The Worker publishes 1.016 (its values do not matter here: identity is checked).
    const s1 = chooseWriteSlot(c);
    publish(c, s1, 1.016, generation);
    source.request(model.sea, 1.032);
    source.request(model.sea, 1.032);
    expect(delivered).toEqual([1.016]);
    expect(model.ocean.fields[0].displacement.buffer === slots[s1]).toBe(true);

    // A publication older than what the model holds (it computed 5 itself, a jump): refused,
    // and the slot it holds stays marked read, so the Worker never writes under its feet.
    model.ocean.setTime(5);
    const s2 = chooseWriteSlot(c);
    publish(c, s2, 1.032, generation);
    source.request(model.sea, 5.016);
    expect(delivered).toEqual([1.016, 1.032]);
    expect(model.ocean.fields[0].displacement.buffer === slots[s1]).toBe(true);
    expect(chooseWriteSlot(c)).not.toBe(s1);

    // A new sea: a new channel (one message), of the new generation.
    model.setParams({ ...defaultParams(), fftSize: '64' as const, windSpeed: 14 });
    source.request(model.sea, 5.032);
    expect(worker.posted).toHaveLength(2);
    expect(worker.posted[1].generation).toBe(generation + 1);
    expect(worker.posted[1].sea === model.sea).toBe(true);
    model.dispose();
  });
});

describe('FftWaveModel with a source that delivers inside request', () => {
  it('answers from the delivered fields, computing no FFT on the calling thread', () => {
    const model = new FftWaveModel({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });
    const worker = new FftWaveModel({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });
    model.height(1, 2, 10); // the first frame: computed here
    model.attachSource({
      transport: 'shared-memory',
      request: (sea, time) => {
        worker.ocean.setTime(time - 0.016);
        model.receive(sea, time - 0.016, worker.ocean.fields.map((f) => ({ displacement: f.displacement.slice(), derivatives: f.derivatives.slice() })));
      },
      dispose: () => {},
    });
    let computed = 0;
    const setTime = model.ocean.setTime.bind(model.ocean);
    model.ocean.setTime = (t: number) => {
      if (t !== model.ocean.fieldsTime) computed++;
      setTime(t);
    };
    for (let frame = 1; frame <= 5; frame++) model.height(1, 2, 10 + frame * 0.016);
    expect(model.ocean.fieldsTime).toBeCloseTo(10 + 4 * 0.016, 9);
    expect(computed).toBe(0);
  });
});
