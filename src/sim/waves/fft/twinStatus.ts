/**
 * How a CPU twin's Worker hands its data to the main thread. 'shared-memory': on a
 * cross-origin isolated page, no message per frame (SharedFieldSource); 'messages': anywhere
 * else, a request and a reply per frame (WorkerFieldSource).
 */
export type TwinTransport = 'shared-memory' | 'messages';

/** A CPU twin fed by a Worker, as seen from the main thread (stats().twin). */
export interface TwinStatus {
  /** How the Worker hands its data over; null when there is no Worker (the twin computes on the main thread). */
  transport: TwinTransport | null;
  /** Data sets adopted from the Worker since it started. */
  fieldsReceived: number;
  /** The time of the data the twin holds now (s); NaN before any. */
  fieldsTime: number;
}
