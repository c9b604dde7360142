/**
 * The messages between the FFT twin's Worker (fftFieldsWorker.ts) and its main-thread end
 * (fftFieldsSource.ts), and the buffer handling both sides share. Its own module, so that
 * neither end imports the other.
 */
import type { CascadeFields } from '../../../sim/waves/fft/fftOcean';
import type { SeaState } from '../../../sim/waves/spectra/seaState';

export interface FieldsRequest {
  sea: SeaState;
  time: number;
  /**
   * Arrays the main thread no longer reads (FieldSource.recycle), transferred back for the
   * Worker to fill: replies then reuse the same few buffers instead of allocating fresh
   * fields for every frame, whose garbage the main thread would collect.
   */
  spare: CascadeFields[] | null;
}

/** The fields at `time` of the sea last requested (the main thread knows which sea it asked about). */
export interface FieldsReply {
  time: number;
  fields: CascadeFields[];
}

/** The buffers a message carries, each once, to be transferred (moved, not copied). */
export function fieldBuffers(fields: readonly CascadeFields[]): ArrayBuffer[] {
  return [...new Set(fields.flatMap((f) => [f.displacement.buffer as ArrayBuffer, f.derivatives.buffer as ArrayBuffer]))];
}

/** Whether every array of `fields` is a view of one ArrayBuffer (packedFields' layout). */
function packed(fields: readonly CascadeFields[]): boolean {
  const buffer = fields[0]?.displacement.buffer;
  return fields.every((f) => f.displacement.buffer === buffer && f.derivatives.buffer === buffer);
}

/**
 * Empty fields shaped like `like`, all views of ONE ArrayBuffer: a reply then transfers one
 * buffer, not two per cascade, and reading the message on the main thread (deserialised on
 * first access) has one buffer to take over instead of six.
 */
export function packedFields(like: readonly CascadeFields[]): CascadeFields[] {
  const total = like.reduce((sum, f) => sum + f.displacement.length + f.derivatives.length, 0);
  const buffer = new ArrayBuffer(total * Float64Array.BYTES_PER_ELEMENT);
  let offset = 0;
  const view = (length: number) => {
    const array = new Float64Array(buffer, offset * Float64Array.BYTES_PER_ELEMENT, length);
    offset += length;
    return array;
  };
  return like.map((f) => ({ displacement: view(f.displacement.length), derivatives: view(f.derivatives.length) }));
}

/**
 * The ocean's fields copied into `spare` where its arrays fit (same cascades, same size, one
 * buffer), else into new packed arrays (packedFields).
 */
export function copyFields(from: readonly CascadeFields[], spare: CascadeFields[] | null): CascadeFields[] {
  const fits =
    spare !== null &&
    spare.length === from.length &&
    spare.every((f, c) => f.displacement.length === from[c].displacement.length && f.derivatives.length === from[c].derivatives.length) &&
    packed(spare);
  const to = fits ? spare : packedFields(from);
  to.forEach((f, c) => {
    f.displacement.set(from[c].displacement);
    f.derivatives.set(from[c].derivatives);
  });
  return to;
}
