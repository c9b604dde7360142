varying vec4 vResult;

void main() {
  gl_FragColor = vResult;
}
