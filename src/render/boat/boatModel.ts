import { Box3, type Object3D } from 'three';
import type { HullSize } from '../../sim/boat/boatPose';
import { message, MessageError } from '../../sim/params/message';
import { oneDrawBoat } from './oneDrawBoat';

export interface BoatModel {
  object: Object3D;
  /** Length (z extent) and beam (x extent) of the model's bounding box, metres. */
  hull: HullSize;
}

/**
 * Loads the boat's glTF. The model's frame is the one scripts/build/make-boat.ts writes: bow
 * towards −z, starboard +x, waterline at y = 0. Fetching and parsing are separate steps so
 * that each failure gets its own message, fit for a notice: unreachable, not found, a web
 * page where the model should be (what single-page servers answer for a missing file), or
 * bytes that are not glTF.
 */
/** A GLB starts with the magic "glTF"; a .gltf is JSON, so its first visible character is "{". */
function looksLikeGltf(data: ArrayBuffer): boolean {
  const head = new Uint8Array(data, 0, Math.min(64, data.byteLength));
  if (String.fromCharCode(...head.subarray(0, 4)) === 'glTF') return true;
  const firstVisible = head.find((byte) => ![0x20, 0x09, 0x0a, 0x0d, 0xef, 0xbb, 0xbf].includes(byte));
  return firstVisible === 0x7b;
}

/**
 * Every failure comes out as a MessageError, whose notice the page shows in its own
 * language; the technical detail of an unexpected one goes to the console.
 */
export async function loadBoatModel(url: string): Promise<BoatModel> {
  try {
    return await fetchBoatModel(url);
  } catch (error) {
    if (error instanceof MessageError) throw error;
    console.warn('Oceano: the boat model could not be loaded:', error);
    const reason = error instanceof Error ? error.message : String(error);
    throw new MessageError(message('boatLoadFailed', { reason }), reason);
  }
}

async function fetchBoatModel(url: string): Promise<BoatModel> {
  let response: Response;
  try {
    response = await fetch(url);
  } catch {
    throw new MessageError(message('boatUnreachable', { url }), `The boat model "${url}" could not be fetched.`);
  }
  if (!response.ok) {
    throw new MessageError(
      message('boatNotFound', { url, status: response.status }),
      `The boat model "${url}" was not found (HTTP ${response.status}).`,
    );
  }
  if ((response.headers.get('content-type') ?? '').includes('text/html')) {
    throw new MessageError(message('boatWebPage', { url }), `The boat model "${url}" is missing: the server sent a web page in its place.`);
  }
  const data = await response.arrayBuffer();
  if (!looksLikeGltf(data)) {
    throw new MessageError(
      message('boatNotGltf', { url }),
      `The boat model "${url}" is not a valid glTF model: it is neither a binary .glb nor a JSON .gltf file.`,
    );
  }
  // The loader is fetched with the model, after the first frame: the page's first load stays small.
  const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
  let object: Object3D;
  try {
    object = (await new GLTFLoader().parseAsync(data, url.slice(0, url.lastIndexOf('/') + 1))).scene;
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    // The loader's reason is English and technical: the console gets it, the notice does not.
    console.warn(`Oceano: the boat model "${url}" could not be parsed: ${reason}`);
    throw new MessageError(message('boatNotGltf', { url }), `The boat model "${url}" is not a valid glTF model (${reason}).`);
  }
  const box = new Box3().setFromObject(object);
  const length = box.max.z - box.min.z;
  const beam = box.max.x - box.min.x;
  if (!(length > 0) || !(beam > 0))
    throw new MessageError(message('boatNoGeometry', { url }), `The boat model "${url}" has no geometry to float.`);
  // One draw for the whole boat (its parts' colours and finishes carried per vertex).
  return { object: oneDrawBoat(object), hull: { length, beam } };
}
