import { Vector4, type IUniform, type Texture } from 'three';
import { IWAVE_GRID_SIZE, IWAVE_SPACING } from '../../sim/iwave/fieldSize';

/**
 * What the ocean's shaders read of the interactive waves (shaders/iwave.glsl): the field, its
 * grid (origin x, z, spacing, size), and the hand-over to the analytic wake (boat x, z, D, on).
 */
export interface InteractiveWaveUniforms {
  uIWaveField: IUniform<Texture | null>;
  uIWaveGrid: IUniform<Vector4>;
  uIWaveHandOver: IUniform<Vector4>;
}

export function createInteractiveWaveUniforms(): InteractiveWaveUniforms {
  return {
    uIWaveField: { value: null },
    uIWaveGrid: { value: new Vector4(0, 0, IWAVE_SPACING, IWAVE_GRID_SIZE) },
    uIWaveHandOver: { value: new Vector4() },
  };
}
