import type { CoastField, CoastSetting } from '../../sim/coast/coastField';
import { buildCoastField } from '../../sim/coast/coastSwellField';
import { startModuleWorker } from '../waves/fft/moduleWorker';
import type { CoastFieldReply, CoastFieldRequest } from './coastFieldMessages';
import coastFieldWorkerUrl from './coastFieldWorker.ts?worker&url';

/**
 * Builds the coast's swell fields in a Worker (coastFieldWorker.ts), so that choosing the
 * island, or moving a swell control, never freezes the page. Each call's promise settles with
 * its own setting's field; where no Worker can start, the field is built here instead.
 */
export class CoastFieldBuilder {
  private worker: Worker | null = null;
  private nextId = 0;
  private readonly waiting = new Map<number, { setting: CoastSetting; resolve: (field: CoastField | null) => void }>();

  constructor() {
    try {
      this.worker = startModuleWorker(new URL(coastFieldWorkerUrl, import.meta.url));
      this.worker.onmessage = (event: MessageEvent<CoastFieldReply>) => {
        const { id, field } = event.data;
        this.waiting.get(id)?.resolve(field);
        this.waiting.delete(id);
      };
      this.worker.onerror = (event) => {
        event.preventDefault();
        this.failOver(new Error(`the coast's field Worker failed: ${event.message}`));
      };
    } catch {
      this.worker = null;
    }
  }

  build(setting: CoastSetting): Promise<CoastField | null> {
    if (!this.worker) return Promise.resolve(buildCoastField(setting));
    const id = this.nextId++;
    const request: CoastFieldRequest = { id, setting };
    return new Promise((resolve) => {
      this.waiting.set(id, { setting, resolve });
      this.worker!.postMessage(request);
    });
  }

  /** A Worker that fails answers nothing more: what it was asked is built here, and so is what follows. */
  private failOver(error: Error): void {
    console.warn(`Oceano: ${error.message}; building on the main thread.`);
    this.worker?.terminate();
    this.worker = null;
    for (const { setting, resolve } of this.waiting.values()) resolve(buildCoastField(setting));
    this.waiting.clear();
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
    this.waiting.clear();
  }
}
