import { Vector2, type IUniform } from 'three';
import { windVector } from '../../sim/waves/spectra/seaState';

/**
 * The uniforms of the foam material (shaders/foam/foamMaterial.glsl), shared by every ocean
 * material of a view: the detail texture (null until its code has been fetched, or while foam
 * is drawn as paint) with its mean density, and the direction the wind blows, which the foam's
 * streaks follow.
 */
export type FoamUniforms = Record<'uFoamDetail' | 'uFoamDensityMean' | 'uWindDirection', IUniform>;

export function createFoamUniforms(): FoamUniforms {
  return { uFoamDetail: { value: null }, uFoamDensityMean: { value: 0.5 }, uWindDirection: { value: new Vector2() } };
}

export function setFoamWind(uniforms: FoamUniforms, windDirectionDeg: number): void {
  (uniforms.uWindDirection.value as Vector2).fromArray(windVector(windDirectionDeg));
}
