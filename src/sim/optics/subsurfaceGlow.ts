import { PURE_WATER_ABSORPTION, WAVELENGTHS } from './waterColor';

/**
 * Why a thin crest seen against the sun glows green: sunlight enters the back of the crest,
 * crosses it, and some of it is scattered forward, towards the eye, before it leaves through
 * the face we see. In single scattering along a path of length d through the crest, the
 * radiance that leaves towards the eye is (the n² of entering and leaving cancel)
 *
 *   L(λ) = E_sun T_in T_out · b(λ) d e^{−(a(λ) + b(λ)) d} · p(θ) · w,
 *
 * with a and b the water's absorption and scattering coefficients, p the scattering phase
 * function at the angle θ between the sun's ray and the line of sight inside the water, and w
 * the share of the pixel that is such a crest, lit from behind (the geometry, in the shader).
 * Pure water scatters too little to glow (b ≈ 0.003 m⁻¹: 10⁻³ of the sun per metre); the
 * glow seen at sea comes from particles, mostly phytoplankton, which scatter strongly and almost
 * all forward. So here:
 * - b = b_p, the particles' scattering, b_p(550 nm) = 0.30 C^0.62 m⁻¹ for a chlorophyll
 *   concentration C in mg m⁻³, varying as 550/λ (Morel, A. 1988, "Optical modeling of the upper
 *   ocean in relation to its biogenous matter content (case I waters)", J. Geophys. Res.
 *   93(C9), 10749–10768, eq. 14); C = 1 mg m⁻³, a productive open sea (0.05 in the clearest, above 3 on shelves);
 * - a = pure water's (Pope & Fry 1997, waterColor.ts): red is absorbed over the path, green
 *   and blue pass, so the glow is green-blue, far greener than the deep water's own blue;
 * - p = Henyey–Greenstein with mean cosine g = 0.924, that of Petzold's average particle
 *   phase function (Mobley, C. D. 1994, Light and Water, §3.8): the glow is strong only
 *   within some 20° of looking into the sun (inside the water; refraction narrows the angles
 *   by n), as the glow of backlit waves is;
 * - d = 1 m, the thickness of a crest's top that light crosses.
 * The geometry w (height of the crest, how pinched it is, its face turned from the sun) follows
 * the published real-time forms: the Atlas water (Mihelich & Tcheblokov 2019, "Wakes,
 * Explosions and Lighting: Interactive Water Simulation in Atlas", GDC; as in 2Retr0's
 * GodotOceanWaves) and Crest's pinch (wave-harmonic/crest, OceanEmission), see
 * shaders/subsurface.glsl.
 */
export const CHLOROPHYLL = 1;
export const CREST_PATH = 1;
export const PARTICLE_MEAN_COSINE = 0.924;

/** b_p(λ), m⁻¹, for chlorophyll C mg m⁻³ (Morel 1988). */
export function particleScattering(wavelength: number, chlorophyll = CHLOROPHYLL): number {
  return 0.3 * Math.pow(chlorophyll, 0.62) * (550 / wavelength);
}

/** The Henyey–Greenstein phase function, sr⁻¹, at scattering angle θ (cos θ given): ∫ p dΩ = 1, mean cosine g. */
export function henyeyGreenstein(cosTheta: number, g = PARTICLE_MEAN_COSINE): number {
  return (1 - g * g) / (4 * Math.PI * Math.pow(1 + g * g - 2 * g * cosTheta, 1.5));
}

/** b_p d e^{−(a + b_p) d} at red, green and blue: the share of the sun's light a crest scatters per steradian of phase. */
export function crestScattering(path = CREST_PATH, chlorophyll = CHLOROPHYLL): [number, number, number] {
  return WAVELENGTHS.map((wavelength, i) => {
    const b = particleScattering(wavelength, chlorophyll);
    return b * path * Math.exp(-(PURE_WATER_ABSORPTION[i] + b) * path);
  }) as [number, number, number];
}
