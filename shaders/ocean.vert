#include <oceano_displacement>

// The seed's "normales incorrectas": every vertex keeps the flat plane's (0, 1, 0).
uniform bool uFlatNormals;

varying vec3 vWorldPosition;
varying vec3 vNormal;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  float height = oceanHeight(world.xz);
  vNormal = uFlatNormals ? vec3(0.0, 1.0, 0.0) : oceanNormal(world.xz, height);
  world.y += height;
  vWorldPosition = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
}
