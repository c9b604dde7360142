// The colour of the water itself from its optics (OCEAN_WATER_OPTICS; src/sim/optics/waterColor.ts):
// the light that reaches just below the surface, the sun's through the surface plus the
// sky's (taken as a sky as bright as its zenith all over, π L), is scattered back up by the
// water molecules in the share R(λ) = 0.33 b_b/(a + b_b), evenly over the upward directions
// (radiance R E / π), and leaves through the surface, its beam widened by n² (the (1 − F)
// is the mix with the reflected sky below). Red is absorbed within metres, blue scattered:
// deep clear water is dark blue, whatever colour was picked.
// Needs <oceano_constants>, <oceano_sky_cube> and <oceano_fresnel_lookup> included before it.
vec3 waterBodyColor(vec3 sunDirection, vec3 sunColor, sampler2D fresnelTable) {
  float sunHeight = max(sunDirection.y, 0.0);
  vec3 sunThrough = sunColor * SUN_IRRADIANCE * sunHeight * (1.0 - fresnelLookup(fresnelTable, sunHeight));
  vec3 skyThrough = 3.14159265 * skyCubeColor(vec3(0.0, 1.0, 0.0));
  return WATER_BODY_REFLECTANCE * (sunThrough + skyThrough) / (3.14159265 * WATER_IOR * WATER_IOR);
}
