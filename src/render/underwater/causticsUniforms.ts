import { Vector3, type IUniform } from 'three';
import { refractedSunDirection } from '../../sim/underwater/snellWindow';

/**
 * The uniforms of shaders/caustics.glsl (`#include <oceano_caustics>`, after
 * `#include <oceano_waves>`). To light any mesh under the water with caustics —
 * the sea bed here, a boat's hull — bind its ShaderMaterial to the ocean's WaveBinding,
 * give it this set (shared objects, so one update reaches all), pass the world position to the
 * fragment shader and multiply the direct sunlight by `causticLight(worldPosition)`.
 */
export type CausticsUniforms = Record<'uCausticsSunDirection' | 'uCausticsRefractedSun' | 'uCausticsStrength', IUniform>;

export function createCausticsUniforms(): CausticsUniforms {
  return {
    uCausticsSunDirection: { value: new Vector3(0, 1, 0) },
    uCausticsRefractedSun: { value: new Vector3(0, -1, 0) },
    uCausticsStrength: { value: 1 },
  };
}

export function applyCaustics(
  u: CausticsUniforms,
  towardsSun: readonly [number, number, number],
  enabled: boolean,
  intensity: number,
): void {
  const sun = (u.uCausticsSunDirection.value as Vector3).fromArray(towardsSun).normalize();
  // The sunlight's direction under a flat sea is the same for every fragment: refracted once
  // here instead of per fragment in the shader. A sun at or below the horizon gets no
  // caustics (the shader returns 1 first), so any downward ray will do there.
  const refracted = sun.y > 0 ? refractedSunDirection([sun.x, sun.y, sun.z]) : null;
  (u.uCausticsRefractedSun.value as Vector3).fromArray(refracted ?? [0, -1, 0]);
  u.uCausticsStrength.value = enabled ? intensity : 0;
}
