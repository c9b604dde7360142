/**
 * Where the ocean's shaders measure positions from: the camera's (x, z) rounded to a
 * multiple of RENDER_ORIGIN_STEP. float32 holds such a point exactly, and the chunk corners
 * (multiples of 2 m) less it are exact too, so the GPU works with numbers of a few km at
 * most wherever the camera is. Within RENDER_ORIGIN_STEP / 2 of the world's origin it is
 * the origin itself, so views there are drawn exactly as with world coordinates.
 */
export const RENDER_ORIGIN_STEP = 4096;

export function renderOrigin(cameraX: number, cameraZ: number): [number, number] {
  // + 0 turns a rounded −0 into 0.
  return [
    Math.round(cameraX / RENDER_ORIGIN_STEP) * RENDER_ORIGIN_STEP + 0,
    Math.round(cameraZ / RENDER_ORIGIN_STEP) * RENDER_ORIGIN_STEP + 0,
  ];
}
