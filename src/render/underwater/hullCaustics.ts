import type { IUniform, Material, Mesh, Object3D } from 'three';
import type { WaveBinding } from '../waves/waveBinding';

/**
 * Lights a loaded model's standard materials with the ocean's caustics: the direct sunlight
 * on every fragment is multiplied by `causticLight(world position)` from
 * shaders/caustics.glsl, which is 1 above the surface, so only the wet part of a hull shows
 * the moving net of light. The uniforms are the ocean's own objects, so the hull follows the
 * waves without any per-frame work here; the waves are the binding's model at compile time.
 */
export function lightWithCaustics(model: Object3D, waves: WaveBinding, uniforms: Record<string, IUniform>): void {
  model.traverse((object) => {
    const mesh = object as Mesh;
    if (!mesh.isMesh) return;
    const materials: Material[] = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
    for (const material of materials) {
      material.onBeforeCompile = (shader) => {
        Object.assign(shader.uniforms, waves.uniforms, uniforms);
        shader.vertexShader = shader.vertexShader
          .replace('#include <common>', '#include <common>\nvarying vec3 vOceanoWorld;')
          .replace('#include <project_vertex>', '#include <project_vertex>\nvOceanoWorld = (modelMatrix * vec4(transformed, 1.0)).xyz;');
        shader.fragmentShader = shader.fragmentShader
          .replace(
            '#include <common>',
            waves.resolve('#include <common>\nvarying vec3 vOceanoWorld;\n#include <oceano_waves>\n#include <oceano_caustics>'),
          )
          .replace(
            '#include <lights_fragment_end>',
            '#include <lights_fragment_end>\nfloat oceanoCaustic = causticLight(vOceanoWorld);\nreflectedLight.directDiffuse *= oceanoCaustic;\nreflectedLight.directSpecular *= oceanoCaustic;',
          );
      };
      // A distinct program from three's plain standard material, which must stay untouched.
      material.customProgramCacheKey = () => `oceano-hull-caustics-${waves.model.chunkName}`;
      material.needsUpdate = true;
      waves.attachPatched(material);
    }
  });
}
