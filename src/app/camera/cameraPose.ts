import type { CameraPose } from '../../sim/camera/defaultCamera';

export { DEFAULT_CAMERA, type CameraPose } from '../../sim/camera/defaultCamera';

/** Farther than this from the origin is no view of the sea, and a likely typo. */
const CAMERA_LIMIT = 1e6;

function isVector(v: unknown): v is [number, number, number] {
  return Array.isArray(v) && v.length === 3 && v.every((c) => typeof c === 'number' && Number.isFinite(c) && Math.abs(c) <= CAMERA_LIMIT);
}

/** A pose the orbit controls can use: finite, within range, and the target apart from the eye. */
export function isCameraPose(pose: unknown): pose is CameraPose {
  if (typeof pose !== 'object' || pose === null) return false;
  const { position, target } = pose as Partial<CameraPose>;
  return isVector(position) && isVector(target) && position.some((c, i) => c !== target[i]);
}

/** `x,y,z,tx,ty,tz`: numbers written so they read back bit for bit. */
export function formatCameraText(pose: CameraPose): string {
  return [...pose.position, ...pose.target].map((c) => String(c)).join(',');
}

export function parseCameraText(text: string): CameraPose | null {
  const parts = text.split(',');
  if (parts.length !== 6 || parts.some((p) => p.trim() === '')) return null;
  const c = parts.map(Number);
  const pose: CameraPose = { position: [c[0], c[1], c[2]], target: [c[3], c[4], c[5]] };
  return isCameraPose(pose) ? pose : null;
}
