/** One GPU pass's time in a profiled frame (oceano.debug.passTimings), ms, the GPU waited for after it. */
export interface PassTiming {
  name: string;
  ms: number;
}
