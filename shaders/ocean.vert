// One ocean chunk (an instance, or one copy of the grid in an expanded batch: chunkBatch.ts),
// a band's shared grid (integer grid coordinates in position.xz), placed at its world corner,
// with edge vertices snapped onto a coarser neighbour's edge (the GLSL twin of
// src/sim/lod/edgeSnap.ts), then displaced by the active wave model's chunk (waveDisplacement /
// waveNormal, see shaders/waves/).
#include <oceano_constants>
// Tells a wave-model chunk it is compiled for the ocean's vertices (WAVE_VERTEX_SLOPES below).
#define WAVE_VERTEX_STAGE
#include <oceano_waves>
// The boat's Kelvin wake, added to whichever model is active (src/sim/wake/boatWake.ts); compiled
// in only while the wake is on (OceanMaterial).
#ifdef OCEAN_WAKE
#include <oceano_wake>
#endif
// The interactive waves (iWave), compiled in only while interactiveWaves is on.
#ifdef OCEAN_IWAVE
#include <oceano_iwave>
#endif
#ifdef OCEAN_COAST
#include <oceano_coast>
#endif

// The seed's "normales incorrectas": every vertex keeps the flat plane's (0, 1, 0).
uniform bool uFlatNormals;
uniform int uChunkQuads;
// The grid's centre and the Chebyshev distances from it over which the far rings' waves
// fade out (src/sim/lod/farRings.ts): 1 on every chunk of the grid, 0 past ring 2.
uniform vec2 uOceanCenter;
uniform vec2 uFarFade;
// Geomorphing (the GLSL twin of src/sim/lod/lodMorph.ts): the camera and wave height the bands
// were chosen with, and per band the distance where its vertices start to slide towards the
// next band's grid and 1 / the zone's width.
uniform vec3 uLodCamera;
uniform float uLodHeight;
uniform vec2 uMorphZones[LOD_BAND_COUNT];

attribute vec4 aChunk;     // world x, world z of the chunk's corner, band, metres per grid unit
attribute vec4 aEdgeSteps; // step shared with the neighbour on sides -x, +x, -z, +z
attribute vec2 aTile;      // a tile's first grid point inside its chunk (compare strips), else 0

// Positions relative to uRenderOrigin, a point near the camera that float32 holds exactly
// (see OceanMaterial.onBeforeRender): 10⁶ m from the world's origin a float32 world
// position is rounded to 6 cm, which moved the vertices and turned the eye vector, and
// with it the sun glint, into a checkerboard. uViewRelative is the view matrix for these
// relative positions, made in double precision on the CPU.
uniform vec2 uRenderOrigin;
uniform mat4 uViewRelative;
varying vec3 vRelativePosition;
uniform vec3 uEyeRelative;
#ifdef OCEAN_WATER_OPTICS
// The water's own colour (shaders/waterBody.glsl), handed to the pixels as it is.
#include <oceano_sky_cube>
#include <oceano_fresnel_lookup>
#include <oceano_water_body>
uniform vec3 uSunDirection;
uniform vec3 uSunColor;
uniform sampler2D uFresnelTable;
flat varying vec3 vWaterBody;
#endif
#ifdef OCEAN_NEAR_BANDS
// The near bands' haze: its colour, the sky at the horizon beyond the vertex, and its weight
// by the vertex's distance from the eye (see ocean.frag).
#include <oceano_sky_cube>
#include <oceano_haze>
varying vec3 vHorizon;
varying float vHaze;
#endif
varying vec3 vNormal;
varying float vBand;
// Metres between this chunk's vertices, and the far rings' wave fade (1 on the grid): the
// fragment shader's per-pixel detail normals fade in where the vertices miss the ripples.
flat varying float vVertexSpacing;
varying float vWaveFade;
// The undisplaced grid point, for models whose normals and foam are evaluated per pixel.
varying vec2 vGridXZ;
// The same relative to uRenderOrigin: a few km at most, so interpolated it keeps its bits
// (vGridXZ 10⁶ m out moves in 6 cm steps). Models with WAVE_PIXEL_NORMALS shade from it.
varying vec2 vRelativeGridXZ;
// The wake's slope (∂η/∂x, ∂η/∂z), to tilt per-pixel normals in ocean.frag, and its foam.
varying vec2 vWakeSlope;
varying float vWakeFoam;
#ifdef OCEAN_IWAVE
// The interactive field's own slope, for the tint and foam of its steep water (ocean.frag).
varying vec2 vIWaveSlope;
#endif

// Integers, so the snapped vertex lands exactly on the neighbour's vertex.
int snapEdge(int k, int step) {
  return ((k + step / 2) / step) * step;
}

// Each grid band's vertex step, in full-resolution quads (src/sim/lod/lodBands.ts): bands
// 0 to LOD_BAND_COUNT - 1 are the grid's, the far rings come after.
const int BAND_STEPS[LOD_BAND_COUNT] = LOD_BAND_STEPS;
const int LAST_GRID_BAND = LOD_BAND_COUNT - 1;

void main() {
  // Integer grid coordinates within the chunk: a tile's are the whole chunk's, exactly.
  ivec2 grid = ivec2(position.xz + 0.5) + ivec2(aTile + 0.5);
  int band = int(aChunk.z + 0.5);
  // The far rings never morph and always snap their sides.
  bool farRing = band > LAST_GRID_BAND;
  // A refined chunk of the nearest band (src/render/lod/oceanChunks.ts) splits each quad
  // `refine` times per side: its grid units, its neighbours' steps and its side count in those.
  int refine = farRing ? 1 : int(LOD_BASE_STEP / aChunk.w + 0.5);
  int quads = uChunkQuads * refine;
  int own = farRing ? 0 : BAND_STEPS[band];
  vec2 morphed = vec2(grid);
  if (band < LAST_GRID_BAND) {
    // Distance of the unmorphed vertex, measured as the bands measure chunks.
    // The unmorphed place first (exact, as every chunk sharing the vertex computes it), so
    // they all get the same factor.
    vec2 fromCamera = (aChunk.xy + vec2(grid) * aChunk.w) - uLodCamera.xz;
    float dy = max(uLodCamera.y - uLodHeight, 0.0) + max(-uLodHeight - uLodCamera.y, 0.0);
    float factor = clamp((length(vec3(fromCamera.x, dy, fromCamera.y)) - uMorphZones[band].x) * uMorphZones[band].y, 0.0, 1.0);
    int next = BAND_STEPS[band + 1] * refine;
    morphed += factor * (vec2(snapEdge(grid.x, next), snapEdge(grid.y, next)) - vec2(grid));
  }
  if (grid.x == 0 && int(aEdgeSteps.x) > own) morphed.y = float(snapEdge(grid.y, int(aEdgeSteps.x)));
  else if (grid.x == quads && int(aEdgeSteps.y) > own) morphed.y = float(snapEdge(grid.y, int(aEdgeSteps.y)));
  if (grid.y == 0 && int(aEdgeSteps.z) > own) morphed.x = float(snapEdge(grid.x, int(aEdgeSteps.z)));
  else if (grid.y == quads && int(aEdgeSteps.w) > own) morphed.x = float(snapEdge(grid.x, int(aEdgeSteps.w)));

  // The chunk's corner less the origin is exact (both lie on the 2 m lattice and are close);
  // the rest is small. So the relative position keeps its bits wherever the camera is.
  vec2 relativeGrid = (aChunk.xy - uRenderOrigin) + morphed * aChunk.w;
  vVertexSpacing = aChunk.w * float(farRing ? 1 : BAND_STEPS[band]);
#ifdef WAVE_VERTEX_SLOPES
  // A model that sums its long waves' slopes per vertex for ocean.frag, in the same sum as the
  // displacement (waveVertexDisplacement, shaders/waves/gerstner.glsl), is told the vertex
  // step and the way to the eye.
  waveVertexSpacing = vVertexSpacing;
  waveVertexToEye = uEyeRelative - vec3(relativeGrid.x, 0.0, relativeGrid.y);
#endif
  // Corner and step are whole multiples of the base step: unmorphed, the sum is exact in
  // float32, and a shared vertex's morph is computed from the same numbers by both chunks,
  // so they agree bit for bit on its position (and height).
  vec2 gridXZ = vec2(aChunk.x + morphed.x * aChunk.w, aChunk.y + morphed.y * aChunk.w);
  vec2 fromCenter = abs(gridXZ - uOceanCenter);
  float waves = 1.0 - smoothstep(uFarFade.x, uFarFade.y, max(fromCenter.x, fromCenter.y));
#ifdef WAVE_VERTEX_SLOPES
  vec3 d = waveVertexDisplacement(gridXZ);
#else
  vec3 d = waveDisplacement(gridXZ);
#endif
  // A model with WAVE_PIXEL_NORMALS has its normal evaluated per pixel by ocean.frag, which
  // then reads this one only on the comparison view's right half (OCEAN_NORMALS_COMPARE) or
  // flat: it is left out of the program otherwise (perf: a define, not a uniform branch, so the
  // program holds no unused code or registers; docs/shader-notes.md).
#if defined(WAVE_PIXEL_NORMALS) && !defined(OCEAN_NORMALS_COMPARE)
  vNormal = vec3(0.0, 1.0, 0.0);
#else
  vNormal = uFlatNormals ? vec3(0.0, 1.0, 0.0) : waveNormal(gridXZ);
#endif
#if defined(WAVE_FABRICATED_NORMAL) && defined(OCEAN_NORMALS_COMPARE)
  if (!uFlatNormals) vNormal = waveFabricatedNormal(gridXZ);
#endif
  vGridXZ = gridXZ;
  // The fade scales the model's whole displacement (horizontal too, so the far rings'
  // vertices stay on their snapped grid) and tilts the normal back to straight up.
  if (waves < 1.0) {
    d *= waves;
    vNormal = normalize(mix(vec3(0.0, 1.0, 0.0), vNormal, waves));
  }
#ifdef OCEAN_COAST
  coastDisplace(d, vNormal, gridXZ, waves, uFlatNormals);
#endif
  vec3 world = vec3(gridXZ.x + d.x, d.y, gridXZ.y + d.z);
#ifdef OCEAN_IWAVE
  // Near the boat the interactive field carries its waves, farther out the analytic wake:
  // (the wake's weight, the field's), each wave counted once (shaders/iwave.glsl).
  vec2 handOver = iwaveHandOver(relativeGrid + d.xz, uRenderOrigin);
#else
  const vec2 handOver = vec2(1.0);
#endif
  // The wake at the displaced point's own (x, z), so the height above a world point is the
  // model's plus the wake's there, as the CPU twin adds them (addWake). Off, nothing changes.
  vWakeSlope = vec2(0.0);
  vWakeFoam = 0.0;
#ifdef OCEAN_WAKE
  if (uWakeCount >= 2) {
    vec3 wake = handOver.x * wakeHeightAndGradient(world.xz);
    world.y += wake.x;
    if (!uFlatNormals) vNormal = wakeTiltNormal(vNormal, wake.yz);
    vWakeSlope = wake.yz;
    vWakeFoam = wakeFoam(world.xz);
  }
#endif
#ifdef OCEAN_IWAVE
  // The interactive field at the displaced point, like the wake: its slope joins the wake's for
  // ocean.frag's per-pixel normals (OCEAN_WAKE is compiled in alongside), and on its own tints
  // the steep water there.
  vec3 field = handOver.y * iwaveHeightAndGradient(relativeGrid + d.xz, uRenderOrigin);
  world.y += field.x;
  if (!uFlatNormals) vNormal = wakeTiltNormal(vNormal, field.yz);
  vWakeSlope += field.yz;
  vIWaveSlope = field.yz;
#endif
  vec3 relative = vec3(relativeGrid.x + d.x, world.y, relativeGrid.y + d.z);
  vRelativePosition = relative;
#ifdef OCEAN_NEAR_BANDS
  // A cube lookup needs a non-zero direction, not a unit one: a vertex right under the eye
  // gets the +x horizon (the haze's weight is 0 there).
  vec2 away = relative.xz - uEyeRelative.xz + vec2(1e-20, 0.0);
  vHorizon = skyCubeColor(vec3(away.x, 0.0, away.y));
  vHaze = hazeWeightBetween(uEyeRelative, relative);
#endif
#ifdef OCEAN_WATER_OPTICS
  vWaterBody = waterBodyColor(uSunDirection, uSunColor, uFresnelTable);
#endif
  vRelativeGridXZ = relativeGrid;
  vBand = aChunk.z;
  vWaveFade = waves;
  vec4 view = uViewRelative * vec4(relative, 1.0);
  // A vertex exactly in the eye's plane (view z = 0, so clip w = 0: a level camera whose z
  // lies on a grid row) made SwiftShader drop every triangle touching it, a hole in the
  // water right in front of the eye (seen 5 cm up at (300, 300)). A micrometre behind the
  // eye the near plane clips those triangles as it should. Never exactly 0 in the default view.
  if (view.z == 0.0) view.z = 1e-6;
  gl_Position = projectionMatrix * view;
}
