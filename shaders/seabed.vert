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
