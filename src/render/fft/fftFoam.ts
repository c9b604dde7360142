import { FloatType, GLSL3, LinearFilter, NearestFilter, RawShaderMaterial, RepeatWrapping, RGBAFormat, WebGLRenderTarget, type Texture } from 'three';
import quadVertex from '../../../shaders/fftQuad.vert?raw';
import foamFragment from '../../../shaders/fftFoam.frag?raw';
import type { GpuFftOcean } from './gpuFft';

/** `filtered`: LINEAR, for the ocean's pixels' filtered reads (shaders/waves/fft.glsl). */
function foamTarget(n: number, filtered: boolean): WebGLRenderTarget {
  const filter = filtered ? LinearFilter : NearestFilter;
  return new WebGLRenderTarget(n, n, {
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

/**
 * Per cascade, foam accumulated in the texel grid of its FFT tile (two targets, ping-pong):
 * each step keeps the larger of the old foam faded by e^{−Δt/τ} and the foam where this
 * cascade's Jacobian is below its threshold now (shaders/fftFoam.frag). Each cascade has its
 * own threshold, from its own Jacobian spread (src/sim/whitecaps.ts foamThresholdForSpread):
 * one band alone folds less often than the whole sea does.
 */
export class FftFoam {
  private readonly pairs: [WebGLRenderTarget, WebGLRenderTarget][];
  private readonly material: RawShaderMaterial;
  private current = 0;

  constructor(private readonly gpu: GpuFftOcean) {
    const n = gpu.fft.n;
    this.pairs = gpu.targets.map(() => [foamTarget(n, gpu.filtered), foamTarget(n, gpu.filtered)]);
    this.material = new RawShaderMaterial({
      name: 'FftFoam',
      glslVersion: GLSL3,
      vertexShader: quadVertex,
      fragmentShader: foamFragment,
      uniforms: {
        uDisplacement: { value: null },
        uDerivatives: { value: null },
        uPrevious: { value: null },
        uDecay: { value: 0 },
        uThreshold: { value: 0 },
        uSoftness: { value: 0.01 },
      },
      depthTest: false,
      depthWrite: false,
    });
  }

  /** The foam now, one texture per cascade (r channel). */
  get textures(): Texture[] {
    return this.pairs.map((pair) => pair[this.current].texture);
  }

  /**
   * One step on the GPU's current fields; decay = e^{−Δt/τ} (0 forgets all earlier foam).
   * Per cascade its own Jacobian threshold and the half-width of the soft edge around it.
   */
  step(decay: number, thresholds: readonly number[], softness: readonly number[]): void {
    const next = 1 - this.current;
    const u = this.material.uniforms;
    u.uDecay.value = decay;
    this.gpu.targets.forEach((target, c) => {
      u.uThreshold.value = thresholds[c];
      u.uSoftness.value = softness[c];
      u.uDisplacement.value = target.textures[0];
      u.uDerivatives.value = target.textures[1];
      u.uPrevious.value = this.pairs[c][this.current].texture;
      this.gpu.fft.draw(this.material, this.pairs[c][next]);
    });
    this.current = next;
  }

  dispose(): void {
    this.material.dispose();
    for (const pair of this.pairs) for (const t of pair) t.dispose();
  }
}
