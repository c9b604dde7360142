import type { CoastField, CoastSetting } from '../../sim/coast/coastField';

/** A request to the coast's field Worker (coastFieldWorker.ts): build the field of `setting`. */
export interface CoastFieldRequest {
  id: number;
  setting: CoastSetting;
}

/** Its answer: the field of request `id` (null for a deep sea). */
export interface CoastFieldReply {
  id: number;
  field: CoastField | null;
}

/** The field's arrays, to transfer rather than copy. */
export function coastFieldBuffers(field: CoastField | null): ArrayBuffer[] {
  return field ? field.components.map((component) => component.texels.buffer as ArrayBuffer) : [];
}
