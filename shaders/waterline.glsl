// Which side of the waterline a pixel's line of sight starts on. Needs <oceano_waves> first.
// Where the line of sight hit the ocean mesh, the face it hit says which side it came
// from (the ocean writes alpha 0 on its top, 0.5 on its underside): that follows the drawn
// triangles exactly, so the waterline has no gap. The sea bed writes SEA_BED_ALPHA: it lies
// under the drawn surface everywhere, so a line of sight that reached it met no face of the
// ocean after the near plane and started under the drawn surface, in the water. Elsewhere
// (sky, boat, other meshes) the near-plane point is compared with the surface height above it.
//
// Why the sea bed needs its own mark: the drawn surface interpolates its vertices linearly
// (band 0's are 0.75 m apart), so near the eye it lies centimetres off the surface function.
// With the eye 5 cm above the water, the near plane (0.5 m out) crosses the water, and
// where its points lay between the two surfaces (above the function, under the triangles)
// the sand behind was taken for air and drawn sharp and unfogged: a band of bright green
// caustics along the waterline.
const float SEA_BED_ALPHA = 0.875;

bool startsInAir(float alpha, float depthSample, vec3 nearWorld) {
  if (depthSample < 1.0 && alpha < 0.25) return true;
  if (depthSample < 1.0 && alpha < 0.9375) return false;
  return nearWorld.y >= waveDisplacement(nearWorld.xz).y;
}
