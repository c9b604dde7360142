// Where the spectral sea breaks (the GLSL twin of src/sim/waves/fft/breaking.ts, read the
// sources there): the smaller of the determinant and the smaller eigenvalue λ_min of the
// choppy map's Jacobian [1 + Jxx, Jxz; Jxz, 1 + Jzz]. The determinant drops where the surface
// loops, λ_min where it folds along one direction while stretched along the other (a crest).
float fftBreaking(float jxx, float jzz, float jxz) {
  float halfDifference = 0.5 * (jxx - jzz);
  float minEigenvalue = 1.0 + 0.5 * (jxx + jzz) - sqrt(halfDifference * halfDifference + jxz * jxz);
  float determinant = (1.0 + jxx) * (1.0 + jzz) - jxz * jxz;
  return min(determinant, minEigenvalue);
}
