import type { PerspectiveCamera, Scene, WebGLRenderer } from 'three';
import type { OceanEngine } from '../ocean/oceanEngine';
import type { OceanUnderwater } from './oceanUnderwater';
import type { EncodedScene } from './underwaterPost';

/**
 * The app's underwater passes, built on first use: their code (the composer, its passes and
 * shaders) is fetched only when the camera first goes below the surface. Until it has
 * arrived, `passes()` is undefined and the canvas keeps its last frame; `redraw` is called
 * once it is there. If it cannot be fetched, frames below the surface are drawn plainly.
 */
export class UnderwaterStage {
  /** The code could not be fetched: the sea is drawn from below without fog, god rays or blur. */
  failed = false;
  private underwater?: OceanUnderwater;
  private code?: typeof import('./oceanUnderwater');
  private load?: Promise<void>;
  private shaftLightWindowForced = false;
  /** The app's scene holds the boat: its materials write the faster encoding too (an opt-in the library leaves off). */
  private encodedScene: EncodedScene = 'every-material';

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly scene: Scene,
    private readonly camera: PerspectiveCamera,
    private readonly ocean: OceanEngine,
    private readonly redraw: () => void,
    private readonly partFailed: () => void,
  ) {}

  /** The passes, once loaded; starts loading them on the first call. */
  passes(): OceanUnderwater | undefined {
    if (!this.underwater && this.code) {
      this.underwater = new this.code.OceanUnderwater(this.renderer, this.scene, this.camera, this.ocean, {
        encodedScene: this.encodedScene,
      });
      this.underwater.forceShaftLightWindow = this.shaftLightWindowForced;
    }
    this.load ??= import('./oceanUnderwater').then(
      (code) => {
        this.code = code;
        this.redraw();
      },
      () => {
        // The browser keeps a failed module import failed, so only a reload tries again.
        this.failed = true;
        this.partFailed();
        this.redraw();
      },
    );
    return this.underwater;
  }

  /** Settles once the passes have loaded, when a frame has needed them; at once otherwise. */
  whenLoaded(): Promise<void> {
    return this.load ?? Promise.resolve();
  }

  /** Every material back to plain linear colour (if the passes had turned the encoding on), for a frame drawn without them. */
  resetEncoding(): void {
    this.underwater?.resetEncoding();
  }

  fitToCanvas(): void {
    this.underwater?.fitToCanvas();
  }

  /** Bakes the shaft light as a window even where the lens repeats (a diagnostic). */
  forceShaftLightWindow(on: boolean): void {
    this.shaftLightWindowForced = on;
    if (this.underwater) this.underwater.forceShaftLightWindow = on;
  }

  /** Draws through another kind of scene target from the next frame (the bench measures both). */
  setEncodedScene(mode: EncodedScene): void {
    if (mode === this.encodedScene) return;
    this.underwater?.resetEncoding();
    this.underwater?.dispose();
    this.underwater = undefined;
    this.encodedScene = mode;
  }

  dispose(): void {
    this.underwater?.dispose();
  }
}
