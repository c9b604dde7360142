import type { CubeTexture } from 'three';
import { message, messageOf, type Message } from '../../sim/params/message';
import type { BoatModel } from '../../render/boat/boatModel';
import { loadSkyCube } from '../../render/sky/skyCube';
import type { LoadingProgress } from './loadingProgress';

/**
 * A page's own six images (`sky=` names `custom`, loaded from `base`), with a notice that
 * their sun is painted in; null for the sky painted from the sun: when the page names none,
 * or when its images cannot be loaded (with a notice naming them).
 */
export async function loadCustomSky(base: string, custom: string | null, notify: (m: Message) => void): Promise<CubeTexture | null> {
  if (custom === null) return null;
  try {
    const sky = await loadSkyCube(base);
    notify(message('skyCustomSunFixed', { base: custom }));
    return sky;
  } catch {
    notify(message('skyLoadFailed', { base: custom }));
    return null;
  }
}

/** The boat's model, shown as the loading step under way; where it cannot be had, null and a notice saying why (the sea runs on without a boat). */
export async function loadBoatOrNotify(url: string, notify: (m: Message) => void, loading: LoadingProgress): Promise<BoatModel | null> {
  loading.begin('boat');
  try {
    // The loader's code, with the texts of its own notices, is fetched only now (boatLoad.ts).
    const { loadBoatModel } = await import('./boatLoad').catch((error: unknown) => {
      // The notice (boatLoadFailed) leaves the technical detail to the console, as loadBoatModel does.
      console.warn('Oceano: the boat loader could not be downloaded:', error);
      throw error;
    });
    return await loadBoatModel(url);
  } catch (error) {
    notify(messageOf(error, 'boatLoadFailed'));
    return null;
  }
}
