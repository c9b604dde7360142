// One ocean chunk instance: a band's shared grid (integer grid coordinates in
// position.xz), placed at its world corner, with edge vertices snapped onto a coarser
// neighbour's edge (the GLSL twin of src/sim/edgeSnap.ts), then displaced by the active wave
// model's chunk (waveDisplacement / waveNormal, see shaders/waves/).
#include <oceano_waves>
// The boat's Kelvin wake, added to whichever model is active (src/sim/boatWake.ts).
#include <oceano_wake>

// The seed's "normales incorrectas": every vertex keeps the flat plane's (0, 1, 0).
uniform bool uFlatNormals;
uniform int uChunkQuads;
// The grid's centre and the Chebyshev distances from it over which the far rings' waves
// fade out (src/sim/farRings.ts): 1 on every chunk of the grid, 0 past ring 2.
uniform vec2 uOceanCenter;
uniform vec2 uFarFade;

attribute vec4 aChunk;     // world x, world z of the chunk's corner, band, metres per grid unit
attribute vec4 aEdgeSteps; // step shared with the neighbour on sides -x, +x, -z, +z

varying vec3 vWorldPosition;
varying vec3 vNormal;
varying float vBand;
// The undisplaced grid point, for models whose normals and foam are evaluated per pixel.
varying vec2 vGridXZ;
// The wake's slope (∂η/∂x, ∂η/∂z), to tilt per-pixel normals in ocean.frag, and its foam.
varying vec2 vWakeSlope;
varying float vWakeFoam;
#ifdef WAVE_FABRICATED_NORMAL
uniform bool uNormalsCompare;
#endif

// Integers, so the snapped vertex lands exactly on the neighbour's vertex.
int snapEdge(int k, int step) {
  return ((k + step / 2) / step) * step;
}

void main() {
  ivec2 grid = ivec2(position.xz + 0.5);
  ivec2 snapped = grid;
  if (grid.x == 0) snapped.y = snapEdge(grid.y, int(aEdgeSteps.x));
  else if (grid.x == uChunkQuads) snapped.y = snapEdge(grid.y, int(aEdgeSteps.y));
  if (grid.y == 0) snapped.x = snapEdge(grid.x, int(aEdgeSteps.z));
  else if (grid.y == uChunkQuads) snapped.x = snapEdge(grid.x, int(aEdgeSteps.w));

  // Corner and step are whole multiples of the base step: the sum is exact in float32, so
  // two chunks compute bit-identical positions (and heights) for a shared vertex.
  vec2 gridXZ = vec2(aChunk.x + float(snapped.x) * aChunk.w, aChunk.y + float(snapped.y) * aChunk.w);
  vec2 fromCenter = abs(gridXZ - uOceanCenter);
  float waves = 1.0 - smoothstep(uFarFade.x, uFarFade.y, max(fromCenter.x, fromCenter.y));
  vec3 d = waveDisplacement(gridXZ);
  vNormal = uFlatNormals ? vec3(0.0, 1.0, 0.0) : waveNormal(gridXZ);
#ifdef WAVE_FABRICATED_NORMAL
  if (uNormalsCompare && !uFlatNormals) vNormal = waveFabricatedNormal(gridXZ);
#endif
  vGridXZ = gridXZ;
  // The fade scales the model's whole displacement (horizontal too, so the far rings'
  // vertices stay on their snapped grid) and tilts the normal back to straight up.
  if (waves < 1.0) {
    d *= waves;
    vNormal = normalize(mix(vec3(0.0, 1.0, 0.0), vNormal, waves));
  }
  vec3 world = vec3(gridXZ.x + d.x, d.y, gridXZ.y + d.z);
  // The wake at the displaced point's own (x, z), so the height above a world point is the
  // model's plus the wake's there, as the CPU twin adds them (addWake). Off, nothing changes.
  vWakeSlope = vec2(0.0);
  vWakeFoam = 0.0;
  if (uWakeCount >= 2) {
    vec3 wake = wakeHeightAndGradient(world.xz);
    world.y += wake.x;
    if (!uFlatNormals) vNormal = wakeTiltNormal(vNormal, wake.yz);
    vWakeSlope = wake.yz;
    vWakeFoam = wakeFoam(world.xz);
  }
  vWorldPosition = world;
  vBand = aChunk.z;
  gl_Position = projectionMatrix * viewMatrix * vec4(world, 1.0);
}
