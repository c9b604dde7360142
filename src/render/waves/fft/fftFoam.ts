import {
  FloatType,
  GLSL3,
  Vector2,
  LinearFilter,
  NearestFilter,
  RawShaderMaterial,
  RepeatWrapping,
  RGBAFormat,
  WebGLRenderTarget,
  type Texture,
} from 'three';
import quadVertex from '../../../../shaders/fftQuad.vert?raw';
import packFragment from '../../../../shaders/fftFoam.frag?raw';
import memoryFragment from '../../../../shaders/fftFoamMemory.frag?raw';
import breakingChunk from '../../../../shaders/waves/fftBreaking.glsl?raw';
import { resolveChunks } from '../../shaders/shaderChunks';
import { glslFloat } from '../../shaders/shaderConstants';
import { FOAM_POTENTIAL_MAX, FOAM_POTENTIAL_VISIBLE } from '../../../sim/waves/fft/foamMemory';
import type { GpuFftOcean } from './gpuFft';

/** `count` float textures of n × n (MRT); `filtered`: LINEAR, for the ocean's pixels' filtered reads (shaders/waves/fft.glsl). */
function foamTarget(n: number, count: number, filtered: boolean): WebGLRenderTarget {
  const filter = filtered ? LinearFilter : NearestFilter;
  return new WebGLRenderTarget(n, n, {
    count,
    type: FloatType,
    format: RGBAFormat,
    minFilter: filter,
    magFilter: filter,
    wrapS: RepeatWrapping,
    wrapT: RepeatWrapping,
    depthBuffer: false,
    stencilBuffer: false,
    generateMipmaps: false,
  });
}

function passMaterial(name: string, fragmentShader: string, uniforms: RawShaderMaterial['uniforms']): RawShaderMaterial {
  return new RawShaderMaterial({
    name,
    glslVersion: GLSL3,
    vertexShader: quadVertex,
    fragmentShader,
    uniforms,
    depthTest: false,
    depthWrite: false,
  });
}

/** The cascade whose tile remembers foam: the smallest, whose texels are finer than a whitecap. */
export const REMEMBERING_CASCADE = 2;

/**
 * The foam passes of the spectral sea:
 * - remember: one step of the lattice of simulation times (src/sim/waves/fft/foamMemory.ts) on
 *   the smallest cascade's fields at that lattice time, which the caller has just computed in the
 *   ocean's lattice tile (GpuFftOcean.lattice; shaders/fftFoamMemory.frag), ping-ponged between two targets;
 * - pack: every frame, what the ocean's pixels read besides the derivatives, per cascade in one
 *   texture of its tile's texel grid (shaders/fftFoam.frag): the remembered foam faded to now,
 *   and ∂Dx/∂x (one draw, three colour attachments).
 */
export class FftFoam {
  private readonly memory: [WebGLRenderTarget, WebGLRenderTarget];
  private readonly packed: WebGLRenderTarget;
  private readonly memoryMaterial: RawShaderMaterial;
  private readonly packMaterial: RawShaderMaterial;
  private current = 0;

  constructor(private readonly gpu: GpuFftOcean) {
    const n = gpu.fft.n;
    if (gpu.targets.length !== 3) throw new RangeError(`shaders/fftFoam.frag packs 3 cascades, the sea has ${gpu.targets.length}.`);
    if (!gpu.lattice) throw new Error('The remembered foam needs the ocean built with a lattice tile (REMEMBERING_CASCADE).');
    this.memory = [foamTarget(n, 1, false), foamTarget(n, 1, false)];
    this.packed = foamTarget(n, 3, gpu.filtered);
    const constants = `#define FOAM_POTENTIAL_MAX ${glslFloat(FOAM_POTENTIAL_MAX)}\n#define FOAM_POTENTIAL_VISIBLE ${glslFloat(FOAM_POTENTIAL_VISIBLE)}\n`;
    this.memoryMaterial = passMaterial('FftFoamMemory', constants + resolveChunks(memoryFragment, { oceano_fft_breaking: breakingChunk }), {
      uDisplacement: { value: gpu.lattice.textures[0] },
      uDerivatives: { value: gpu.lattice.textures[1] },
      uPrevious: { value: null },
      uDrift: { value: new Vector2() },
      uDecay: { value: 0 },
      uThreshold: { value: 0 },
      uSoftness: { value: 1 },
    });
    this.packMaterial = passMaterial('FftFoamPack', packFragment, {
      uDisplacement0: { value: gpu.displacement[0] },
      uDisplacement1: { value: gpu.displacement[1] },
      uDisplacement2: { value: gpu.displacement[2] },
      uMemory: { value: null },
      uFade: { value: 0 },
    });
  }

  /** What the pixels read, one texture per cascade: (remembered foam now, 0, ∂Dx/∂x, 1). */
  get textures(): Texture[] {
    return this.packed.textures.slice();
  }

  /**
   * One lattice step, on the fields in the ocean's lattice tile: decay = e^{−Δ/τ} (0 starts from nothing); the smallest cascade's
   * breaking threshold and the potential's unit; the whole texels the older foam drifts
   * (src/sim/waves/fft/foamDrift.ts). `keep`: false draws the step without making it the
   * memory (a timing of the pass that leaves the foam as it was).
   */
  remember(decay: number, threshold: number, softness: number, drift: readonly [number, number], keep = true): void {
    const next = 1 - this.current;
    const u = this.memoryMaterial.uniforms;
    (u.uDrift.value as Vector2).fromArray(drift);
    u.uDecay.value = decay;
    u.uThreshold.value = threshold;
    u.uSoftness.value = softness;
    u.uPrevious.value = this.memory[this.current].texture;
    this.gpu.fft.draw(this.memoryMaterial, this.memory[next]);
    if (keep) this.current = next;
  }

  /** The memory as it stands: n × n potentials, row by row (for oceano.debug.foamMemory). */
  readMemory(): Float32Array {
    const n = this.gpu.fft.n;
    const rgba = new Float32Array(4 * n * n);
    this.gpu.fft.read(this.memory[this.current], rgba);
    return Float32Array.from({ length: n * n }, (_, i) => rgba[4 * i]);
  }

  /** Packs the current fields with the memory faded by `fade` (0: no remembered foam). */
  pack(fade: number): void {
    this.packMaterial.uniforms.uMemory.value = this.memory[this.current].texture;
    this.packMaterial.uniforms.uFade.value = fade;
    this.gpu.fft.draw(this.packMaterial, this.packed);
  }

  dispose(): void {
    this.memoryMaterial.dispose();
    this.packMaterial.dispose();
    for (const t of this.memory) t.dispose();
    this.packed.dispose();
  }
}
