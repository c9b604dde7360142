import { cascadeLayout } from '../../../sim/waves/fft/cascades';
import type { CascadeFields } from '../../../sim/waves/fft/fftOcean';
import { seaKey, type FieldSource } from '../../../sim/waves/fft/fftWaveModel';
import { startFieldsWorker } from './fftFieldsSource';
import type { SeaState } from '../../../sim/waves/spectra/seaState';
import { controlViews, CONTROL_BYTES, fieldsOn, release, slotBytes, SLOTS, takePublication, writeRequest, type ChannelMessage, type SharedControl } from './sharedFieldsProtocol';
import { peakWavelength } from '../../../sim/waves/spectra/waveSpectrum';

/** Whether this page may share memory with a Worker (cross-origin isolated: COOP + COEP headers). */
export function sharedMemoryAvailable(): boolean {
  return typeof SharedArrayBuffer === 'function' && (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true;
}

interface Channel {
  sea: SeaState;
  key: string;
  generation: number;
  control: SharedControl;
  slots: CascadeFields[][];
  /** The PUBLISHED word last taken. */
  seen: number;
  /** The time last requested. */
  requested: number;
}

/**
 * A FieldSource over shared memory, for a cross-origin isolated page: per frame the main
 * thread stores the time it wants and adopts the Worker's newest published fields as views
 * of a shared slot, with no message either way (a round trip cost ~0.1-0.2 ms of main thread
 * per frame: README, Performance). A new sea opens a new channel: one message.
 * `deliver` is FftWaveModel.receive: it says whether the fields were adopted; refused ones
 * leave the slot read before marked as read.
 */
export class SharedFieldSource implements FieldSource {
  private readonly worker: Worker | null;
  private failed = false;
  private channel: Channel | null = null;
  private generation = 0;

  constructor(private readonly deliver: (sea: SeaState, time: number, fields: CascadeFields[]) => boolean) {
    this.worker = startFieldsWorker(() => (this.failed = true));
  }

  get transport(): 'shared-memory' | null {
    return this.worker && !this.failed ? 'shared-memory' : null;
  }

  request(sea: SeaState, time: number): void {
    if (!this.worker || this.failed) return;
    let channel = this.channel;
    if (!channel || channel.sea !== sea) {
      const key = seaKey(sea);
      if (channel && channel.key === key) channel.sea = sea;
      else channel = this.open(this.worker, sea, key);
    }
    if (time !== channel.requested) {
      writeRequest(channel.control, time);
      channel.requested = time;
    }
    const publication = takePublication(channel.control, channel.seen, channel.generation);
    if (!publication) return;
    channel.seen = publication.word;
    if (!this.deliver(channel.sea, publication.time, channel.slots[publication.slot])) release(channel.control, publication);
  }

  private open(worker: Worker, sea: SeaState, key: string): Channel {
    const generation = ++this.generation;
    const n = sea.fftSize;
    const cascades = cascadeLayout(peakWavelength(sea), n).length;
    const control = new SharedArrayBuffer(CONTROL_BYTES);
    const slots = Array.from({ length: SLOTS }, () => new SharedArrayBuffer(slotBytes(cascades, n)));
    // Initialised before the Worker can see it.
    const views = controlViews(control, generation);
    const message: ChannelMessage = { kind: 'channel', sea, generation, control, slots };
    worker.postMessage(message);
    this.channel = {
      sea,
      key,
      generation,
      control: views,
      slots: slots.map((s) => fieldsOn(s, cascades, n)),
      seen: -1,
      requested: Number.NaN,
    };
    return this.channel;
  }

  dispose(): void {
    this.worker?.terminate();
    this.failed = true;
    this.channel = null;
  }
}
