import { FloatType, GLSL3, LinearFilter, NearestFilter, RawShaderMaterial, RepeatWrapping, RGBAFormat, Vector3, WebGLRenderTarget, type Texture } from 'three';
import quadVertex from '../../../../shaders/fftQuad.vert?raw';
import foamFragment from '../../../../shaders/fftFoam.frag?raw';
import type { GpuFftOcean } from './gpuFft';

/** One texture per cascade (MRT). `filtered`: LINEAR, for the ocean's pixels' filtered reads (shaders/waves/fft.glsl). */
function foamTarget(n: number, cascades: number, filtered: boolean): WebGLRenderTarget {
  const filter = filtered ? LinearFilter : NearestFilter;
  return new WebGLRenderTarget(n, n, {
    count: cascades,
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
 * Per cascade, foam accumulated in the texel grid of its FFT tile (two targets of one texture
 * per cascade, ping-pong; one draw steps every cascade):
 * each step keeps the larger of the old foam faded by e^{−Δt/τ} and the foam where this
 * cascade's Jacobian is below its threshold now (shaders/fftFoam.frag). Each cascade has its
 * own threshold, from its own Jacobian spread (src/sim/waves/fft/whitecaps.ts foamThresholdForSpread):
 * one band alone folds less often than the whole sea does.
 */
export class FftFoam {
  private readonly pair: [WebGLRenderTarget, WebGLRenderTarget];
  private readonly material: RawShaderMaterial;
  private current = 0;

  constructor(private readonly gpu: GpuFftOcean) {
    const n = gpu.fft.n;
    if (gpu.targets.length !== 3) throw new RangeError(`shaders/fftFoam.frag steps 3 cascades, the sea has ${gpu.targets.length}.`);
    this.pair = [foamTarget(n, 3, gpu.filtered), foamTarget(n, 3, gpu.filtered)];
    this.material = new RawShaderMaterial({
      name: 'FftFoam',
      glslVersion: GLSL3,
      vertexShader: quadVertex,
      fragmentShader: foamFragment,
      uniforms: {
        uDisplacement0: { value: gpu.displacement[0] },
        uDisplacement1: { value: gpu.displacement[1] },
        uDisplacement2: { value: gpu.displacement[2] },
        uDerivatives0: { value: gpu.derivatives[0] },
        uDerivatives1: { value: gpu.derivatives[1] },
        uDerivatives2: { value: gpu.derivatives[2] },
        uPrevious0: { value: null },
        uPrevious1: { value: null },
        uPrevious2: { value: null },
        uDecay: { value: 0 },
        uThreshold: { value: new Vector3() },
        uSoftness: { value: new Vector3(0.01, 0.01, 0.01) },
      },
      depthTest: false,
      depthWrite: false,
    });
  }

  /** The foam now, one texture per cascade (r channel). */
  get textures(): Texture[] {
    return this.pair[this.current].textures.slice();
  }

  /**
   * One step on the GPU's current fields; decay = e^{−Δt/τ} (0 forgets all earlier foam).
   * Per cascade its own Jacobian threshold and the half-width of the soft edge around it.
   */
  step(decay: number, thresholds: readonly number[], softness: readonly number[]): void {
    const next = 1 - this.current;
    const u = this.material.uniforms;
    u.uDecay.value = decay;
    (u.uThreshold.value as Vector3).set(thresholds[0], thresholds[1], thresholds[2]);
    (u.uSoftness.value as Vector3).set(softness[0], softness[1], softness[2]);
    const previous = this.pair[this.current].textures;
    u.uPrevious0.value = previous[0];
    u.uPrevious1.value = previous[1];
    u.uPrevious2.value = previous[2];
    this.gpu.fft.draw(this.material, this.pair[next]);
    this.current = next;
  }

  dispose(): void {
    this.material.dispose();
    for (const t of this.pair) t.dispose();
  }
}
