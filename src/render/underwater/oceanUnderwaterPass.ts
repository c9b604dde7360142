import { DepthTexture, ShaderMaterial, type PerspectiveCamera, type WebGLRenderer, type WebGLRenderTarget } from 'three';
import { FullScreenQuad, Pass } from 'three/addons/postprocessing/Pass.js';
import fullscreenVertex from '../../../shaders/fullscreen.vert?raw';
import type { OceanEngine } from '../ocean/oceanEngine';
import { UnderwaterPost } from './underwaterPost';

export interface OceanUnderwaterPassOptions {
  /**
   * The scene target holds the encoding of Oceano's faster RGBA8 scene target (what
   * OceanUnderwater's encoded modes write) rather than linear colour. Leave it off in a
   * composer of your own.
   */
  sceneEncoded?: boolean;
}

/**
 * The picture unchanged: onto the canvas (the last pass) through the renderer's tone mapping
 * and output colour space, as OutputPass would; into a render target three.js leaves both out.
 */
function passThroughMaterial(): ShaderMaterial {
  return new ShaderMaterial({
    name: 'UnderwaterPassThrough',
    uniforms: { tDiffuse: { value: null } },
    vertexShader: fullscreenVertex,
    fragmentShader: /* glsl */ `
      uniform sampler2D tDiffuse;
      varying vec2 vUv;
      void main() {
        gl_FragColor = texture2D(tDiffuse, vUv);
        #include <tonemapping_fragment>
        #include <colorspace_fragment>
      }`,
  });
}

/**
 * The view from under the water as a pass of your own EffectComposer, after the RenderPass
 * and before passes such as bloom and OutputPass: water fog and absorption, god rays, the blur
 * and the waterline across the frame, drawn over the scene's colour and depth while the eye is
 * in the water; above it the picture passes through unchanged. It follows the ocean's
 * parameters (blurStrength, godRays, godRaysIntensity) and `ocean.update(time, camera)`'s
 * camera, which must be the one given here.
 *
 * The pass reads the scene's depth from a DepthTexture of the composer's buffers. A plain
 * `new EffectComposer(renderer)` has none: the pass attaches one to each buffer on its first
 * frame (three binds it at the buffer's next use), and that frame, whose depth the RenderPass
 * already wrote elsewhere, passes through. A target of your own with a depth texture is used as it is.
 */
export class OceanUnderwaterPass extends Pass {
  private readonly post: UnderwaterPost;
  private readonly passThroughMaterial = passThroughMaterial();
  private readonly passThrough = new FullScreenQuad(this.passThroughMaterial);
  private blur = Number.NaN;
  private godRays = Number.NaN;
  /** The depth textures this pass attached to buffers that had none, and to which (dispose takes them back). */
  private readonly attached: { target: WebGLRenderTarget; depth: DepthTexture }[] = [];
  /** The passes the last frame ran (0 above the water); diagnostics read it. */
  passesRun = 0;

  constructor(
    private readonly ocean: OceanEngine,
    camera: PerspectiveCamera,
    options: OceanUnderwaterPassOptions = {},
  ) {
    super();
    this.post = new UnderwaterPost(camera, ocean.binding, ocean.lightUniforms, options.sceneEncoded ?? false);
  }

  setSize(width: number, height: number): void {
    this.post.setSize(width, height);
  }

  render(renderer: WebGLRenderer, writeBuffer: WebGLRenderTarget, readBuffer: WebGLRenderTarget): void {
    this.draw(renderer, writeBuffer, readBuffer);
  }

  /** The frame's passes, with `afterEachPass` called after each (OceanUnderwater's profile). */
  draw(
    renderer: WebGLRenderer,
    writeBuffer: WebGLRenderTarget,
    readBuffer: WebGLRenderTarget,
    afterEachPass?: (name: string) => void,
  ): void {
    const submersion = this.ocean.submersion;
    const output = this.renderToScreen ? null : writeBuffer;
    // Attached above the water too, so the depth is there when the eye goes under.
    const depthWritten = readBuffer.depthTexture !== null;
    this.attachDepth(readBuffer);
    this.attachDepth(writeBuffer);
    if (submersion === 'above' || !depthWritten) {
      this.passesRun = 0;
      // Into the composer's buffers nothing needs drawing: the next pass reads the same buffer.
      this.needsSwap = this.renderToScreen;
      if (this.renderToScreen) {
        this.passThroughMaterial.uniforms.tDiffuse.value = readBuffer.texture;
        renderer.setRenderTarget(null);
        this.passThrough.render(renderer);
      }
      return;
    }
    this.needsSwap = true;
    this.followParams();
    this.passesRun = this.post.render(renderer, readBuffer, output, submersion === 'straddling', afterEachPass);
  }

  /** A DepthTexture on `target` if it has none: the composer sizes it with the buffer from then on (RenderTarget.setSize). */
  private attachDepth(target: WebGLRenderTarget): void {
    if (target.depthTexture !== null) return;
    const depth = new DepthTexture(target.width, target.height);
    target.depthTexture = depth;
    this.attached.push({ target, depth });
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
    for (const { target, depth } of this.attached.splice(0)) {
      if (target.depthTexture === depth) target.depthTexture = null;
      depth.dispose();
    }
    this.post.dispose();
    this.passThroughMaterial.dispose();
    this.passThrough.dispose();
  }
}
