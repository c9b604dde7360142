import { afterEach, describe, expect, it, vi } from 'vitest';
import { FftOcean } from '../../../../../src/sim/waves/fft/fftOcean';
import { seaStateFromParams } from '../../../../../src/sim/waves/spectra/seaState';
import { defaultParams } from '../../../../../src/sim/params/params';
import { fieldBuffers, packedFields, type FieldsReply, type FieldsRequest } from '../../../../../src/render/waves/fft/fftFieldsMessages';
import { WorkerFieldSource } from '../../../../../src/render/waves/fft/fftFieldsSource';
import type { CascadeFields } from '../../../../../src/sim/waves/fft/fftOcean';

/** The Worker's script run in node against a stand-in for its global scope, with fake timers. */
async function startWorker() {
  const replies: { reply: FieldsReply; transfer: Transferable[] }[] = [];
  const scope: {
    onmessage: ((event: MessageEvent<FieldsRequest>) => void) | null;
    postMessage(reply: FieldsReply, transfer: Transferable[]): void;
  } = {
    onmessage: null,
    postMessage: (reply, transfer) => replies.push({ reply, transfer }),
  };
  vi.stubGlobal('self', scope);
  vi.resetModules();
  await import('../../../../../src/render/waves/fft/fftFieldsWorker');
  const send = (request: FieldsRequest) => scope.onmessage?.({ data: request } as MessageEvent<FieldsRequest>);
  return { replies, send };
}

const sea = seaStateFromParams({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });

describe('fftFieldsWorker: when and what it answers', () => {
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });

  // The newer request keeps the arrays the older one brought.
  it('answers 2 ms after a request; a newer request before then replaces it', async () => {
    vi.useFakeTimers();
    const { replies, send } = await startWorker();
    const reference = new FftOcean(sea);
    reference.setTime(3);
    const spare = packedFields(reference.fields);
    send({ sea, time: 2, spare });
    send({ sea, time: 3, spare: null });
    vi.advanceTimersByTime(1);
    expect(replies).toHaveLength(0);
    vi.advanceTimersByTime(1);
    expect(replies).toHaveLength(1);
    const { reply, transfer } = replies[0];
    expect(reply.time).toBe(3);
    // Written into the arrays the first request brought, one buffer, transferred.
    // (Identity as booleans: a failing toBe would print 196 608 floats.)
    expect(reply.fields === spare).toBe(true);
    expect(transfer.length === 1 && transfer[0] === fieldBuffers(spare)[0]).toBe(true);
    reply.fields.forEach((f, c) => {
      expect(f.displacement.every((v, i) => v === reference.fields[c].displacement[i])).toBe(true);
      expect(f.derivatives.every((v, i) => v === reference.fields[c].derivatives[i])).toBe(true);
    });
    // Nothing more comes; the next request is answered on its own.
    vi.advanceTimersByTime(10);
    expect(replies).toHaveLength(1);
    send({ sea, time: 4, spare: null });
    vi.advanceTimersByTime(2);
    expect(replies.map((r) => r.reply.time)).toEqual([3, 4]);
  });
});

/** A stand-in for the page's Worker: records what the source posts, and replies when told. */
class FakeWorker {
  static last: FakeWorker | null = null;
  posted: { request: FieldsRequest; transfer: Transferable[] }[] = [];
  onmessage: ((event: MessageEvent<FieldsReply>) => void) | null = null;
  terminated = false;
  constructor(readonly url: URL) {
    FakeWorker.last = this;
  }
  postMessage(request: FieldsRequest, transfer: Transferable[]): void {
    this.posted.push({ request, transfer });
  }
  reply(reply: FieldsReply): void {
    this.onmessage?.({ data: reply } as MessageEvent<FieldsReply>);
  }
  terminate(): void {
    this.terminated = true;
  }
}

describe('WorkerFieldSource: one request in flight, the newest waiting, the arrays handed back', () => {
  afterEach(() => vi.unstubAllGlobals());

  // The recycled arrays go with the next request.
  it('asks once per time, keeps only the newest request in flight, and sends the recycled arrays', () => {
    vi.stubGlobal('Worker', FakeWorker);
    // A page that serves the Worker's script itself, as the app's does: its origin is the script's.
    vi.stubGlobal('location', { origin: new URL(import.meta.url).origin });
    const delivered: { sea: unknown; time: number; fields: CascadeFields[] }[] = [];
    const spent: number[] = [];
    const source = new WorkerFieldSource(
      (sea, time, fields) => delivered.push({ sea, time, fields }),
      (ms) => spent.push(ms),
    );
    const worker = FakeWorker.last;
    if (!worker) throw new Error('No Worker made.');
    expect(worker.url.pathname.endsWith('/fftFieldsWorker.ts')).toBe(true);

    source.request(sea, 1);
    source.request(sea, 1); // the same frame's second question: nothing new
    source.request(sea, 1.016);
    source.request(sea, 1.033); // replaces 1.016, which was still waiting
    expect(worker.posted.map((p) => p.request.time)).toEqual([1]);

    const reference = new FftOcean(sea);
    reference.setTime(1);
    const fields = packedFields(reference.fields);
    worker.reply({ time: 1, fields });
    // Delivered with the sea object it was asked about, not a copy; the next request goes at once.
    expect(delivered).toHaveLength(1);
    expect(delivered[0].sea === sea && delivered[0].time === 1 && delivered[0].fields === fields).toBe(true);
    expect(spent).toHaveLength(1);
    expect(worker.posted.map((p) => p.request.time)).toEqual([1, 1.033]);
    expect(worker.posted[1].request.spare).toBeNull();

    // Arrays handed back travel, transferred, with the next request and only with it.
    source.recycle(fields);
    worker.reply({ time: 1.033, fields: packedFields(reference.fields) });
    expect(worker.posted).toHaveLength(2); // nothing was waiting
    source.request(sea, 1.05);
    expect(worker.posted[2].request.spare === fields).toBe(true);
    expect(worker.posted[2].transfer.length === 1 && worker.posted[2].transfer[0] === fields[0].displacement.buffer).toBe(true);
    source.request(sea, 1.066);
    worker.reply({ time: 1.05, fields: packedFields(reference.fields) });
    expect(worker.posted[3].request.spare).toBeNull();

    source.dispose();
    expect(worker.terminated).toBe(true);
  });
});
