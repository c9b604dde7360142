import { afterEach, describe, expect, it, vi } from 'vitest';
import type { CoastSetting } from '../../../../src/sim/coast/coastField';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import type { CoastFieldReply, CoastFieldRequest } from '../../../../src/render/coast/coastFieldMessages';

/** The Worker's script run in node against a stand-in for its global scope. */
async function startWorker() {
  const replies: { reply: CoastFieldReply; transfer: Transferable[] }[] = [];
  const scope = {
    onmessage: null as ((event: MessageEvent<CoastFieldRequest>) => void) | null,
    postMessage: (reply: CoastFieldReply, transfer: Transferable[]) => replies.push({ reply, transfer }),
  };
  vi.stubGlobal('self', scope);
  vi.resetModules();
  await import('../../../../src/render/coast/coastFieldWorker');
  const send = (request: CoastFieldRequest) => scope.onmessage?.({ data: request } as MessageEvent<CoastFieldRequest>);
  return { replies, send };
}

const BEACH: CoastSetting = {
  bathymetry: 'beach',
  beachSlope: 0.02,
  deepDepth: 60,
  swellHeight: 1.5,
  swellPeriod: 10,
  swellDirection: 10,
  seed: 7,
};

describe('coastFieldWorker: the field built off the main thread', () => {
  afterEach(() => vi.unstubAllGlobals());

  it('answers each request with its id and the very field buildCoastField gives, its arrays transferred', async () => {
    const { replies, send } = await startWorker();
    send({ id: 4, setting: BEACH });
    expect(replies).toHaveLength(1);
    const { reply, transfer } = replies[0];
    expect(reply.id).toBe(4);
    const expected = buildCoastField(BEACH)!;
    expect(reply.field!.components.length).toBe(expected.components.length);
    reply.field!.components.forEach((component, m) => {
      expect(component.angularFrequency).toBe(expected.components[m].angularFrequency);
      // Bit for bit (as a boolean: a failing toEqual would print 131 072 floats).
      expect(component.texels.every((value, t) => Object.is(value, expected.components[m].texels[t]))).toBe(true);
      expect(transfer.includes(component.texels.buffer)).toBe(true);
    });
    // Control: another setting's field is not the same.
    const other = buildCoastField({ ...BEACH, swellPeriod: 12 })!;
    expect(reply.field!.components[0].texels.every((value, t) => Object.is(value, other.components[0].texels[t]))).toBe(false);
  });

  it('answers a deep sea with no field and nothing to transfer', async () => {
    const { replies, send } = await startWorker();
    send({ id: 1, setting: { ...BEACH, bathymetry: 'deep' } });
    expect(replies[0].reply).toEqual({ id: 1, field: null });
    expect(replies[0].transfer).toEqual([]);
  });
});
