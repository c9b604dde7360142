/** A CPU twin fed by a Worker, as seen from the main thread (stats().twin). */
export interface TwinStatus {
  /** Data sets adopted from the Worker since it started (0 while none has arrived, or with no Worker). */
  fieldsReceived: number;
  /** The time of the data the twin holds now (s); NaN before any. */
  fieldsTime: number;
}
