import { Vector3, type IUniform } from 'three';

/**
 * The uniforms of shaders/caustics.glsl (`#include <oceano_caustics>`, after
 * `#include <oceano_waves>`). To light any mesh under the water with caustics —
 * the sea bed here, a boat's hull — bind its ShaderMaterial to the ocean's WaveBinding,
 * give it this set (shared objects, so one update reaches all), pass the world position to the
 * fragment shader and multiply the direct sunlight by `causticLight(worldPosition)`.
 */
export type CausticsUniforms = Record<'uCausticsSunDirection' | 'uCausticsStrength', IUniform>;

export function createCausticsUniforms(): CausticsUniforms {
  return {
    uCausticsSunDirection: { value: new Vector3(0, 1, 0) },
    uCausticsStrength: { value: 1 },
  };
}

export function applyCaustics(u: CausticsUniforms, towardsSun: readonly [number, number, number], enabled: boolean, intensity: number): void {
  (u.uCausticsSunDirection.value as Vector3).fromArray(towardsSun).normalize();
  u.uCausticsStrength.value = enabled ? intensity : 0;
}
