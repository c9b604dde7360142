// Which side of the waterline a pixel's line of sight starts on. Needs <oceano_waves> first.
// Where the line of sight hit the ocean mesh, the face it hit says which side it came
// from (the ocean writes alpha 0 on its top, 0.5 on its underside): that follows the drawn
// triangles exactly, so the waterline has no gap. Elsewhere (sky, sea bed, other meshes)
// the near-plane point is compared with the surface height above it.
bool startsInAir(float alpha, float depthSample, vec3 nearWorld) {
  if (depthSample < 1.0 && alpha < 0.25) return true;
  if (depthSample < 1.0 && alpha < 0.75) return false;
  return nearWorld.y >= waveDisplacement(nearWorld.xz).y;
}
