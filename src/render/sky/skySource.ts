import type { CubeTexture, WebGLRenderer } from 'three';
import { SkyBackground } from './skyBackground';
import { SunSky } from './sunSky';

/**
 * Where the sky the sea reflects comes from: painted from the sun (SunSky, repainted only
 * when the sun moves), or a cube map of the user's own, whose sun stays where it was
 * painted. `background` draws that same sky behind a scene, for whoever adds it.
 */
export class SkySource {
  readonly background: SkyBackground;
  /** Present while the sky is painted from the sun; null while a cube map of the user's is shown. */
  private sunSky: SunSky | null;
  private custom: CubeTexture | null;

  constructor(custom: CubeTexture | null) {
    this.custom = custom;
    this.sunSky = custom ? null : new SunSky();
    this.background = new SkyBackground(this.texture);
  }

  get texture(): CubeTexture {
    return this.custom ?? (this.sunSky as SunSky).texture;
  }

  /** Paints the sun's sky for this sun (nothing when it already shows it, or the sky is the user's). */
  paint(renderer: WebGLRenderer, sun: readonly [number, number, number]): void {
    this.sunSky?.update(renderer, sun);
    this.background.setSun(sun, this.sunSky !== null);
  }

  /** A restored WebGL context gives render targets back empty: the sun's sky is painted again. */
  contextRestored(renderer: WebGLRenderer, sun: readonly [number, number, number]): void {
    if (!this.sunSky) return;
    this.sunSky.forget();
    this.sunSky.update(renderer, sun);
  }

  /** Shows a cube map of the user's from now on; the sun then moves only the lighting. */
  setCustom(sky: CubeTexture): void {
    this.sunSky?.dispose();
    this.sunSky = null;
    this.custom = sky;
    this.background.setSky(sky);
    this.background.setSun([0, 1, 0], false);
  }

  /** How many times the sun's sky has been painted (0 with a cube map of the user's). */
  get paintCount(): number {
    return this.sunSky?.paintCount ?? 0;
  }

  /** The user's cube map stays theirs to dispose. */
  dispose(): void {
    this.sunSky?.dispose();
    this.background.dispose();
  }
}
