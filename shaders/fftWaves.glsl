// The spectral (Tessendorf FFT) sea for the vertex and fragment shaders: the wave-model seam's
// waveDisplacement / waveNormal, plus the Jacobian for foam, read from the three cascades'
// textures that src/render/fft/gpuFft.ts (GpuFftOcean) writes every frame.
//   uFftDisplacementN: (dx, dy, dz, ∂Dx/∂x)     uFftDerivativesN: (∂h/∂x, ∂h/∂z, ∂Dz/∂z, ∂Dx/∂z)
// Texel (p, q) of cascade N is the grid point (p, q)·L_N/n, tiles repeat. Bilinear interpolation
// is done here with four texelFetch (not the texture unit, whose 8-bit weights would cost
// millimetres), exactly as the CPU twin src/sim/fftOcean.ts does, so both give the same surface.
uniform sampler2D uFftDisplacement0;
uniform sampler2D uFftDisplacement1;
uniform sampler2D uFftDisplacement2;
uniform sampler2D uFftDerivatives0;
uniform sampler2D uFftDerivatives1;
uniform sampler2D uFftDerivatives2;
uniform vec3 uFftTileSize;   // L of each cascade, m
uniform float uFftN;         // grid points per side (64, 128 or 256)

vec4 fftBilinear(sampler2D field, vec2 xz, float tileSize) {
  vec2 uv = xz * (uFftN / tileSize);
  vec2 cell = floor(uv);
  vec2 w = uv - cell;
  int n = int(uFftN);
  ivec2 i0 = ivec2(mod(cell, uFftN));
  ivec2 i1 = ivec2((i0.x + 1) % n, (i0.y + 1) % n);
  vec4 top = mix(texelFetch(field, i0, 0), texelFetch(field, ivec2(i1.x, i0.y), 0), w.x);
  vec4 bottom = mix(texelFetch(field, ivec2(i0.x, i1.y), 0), texelFetch(field, i1, 0), w.x);
  return mix(top, bottom, w.y);
}

vec4 fftDisplacementSum(vec2 gridXZ) {
  return fftBilinear(uFftDisplacement0, gridXZ, uFftTileSize.x)
       + fftBilinear(uFftDisplacement1, gridXZ, uFftTileSize.y)
       + fftBilinear(uFftDisplacement2, gridXZ, uFftTileSize.z);
}

vec4 fftDerivativesSum(vec2 gridXZ) {
  return fftBilinear(uFftDerivatives0, gridXZ, uFftTileSize.x)
       + fftBilinear(uFftDerivatives1, gridXZ, uFftTileSize.y)
       + fftBilinear(uFftDerivatives2, gridXZ, uFftTileSize.z);
}

// (dx, dy, dz) for the undisplaced grid point.
vec3 waveDisplacement(vec2 gridXZ) {
  return fftDisplacementSum(gridXZ).xyz;
}

// Unit normal of the displaced surface P = (x + Dx, h, z + Dz): ∂P/∂z × ∂P/∂x, from the exact
// spectral slopes and displacement derivatives (no finite differences).
vec3 waveNormal(vec2 gridXZ) {
  float dxdx = fftDisplacementSum(gridXZ).w;
  vec4 d = fftDerivativesSum(gridXZ);
  vec3 tangentX = vec3(1.0 + dxdx, d.x, d.w);
  vec3 tangentZ = vec3(d.w, d.y, 1.0 + d.z);
  return normalize(cross(tangentZ, tangentX));
}

// Jacobian of the choppy map (x, z) → (x + Dx, z + Dz): below 1 the surface is squeezed, below 0
// it folds over (Tessendorf 2001 §4.3); foam goes where J < foamThreshold.
float fftJacobian(vec2 gridXZ) {
  float dxdx = fftDisplacementSum(gridXZ).w;
  vec4 d = fftDerivativesSum(gridXZ);
  return (1.0 + dxdx) * (1.0 + d.z) - d.w * d.w;
}
