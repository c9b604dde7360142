// The sea bed: sand lit by the sunlight that crossed the waves (with its caustics) and
// by the blue-green light scattered in the water above it. The water between the bed
// and the eye is added by the underwater pass.

#include <oceano_waves>
#include <oceano_tiled_heightmap>
#include <oceano_water_volume>
#include <oceano_caustics>
#include <oceano_waterline>

uniform vec3 uSandColor;
// The mottling heightmap (the second Perlin ripple map of the noise seed) and its tiling.
uniform sampler2D uSandMottle;
uniform float uSandMottleTile;
uniform float uSandMottleSize;
uniform vec3 uSunColor;
uniform vec3 uRefractedSun;
uniform float uSunTransmission;
// Off only for a negative control (OceanView.setShadingFixes): the sand then writes alpha 1.

varying vec3 vWorldPosition;

void main() {
  float depth = max(-vWorldPosition.y, 0.0);
  // Mottling from the seeded heightmap at a scale of its own, so the bed is not a flat card.
  float mottle = sampleTiledHeightmap(uSandMottle, vWorldPosition.xz * 1.7, vec2(0.0), uSandMottleTile, uSandMottleSize);
  vec3 albedo = uSandColor * (0.85 + 0.25 * mottle);

  vec3 direct = vec3(0.0);
  if (uRefractedSun.y < 0.0) {
    float cosSun = -uRefractedSun.y;
    vec3 reach = waterTransmittance(depth / cosSun);
    direct = uSunColor * uSunTransmission * cosSun * reach * causticLight(vWorldPosition);
  }
  vec3 ambient = uWaterScatter * exp(-DEPTH_DARKENING * depth);
  // Alpha marks the sand for the waterline test (shaders/waterline.glsl): always under the water.
  gl_FragColor = vec4(albedo * (direct + ambient), SEA_BED_ALPHA);
  #include <colorspace_fragment>
  #include <oceano_scene_encode>
}
