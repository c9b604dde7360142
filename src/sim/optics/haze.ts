/**
 * The haze between the eye and the sea: light from the sea is lost to the air's aerosols on
 * its way, and the sky's light scattered into the line of sight takes its place. The picture
 * blends the sea's colour with the horizon's by the weight 1 − e^−τ, τ the path's optical depth.
 *
 * The aerosols thin out with height, exponentially, with a scale height of about 1.2 km
 * (Bruneton, E. & Neyret, F. 2008, "Precomputed Atmospheric Scattering", Mie scattering's
 * H_M = 1.2 km), so the sea seen from an aircraft is much clearer than the same distance of
 * air along the sea.
 */
export const AEROSOL_SCALE_HEIGHT = 1200;

/**
 * The extinction coefficient at sea level (m⁻¹) for a visibility given in metres, by
 * Koschmieder's law (Koschmieder, H. 1924, "Theorie der horizontalen Sichtweite"): a dark
 * object vanishes when its contrast against the horizon has fallen to 2 %, e^−βV = 0.02,
 * so β = ln(50) / V ≈ 3.912 / V. A clear day at sea (V = 20 km) gives 1.96·10⁻⁴ m⁻¹.
 */
export function hazeExtinction(visibility: number): number {
  return Math.log(50) / visibility;
}

/**
 * (1 − e^−x) / x, the mean of e^−s over s in [0, x]; 1 at x = 0, where the quotient is 0/0,
 * so small |x| take its series instead.
 */
export function meanDecay(x: number): number {
  return Math.abs(x) < 1e-4 ? 1 - x * (0.5 - x / 6) : -Math.expm1(-x) / x;
}

/**
 * Optical depth of the straight path of length `distance` from an eye at height `eyeHeight`
 * to a point at `pointHeight` (metres), through air of extinction β₀ e^(−y/H) at height y:
 *   τ = ∫₀^d β₀ e^(−y(s)/H) ds = β₀ d e^(−y_eye/H) · (1 − e^−x)/x,  x = (y_point − y_eye)/H,
 * since y grows linearly along the path.
 */
export function hazeOpticalDepth(extinction: number, eyeHeight: number, pointHeight: number, distance: number): number {
  return extinction * distance * Math.exp(-eyeHeight / AEROSOL_SCALE_HEIGHT) * meanDecay((pointHeight - eyeHeight) / AEROSOL_SCALE_HEIGHT);
}

/** The horizon colour's share of a pixel: 1 − e^−τ. */
export function hazeWeight(extinction: number, eyeHeight: number, pointHeight: number, distance: number): number {
  return -Math.expm1(-hazeOpticalDepth(extinction, eyeHeight, pointHeight, distance));
}
