import { Vector2, type PerspectiveCamera, type Scene, type WebGLRenderer } from 'three';
import type { OceanEngine } from '../ocean/oceanEngine';
import type { PassTiming } from '../diagnostics/passTiming';
import { encodeSceneForPost } from './sceneEncoding';
import { UnderwaterPost, type EncodedScene } from './underwaterPost';

export interface OceanUnderwaterOptions {
  /**
   * How the scene reaches the passes (UnderwaterPost's EncodedScene). The default, 'linear',
   * leaves every material of yours as it is; the encoded ones are faster on a software
   * rasterizer, and 'every-material' patches your materials to write the encoding.
   */
  encodedScene?: EncodedScene;
}

/**
 * The view from under the water, for an Ocean in a scene of yours: water fog and absorption,
 * god rays, the blur, and the waterline across the frame. Call `render()` in place of
 * `renderer.render(scene, camera)`, after `ocean.update(time, camera)`: it draws through the
 * passes while the eye is in the water, and directly above it.
 */
export class OceanUnderwater {
  private readonly post: UnderwaterPost;
  private readonly size = new Vector2();
  private readonly encodedScene: EncodedScene;
  private blur = Number.NaN;
  private godRays = Number.NaN;

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly scene: Scene,
    private readonly camera: PerspectiveCamera,
    private readonly ocean: OceanEngine,
    options: OceanUnderwaterOptions = {},
  ) {
    this.encodedScene = options.encodedScene ?? 'linear';
    this.post = new UnderwaterPost(renderer, scene, camera, ocean.binding, ocean.lightUniforms, this.encodedScene);
    this.fitToCanvas();
  }

  /** Follows the renderer's size and pixel ratio; call after resizing the renderer. */
  fitToCanvas(): void {
    const size = this.renderer.getSize(this.size);
    this.post.setSize(size.x, size.y, this.renderer.getPixelRatio());
  }

  /** Draws the frame; returns the passes run (0 when it was drawn directly, above the water). */
  render(afterEachPass?: (name: string) => void): number {
    const submersion = this.ocean.submersion;
    if (submersion === 'above') {
      this.drawDirectly();
      return 0;
    }
    this.followParams();
    return this.post.render(submersion === 'straddling', afterEachPass);
  }

  /** The scene straight to the canvas, every material back to plain linear colour. */
  drawDirectly(): void {
    this.resetEncoding();
    this.renderer.render(this.scene, this.camera);
  }

  /** Every material back to plain linear colour, for a frame drawn some other way. */
  resetEncoding(): void {
    if (this.encodedScene !== 'linear') encodeSceneForPost(this.scene, false, this.encodedScene === 'every-material');
  }

  /** @internal Each pass's cost in one frame below the surface, the GPU waited for after each. */
  profile(sync: () => void): PassTiming[] {
    this.followParams();
    return this.post.profile(this.ocean.submersion === 'straddling', sync);
  }

  /** @internal Bakes the shaft light as the window generic wave models get, even where the lens repeats (a diagnostic). */
  set forceShaftLightWindow(on: boolean) {
    this.post.forceShaftLightWindow = on;
  }

  private followParams(): void {
    this.post.seaLevel = this.ocean.seaLevel;
    const params = this.ocean.getAllParams();
    const godRays = params.godRays ? params.godRaysIntensity : 0;
    if (params.blurStrength !== this.blur) this.post.setBlur((this.blur = params.blurStrength));
    if (godRays !== this.godRays) this.post.setGodRays((this.godRays = godRays));
  }

  dispose(): void {
    this.post.dispose();
  }
}
