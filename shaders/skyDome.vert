// A cube around a cube camera (src/render/sky/cubePainter.ts); each fragment paints the world
// direction from the centre through it.
varying vec3 vDirection;

void main() {
  vDirection = position;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
