// The coast's land (src/render/coast/coastLand.ts): a mesh whose vertices already stand on
// the ground, −seaDepth(x, z), placed in the world as it is.
varying vec3 vWorldPosition;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorldPosition = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
}
