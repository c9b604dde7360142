/**
 * A perspective camera's view-projection matrix (column-major, OpenGL clip space, the
 * same as three's PerspectiveCamera with up = +y), written out so the unit tests check the
 * frustum code against an independent derivation rather than against three itself.
 */
export function viewProjection(
  position: readonly [number, number, number],
  target: readonly [number, number, number],
  fovDegrees: number,
  aspect: number,
  near: number,
  far: number,
): Float64Array {
  const [px, py, pz] = position;
  let zx = px - target[0];
  let zy = py - target[1];
  let zz = pz - target[2];
  const zl = Math.hypot(zx, zy, zz);
  zx /= zl;
  zy /= zl;
  zz /= zl;
  // x = up × z, with up = +y; a view straight up or down borrows +z as its up, as three does.
  let xx = zz;
  let xy = 0;
  let xz = -zx;
  let xl = Math.hypot(xx, xy, xz);
  if (xl < 1e-9) {
    xx = 1;
    xy = 0;
    xz = 0;
    xl = 1;
  }
  xx /= xl;
  xy /= xl;
  xz /= xl;
  const yx = zy * xz - zz * xy;
  const yy = zz * xx - zx * xz;
  const yz = zx * xy - zy * xx;
  const f = 1 / Math.tan(((fovDegrees / 2) * Math.PI) / 180);
  const a = -(far + near) / (far - near);
  const b = (-2 * far * near) / (far - near);
  // view rows: x, y, z axes with translation −axis·position.
  const view = [
    [xx, xy, xz, -(xx * px + xy * py + xz * pz)],
    [yx, yy, yz, -(yx * px + yy * py + yz * pz)],
    [zx, zy, zz, -(zx * px + zy * py + zz * pz)],
    [0, 0, 0, 1],
  ];
  const proj = [
    [f / aspect, 0, 0, 0],
    [0, f, 0, 0],
    [0, 0, a, b],
    [0, 0, -1, 0],
  ];
  const m = new Float64Array(16);
  for (let r = 0; r < 4; r++) {
    for (let c = 0; c < 4; c++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += proj[r][k] * view[k][c];
      m[c * 4 + r] = s;
    }
  }
  return m;
}
