#include <oceano_displacement>

varying vec3 vWorldPosition;
varying vec3 vNormal;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  float height = oceanHeight(world.xz);
  vNormal = oceanNormal(world.xz, height);
  world.y += height;
  vWorldPosition = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
}
