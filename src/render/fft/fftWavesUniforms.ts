import { Vector3, type IUniform, type Texture } from 'three';
import type { GpuFftOcean } from './gpuFft';

/** Uniform names of shaders/fftWaves.glsl. */
export type FftWavesUniforms = Record<
  | 'uFftDisplacement0'
  | 'uFftDisplacement1'
  | 'uFftDisplacement2'
  | 'uFftDerivatives0'
  | 'uFftDerivatives1'
  | 'uFftDerivatives2'
  | 'uFftTileSize'
  | 'uFftN',
  IUniform
>;

/**
 * The uniforms shaders/fftWaves.glsl reads, bound to a GpuFftOcean's render targets. The
 * targets are fixed for the ocean's life (GpuFftOcean.update writes into them), so these
 * uniforms need no per-frame update: call gpu.update(t) before rendering the ocean.
 */
export function fftWavesUniforms(gpu: GpuFftOcean): FftWavesUniforms {
  if (gpu.sizes.length !== 3) throw new Error(`fftWaves.glsl reads 3 cascades, got ${gpu.sizes.length}.`);
  const d: Texture[] = gpu.displacement;
  const g: Texture[] = gpu.derivatives;
  return {
    uFftDisplacement0: { value: d[0] },
    uFftDisplacement1: { value: d[1] },
    uFftDisplacement2: { value: d[2] },
    uFftDerivatives0: { value: g[0] },
    uFftDerivatives1: { value: g[1] },
    uFftDerivatives2: { value: g[2] },
    uFftTileSize: { value: new Vector3(gpu.sizes[0], gpu.sizes[1], gpu.sizes[2]) },
    uFftN: { value: gpu.n },
  };
}
