/**
 * Sun direction from elevation above the horizon and azimuth, both in degrees. Azimuth 0
 * points along −z (where the default camera looks) and grows towards +x.
 */
export function sunDirection(elevationDeg: number, azimuthDeg: number): [number, number, number] {
  const e = (elevationDeg * Math.PI) / 180;
  const a = (azimuthDeg * Math.PI) / 180;
  return [Math.sin(a) * Math.cos(e), Math.sin(e), -Math.cos(a) * Math.cos(e)];
}
