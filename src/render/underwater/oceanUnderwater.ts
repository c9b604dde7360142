import {
  DepthTexture,
  HalfFloatType,
  UnsignedByteType,
  Vector2,
  WebGLRenderTarget,
  type PerspectiveCamera,
  type Scene,
  type WebGLRenderer,
} from 'three';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import type { OceanEngine } from '../ocean/oceanEngine';
import type { PassTiming } from '../diagnostics/passTiming';
import { encodeSceneForPost } from './sceneEncoding';
import { OceanUnderwaterPass } from './oceanUnderwaterPass';
import type { EncodedScene } from './underwaterPost';

export interface OceanUnderwaterOptions {
  /**
   * How the scene reaches the passes (underwaterPost.ts's EncodedScene). The default, 'linear',
   * leaves every material of yours as it is; the encoded ones are faster on a software
   * rasterizer, and 'every-material' patches your materials to write the encoding.
   */
  encodedScene?: EncodedScene;
}

/**
 * The view from under the water, for an Ocean in a scene of yours: water fog and absorption,
 * god rays, the blur, and the waterline across the frame. Call `render()` in place of
 * `renderer.render(scene, camera)`, after `ocean.update(time, camera)`: it draws through the
 * passes while the eye is in the water, and directly above it. The short way to
 * OceanUnderwaterPass: a scene target with depth, a RenderPass and the pass, onto the canvas.
 * For passes of your own beside it (bloom), put OceanUnderwaterPass in your EffectComposer.
 */
export class OceanUnderwater {
  private readonly pass: OceanUnderwaterPass;
  private readonly scenePass: RenderPass;
  /** The scene's colour and depth, which the pass reads. */
  private readonly target: WebGLRenderTarget;
  private readonly size = new Vector2();
  private readonly encodedScene: EncodedScene;

  constructor(
    private readonly renderer: WebGLRenderer,
    private readonly scene: Scene,
    private readonly camera: PerspectiveCamera,
    private readonly ocean: OceanEngine,
    options: OceanUnderwaterOptions = {},
  ) {
    this.encodedScene = options.encodedScene ?? 'linear';
    const encoded = this.encodedScene !== 'linear';
    // perf: encoded, the scene goes to RGBA8 (sceneEncoding.ts), which the software rasterizer writes far faster than half floats (docs/performance.md).
    this.target = new WebGLRenderTarget(1, 1, { type: encoded ? UnsignedByteType : HalfFloatType, depthTexture: new DepthTexture(1, 1) });
    this.scenePass = new RenderPass(scene, camera);
    this.pass = new OceanUnderwaterPass(ocean, camera, { sceneEncoded: encoded });
    this.pass.renderToScreen = true;
    this.fitToCanvas();
  }

  /** Follows the renderer's size and pixel ratio; call after resizing the renderer. */
  fitToCanvas(): void {
    const size = this.renderer.getDrawingBufferSize(this.size);
    this.target.setSize(size.x, size.y);
    this.pass.setSize(size.x, size.y);
  }

  /** Draws the frame; returns the passes run (0 when it was drawn directly, above the water). */
  render(afterEachPass?: (name: string) => void): number {
    if (this.ocean.submersion === 'above') {
      this.drawDirectly();
      return 0;
    }
    if (this.encodedScene !== 'linear') encodeSceneForPost(this.scene, true, this.encodedScene === 'every-material');
    this.scenePass.render(this.renderer, this.target, this.target, 0, false);
    afterEachPass?.('scene');
    this.pass.draw(this.renderer, this.target, this.target, afterEachPass);
    return 1 + this.pass.passesRun;
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
    const timings: PassTiming[] = [];
    sync();
    let start = performance.now();
    this.render((name) => {
      sync();
      const now = performance.now();
      timings.push({ name, ms: now - start });
      start = now;
    });
    return timings;
  }

  /** @internal Bakes the shaft light as the window generic wave models get, even where the lens repeats (a diagnostic). */
  set forceShaftLightWindow(on: boolean) {
    this.pass.forceShaftLightWindow = on;
  }

  dispose(): void {
    this.pass.dispose();
    this.scenePass.dispose();
    this.target.dispose();
  }
}
