import { afterEach, describe, expect, it, vi } from 'vitest';
import { FftOcean } from '../../src/sim/waves/fft/fftOcean';
import { seaStateFromParams } from '../../src/sim/waves/spectra/seaState';
import { defaultParams } from '../../src/sim/params/params';
import { fieldBuffers, packedFields, type FieldsReply, type FieldsRequest } from '../../src/render/waves/fft/fftFieldsSource';

/** The Worker's script run in node against a stand-in for its global scope, with fake timers. */
async function startWorker() {
  const replies: { reply: FieldsReply; transfer: Transferable[] }[] = [];
  const scope: { onmessage: ((event: MessageEvent<FieldsRequest>) => void) | null; postMessage(reply: FieldsReply, transfer: Transferable[]): void } = {
    onmessage: null,
    postMessage: (reply, transfer) => replies.push({ reply, transfer }),
  };
  vi.stubGlobal('self', scope);
  vi.resetModules();
  await import('../../src/render/waves/fft/fftFieldsWorker');
  const send = (request: FieldsRequest) => scope.onmessage?.({ data: request } as MessageEvent<FieldsRequest>);
  return { replies, send };
}

const sea = seaStateFromParams({ ...defaultParams(), fftSize: '64' as const, windSpeed: 12 });

describe('fftFieldsWorker: when and what it answers', () => {
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });

  it('answers 2 ms after a request, not at once; a newer request before then replaces it and keeps the arrays the older one brought', async () => {
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
