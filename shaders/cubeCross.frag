// The sky's cube map unfolded into a cross of its six faces (src/render/teaching/cubeCrossFigure.ts),
// looked up exactly as the sky behind the sea is (shaders/skyBackground.frag), so each texel
// of the cross is the colour the sea reflects in that direction.
#include <oceano_sky_cube>

// The cross's box as fractions of the canvas (left, bottom, right, top), 4 × 3 cells.
uniform vec4 uBox;
// Each face's cell (column, row from the top) and the directions through its centre and
// towards its right and upper edges, from src/sim/optics/cubeCross.ts.
uniform vec2 uCellPlace[6];
uniform vec3 uCellCentre[6];
uniform vec3 uCellRight[6];
uniform vec3 uCellUp[6];

varying vec2 vUv;

void main() {
  vec3 color = vec3(0.12, 0.14, 0.16);
  vec2 inBox = (vUv - uBox.xy) / (uBox.zw - uBox.xy);
  // Cell units: x rightwards 0..4, y downwards 0..3.
  vec2 p = vec2(inBox.x * 4.0, (1.0 - inBox.y) * 3.0);
  vec2 cell = floor(p);
  bool drawn = false;
  for (int i = 0; i < 6; i++) {
    if (inBox.x < 0.0 || inBox.x >= 1.0 || inBox.y < 0.0 || inBox.y >= 1.0 || cell != uCellPlace[i]) continue;
    float a = 2.0 * (p.x - cell.x) - 1.0;
    float b = 1.0 - 2.0 * (p.y - cell.y);
    color = skyCubeColor(normalize(uCellCentre[i] + a * uCellRight[i] + b * uCellUp[i]));
    drawn = true;
  }
  gl_FragColor = vec4(color, 1.0);
  // The sky goes through the renderer's tone mapping and output colour space as the sky
  // behind the sea does; the grey round it is already the screen's.
  if (drawn) {
    #include <tonemapping_fragment>
    #include <colorspace_fragment>
  }
}
