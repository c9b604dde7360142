// The whole frame's tone curve (src/sim/optics/highlightRollOff.ts, its TypeScript twin and its
// reasons): below HIGHLIGHT_KNEE a colour is left as it is; above, each channel rolls off
// exponentially towards white instead of clipping, so the glint keeps its falloff. The app's
// renderer runs it as three.js's CustomToneMapping at the end of every shader that draws to
// the canvas (src/render/tone/wholeFrameToneCurve.ts).
#ifndef OCEANO_HIGHLIGHT_ROLL_OFF
#define OCEANO_HIGHLIGHT_ROLL_OFF
#include <oceano_constants>

vec3 rollOffHighlights(vec3 c) {
  vec3 over = max(c - HIGHLIGHT_KNEE, 0.0) / (1.0 - HIGHLIGHT_KNEE);
  return min(c, HIGHLIGHT_KNEE) + (1.0 - HIGHLIGHT_KNEE) * (1.0 - exp(-over));
}

// Its inverse: the light the curve shows as y, for y below white (kept under 0.9999 of it).
vec3 unrollHighlights(vec3 y) {
  vec3 over = max(y - HIGHLIGHT_KNEE, 0.0) / (1.0 - HIGHLIGHT_KNEE);
  return min(y, HIGHLIGHT_KNEE) - (1.0 - HIGHLIGHT_KNEE) * log(1.0 - min(over, 0.9999));
}

#endif
