// The sky of src/sim/optics/skyPainter.ts painted on the GPU for any sun: the same gradient, glow,
// disc and cloud layer (its Perlin density baked once into uClouds), plus a dusk that the
// PNG faces never had. Written as linear colour into a half-float cube render target;
// the painter's constants are sRGB, so the result is decoded once at the end.

#include <oceano_sun_disc>

uniform vec3 uSunDirection;
uniform sampler2D uClouds;
uniform vec3 uZenith;
uniform vec3 uHorizon;
uniform vec3 uBelowHorizon;
uniform vec3 uSun;
uniform vec3 uCloudLit;
uniform vec3 uCloudShade;
uniform vec3 uDuskHorizon;
uniform vec3 uDuskZenith;
uniform vec3 uNightZenith;
uniform vec3 uNightHorizon;

varying vec3 vDirection;

vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));
}

void main() {
  vec3 d = normalize(vDirection);
  vec3 sun = normalize(uSunDirection);
  float up = d.y;

  // Dusk: as the sun nears the horizon the zenith darkens and the horizon warms, most
  // towards the sun's azimuth; below it the light fades to a blue night over about 10°.
  float dusk = 1.0 - smoothstep(0.0, 0.25, sun.y);
  float night = 1.0 - smoothstep(-0.18, 0.0, sun.y);
  vec2 sunFlat = length(sun.xz) > 1e-4 ? normalize(sun.xz) : vec2(0.0, -1.0);
  vec2 dirFlat = length(d.xz) > 1e-4 ? normalize(d.xz) : vec2(0.0);
  float towardsSun = 0.5 + 0.5 * dot(sunFlat, dirFlat);
  vec3 horizon = mix(uHorizon, uDuskHorizon, dusk * (0.35 + 0.65 * towardsSun * towardsSun));
  vec3 zenith = mix(uZenith, uDuskZenith, dusk);
  horizon = mix(horizon, uNightHorizon, night * (1.0 - 0.6 * towardsSun * towardsSun));
  zenith = mix(zenith, uNightZenith, night);

  vec3 color;
  if (up >= 0.0) {
    color = mix(horizon, zenith, pow(up, 0.55));
  } else {
    color = mix(horizon, uBelowHorizon * (1.0 - 0.7 * night), smoothstep(0.0, 0.12, -up));
  }

  float cosSun = dot(d, sun);
  // The glow stays while the sun is a little below the horizon (the dusk glow), then goes.
  float glowLeft = smoothstep(-0.12, 0.0, sun.y);
  float glow = (pow(max(cosSun, 0.0), 8.0) * 0.35 + pow(max(cosSun, 0.0), 200.0) * 0.6) * glowLeft;
  color = mix(color, uSun, min(1.0, glow));

  if (up > 0.01) {
    // The painter's flat cloud layer: (x, z) / y projects the direction onto a plane overhead.
    vec2 uv = vec2(d.x / up * 0.08 + 0.31, d.z / up * 0.08 + 0.17);
    // Texel i holds the density at u = i / size, its centre sits at (i + 0.5) / size.
    float density = texture2D(uClouds, uv + 0.5 / float(textureSize(uClouds, 0).x)).r * 2.0 - 1.0;
    float cover = smoothstep(0.02, 0.32, density) * smoothstep(0.01, 0.12, up);
    vec3 lit = mix(uCloudShade, uCloudLit, 0.5 + 0.5 * max(cosSun, 0.0));
    lit *= mix(1.0, 0.35, night);
    color = mix(color, lit, cover * 0.85);
  }

  // The disc as white as the cube can hold; the sky behind the scene draws it in its full
  // brightness (skyBackground.frag), which no 8-bit cube could.
  color = mix(color, vec3(1.0), sunDiscCoverage(d, sun));
  // Stored as the square root of the linear colour, in 8 bits (see skyCube.glsl).
  gl_FragColor = vec4(sqrt(srgbToLinear(clamp(color, 0.0, 1.0))), 1.0);
}
