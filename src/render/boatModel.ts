import { Box3, type Object3D } from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import type { HullSize } from '../sim/boatPose';

export interface BoatModel {
  object: Object3D;
  /** Length (z extent) and beam (x extent) of the model's bounding box, metres. */
  hull: HullSize;
}

/**
 * Loads the boat's glTF. The model's frame is the one scripts/make-boat.ts writes: bow
 * towards −z, starboard +x, waterline at y = 0. Rejects with a message fit for a notice.
 */
export async function loadBoatModel(url: string): Promise<BoatModel> {
  let object: Object3D;
  try {
    object = (await new GLTFLoader().loadAsync(url)).scene;
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    throw new Error(`The boat model "${url}" could not be loaded (${reason}).`);
  }
  const box = new Box3().setFromObject(object);
  const length = box.max.z - box.min.z;
  const beam = box.max.x - box.min.x;
  if (!(length > 0) || !(beam > 0)) throw new Error(`The boat model "${url}" has no geometry to float.`);
  return { object, hull: { length, beam } };
}
