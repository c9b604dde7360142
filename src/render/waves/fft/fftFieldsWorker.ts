/**
 * The CPU twin's FFTs off the main thread: a Worker holding an FftOcean of the sea it is
 * sent, answering each { sea, time } with the float64 fields at that time (transferred, not
 * copied, in one buffer: packedFields), written into the arrays the request brought back when
 * they fit, REPLY_DELAY_MS after the request came (see there).
 * FftWaveModel adopts them; see src/sim/waves/fft/fftWaveModel.ts for when it waits for them.
 */
import { FftOcean } from '../../../sim/waves/fft/fftOcean';
import { seaKey } from '../../../sim/waves/fft/fftWaveModel';
import { copyFields, fieldBuffers, type FieldsReply, type FieldsRequest } from './fftFieldsMessages';

interface WorkerScope {
  onmessage: ((event: MessageEvent<FieldsRequest>) => void) | null;
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
 * thread's core straight away when the cores are busy, and the main thread's postMessage then
 * returns only after the Worker's time slice, up to its whole FFT. Waiting a little lets the
 * main thread finish its frame first; the fields still arrive well within a frame.
 */
const REPLY_DELAY_MS = 2;

function answer(): void {
  scheduled = false;
  if (!next) return;
  const { sea, time, spare } = next;
  next = null;
  const k = seaKey(sea);
  if (!ocean || k !== key) {
    ocean = new FftOcean(sea);
    key = k;
  }
  ocean.setTime(time);
  const fields = copyFields(ocean.fields, spare);
  scope.postMessage({ time, fields }, fieldBuffers(fields));
}

scope.onmessage = (event) => {
  // A newer request replaces one not yet started (keeping the arrays the older one brought).
  next = { ...event.data, spare: event.data.spare ?? next?.spare ?? null };
  if (scheduled) return;
  scheduled = true;
  setTimeout(answer, REPLY_DELAY_MS);
};
