// The haze along the line of sight (src/sim/optics/haze.ts): aerosols whose extinction is
// uHazeExtinction at sea level (Koschmieder: 3.912 / visibility) and thins out as e^(−y/H)
// with height y, H = AEROSOL_SCALE_HEIGHT. The picture blends the sea towards the horizon's
// colour by 1 − e^−τ.
uniform float uHazeExtinction;

// (1 − e^−x) / x, the mean of e^−s over [0, x]; its series near 0, where the quotient is 0/0.
float meanDecay(float x) {
  return abs(x) < 1e-2 ? 1.0 - x * (0.5 - x / 6.0) : (1.0 - exp(-x)) / x;
}

// τ = β₀ d e^(−y_eye/H) (1 − e^−x)/x with x = (y_point − y_eye)/H: the density integrated
// along the straight path, on which the height changes linearly.
float hazeWeightBetween(vec3 eye, vec3 point) {
  float opticalDepth = uHazeExtinction * distance(eye, point) * exp(-eye.y / AEROSOL_SCALE_HEIGHT)
    * meanDecay((point.y - eye.y) / AEROSOL_SCALE_HEIGHT);
  return 1.0 - exp(-opticalDepth);
}
