/**
 * Where a probe may stand: world (x, z) in metres, each finite and within ±1e6 m (the camera's
 * own range), as the URL writes it, "x,z".
 */
export const MAX_PROBE_COORDINATE = 1e6;

export function isProbeCoordinate(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value) && Math.abs(value) <= MAX_PROBE_COORDINATE;
}

/** "x,z" as a point, or null for anything else ("1,oops", "1", "1,2,3", ""). */
export function parseProbeText(text: string): { x: number; z: number } | null {
  const parts = text.split(',');
  if (parts.length !== 2 || parts.some((p) => p.trim() === '')) return null;
  const [x, z] = parts.map(Number);
  return isProbeCoordinate(x) && isProbeCoordinate(z) ? { x, z } : null;
}

/** The point as "x,z", numbers written to read back to the same doubles. */
export function formatProbeText(point: { x: number; z: number }): string {
  return `${point.x},${point.z}`;
}
