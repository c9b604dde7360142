import { afterEach, describe, expect, it, vi } from 'vitest';
import { FftOcean } from '../../src/sim/waves/fft/fftOcean';
import { FftWaveModel } from '../../src/sim/waves/fft/fftWaveModel';
import { defaultParams } from '../../src/sim/params/params';
import { seaStateFromParams } from '../../src/sim/waves/spectra/seaState';
import {
  chooseWriteSlot,
  CONTROL_BYTES,
  controlViews,
  fieldsOn,
  publish,
  readRequest,
  release,
  SLOTS,
  takePublication,
  slotBytes,
  writeRequest,
  type ChannelMessage,
  type SharedControl,
} from '../../src/render/waves/fft/sharedFieldsProtocol';

const channel = (generation = 1) => controlViews(new SharedArrayBuffer(CONTROL_BYTES), generation);
/** The READING word (index 2 of the ints), read as the Worker reads it. */
const reading = (c: SharedControl) => Atomics.load(c.ints, 2);

/** A deterministic generator for the interleavings (mulberry32). */
function random(seed: number): () => number {
  let a = seed;
  return () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

describe('sharedFieldsProtocol: slots, publications, requests', () => {
  it('never hands the Worker the slot the main thread reads nor the newest published one', () => {
    for (let publishedSlot = -1; publishedSlot < SLOTS; publishedSlot++) {
      const c = channel();
      if (publishedSlot >= 0) publish(c, publishedSlot, 1, 1);
      // The main thread takes it (marks it read), then the Worker publishes others.
      const taken = takePublication(c, -1, 1);
      for (let step = 0; step < 6; step++) {
        const slot = chooseWriteSlot(c);
        expect(slot).not.toBe(reading(c));
        expect(slot).not.toBe(Atomics.load(c.ints, 1) & 3);
        publish(c, slot, 2 + step, 1);
      }
      expect(taken?.slot ?? -1).toBe(publishedSlot);
    }
  });

  it('in random interleavings the Worker never writes the slot the main thread holds, and the main thread adopts each newest publication once', () => {
    const next = random(7);
    const c = channel(3);
    // The Worker's state: the slot it is writing (between choose and publish) and its time.
    let writing: { slot: number; time: number } | null = null;
    let time = 0;
    let seen = -1;
    let held: { slot: number; time: number } | null = null;
    const adopted: number[] = [];
    for (let step = 0; step < 5000; step++) {
      const r = next();
      if (r < 0.35 && !writing) writing = { slot: chooseWriteSlot(c), time: ++time };
      else if (r < 0.6 && writing) {
        publish(c, writing.slot, writing.time, 3);
        writing = null;
      } else {
        const p = takePublication(c, seen, 3);
        if (p) {
          seen = p.word;
          // The model refuses older fields than it holds (FftWaveModel.receive); here: never older.
          expect(held === null || p.time > held.time).toBe(true);
          held = { slot: p.slot, time: p.time };
          adopted.push(p.time);
        }
      }
      if (writing && held) expect(writing.slot).not.toBe(held.slot);
    }
    expect(adopted.length).toBeGreaterThan(100);
    expect(new Set(adopted).size).toBe(adopted.length);
  });

  it('adopts a publication once: the same word again is nothing new', () => {
    const c = channel();
    publish(c, chooseWriteSlot(c), 5, 1);
    const p = takePublication(c, -1, 1);
    expect(p?.time).toBe(5);
    expect(takePublication(c, p?.word ?? -1, 1)).toBeNull();
    publish(c, chooseWriteSlot(c), 6, 1);
    expect(takePublication(c, p?.word ?? -1, 1)?.time).toBe(6);
  });

  it('refuses a publication of another generation and keeps the slot read before', () => {
    const c = channel(2);
    publish(c, chooseWriteSlot(c), 1, 2);
    const held = takePublication(c, -1, 2);
    expect(held).not.toBeNull();
    publish(c, chooseWriteSlot(c), 2, 1); // a Worker still computing the old sea
    expect(takePublication(c, held?.word ?? -1, 2)).toBeNull();
    expect(reading(c)).toBe(held?.slot);
  });

  it('release puts back the slot held before a refused adoption', () => {
    const c = channel();
    publish(c, chooseWriteSlot(c), 1, 1);
    const first = takePublication(c, -1, 1);
    publish(c, chooseWriteSlot(c), 2, 1);
    const second = takePublication(c, first?.word ?? -1, 1);
    expect(reading(c)).toBe(second?.slot);
    if (second) release(c, second);
    expect(reading(c)).toBe(first?.slot);
  });

  it('reads the newest complete request once, never one being written', () => {
    const c = channel();
    expect(readRequest(c, 0)).toBeNull();
    writeRequest(c, 1.5);
    writeRequest(c, 2.5);
    const r = readRequest(c, 0);
    expect(r?.time).toBe(2.5);
    expect(readRequest(c, r?.seq ?? -1)).toBeNull();
    Atomics.add(c.ints, 0, 1); // a write begun, not finished
    c.floats[0] = 9;
    expect(readRequest(c, r?.seq ?? -1)).toBeNull();
  });
});

describe('fftFieldsWorker over shared memory, with FftWaveModel', () => {
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });

  it('computes the requested time into a free slot with no message, bit-identical to FftOcean; the model adopts the views', async () => {
    vi.useFakeTimers();
    const posted: unknown[] = [];
    const scope: { onmessage: ((event: MessageEvent<ChannelMessage>) => void) | null; postMessage(m: unknown): void } = {
      onmessage: null,
      postMessage: (m) => posted.push(m),
    };
    vi.stubGlobal('self', scope);
    vi.resetModules();
    await import('../../src/render/waves/fft/fftFieldsWorker');

    const model = new FftWaveModel({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });
    const sea = model.sea;
    const cascades = model.ocean.fields.length;
    const n = sea.fftSize;
    const control = new SharedArrayBuffer(CONTROL_BYTES);
    const slots = Array.from({ length: SLOTS }, () => new SharedArrayBuffer(slotBytes(cascades, n)));
    const c = controlViews(control, 4);
    const views = slots.map((s) => fieldsOn(s, cascades, n));
    scope.onmessage?.({ data: { kind: 'channel', sea, generation: 4, control, slots } } as MessageEvent<ChannelMessage>);

    writeRequest(c, 3);
    vi.advanceTimersByTime(1);
    expect(takePublication(c, -1, 4)).toBeNull();
    vi.advanceTimersByTime(2);
    const p = takePublication(c, -1, 4);
    expect(p?.time).toBe(3);
    const reference = new FftOcean(seaStateFromParams({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 }));
    reference.setTime(3);
    const fields = views[p?.slot ?? 0];
    fields.forEach((f, i) => {
      expect(f.displacement.every((v, k) => v === reference.fields[i].displacement[k])).toBe(true);
      expect(f.derivatives.every((v, k) => v === reference.fields[i].derivatives[k])).toBe(true);
    });
    expect(model.receive(sea, 3, fields)).toBe(true);
    expect(model.ocean.fields[0].displacement === fields[0].displacement).toBe(true);
    // Older fields are refused (the source then releases the slot).
    expect(model.receive(sea, 2, views[(p?.slot ?? 0) === 0 ? 1 : 0])).toBe(false);
    // No reply message, no new publication without a new request.
    vi.advanceTimersByTime(100);
    expect(posted).toHaveLength(0);
    expect(takePublication(c, p?.word ?? -1, 4)).toBeNull();
  });
});
