import type { CascadeFields } from '../../../sim/waves/fft/fftOcean';
import type { FieldSource } from '../../../sim/waves/fft/fftWaveModel';
import type { SeaState } from '../../../sim/waves/spectra/seaState';
import { fieldBuffers, type FieldsReply, type FieldsRequest } from './fftFieldsMessages';
import { startModuleWorker } from './moduleWorker';
import fieldsWorkerUrl from './fftFieldsWorker.ts?worker&url';

/**
 * The FFT twin's fields from a Worker (fftFieldsWorker.ts), one request and one reply per
 * frame. One request in flight at a time; a newer request replaces one still waiting, so a
 * slow Worker is never asked for stale times. Messages work on any page; shared memory would
 * need a cross-origin isolated one, which a course site on a static host is not
 * (docs/worker-transport.md).
 */
export class WorkerFieldSource implements FieldSource {
  private readonly worker = startModuleWorker(new URL(fieldsWorkerUrl, import.meta.url));
  /** The request the Worker is working on (null when idle). */
  private inFlight: { sea: SeaState; time: number } | null = null;
  private pending: { sea: SeaState; time: number } | null = null;
  /** Arrays handed back by the model, sent to the Worker with the next request. */
  private spare: CascadeFields[] | null = null;

  /**
   * `deliver` hears each reply, with the sea object it was requested for (the model then
   * knows it by identity). `spent(ms)` hears how long each reply kept the main thread:
   * reading the message (Chromium deserialises `data` on first access), `deliver`, and
   * sending the next request.
   */
  constructor(deliver: (sea: SeaState, time: number, fields: CascadeFields[]) => void, spent: (ms: number) => void = () => {}) {
    this.worker.onmessage = (event: MessageEvent<FieldsReply>) => {
      const start = performance.now();
      const answered = this.inFlight;
      this.inFlight = null;
      const { time, fields } = event.data;
      if (answered) deliver(answered.sea, time, fields);
      this.flush();
      spent(performance.now() - start);
    };
  }

  request(sea: SeaState, time: number): void {
    // A frame asks twice for its time (prefetch, then the surface questions): the Worker is
    // already on it, and a second answer would only cost the main thread another receipt.
    if (this.inFlight && this.inFlight.sea === sea && this.inFlight.time === time) {
      this.pending = null;
      return;
    }
    this.pending = { sea, time };
    if (!this.inFlight) this.flush();
  }

  recycle(fields: CascadeFields[]): void {
    // One set in hand is enough: one request is in flight at a time, so the Worker fills at
    // most one set between two replies (and a set it cannot use, another sea's size, it drops).
    this.spare = fields;
  }

  private flush(): void {
    if (!this.pending) return;
    this.inFlight = this.pending;
    this.pending = null;
    const request: FieldsRequest = { ...this.inFlight, spare: this.spare };
    this.spare = null;
    this.worker.postMessage(request, request.spare ? fieldBuffers(request.spare) : []);
  }

  dispose(): void {
    this.worker.terminate();
  }
}
