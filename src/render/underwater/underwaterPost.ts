import {
  ClampToEdgeWrapping,
  ACESFilmicToneMapping,
  AgXToneMapping,
  CineonToneMapping,
  CustomToneMapping,
  LinearToneMapping,
  NeutralToneMapping,
  ReinhardToneMapping,
  HalfFloatType,
  LinearFilter,
  Matrix4,
  RedFormat,
  RepeatWrapping,
  ShaderMaterial,
  Vector2,
  Vector3,
  UnsignedByteType,
  WebGLRenderTarget,
  type IUniform,
  type PerspectiveCamera,
  type ToneMapping,
  type WebGLRenderer,
} from 'three';
import { FullScreenQuad, Pass } from 'three/addons/postprocessing/Pass.js';
import fullscreenVertex from '../../../shaders/fullscreen.vert?raw';
import underwaterFragment from '../../../shaders/underwater.frag?raw';
import blurFragment from '../../../shaders/gaussianBlur.frag?raw';
import shaftLightFragment from '../../../shaders/shaftLight.frag?raw';
import godRaysFragment from '../../../shaders/godRays.frag?raw';
import compositeFragment from '../../../shaders/underwaterComposite.frag?raw';
import { BLUR_MAX_RADIUS, BLUR_MAX_TAPS, halfResolutionSigma, linearSampledKernel, onePassBlurOffset } from './gaussianKernel';
import { planShaftLightTile, type ShaftLightTile } from './shaftLightTile';
import { resolveChunks } from '../shaders/shaderChunks';
import { withPassChunks } from './passChunks';
import { SCENE_ENCODE_DEFINE, SCENE_LINEAR_DEFINE } from './sceneEncoding';
import { setMaterialDefine } from '../shaders/materialDefines';
import type { WaveBinding } from '../waves/waveBinding';
import type { WaterVolumeUniforms } from './waterVolumeUniforms';

/**
 * The shaft-light texture: repeating for one period of the lens, clamped for a window. One
 * 8-bit channel: the light is in [0, 1], and 8 bits hold it to within a level of the picture.
 * perf: the god rays read it many times a pixel; one 8-bit channel is a quarter of the memory
 * traffic of RGBA16F on any GPU, and filters far faster on a software rasterizer
 * (docs/performance.md, "Software rasterizer").
 */
function shaftLightTarget(tile: ShaftLightTile): WebGLRenderTarget {
  const wrap = tile.kind === 'tile' ? RepeatWrapping : ClampToEdgeWrapping;
  return new WebGLRenderTarget(tile.size, tile.size, {
    format: RedFormat,
    type: UnsignedByteType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    wrapS: wrap,
    wrapT: wrap,
    depthBuffer: false,
  });
}

/** Half of a drawing-buffer size, rounded up so the half-resolution image covers every pixel. */
const half = (pixels: number) => Math.max(1, Math.ceil(pixels / 2));

/**
 * The god rays' target, in the scene target's format and encoding (sceneEncoding.ts),
 * linearly filtered for the water pass's upsample.
 */
function godRaysTarget(encoded: boolean): WebGLRenderTarget {
  return new WebGLRenderTarget(1, 1, {
    type: encoded ? UnsignedByteType : HalfFloatType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
}

/**
 * A full-screen draw of one material into a target chosen when the frame runs: its own, or
 * the chain's output (the composer's write buffer, or the canvas: null).
 */
class QuadPass extends Pass {
  private readonly quad: FullScreenQuad;

  constructor(
    readonly material: ShaderMaterial,
    private readonly prepare: (readBuffer: WebGLRenderTarget) => WebGLRenderTarget | 'output',
  ) {
    super();
    this.quad = new FullScreenQuad(material);
  }

  get uniforms(): Record<string, IUniform> {
    return this.material.uniforms;
  }

  draw(renderer: WebGLRenderer, readBuffer: WebGLRenderTarget, output: WebGLRenderTarget | null): void {
    // A pass that writes what the canvas will show (ENCODE_OUTPUT) runs the renderer's tone curve itself.
    if ('ENCODE_OUTPUT' in this.material.defines) setToneMappingDefine(this.material, renderer.toneMapping);
    const target = this.prepare(readBuffer);
    renderer.setRenderTarget(target === 'output' ? output : target);
    this.quad.render(renderer);
  }

  render(renderer: WebGLRenderer, writeBuffer: WebGLRenderTarget, readBuffer: WebGLRenderTarget): void {
    this.draw(renderer, readBuffer, this.renderToScreen ? null : writeBuffer);
  }

  dispose(): void {
    this.material.dispose();
    this.quad.dispose();
  }
}

/** three.js's tone-mapping functions (its tonemapping_pars_fragment chunk), by the renderer's setting. */
const TONE_MAPPING_FUNCTIONS: Readonly<Record<number, string>> = {
  [LinearToneMapping]: 'LinearToneMapping',
  [ReinhardToneMapping]: 'ReinhardToneMapping',
  [CineonToneMapping]: 'CineonToneMapping',
  [ACESFilmicToneMapping]: 'ACESFilmicToneMapping',
  [CustomToneMapping]: 'CustomToneMapping',
  [AgXToneMapping]: 'AgXToneMapping',
  [NeutralToneMapping]: 'NeutralToneMapping',
};

/** OCEANO_TONE_MAPPING: the name of the renderer's tone-mapping function, absent for none; a change recompiles. */
function setToneMappingDefine(material: ShaderMaterial, toneMapping: ToneMapping): void {
  const wanted = TONE_MAPPING_FUNCTIONS[toneMapping];
  if (material.defines.OCEANO_TONE_MAPPING === wanted) return;
  if (wanted === undefined) delete material.defines.OCEANO_TONE_MAPPING;
  else material.defines.OCEANO_TONE_MAPPING = wanted;
  material.needsUpdate = true;
}

function blurMaterial(name: string, step: Vector2): ShaderMaterial {
  return new ShaderMaterial({
    name,
    vertexShader: fullscreenVertex,
    fragmentShader: resolveChunks(blurFragment),
    uniforms: {
      tDiffuse: { value: null },
      uStep: { value: step },
      uOffsets: { value: Array.from(new Float32Array(BLUR_MAX_TAPS)) },
      uWeights: { value: Array.from(new Float32Array(BLUR_MAX_TAPS)) },
      uTaps: { value: 1 },
    },
  });
}

/**
 * How the scene reaches the underwater passes. 'linear': a half-float target, every
 * material as it is. 'oceano-materials': an RGBA8 target holding an encoding that Oceano's
 * own materials write, for scenes with nothing else in them. 'every-material': the same, and
 * every other material in the scene is patched to write it too (an explicit opt-in: it
 * changes materials that are not Oceano's).
 */
export type EncodedScene = 'linear' | 'oceano-materials' | 'every-material';

/**
 * The blur's result, which the composite upsamples. Onto the canvas: RGBA8 holding the water
 * colour as the canvas will (sRGB), premultiplied (shaders/gaussianBlur.frag, ENCODE_OUTPUT);
 * the two passes before it keep half floats: three roundings to 8 bits grained the smooth
 * water (neighbouring pixels one level apart in 45 % of the deep view instead of 25 %); one,
 * as here, does not. Into a composer's buffer: linear colour in half floats, as the passes
 * after it (bloom, OutputPass) expect.
 */
function blurredTarget(toCanvas: boolean): WebGLRenderTarget {
  return new WebGLRenderTarget(1, 1, {
    type: toCanvas ? UnsignedByteType : HalfFloatType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    depthBuffer: false,
  });
}

/**
 * What the camera sees from under the water, drawn from a scene already rendered (colour and
 * depth): the shaft-light tile the god rays read; the water volume (fog, absorption, god
 * rays, and the per-pixel waterline mask); and with the blur on, a separable Gaussian blur
 * (horizontal, then vertical) and a composite that puts the sharp air side back. The water
 * pass and the blur run at half resolution when the blur is on: the blur softens that detail
 * anyway. With the blur off, the water pass runs at full resolution and writes the output
 * itself. Onto the canvas the last pass tone-maps and encodes as the renderer would; into a
 * render target it writes linear colour. OceanUnderwaterPass runs it as one composer pass.
 */
export class UnderwaterPost {
  private readonly shaftPass: QuadPass;
  private readonly raysPass: QuadPass;
  private readonly volumePass: QuadPass;
  private readonly blurH: QuadPass;
  private readonly blurV: QuadPass;
  private readonly compositePass: QuadPass;
  private readonly named: [string, QuadPass][];
  /** The baked shaft light; remade when the tile's kind or size changes (a switch of wave model). */
  private shaftTarget: WebGLRenderTarget;
  private shaftTile: ShaftLightTile = { kind: 'tile', origin: [0, 0], extent: 1, size: 1 };
  /** Debug: bake a window even for a model whose lens repeats (tests compare the two). */
  forceShaftLightWindow = false;
  /** The height of the sea at rest (the Ocean's position.y): the passes work with the surface at y = 0. */
  seaLevel = 0;
  /** Half-resolution premultiplied water: water → A, blurH → B, blurV → blurred (one pass: A → blurred). */
  private readonly halfA: WebGLRenderTarget;
  private readonly halfB: WebGLRenderTarget;
  /** The blur's result (blurredTarget), remade when the output moves between the canvas and a render target. */
  private blurred: WebGLRenderTarget;
  private blurredToCanvas = true;
  /** The god rays, at half the water pass's resolution (a quarter of the canvas's with the blur on). */
  private readonly rays: WebGLRenderTarget;
  private blurOn = false;
  /** The one-pass blur's tap offset in texels (src/render/underwater/gaussianKernel.ts), or null: two passes. */
  private onePassOffset: number | null = null;
  /** The output's size in pixels (the scene target's). */
  private readonly size = new Vector2(1, 1);

  /** sceneEncoded: the scene target holds the encoding of sceneEncoding.ts (RGBA8) rather than linear half floats. */
  constructor(
    private readonly camera: PerspectiveCamera,
    private readonly waves: WaveBinding,
    shared: WaterVolumeUniforms & Record<'uRefractedSun' | 'uSunColor', IUniform>,
    sceneEncoded = false,
  ) {
    this.rays = godRaysTarget(sceneEncoded);
    const decode = sceneEncoded ? {} : { [SCENE_LINEAR_DEFINE]: '' };
    const halfOptions = { type: HalfFloatType, minFilter: LinearFilter, magFilter: LinearFilter, depthBuffer: false };
    this.halfA = new WebGLRenderTarget(1, 1, halfOptions);
    this.halfB = new WebGLRenderTarget(1, 1, halfOptions);
    this.blurred = blurredTarget(this.blurredToCanvas);
    this.shaftTarget = shaftLightTarget(this.shaftTile);

    // Where the bake lies, the same objects in the bake and the water pass.
    const tile: Record<string, IUniform> = { uShaftOrigin: { value: new Vector2() }, uShaftExtent: { value: 1 } };
    this.shaftPass = new QuadPass(
      waves.attach(
        new ShaderMaterial({
          name: 'UnderwaterShaftLight',
          vertexShader: fullscreenVertex,
          fragmentShader: shaftLightFragment,
          uniforms: { ...tile },
        }),
      ),
      () => this.shaftTarget,
    );
    // The view's uniforms, the same objects in the water pass and the composite.
    const view: Record<string, IUniform> = {
      tDepth: { value: null },
      uProjectionInverse: { value: new Matrix4() },
      uCameraWorld: { value: new Matrix4() },
      uEye: { value: new Vector3() },
      uNear: { value: 0.1 },
      uFar: { value: 1000 },
    };
    // The god rays' march, at half the water pass's resolution: the shafts are soft there.
    // perf: the march was the dearest part of the underwater frame at the water pass's resolution (docs/performance.md).
    this.raysPass = new QuadPass(
      new ShaderMaterial({
        name: 'UnderwaterGodRays',
        defines: sceneEncoded ? { [SCENE_ENCODE_DEFINE]: '' } : {},
        vertexShader: fullscreenVertex,
        fragmentShader: resolveChunks(withPassChunks(godRaysFragment)),
        uniforms: { ...shared, ...view, ...tile, tShaftLight: { value: this.shaftTarget.texture }, uGodRays: { value: 0 } },
      }),
      (readBuffer) => {
        view.tDepth.value = readBuffer.depthTexture;
        return this.rays;
      },
    );
    this.volumePass = new QuadPass(
      waves.attach(
        new ShaderMaterial({
          name: 'UnderwaterVolume',
          defines: { ...decode },
          vertexShader: fullscreenVertex,
          fragmentShader: withPassChunks(underwaterFragment),
          uniforms: { ...shared, ...view, tDiffuse: { value: null }, tGodRays: { value: this.rays.texture }, uWriteMask: { value: false } },
        }),
      ),
      (readBuffer) => {
        this.volumePass.uniforms.tDiffuse.value = readBuffer.texture;
        view.tDepth.value = readBuffer.depthTexture;
        return this.blurOn ? this.halfA : 'output';
      },
    );
    const stepH = new Vector2();
    const stepV = new Vector2();
    this.blurH = new QuadPass(blurMaterial('BlurHorizontal', stepH), () => {
      this.blurH.uniforms.tDiffuse.value = this.halfA.texture;
      return this.halfB;
    });
    this.blurV = new QuadPass(blurMaterial('BlurVertical', stepV), () => {
      this.blurV.uniforms.tDiffuse.value = (this.blurH.enabled ? this.halfB : this.halfA).texture;
      return this.blurred;
    });
    this.compositePass = new QuadPass(
      waves.attach(
        new ShaderMaterial({
          name: 'UnderwaterComposite',
          defines: { ...decode },
          vertexShader: fullscreenVertex,
          fragmentShader: withPassChunks(compositeFragment),
          uniforms: { ...shared, ...view, tDiffuse: { value: null }, tBlurred: { value: this.blurred.texture } },
        }),
      ),
      (readBuffer) => {
        this.compositePass.uniforms.tDiffuse.value = readBuffer.texture;
        view.tDepth.value = readBuffer.depthTexture;
        return 'output';
      },
    );
    this.named = [
      ['shafts', this.shaftPass],
      ['rays', this.raysPass],
      ['water', this.volumePass],
      ['blurH', this.blurH],
      ['blurV', this.blurV],
      ['composite', this.compositePass],
    ];
    this.setBlur(0);
  }

  /** The scene target's size in pixels (the drawing buffer's, for a composer sized to the canvas). */
  setSize(width: number, height: number): void {
    this.size.set(Math.max(1, width), Math.max(1, height));
    this.fitTargets();
  }

  /**
   * What follows the output's size and the blur: the half-resolution targets, the blur
   * passes' texel steps (one texel across, then down; or the one-pass blur's diagonal tap), and
   * the god rays' target at half the water pass's size (half the canvas's with the blur on).
   */
  private fitTargets(): void {
    const size = this.size;
    const width = half(size.x);
    const height = half(size.y);
    for (const target of [this.halfA, this.halfB, this.blurred]) target.setSize(width, height);
    const o = this.onePassOffset;
    (this.blurH.uniforms.uStep.value as Vector2).set(1 / width, 0);
    (this.blurV.uniforms.uStep.value as Vector2).set(o === null ? 0 : o / width, o === null ? 1 / height : o / height);
    this.rays.setSize(half(this.blurOn ? width : size.x), half(this.blurOn ? height : size.y));
  }

  /** Blur σ in screen pixels; 0 switches the blur, and the half-resolution water, off. */
  setBlur(sigma: number): void {
    this.blurOn = sigma > 0;
    const kernel = linearSampledKernel(halfResolutionSigma(sigma), BLUR_MAX_RADIUS, BLUR_MAX_TAPS);
    // The default σ's kernel lies within 1 texel: one pass of four taps instead of two passes.
    // perf: one pass fewer of the half-resolution target (docs/performance.md, "Software rasterizer").
    this.onePassOffset = this.blurOn ? onePassBlurOffset(halfResolutionSigma(sigma)) : null;
    this.volumePass.uniforms.uWriteMask.value = this.blurOn;
    for (const pass of [this.blurV, this.compositePass]) pass.enabled = this.blurOn;
    this.blurH.enabled = this.blurOn && this.onePassOffset === null;
    setMaterialDefine(this.blurV.material, 'ONE_PASS', this.onePassOffset !== null);
    this.fitTargets();
    for (const pass of [this.blurH, this.blurV]) {
      pass.uniforms.uOffsets.value = Array.from(kernel.offsets);
      pass.uniforms.uWeights.value = Array.from(kernel.weights);
      pass.uniforms.uTaps.value = kernel.taps;
    }
  }

  setGodRays(intensity: number): void {
    this.raysPass.uniforms.uGodRays.value = intensity;
    setMaterialDefine(this.volumePass.material, 'GOD_RAYS', intensity > 0);
    // No god rays, nothing reads the shaft light, and no march.
    this.shaftPass.enabled = intensity > 0;
    this.raysPass.enabled = intensity > 0;
  }

  /**
   * Draws the water over `scene` (its colour and depth texture) into `output` (null: the
   * canvas); perPixelWaterline when the near plane may cross the surface. Returns the passes run.
   */
  render(
    renderer: WebGLRenderer,
    scene: WebGLRenderTarget,
    output: WebGLRenderTarget | null,
    perPixelWaterline: boolean,
    afterEachPass?: (name: string) => void,
  ): number {
    const u = this.volumePass.uniforms; // the view uniforms are shared with the god rays and the composite
    this.camera.updateMatrixWorld();
    (u.uProjectionInverse.value as Matrix4).copy(this.camera.projectionMatrixInverse);
    // In the sea's own frame, where the surface at rest is y = 0 (Ocean.seaLevel).
    (u.uCameraWorld.value as Matrix4).makeTranslation(0, -this.seaLevel, 0).multiply(this.camera.matrixWorld);
    (u.uEye.value as Vector3).setFromMatrixPosition(u.uCameraWorld.value as Matrix4);
    u.uNear.value = this.camera.near;
    u.uFar.value = this.camera.far;
    if (this.shaftPass.enabled) this.placeShaftLight();
    for (const pass of [this.volumePass, this.compositePass]) setMaterialDefine(pass.material, 'PER_PIXEL_WATERLINE', perPixelWaterline);
    if (this.blurOn) this.blurInto(output === null);
    let run = 0;
    for (const [name, pass] of this.named) {
      if (!pass.enabled) continue;
      pass.draw(renderer, scene, output);
      run++;
      afterEachPass?.(pass === this.blurV && this.onePassOffset !== null ? 'blur' : name);
    }
    return run;
  }

  /** The blur's last pass writes as the canvas holds colour, or linear for a render target (blurredTarget). */
  private blurInto(toCanvas: boolean): void {
    setMaterialDefine(this.blurV.material, 'ENCODE_OUTPUT', toCanvas);
    if (toCanvas === this.blurredToCanvas) return;
    this.blurredToCanvas = toCanvas;
    this.blurred.dispose();
    this.blurred = blurredTarget(toCanvas);
    this.compositePass.uniforms.tBlurred.value = this.blurred.texture;
    this.fitTargets();
  }

  /** Plans this frame's bake of the shaft light (src/render/underwater/shaftLightTile.ts) and points the passes at it. */
  private placeShaftLight(): void {
    const model = this.waves.model;
    const eye = this.volumePass.uniforms.uEye.value as Vector3;
    const sun = this.raysPass.uniforms.uRefractedSun.value as Vector3;
    const period = this.forceShaftLightWindow ? null : model.lensPeriod;
    const tile = planShaftLightTile(period, [eye.x, eye.y, eye.z], [sun.x, sun.y, sun.z]);
    if (tile.kind !== this.shaftTile.kind || tile.size !== this.shaftTile.size) {
      this.shaftTarget.dispose();
      this.shaftTarget = shaftLightTarget(tile);
      this.raysPass.uniforms.tShaftLight.value = this.shaftTarget.texture;
    }
    this.shaftTile = tile;
    const u = this.raysPass.uniforms;
    (u.uShaftOrigin.value as Vector2).fromArray(tile.origin);
    u.uShaftExtent.value = tile.extent;
    setMaterialDefine(this.raysPass.material, 'SHAFT_LIGHT_WINDOW', tile.kind === 'window');
  }

  dispose(): void {
    for (const pass of [this.shaftPass, this.volumePass, this.compositePass]) this.waves.detach(pass.material);
    for (const [, pass] of this.named) pass.dispose();
    for (const target of [this.shaftTarget, this.halfA, this.halfB, this.blurred, this.rays]) target.dispose();
  }
}
