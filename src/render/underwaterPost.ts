import {
  DepthTexture,
  HalfFloatType,
  Matrix4,
  ShaderMaterial,
  Vector2,
  Vector3,
  WebGLRenderTarget,
  type IUniform,
  type PerspectiveCamera,
  type Scene,
  type WebGLRenderer,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { RenderPass } from 'three/addons/postprocessing/RenderPass.js';
import { ShaderPass } from 'three/addons/postprocessing/ShaderPass.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import type { Pass } from 'three/addons/postprocessing/Pass.js';
import fullscreenVertex from '../../shaders/fullscreen.vert?raw';
import underwaterFragment from '../../shaders/underwater.frag?raw';
import blurFragment from '../../shaders/gaussianBlur.frag?raw';
import { BLUR_MAX_RADIUS, gaussianKernel } from '../sim/gaussianKernel';
import { registerShaderChunks } from './shaderChunks';
import type { WaveBinding } from './waveModels/waveBinding';
import type { WaterVolumeUniforms } from './waterVolumeUniforms';

export interface PassTiming {
  name: string;
  ms: number;
}

/** The water pass reads the depth the scene pass wrote along with its colour. */
class WaterVolumePass extends ShaderPass {
  render(renderer: WebGLRenderer, writeBuffer: WebGLRenderTarget, readBuffer: WebGLRenderTarget, deltaTime: number, maskActive: boolean): void {
    this.uniforms.tDepth.value = readBuffer.depthTexture;
    super.render(renderer, writeBuffer, readBuffer, deltaTime, maskActive);
  }
}

function blurPass(name: string): ShaderPass {
  const material = new ShaderMaterial({
    name,
    vertexShader: fullscreenVertex,
    fragmentShader: blurFragment,
    uniforms: {
      tDiffuse: { value: null },
      uStep: { value: new Vector2() },
      uWeights: { value: Array.from(gaussianKernel(0, BLUR_MAX_RADIUS)) },
      uRadius: { value: 0 },
      uLastMaskUse: { value: name === 'BlurVertical' },
    },
  });
  return new ShaderPass(material);
}

/**
 * What the camera sees from under the water, as EffectComposer passes: the scene, the
 * water volume (fog, absorption, god rays, and the per-pixel waterline mask), a separable
 * Gaussian blur (horizontal, then vertical) and the output pass (tone mapping, sRGB).
 * Only used while some of the view is under the water; above it, the view renders directly.
 */
export class UnderwaterPost {
  private readonly composer: EffectComposer;
  private readonly scenePass: RenderPass;
  private readonly volumePass: WaterVolumePass;
  private readonly blurH: ShaderPass;
  private readonly blurV: ShaderPass;
  private readonly outputPass: OutputPass;
  private readonly named: [string, Pass][];

  constructor(
    private readonly renderer: WebGLRenderer,
    scene: Scene,
    private readonly camera: PerspectiveCamera,
    waves: WaveBinding,
    shared: WaterVolumeUniforms & Record<'uRefractedSun' | 'uSunColor', IUniform>,
  ) {
    registerShaderChunks();
    const size = renderer.getDrawingBufferSize(new Vector2());
    const target = new WebGLRenderTarget(size.x, size.y, { type: HalfFloatType, depthTexture: new DepthTexture(size.x, size.y) });
    this.composer = new EffectComposer(renderer, target);
    this.scenePass = new RenderPass(scene, camera);
    this.volumePass = new WaterVolumePass(
      waves.attach(new ShaderMaterial({
        name: 'UnderwaterVolume',
        vertexShader: fullscreenVertex,
        fragmentShader: underwaterFragment,
        uniforms: {
          ...shared,
          tDiffuse: { value: null },
          tDepth: { value: null },
          uProjectionInverse: { value: new Matrix4() },
          uCameraWorld: { value: new Matrix4() },
          uEye: { value: new Vector3() },
          uNear: { value: 0.1 },
          uFar: { value: 1000 },
          uPerPixelWaterline: { value: false },
          uGodRays: { value: 0 },
          uWriteMask: { value: false },
        },
      })),
    );
    this.blurH = blurPass('BlurHorizontal');
    this.blurV = blurPass('BlurVertical');
    this.outputPass = new OutputPass();
    this.named = [
      ['scene', this.scenePass],
      ['water', this.volumePass],
      ['blurH', this.blurH],
      ['blurV', this.blurV],
      ['output', this.outputPass],
    ];
    for (const [, pass] of this.named) this.composer.addPass(pass);
  }

  setSize(width: number, height: number, pixelRatio: number): void {
    this.composer.setPixelRatio(pixelRatio);
    this.composer.setSize(width, height);
    this.updateBlurSteps();
  }

  /** Blur σ in pixels; 0 switches both blur passes off. */
  setBlur(sigma: number): void {
    const weights = Array.from(gaussianKernel(sigma, BLUR_MAX_RADIUS));
    const radius = sigma === 0 ? 0 : Math.min(BLUR_MAX_RADIUS, Math.ceil(3 * sigma));
    this.volumePass.uniforms.uWriteMask.value = sigma > 0;
    for (const pass of [this.blurH, this.blurV]) {
      pass.enabled = sigma > 0;
      pass.uniforms.uWeights.value = weights;
      pass.uniforms.uRadius.value = radius;
    }
  }

  setGodRays(intensity: number): void {
    this.volumePass.uniforms.uGodRays.value = intensity;
  }

  private updateBlurSteps(): void {
    const size = this.renderer.getDrawingBufferSize(new Vector2());
    (this.blurH.uniforms.uStep.value as Vector2).set(1 / size.x, 0);
    (this.blurV.uniforms.uStep.value as Vector2).set(0, 1 / size.y);
  }

  /** Draws the frame; perPixelWaterline when the near plane may cross the surface. Returns the passes run. */
  render(perPixelWaterline: boolean, afterEachPass?: (name: string) => void): number {
    const u = this.volumePass.uniforms;
    this.camera.updateMatrixWorld();
    (u.uProjectionInverse.value as Matrix4).copy(this.camera.projectionMatrixInverse);
    (u.uCameraWorld.value as Matrix4).copy(this.camera.matrixWorld);
    (u.uEye.value as Vector3).copy(this.camera.position);
    u.uNear.value = this.camera.near;
    u.uFar.value = this.camera.far;
    u.uPerPixelWaterline.value = perPixelWaterline;
    const restore: [Pass, Pass['render']][] = [];
    if (afterEachPass) {
      for (const [name, pass] of this.named) {
        const original = pass.render;
        restore.push([pass, original]);
        pass.render = (...args: Parameters<Pass['render']>) => {
          original.apply(pass, args);
          afterEachPass(name);
        };
      }
    }
    try {
      this.composer.render(0);
    } finally {
      for (const [pass, original] of restore) pass.render = original;
    }
    return this.named.filter(([, pass]) => pass.enabled).length;
  }

  /** Each enabled pass's cost in one frame, with the GPU waited for after each. */
  profile(perPixelWaterline: boolean, sync: () => void): PassTiming[] {
    const timings: PassTiming[] = [];
    sync();
    let start = performance.now();
    this.render(perPixelWaterline, (name) => {
      sync();
      const now = performance.now();
      timings.push({ name, ms: now - start });
      start = now;
    });
    return timings;
  }

  dispose(): void {
    for (const [, pass] of this.named) pass.dispose();
    this.composer.dispose();
  }
}
