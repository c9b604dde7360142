import { Vector4, type IUniform, type Texture } from 'three';
import { IWAVE_GRID_SIZE, IWAVE_SPACING } from '../../sim/iwave/fieldSize';

/** What the ocean's shaders read of the interactive waves (shaders/iwave.glsl): the field, and its grid (origin x, z, spacing, size). */
export interface InteractiveWaveUniforms {
  uIWaveField: IUniform<Texture | null>;
  uIWaveGrid: IUniform<Vector4>;
}

export function createInteractiveWaveUniforms(): InteractiveWaveUniforms {
  return { uIWaveField: { value: null }, uIWaveGrid: { value: new Vector4(0, 0, IWAVE_SPACING, IWAVE_GRID_SIZE) } };
}
