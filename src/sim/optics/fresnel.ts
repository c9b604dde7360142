/**
 * Exact Fresnel reflectance for unpolarised light: the mean of the s- and p-polarised
 * reflectances, from Snell's law and the Fresnel equations. Light travels from a medium
 * of index n1 into one of index n2; cosIncidence is the cosine of the angle between the
 * ray and the surface normal. Beyond the critical angle (n1 > n2) reflection is total.
 */
export const WATER_IOR = 1.333;
export const AIR_IOR = 1.0;

export function fresnelReflectance(cosIncidence: number, n1: number, n2: number): number {
  const cosI = Math.min(1, Math.max(0, cosIncidence));
  const sinT = (n1 / n2) * Math.sqrt(Math.max(0, 1 - cosI * cosI));
  if (sinT >= 1) return 1;
  const cosT = Math.sqrt(1 - sinT * sinT);
  const rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  const rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

/**
 * The same reflectance in the closed form Cook & Torrance (1982) give for it, as each facet of
 * the sun's glint evaluates it (shaders/ocean.frag facetFresnel): with g = √(n² − 1 + c²) and
 * n = n2 / n1 > 1, F = ½ ((g − c)/(g + c))² (1 + ((c (g + c) − 1)/(c (g − c) + 1))²).
 */
export function fresnelClosedForm(cosIncidence: number, n1: number, n2: number): number {
  const c = Math.min(1, Math.max(0, cosIncidence));
  const n = n2 / n1;
  const g = Math.sqrt(n * n - 1 + c * c);
  const a = (g - c) / (g + c);
  const b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 0.5 * a * a * (1 + b * b);
}

/** Schlick's approximation, kept for comparison with the exact function. */
export function schlickReflectance(cosIncidence: number, n1: number, n2: number): number {
  const r0 = ((n1 - n2) / (n1 + n2)) ** 2;
  return r0 + (1 - r0) * (1 - Math.min(1, Math.max(0, cosIncidence))) ** 5;
}

/** Critical angle in radians for light leaving a denser medium (n1 > n2). */
export function criticalAngle(n1: number, n2: number): number {
  return Math.asin(n2 / n1);
}

/**
 * The reflectance tabulated for upload as a 1D texture: entry i holds the reflectance at
 * cos θ = i / (size − 1), so entry 0 is grazing incidence and the last is normal incidence.
 */
export function fresnelTable(size = 256, n1 = AIR_IOR, n2 = WATER_IOR): Float32Array {
  const table = new Float32Array(size);
  for (let i = 0; i < size; i++) table[i] = fresnelReflectance(i / (size - 1), n1, n2);
  return table;
}
