import type { CDPSession } from 'puppeteer';

/** A page's JavaScript heap after a full garbage collection, with V8's compiled code counted apart. */
export interface HeapFigures {
  /** Runtime.getHeapUsage's used size after GC, bytes. */
  used: number;
  /** From a heap snapshot: everything (the page's native objects too) and V8's compiled code, bytes. */
  snapshot: { total: number; code: number };
}

/** The JS heap in use after a full garbage collection, bytes. */
export async function heapAfterGc(session: CDPSession): Promise<number> {
  // Twice: objects freed by the first collection's finalizers go in the second.
  await session.send('HeapProfiler.collectGarbage');
  await session.send('HeapProfiler.collectGarbage');
  return (await session.send('Runtime.getHeapUsage')).usedSize;
}

export async function heapFigures(session: CDPSession): Promise<HeapFigures> {
  const used = await heapAfterGc(session);
  return { used, snapshot: await heapSnapshot(session) };
}

/** The heap less V8's compiled code: what the page's own objects take. */
export const heapLessCode = (heap: HeapFigures): number => heap.used - heap.snapshot.code;

/**
 * The heap after GC from a heap snapshot: everything, and V8's compiled code among it
 * (bytecode, optimized code, feedback), which the engine grows while it compiles and
 * optimizes functions the page runs for the first time or often, and flushes on its own.
 */
async function heapSnapshot(session: CDPSession): Promise<{ total: number; code: number }> {
  const chunks: string[] = [];
  const collect = (event: { chunk: string }) => chunks.push(event.chunk);
  session.on('HeapProfiler.addHeapSnapshotChunk', collect);
  await session.send('HeapProfiler.takeHeapSnapshot', { reportProgress: false });
  session.off('HeapProfiler.addHeapSnapshotChunk', collect);
  const snapshot = JSON.parse(chunks.join('')) as { snapshot: { meta: { node_fields: string[]; node_types: [string[]] } }; nodes: number[] };
  const fields = snapshot.snapshot.meta.node_fields;
  const typeNames = snapshot.snapshot.meta.node_types[0];
  const [typeAt, sizeAt, stride] = [fields.indexOf('type'), fields.indexOf('self_size'), fields.length];
  let total = 0;
  let code = 0;
  for (let i = 0; i < snapshot.nodes.length; i += stride) {
    const size = snapshot.nodes[i + sizeAt];
    total += size;
    if (typeNames[snapshot.nodes[i + typeAt]] === 'code') code += size;
  }
  return { total, code };
}
