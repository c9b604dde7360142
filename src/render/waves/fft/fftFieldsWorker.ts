/**
 * The CPU twin's FFTs off the main thread: a Worker holding an FftOcean of the sea it is
 * sent, answering each { sea, time } with the float64 fields at that time (transferred, not
 * copied, in one buffer: packedFields), written into the arrays the request brought back when
 * they fit, REPLY_DELAY_MS after the request came (see there).
 * FftWaveModel adopts them; see src/sim/waves/fft/fftWaveModel.ts for when it waits for them.
 */
import { FftOcean } from '../../../sim/waves/fft/fftOcean';
import { seaKey } from '../../../sim/waves/fft/fftWaveModel';
import { chooseWriteSlot, controlViews, fieldsOn, publish, readRequest, slotBytes, type ChannelMessage, type SharedControl } from './sharedFieldsProtocol';
import { copyFields, fieldBuffers, type FieldsReply, type FieldsRequest } from './fftFieldsSource';

interface WorkerScope {
  onmessage: ((event: MessageEvent<FieldsRequest | ChannelMessage>) => void) | null;
  postMessage(message: FieldsReply, transfer: Transferable[]): void;
}

const scope = self as unknown as WorkerScope;
let ocean: FftOcean | null = null;
let key = '';
/** The request to answer next (the newest), and whether an answer is already scheduled. */
let next: FieldsRequest | null = null;
let scheduled = false;

/**
 * How long the Worker waits after a request arrives before computing it, ms. A Worker woken
 * by postMessage that starts its FFTs at once is often run by the kernel on the posting
 * thread's core straight away when the cores are busy (here: 2 cores, SwiftShader drawing on
 * both), and the main thread's postMessage then returns only after the Worker's time slice,
 * up to its whole FFT. Measured in the browser, an echo Worker spending 20 ms per request,
 * requests every 60 ms while the app played, load 8: postMessage took 0.21-0.76 ms on average
 * (max 12.5 ms) answered at once, 0.08-0.13 ms (max 0.3 ms) after a 2 ms timer; medians
 * 0.07 ms either way. The fields arrive 2 ms later: still well within a frame.
 */
const REPLY_DELAY_MS = 2;

function oceanAt(sea: FftOcean['setup']['sea'], time: number): FftOcean {
  const k = seaKey(sea);
  if (!ocean || k !== key) {
    ocean = new FftOcean(sea);
    key = k;
  }
  ocean.setTime(time);
  return ocean;
}

function answer(): void {
  scheduled = false;
  if (!next) return;
  const { sea, time, spare } = next;
  next = null;
  const ocean = oceanAt(sea, time);
  const fields = copyFields(ocean.fields, spare);
  scope.postMessage({ sea, time, fields }, fieldBuffers(fields));
}

/**
 * The shared-memory channel (SharedFieldSource, a cross-origin isolated page): no message per
 * frame; the Worker polls the requested time on its own timer, POLL_MS while requests come,
 * IDLE_POLL_MS after IDLE_AFTER_MS without one (a paused page). Polling rather than being
 * notified keeps the main thread from waking the Worker onto its own core (REPLY_DELAY_MS).
 */
const POLL_MS = 2;
const IDLE_POLL_MS = 50;
const IDLE_AFTER_MS = 500;
let channel: { sea: ChannelMessage['sea']; generation: number; control: SharedControl; slots: ReturnType<typeof fieldsOn>[]; seen: number } | null = null;
let polling = false;
let lastRequestAt = 0;

function poll(): void {
  const c = channel;
  if (!c) {
    polling = false;
    return;
  }
  const request = readRequest(c.control, c.seen);
  if (request) {
    c.seen = request.seq;
    lastRequestAt = performance.now();
    const fields = oceanAt(c.sea, request.time).fields;
    const slot = chooseWriteSlot(c.control);
    copyFields(fields, c.slots[slot]);
    publish(c.control, slot, request.time, c.generation);
  }
  setTimeout(poll, performance.now() - lastRequestAt > IDLE_AFTER_MS ? IDLE_POLL_MS : POLL_MS);
}

function openChannel(message: ChannelMessage): void {
  const n = message.sea.fftSize;
  const cascades = message.slots[0].byteLength / slotBytes(1, n);
  channel = { sea: message.sea, generation: message.generation, control: controlViews(message.control), slots: message.slots.map((s) => fieldsOn(s, cascades, n)), seen: 0 };
  lastRequestAt = performance.now();
  if (!polling) {
    polling = true;
    setTimeout(poll, POLL_MS);
  }
}

scope.onmessage = (event) => {
  if ('kind' in event.data) {
    openChannel(event.data);
    return;
  }
  // A newer request replaces one not yet started (keeping the arrays the older one brought).
  next = { ...event.data, spare: event.data.spare ?? next?.spare ?? null };
  if (scheduled) return;
  scheduled = true;
  setTimeout(answer, REPLY_DELAY_MS);
};
