// sin and cos of an angle counted in turns (1 turn = 2π). Wave phases reach hundreds of
// radians far out, and GLSL's sin and cos only promise about 2^-11 absolute accuracy
// (SwiftShader gives just that: 7e-4 m on a 1-m swell, ten times the parity budgets). So the
// turn is folded into [-1/4, 1/4] and the sine is the Taylor series to x^11, accurate to 6e-8
// over [-π/2, π/2], which keeps float32 GPUs within 1e-5 m of the float64 CPU twins.
// Shared by the seed's swell, the Gerstner sum, the Kelvin wake and the FFT's spectrum: one
// program may hold several of them, so the definitions are guarded.
#ifndef OCEANO_SIN_TURNS
#define OCEANO_SIN_TURNS

const float TURN_RADIANS = 6.283185307179586;

float sinTurns(float turns) {
  float s = fract(turns) - 0.5;
  float folded = sign(s) * (0.25 - abs(abs(s) - 0.25));
  float x = TURN_RADIANS * folded;
  float x2 = x * x;
  float series = 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0 * (1.0 - x2 / 110.0))));
  // sin(2π turns) = −sin(2π s), and folding keeps the sine of s.
  return -x * series;
}

float cosTurns(float turns) {
  return sinTurns(turns + 0.25);
}

#endif
