import type { CubeTexture } from 'three';
import { message, messageOf, type Message } from '../sim/message';
import { sunDirection } from '../sim/sun';
import type { OceanParams } from '../sim/params';
import { loadBoatModel, type BoatModel } from '../render/boatModel';
import { loadSkyCube, paintedSkyCube } from '../render/skyCube';

/** The sky's six images; where they cannot be loaded, a sky painted for the sun, with a notice naming `shownBase`. */
export async function loadSkyOrPaint(base: string, shownBase: string, params: OceanParams, notify: (m: Message) => void): Promise<CubeTexture> {
  try {
    return await loadSkyCube(base);
  } catch {
    notify(message('skyLoadFailed', { base: shownBase }));
    return paintedSkyCube(sunDirection(params.sunElevation, params.sunAzimuth));
  }
}

/**
 * The boat's model, with a loading indicator over the running sea meanwhile; where it
 * cannot be had, null and a notice saying why (the sea runs on without a boat).
 */
export async function loadBoatOrNotify(container: HTMLElement, url: string, loadingText: string, notify: (m: Message) => void): Promise<BoatModel | null> {
  const indicator = document.createElement('div');
  indicator.className = 'oceano-loading';
  indicator.setAttribute('role', 'status');
  indicator.textContent = loadingText;
  container.appendChild(indicator);
  try {
    return await loadBoatModel(url);
  } catch (error) {
    notify(messageOf(error, 'boatLoadFailed'));
    return null;
  } finally {
    indicator.remove();
  }
}
