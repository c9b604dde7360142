/**
 * Colour of the sunlight on the water, the sea bed and the god rays (linear RGB; the
 * shaders' uSunColor). The painted sky's sun disc and the boat's directional light use
 * skyPainter's SUN, a slightly whiter value: the two have always differed, and making them
 * one would change every reference picture, so each has its single definition.
 */
export const SUN_LIGHT_COLOR: readonly [number, number, number] = [1.0, 0.93, 0.8];

/**
 * Sun direction from elevation above the horizon and azimuth, both in degrees. Azimuth 0
 * points along −z (where the default camera looks) and grows towards +x.
 */
export function sunDirection(elevationDeg: number, azimuthDeg: number): [number, number, number] {
  const e = (elevationDeg * Math.PI) / 180;
  const a = (azimuthDeg * Math.PI) / 180;
  return [Math.sin(a) * Math.cos(e), Math.sin(e), -Math.cos(a) * Math.cos(e)];
}

/**
 * The sun's irradiance on a surface facing it, in the units of the sky's radiance (the sky
 * cube's colours are radiances of about 0.3–0.8): a clear sky's direct normal irradiance,
 * about 900 W/m², over the sky's radiance on the sun's side, some 100–200 W/m²/sr, is 4–9 sr.
 * The low end, so that the glint's core stays below white over a wider part of the path on a
 * screen without tone mapping. What the glint (shaders/ocean.frag, sunGlint) multiplies its BRDF by.
 */
export const SUN_IRRADIANCE = 4;
