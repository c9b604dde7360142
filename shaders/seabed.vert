// The sea bed: flat at its depth (the mesh's height), or on a coast (OCEAN_COAST) on the
// floor itself, −seaDepth(x, z) (shaders/coast.glsl), whatever the mesh's height.
#ifdef OCEAN_COAST
#include <oceano_coast>
#endif
varying vec3 vWorldPosition;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
#ifdef OCEAN_COAST
  world.y = -coastSeaDepth(world.xz);
#endif
  vWorldPosition = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
}
