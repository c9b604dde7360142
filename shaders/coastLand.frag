// The coast's land: sand lit by the sun and the sky as the water's body is (shaders/waterBody.glsl:
// the sun's irradiance on the surface plus a sky as bright as its zenith, π L), reflected
// diffusely by the sand's albedo, darker where the sea wets it, then hazed towards the horizon.
#include <oceano_constants>
#include <oceano_sky_cube>
#include <oceano_haze>

uniform vec3 uSunDirection;
uniform vec3 uSunColor;
uniform vec3 uSandAlbedo;
varying vec3 vWorldPosition;

void main() {
  // The ground's facet normal: the mesh is flat between its vertices.
  vec3 n = normalize(cross(dFdx(vWorldPosition), dFdy(vWorldPosition)));
  if (n.y < 0.0) n = -n;
  // Wet sand, up to half a metre above the still water, is darker (water fills its pores).
  float wet = 1.0 - smoothstep(0.0, 0.5, vWorldPosition.y);
  vec3 albedo = uSandAlbedo * mix(1.0, 0.6, wet);
  float sunHeight = max(dot(n, uSunDirection), 0.0) * step(0.0, uSunDirection.y);
  vec3 light = uSunColor * SUN_IRRADIANCE * sunHeight + 3.14159265 * skyCubeColor(vec3(0.0, 1.0, 0.0)) * (0.5 + 0.5 * n.y);
  vec3 color = albedo * light / 3.14159265;
  vec3 toEye = cameraPosition - vWorldPosition;
  vec3 horizon = skyCubeColor(normalize(vec3(-toEye.x, 0.0, -toEye.z) + vec3(1e-6, 0.0, 0.0)));
  color = mix(color, horizon, hazeWeightBetween(cameraPosition, vWorldPosition));
  gl_FragColor = vec4(color, 1.0);
  #include <tonemapping_fragment>
  #include <colorspace_fragment>
}
