import type { CascadeFields } from '../../../sim/waves/fft/fftOcean';
import type { FieldSource } from '../../../sim/waves/fft/fftWaveModel';
import type { SeaState } from '../../../sim/waves/spectra/seaState';

export interface FieldsRequest {
  sea: SeaState;
  time: number;
  /**
   * Arrays the main thread no longer reads (FieldSource.recycle), transferred back for the
   * Worker to fill: with them, replies reuse the same few buffers instead of allocating 6
   * arrays of 4n² float64 (3 MB at n = 128) for every frame, whose garbage the main thread
   * then collected (single slow frames of stats().twinMs).
   */
  spare: CascadeFields[] | null;
}

export interface FieldsReply {
  sea: SeaState;
  time: number;
  fields: CascadeFields[];
}

/** The buffers a message carries, each once, to be transferred (moved, not copied). */
export function fieldBuffers(fields: readonly CascadeFields[]): ArrayBuffer[] {
  return [...new Set(fields.flatMap((f) => [f.displacement.buffer as ArrayBuffer, f.derivatives.buffer as ArrayBuffer]))];
}

/** Whether every array of `fields` is a view of one ArrayBuffer (packedFields' layout). */
function packed(fields: readonly CascadeFields[]): boolean {
  const buffer = fields[0]?.displacement.buffer;
  return fields.every((f) => f.displacement.buffer === buffer && f.derivatives.buffer === buffer);
}

/**
 * Empty fields shaped like `like`, all views of ONE ArrayBuffer: a reply then transfers one
 * buffer, not two per cascade. Reading the message (`event.data`, deserialised on first
 * access) cost the main thread about 0.1 ms with six transferred buffers.
 */
export function packedFields(like: readonly CascadeFields[]): CascadeFields[] {
  const total = like.reduce((sum, f) => sum + f.displacement.length + f.derivatives.length, 0);
  const buffer = new ArrayBuffer(total * Float64Array.BYTES_PER_ELEMENT);
  let offset = 0;
  const view = (length: number) => {
    const array = new Float64Array(buffer, offset * Float64Array.BYTES_PER_ELEMENT, length);
    offset += length;
    return array;
  };
  return like.map((f) => ({ displacement: view(f.displacement.length), derivatives: view(f.derivatives.length) }));
}

/**
 * The ocean's fields copied into `spare` where its arrays fit (same cascades, same size, one
 * buffer), else into new packed arrays (packedFields).
 */
export function copyFields(from: readonly CascadeFields[], spare: CascadeFields[] | null): CascadeFields[] {
  const fits =
    spare !== null &&
    spare.length === from.length &&
    spare.every((f, c) => f.displacement.length === from[c].displacement.length && f.derivatives.length === from[c].derivatives.length) &&
    packed(spare);
  const to = fits ? spare : packedFields(from);
  to.forEach((f, c) => {
    f.displacement.set(from[c].displacement);
    f.derivatives.set(from[c].derivatives);
  });
  return to;
}

/**
 * The twin's Worker (fftFieldsWorker.ts), or null where it cannot start (a
 * Content-Security-Policy without worker-src for the bundled web component, say). One that
 * fails later is terminated and `failed` is told.
 */
export function startFieldsWorker(failed: () => void): Worker | null {
  try {
    const worker = new Worker(new URL('./fftFieldsWorker.ts', import.meta.url), { type: 'module' });
    worker.onerror = () => {
      worker.terminate();
      failed();
    };
    return worker;
  } catch {
    return null;
  }
}

/**
 * A FieldSource backed by fftFieldsWorker.ts. One request in flight at a time; a newer request
 * replaces one still waiting, so a slow Worker is never asked for stale times.
 * If the Worker cannot start (a Content-Security-Policy without worker-src for the bundled
 * web component, say), requests are dropped and FftWaveModel computes on the calling thread.
 */
export class WorkerFieldSource implements FieldSource {
  private readonly worker: Worker | null;
  private busy = false;
  /** The request the Worker is working on (null when idle). */
  private inFlight: Omit<FieldsRequest, 'spare'> | null = null;
  private pending: Omit<FieldsRequest, 'spare'> | null = null;
  /** Arrays handed back by the model, sent to the Worker with the next request. */
  private spare: CascadeFields[] | null = null;

  /**
   * `spent(ms)` hears how long each reply kept the main thread: reading the message (Chromium
   * deserialises `data` on first access) and `deliver`.
   */
  constructor(deliver: (reply: FieldsReply) => void, spent: (ms: number) => void = () => {}) {
    this.worker = startFieldsWorker(() => (this.failed = true));
    if (!this.worker) return;
    this.worker.onmessage = (event: MessageEvent<FieldsReply>) => {
      const start = performance.now();
      this.busy = false;
      this.inFlight = null;
      deliver(event.data);
      this.flush();
      spent(performance.now() - start);
    };
  }

  private failed = false;

  get transport(): 'messages' | null {
    return this.worker && !this.failed ? 'messages' : null;
  }

  request(sea: SeaState, time: number): void {
    if (!this.worker || this.failed) return;
    // A frame asks twice for its time (prefetch, then the surface questions): the Worker is
    // already on it, and a second answer would only cost the main thread another receipt.
    if (this.inFlight && this.inFlight.sea === sea && this.inFlight.time === time) {
      this.pending = null;
      return;
    }
    this.pending = { sea, time };
    if (!this.busy) this.flush();
  }

  recycle(fields: CascadeFields[]): void {
    // One set in hand is enough: one request is in flight at a time, so the Worker fills at
    // most one set between two replies (and a set it cannot use, another sea's size, it drops).
    this.spare = fields;
  }

  private flush(): void {
    if (!this.worker || !this.pending || this.failed) return;
    this.busy = true;
    this.inFlight = this.pending;
    const request: FieldsRequest = { ...this.pending, spare: this.spare };
    this.spare = null;
    this.worker.postMessage(request, request.spare ? fieldBuffers(request.spare) : []);
    this.pending = null;
  }

  dispose(): void {
    this.worker?.terminate();
    this.failed = true;
  }
}
