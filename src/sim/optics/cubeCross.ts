type Vec3 = [number, number, number];

/** One face of the unfolded cube: where it sits in the cross and which world directions it shows. */
export interface CrossCell {
  /** The world axis the face looks along, as three.js names a cube's faces (px, nx, py, ny, pz, nz). */
  face: 'px' | 'nx' | 'py' | 'ny' | 'pz' | 'nz';
  column: number;
  row: number;
  /** The direction through the cell's centre, and the directions its right and upper edges lean towards. */
  centre: Vec3;
  right: Vec3;
  up: Vec3;
}

/**
 * The sky's cube map unfolded into a cross, as seen from inside the cube: the middle row
 * is the horizon all round, from −x on the left through −z (where the default camera
 * looks) to +x and +z; the sky (+y) above −z, the sea's side (−y) below it. Every edge
 * shared by two cells in the cross shows the same directions on both sides, so the sky
 * runs across the seams unbroken (unit-tested), as it does round the camera.
 */
export const CROSS_COLUMNS = 4;
export const CROSS_ROWS = 3;
export const CROSS_CELLS: readonly CrossCell[] = [
  { face: 'nx', column: 0, row: 1, centre: [-1, 0, 0], right: [0, 0, -1], up: [0, 1, 0] },
  { face: 'nz', column: 1, row: 1, centre: [0, 0, -1], right: [1, 0, 0], up: [0, 1, 0] },
  { face: 'px', column: 2, row: 1, centre: [1, 0, 0], right: [0, 0, 1], up: [0, 1, 0] },
  { face: 'pz', column: 3, row: 1, centre: [0, 0, 1], right: [-1, 0, 0], up: [0, 1, 0] },
  { face: 'py', column: 1, row: 0, centre: [0, 1, 0], right: [1, 0, 0], up: [0, 0, 1] },
  { face: 'ny', column: 1, row: 2, centre: [0, -1, 0], right: [1, 0, 0], up: [0, 0, -1] },
];

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * The world direction (not normalised) at a point of the cross, in cell units: x from 0 to
 * CROSS_COLUMNS rightwards, y from 0 to CROSS_ROWS downwards; null off the six cells.
 */
export function crossDirection(x: number, y: number, cells: readonly CrossCell[] = CROSS_CELLS): Vec3 | null {
  const column = Math.floor(x);
  const row = Math.floor(y);
  const cell = cells.find((c) => c.column === column && c.row === row);
  if (!cell) return null;
  // a rightwards, b upwards, both from −1 to 1 across the cell.
  const a = 2 * (x - column) - 1;
  const b = 1 - 2 * (y - row);
  return [0, 1, 2].map((k) => cell.centre[k] + a * cell.right[k] + b * cell.up[k]) as Vec3;
}

/** Where a world direction appears in the cross, in cell units: in the face it points at most nearly. */
export function crossPoint(direction: Vec3): [number, number] {
  let cell = CROSS_CELLS[0];
  for (const c of CROSS_CELLS) if (dot(direction, c.centre) > dot(direction, cell.centre)) cell = c;
  const along = dot(direction, cell.centre);
  const a = dot(direction, cell.right) / along;
  const b = dot(direction, cell.up) / along;
  return [cell.column + (a + 1) / 2, cell.row + (1 - b) / 2];
}
