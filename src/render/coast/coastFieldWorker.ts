/**
 * The coast's swell field built off the main thread: the island's eikonal solves and ray
 * tracings, one per component of the swell, take a few hundred milliseconds that would
 * otherwise freeze the page. Each request { id, setting } is answered with { id, field }, the
 * field's arrays transferred, not copied.
 */
import { buildCoastField } from '../../sim/coast/coastSwellField';
import { coastFieldBuffers, type CoastFieldReply, type CoastFieldRequest } from './coastFieldMessages';

interface WorkerScope {
  onmessage: ((event: MessageEvent<CoastFieldRequest>) => void) | null;
  postMessage(message: CoastFieldReply, transfer: Transferable[]): void;
}

const scope = self as unknown as WorkerScope;

scope.onmessage = (event) => {
  const { id, setting } = event.data;
  const field = buildCoastField(setting);
  scope.postMessage({ id, field }, coastFieldBuffers(field));
};
