/**
 * The CPU twin's FFTs off the main thread: a Worker holding an FftOcean of the sea it is
 * sent, answering each { sea, time } with the float64 fields at that time (transferred, not
 * copied), written into the arrays the request brought back when it brought some.
 * FftWaveModel adopts them; see src/sim/fftWaveModel.ts for when it waits for them.
 */
import { FftOcean } from '../../sim/fftOcean';
import { seaKey } from '../../sim/fftWaveModel';
import { copyFields, fieldBuffers, type FieldsReply, type FieldsRequest } from './fftFieldsSource';

interface WorkerScope {
  onmessage: ((event: MessageEvent<FieldsRequest>) => void) | null;
  postMessage(message: FieldsReply, transfer: Transferable[]): void;
}

const scope = self as unknown as WorkerScope;
let ocean: FftOcean | null = null;
let key = '';

scope.onmessage = (event) => {
  const { sea, time, spare } = event.data;
  const k = seaKey(sea);
  if (!ocean || k !== key) {
    ocean = new FftOcean(sea);
    key = k;
  }
  ocean.setTime(time);
  const fields = copyFields(ocean.fields, spare);
  scope.postMessage({ sea, time, fields }, fieldBuffers(fields));
};
