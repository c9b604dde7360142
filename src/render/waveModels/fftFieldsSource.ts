import type { CascadeFields } from '../../sim/fftOcean';
import type { FieldSource } from '../../sim/fftWaveModel';
import type { SeaState } from '../../sim/seaState';

export interface FieldsRequest {
  sea: SeaState;
  time: number;
}

export interface FieldsReply extends FieldsRequest {
  fields: CascadeFields[];
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
  private inFlight: FieldsRequest | null = null;
  private pending: FieldsRequest | null = null;

  /**
   * `spent(ms)` hears how long each reply kept the main thread: reading the message (Chromium
   * deserialises `data` on first access) and `deliver`.
   */
  constructor(deliver: (reply: FieldsReply) => void, spent: (ms: number) => void = () => {}) {
    let worker: Worker | null = null;
    try {
      worker = new Worker(new URL('./fftFieldsWorker.ts', import.meta.url), { type: 'module' });
      worker.onmessage = (event: MessageEvent<FieldsReply>) => {
        const start = performance.now();
        this.busy = false;
        this.inFlight = null;
        deliver(event.data);
        this.flush();
        spent(performance.now() - start);
      };
      worker.onerror = () => {
        this.worker?.terminate();
        this.failed = true;
      };
    } catch {
      worker = null;
    }
    this.worker = worker;
  }

  private failed = false;

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

  private flush(): void {
    if (!this.worker || !this.pending || this.failed) return;
    this.busy = true;
    this.inFlight = this.pending;
    this.worker.postMessage(this.pending);
    this.pending = null;
  }

  dispose(): void {
    this.worker?.terminate();
    this.failed = true;
  }
}
