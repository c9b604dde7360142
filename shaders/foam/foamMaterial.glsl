// Foam that looks like foam (OCEAN_FOAM_TEXTURE; docs/light.md §5), for the whitecaps and the
// boat's wake alike. `amount` in [0, 1] says how thick the foam is: thick foam is solid, thin
// foam only the densest lace of the detail texture (shaders/foam/foamDetail.frag), so its
// edges feather into bubbles as it thins. The texture is laid along the wind and stretched
// there, so the lace is drawn out into streaks; two layers at different scales and angles,
// whose periods do not divide each other, so no tile repeats. Foam is a rough, bright,
// nearly diffuse surface: lit by the sun on its own bumpy normal and by the sky, with a wet
// sheen from a rough microfacet lobe, off-white (sea foam reflects less red than blue: Frouin,
// Schwindling & Deschamps 1996, J. Geophys. Res. 101(C6)).
uniform sampler2D uFoamDetail;
uniform vec2 uWindDirection;   // unit (x, z) the wind blows towards
uniform vec2 uRenderOrigin;    // the render origin (ocean.vert): only its place within a tile matters

// Foam's reflectance (fresh whitecaps about 0.5–0.6 in the visible, Whitlock, Bartlett & Gurganus 1982; less in the red).
const vec3 FOAM_ALBEDO = vec3(0.72, 0.77, 0.80);
// The wet sheen: mean-square slope of the bubbles' facets, and water's Fresnel at normal incidence.
const float FOAM_SHEEN_VARIANCE = 0.3;
const float FOAM_SHEEN_FRESNEL = 0.02;
// Relief of the foam's surface, m per unit of density: bubbles a few centimetres high.
const float FOAM_RELIEF = 0.04;
// The two layers: tile width across the wind (m), stretch along it, turn from the wind (rad).
const vec3 FOAM_LAYER_A = vec3(5.0, 3.0, 0.0);
const vec3 FOAM_LAYER_B = vec3(3.09, 2.0, 0.41);
const float FOAM_FEATHER = 0.06;

// One layer at p (relative to the render origin): (density, world slope of the density).
vec3 foamLayer(vec2 p, vec3 layer) {
  float c = cos(layer.z);
  float s = sin(layer.z);
  vec2 along = vec2(c * uWindDirection.x - s * uWindDirection.y, s * uWindDirection.x + c * uWindDirection.y);
  vec2 across = vec2(-along.y, along.x);
  vec2 scale = vec2(1.0 / (layer.x * layer.y), 1.0 / layer.x);
  vec2 origin = fract(vec2(dot(uRenderOrigin, along), dot(uRenderOrigin, across)) * scale);
  vec2 uv = vec2(dot(p, along), dot(p, across)) * scale + origin;
  vec3 t = texture(uFoamDetail, uv).rgb;
  // Stored slope: 4 × the density's change over two texels of 512 (foamDetail.frag).
  vec2 slopeUv = (t.gb - 0.5) * 64.0;
  return vec3(t.r, (slopeUv.x * scale.x) * along + (slopeUv.y * scale.y) * across);
}

// What a foam of thickness `amount` does to a pixel of colour `color`, normal n, eye direction v.
vec3 foamOver(vec3 color, float amount, vec3 n, vec3 v, vec2 p) {
  vec3 a = foamLayer(p, FOAM_LAYER_A);
  vec3 b = foamLayer(p, FOAM_LAYER_B);
  float density = 0.5 * (a.x + b.x);
  vec2 slope = 0.5 * (a.yz + b.yz);
  float laced = smoothstep(1.0 - amount - FOAM_FEATHER, 1.0 - amount + FOAM_FEATHER, density);
  // Where a pixel covers many bubbles the mipmaps average the lace away: there the foam's
  // share of the pixel is its thickness itself, so far foam keeps its coverage.
  float texels = length(fwidth(p)) * 512.0 / FOAM_LAYER_B.x;
  float cover = mix(laced, amount, smoothstep(1.0, 6.0, log2(max(texels, 1.0))));
  vec3 nf = normalize(n - FOAM_RELIEF * vec3(slope.x, 0.0, slope.y));
  float sunUp = step(0.0, uSunDirection.y);
  vec3 sunLight = uSunColor * SUN_IRRADIANCE * max(dot(nf, uSunDirection), 0.0) * sunUp;
  vec3 skyLight = 3.14159265 * skyCubeColor(normalize(nf + vec3(0.0, 1.0, 0.0)));
  vec3 foam = FOAM_ALBEDO * (sunLight + skyLight) / 3.14159265 + sunGlint(nf, v, FOAM_SHEEN_VARIANCE, FOAM_SHEEN_FRESNEL);
  return mix(color, foam, cover);
}
