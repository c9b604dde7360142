// Foam that looks like foam (OCEAN_FOAM_TEXTURE; docs/light-foam.md), for the whitecaps and the
// boat's wake alike. `amount` in [0, 1] says how thick the foam is: thick foam is solid, thin
// foam only the densest lace of the detail texture (shaders/foam/foamDetail.frag), so its
// edges feather into bubbles as it thins. The texture is laid along the wind and stretched
// there, so the lace is drawn out into streaks, and pushed about by a field that never repeats,
// so neither does the tile. Foam is a rough, bright,
// nearly diffuse surface: lit by the sun on its own bumpy normal and by the sky, with a wet
// sheen from a rough microfacet lobe. Its reflectance, FOAM_REFLECTANCE (defined before this text by foamDetail.ts), is measured foam's:
// 0.55, a little less in the red (src/sim/optics/foamReflectance.ts).
uniform sampler2D uFoamDetail;
uniform float uFoamDensityMean; // the detail tile's mean density, read back once it is drawn (foamDetail.ts)
uniform vec2 uWindDirection;   // unit (x, z) the wind blows towards
uniform vec2 uRenderOrigin;    // the render origin (ocean.vert): only its place within a tile matters

// The wet sheen: mean-square slope of the bubbles' facets, and water's Fresnel at normal incidence.
const float FOAM_SHEEN_VARIANCE = 0.3;
const float FOAM_SHEEN_FRESNEL = 0.02;
// Relief of the foam's surface, m per unit of density: bubbles a few centimetres high.
const float FOAM_RELIEF = 0.04;
// The detail tile: width across the wind, m, and how far it is stretched along it.
const float FOAM_TILE = 5.0;
const float FOAM_STRETCH = 3.0;
const float FOAM_FEATHER = 0.06;

// The texture's coordinates at p (relative to the render origin), laid along the wind. The tile
// would repeat every 15 m along the wind and 5 m across; the coordinates are pushed about by
// two waves of periods 37 m and 23 m in directions 71° apart, whose ratio is irrational, so
// the push never repeats and neither does the lace (the push's slope stays under 0.1, so the
// bubbles keep their shape).
vec2 foamDetailCoordinates(vec2 p, vec2 along, vec2 across) {
  // Phases in turns, reduced before the sine so it stays exact far from the world's origin.
  vec2 world = p + uRenderOrigin;
  vec2 turns = fract(vec2(dot(world, vec2(0.027027, 0.0)), dot(world, vec2(0.014155, 0.041108))));
  vec2 push = sin(6.2831853 * turns);
  vec2 q = p + 0.55 * push;
  return vec2(dot(q, along) / (FOAM_TILE * FOAM_STRETCH), dot(q, across) / FOAM_TILE)
    + fract(vec2(dot(uRenderOrigin, along) / (FOAM_TILE * FOAM_STRETCH), dot(uRenderOrigin, across) / FOAM_TILE));
}

// What a foam of thickness `amount` does to a pixel of colour `color`, normal n, eye direction v.
vec3 foamOver(vec3 color, float amount, vec3 n, vec3 v, vec2 p) {
  vec2 along = uWindDirection;
  vec2 across = vec2(-along.y, along.x);
  vec3 t = texture(uFoamDetail, foamDetailCoordinates(p, along, across)).rgb;
  float density = t.r;
  // Stored slope: 4 × the density's change over two texels of 512 (foamDetail.frag), per tile.
  vec2 slopeUv = (t.gb - 0.5) * 64.0;
  vec2 slope = (slopeUv.x / (FOAM_TILE * FOAM_STRETCH)) * along + (slopeUv.y / FOAM_TILE) * across;
  float laced = smoothstep(1.0 - amount - FOAM_FEATHER, 1.0 - amount + FOAM_FEATHER, density);
  // Where a pixel covers many bubbles the mipmaps average them away, but not the lace's
  // coarser patches and streaks: there the foam's share of the pixel is its thickness, shaded
  // by the density the mipmaps give over the pixel against the whole tile's mean, so far foam
  // keeps its coverage on average and its streaks where they are.
  float texels = length(fwidth(p)) * 512.0 / FOAM_TILE;
  float cover = mix(laced, clamp(amount * density / uFoamDensityMean, 0.0, 1.0), smoothstep(1.0, 6.0, log2(max(texels, 1.0))));
  vec3 nf = normalize(n - FOAM_RELIEF * vec3(slope.x, 0.0, slope.y));
  float sunUp = step(0.0, uSunDirection.y);
  vec3 sunLight = uSunColor * SUN_IRRADIANCE * max(dot(nf, uSunDirection), 0.0) * sunUp;
  vec3 skyLight = 3.14159265 * skyCubeColor(normalize(nf + vec3(0.0, 1.0, 0.0)));
  // The sheen: a Beckmann lobe of the bubbles' slopes (no shadowing term: at this roughness it
  // changes the lobe by less than its Fresnel does).
  vec3 h = normalize(uSunDirection + v);
  float cosH = max(dot(h, nf), 0.05);
  float tan2 = (1.0 - cosH * cosH) / (cosH * cosH);
  float sheen = FOAM_SHEEN_FRESNEL * exp(-tan2 / FOAM_SHEEN_VARIANCE) / (3.14159265 * FOAM_SHEEN_VARIANCE * cosH * cosH * cosH * cosH * 4.0 * max(dot(nf, v), 0.05));
  vec3 foam = FOAM_REFLECTANCE * (sunLight + skyLight) / 3.14159265 + uSunColor * SUN_IRRADIANCE * sheen * sunUp;
  return mix(color, foam, cover);
}
