import type { CDPSession } from 'puppeteer';

/** A page's JavaScript heap after a full garbage collection, with V8's compiled code counted apart. */
export interface HeapFigures {
  /** Runtime.getHeapUsage's used size after GC, bytes. */
  used: number;
  /**
   * From a heap snapshot, bytes: everything (the page's native objects too), V8's compiled code,
   * and the JavaScript values (objects, arrays, strings, closures, numbers, symbols, regexps),
   * which leave out the engine's own structures (compiled code, hidden classes) and the natives.
   */
  snapshot: { total: number; code: number; values: number };
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

/** The heap less V8's compiled code. */
export const heapLessCode = (heap: HeapFigures): number => heap.used - heap.snapshot.code;

/** Snapshot node types that are the page's JavaScript values, not the engine's structures. */
const VALUE_TYPES = new Set([
  'object',
  'array',
  'string',
  'concatenated string',
  'sliced string',
  'closure',
  'number',
  'symbol',
  'bigint',
  'regexp',
]);

/**
 * The heap after GC from a heap snapshot: everything, and V8's compiled code among it
 * (bytecode, optimized code, feedback), which the engine grows while it compiles and
 * optimizes functions the page runs for the first time or often, and flushes on its own.
 */
async function heapSnapshot(session: CDPSession): Promise<HeapFigures['snapshot']> {
  const chunks: string[] = [];
  const collect = (event: { chunk: string }) => chunks.push(event.chunk);
  session.on('HeapProfiler.addHeapSnapshotChunk', collect);
  await session.send('HeapProfiler.takeHeapSnapshot', { reportProgress: false });
  session.off('HeapProfiler.addHeapSnapshotChunk', collect);
  const snapshot = JSON.parse(chunks.join('')) as {
    snapshot: { meta: { node_fields: string[]; node_types: [string[]] } };
    nodes: number[];
  };
  const fields = snapshot.snapshot.meta.node_fields;
  const typeNames = snapshot.snapshot.meta.node_types[0];
  const [typeAt, sizeAt, stride] = [fields.indexOf('type'), fields.indexOf('self_size'), fields.length];
  let total = 0;
  let code = 0;
  let values = 0;
  for (let i = 0; i < snapshot.nodes.length; i += stride) {
    const size = snapshot.nodes[i + sizeAt];
    const type = typeNames[snapshot.nodes[i + typeAt]];
    total += size;
    if (type === 'code') code += size;
    if (VALUE_TYPES.has(type)) values += size;
  }
  return { total, code, values };
}
