import type { QuoteSource } from './quoteExtraction';

/**
 * The code each lesson card quotes, by lesson id: read from the file at build time
 * (scripts/build/lessonQuotes.ts), never copied here, so a card cannot show code that has
 * drifted from what runs. Data only: vite.config.ts imports this file.
 */
export const LESSON_QUOTE_SOURCES: Record<string, QuoteSource> = {
  'flat-plane': { file: 'shaders/ocean.vert', from: 'vec2 gridXZ = vec2(aChunk.x + morphed.x', to: 'vec3 d = waveDisplacement(gridXZ);' },
  'displaced-plane': { file: 'shaders/waves/seed.glsl', from: 'vec3 waveDisplacement(vec2 gridXZ) {', to: '}' },
  swell: { file: 'shaders/waves/seed.glsl', from: 'float swellHeight(vec2 p) {', to: 'return uSwellAmplitude * (first' },
  'swell-maximum': { file: 'shaders/waves/seed.glsl', from: 'float swellTurns(float cyclesPerMetre', to: '}' },
  'perlin-hash': { file: 'src/sim/noise/integerHash.ts', from: 'export function integerNoise(', to: 'return (h >>> 0)' },
  'perlin-smoothing': { file: 'src/sim/noise/perlinNoise.ts', from: 'function smoothedLattice(', to: 'return lattice;' },
  'perlin-octaves': {
    file: 'src/sim/noise/perlinNoise.ts',
    from: 'for (let o = 0; o < settings.octaves; o++) {',
    to: 'this.amplitudeSum = sum;',
  },
  'heightmap-blend': {
    file: 'shaders/waves/seed.glsl',
    from: 'float rippleHeight(vec2 p) {',
    to: 'return uRippleStrength * mix(a, b, uRippleBlend);',
  },
  'normals-wrong': { file: 'shaders/ocean.vert', from: '#if defined(WAVE_PIXEL_NORMALS) && !defined(OCEAN_NORMALS_COMPARE)', to: '#endif' },
  'normals-right': { file: 'shaders/waves/seed.glsl', from: "// The seed's fabricated neighbours", to: 'return normalize(vec3(-(h2 - h1)' },
  'sky-cube': { file: 'shaders/skyCube.glsl', from: 'vec3 skyCubeColor(vec3 direction) {', to: '}' },
  reflection: { file: 'shaders/ocean.frag', from: 'vec3 r = reflect(-v, n);', to: 'vec3 sky = skyCubeColorRough(r, roughness);' },
  fresnel: { file: 'src/sim/optics/fresnel.ts', from: 'export function fresnelReflectance(', to: 'return 0.5 * (rs * rs + rp * rp);' },
  'fresnel-schlick': { file: 'src/sim/optics/fresnel.ts', from: 'export function schlickReflectance(', to: '}' },
  'sun-glint': { file: 'shaders/highlightRollOff.glsl', from: 'vec3 rollOffHighlights(vec3 c) {', to: '}' },
  'boat-twin': {
    file: 'src/sim/waves/seed/seedSurface.ts',
    from: 'export function swellHeight(state: SurfaceState',
    to: 'return state.swellAmplitude * (first',
  },
  'boat-pitch': { file: 'src/sim/boat/boatPose.ts', from: 'const points = hullSamplePoints(', to: 'roll: Math.atan2(' },
  'snell-window': {
    file: 'shaders/ocean.frag',
    from: 'vec3 shadeFromBelow(vec3 v, vec3 n) {',
    to: 'float reflectance = uFresnelEnabled ? fresnelLookup(uFresnelFromBelow',
  },
  'underwater-fog': {
    file: 'shaders/waterVolume.glsl',
    from: 'vec3 waterTransmittance(float distance) {',
    to: 'return color * transmittance',
  },
  caustics: {
    file: 'shaders/caustics.glsl',
    from: 'vec2 a = causticLanding(s, p.y, light);',
    to: 'return max(mix(1.0, gain, uCausticsStrength), 0.0);',
  },
  'god-rays': {
    file: 'shaders/godRays.frag',
    from: 'vec3 godRays(vec3 origin, vec3 direction, float distance) {',
    to: 'vec2 s = origin.xz',
  },
  'lod-bands': { file: 'src/sim/lod/lodBands.ts', from: 'export function bandStart(', to: 'return band;' },
  'lod-morph': { file: 'src/sim/lod/lodMorph.ts', from: 'export function morphCoordinate(', to: '}' },
  'frustum-culling': {
    file: 'src/sim/lod/chunkQuadtree.ts',
    from: 'const verdict = classifyBox(',
    to: 'for (let c = 0; c < childCount; c++)',
  },
  'fft-calm': { file: 'src/sim/waves/spectra/piersonMoskowitz.ts', from: 'export function piersonMoskowitz(', to: 'return ((PM_ALPHA' },
  'fft-fresh-breeze': {
    file: 'src/sim/waves/dispersion.ts',
    from: 'export function angularFrequency(',
    to: 'return Math.sqrt(GRAVITY * k * t);',
  },
  'fft-short-fetch': { file: 'src/sim/waves/spectra/jonswap.ts', from: 'export function jonswapWithShape(', to: 'return ((alpha' },
  'fft-gale': {
    file: 'shaders/waves/fftBreaking.glsl',
    from: 'float fftBreaking(float jxx, float jzz, float jxz) {',
    to: 'return min(determinant, minEigenvalue);',
  },
  'fft-normals': { file: 'shaders/waves/fft.glsl', from: 'vec3 fftNormal(vec2 p, bool near) {', to: 'return normalize(cross(tz, tx));' },
  'gerstner-gentle': {
    file: 'shaders/waves/gerstner.glsl',
    from: 'vec2 gerstnerAddDisplacement(int i, vec2 gridXZ, inout vec3 d) {',
    to: 'return vec2(s, c);',
  },
  'gerstner-steepness': {
    file: 'src/sim/waves/gerstner/gerstnerSpectrum.ts',
    from: 'export function limitSteepness(',
    to: 'return waves.map(',
  },
  'compare-models': { file: 'src/sim/compare/compareLayout.ts', from: 'export function compareStrips(', to: 'return strips;' },
  'physics-panel': {
    file: 'src/sim/physics/physicsEstimators.ts',
    from: 'export function significantWaveHeight(',
    to: 'return 4 * Math.sqrt(variance',
  },
  'kelvin-wake': { file: 'src/sim/wake/kelvinGuide.ts', from: 'export function kelvinGuideLines(', to: 'return [x, z,' },
  'wake-turn': { file: 'src/sim/wake/kelvinWake.ts', from: 'export function wakeSources(', to: 'return out;' },
  'waves-as-simulation': { file: 'shaders/iwaveStep.frag', from: 'float half_ = 0.5 * (uDamping', to: 'outHeights = vec4(' },
  'iwave-stone': { file: 'src/sim/iwave/cauchyPoissonRings.ts', from: 'for (let n = 1; ; n++) {', to: 'if (2 * Math.PI * n >= minPhase' },
  'iwave-compare': {
    file: 'src/sim/iwave/verticalDerivativeKernel.ts',
    from: 'export function waveEquationKernel(',
    to: 'return { radius: 1, weights };',
  },
  'iwave-boat': { file: 'src/sim/iwave/movingHull.ts', from: 'export function hullSources(', to: '];' },
  horizon: { file: 'src/sim/lod/farRings.ts', from: 'export function farRings(', to: 'return rings;' },
  'airy-waves': { file: 'src/sim/waves/gerstner/gerstnerSpectrum.ts', from: 'let m0 = 0;', to: 'const amplitude = Math.sqrt(' },
  'group-velocity': {
    file: 'src/sim/waves/dispersion.ts',
    from: 'export function groupVelocity(',
    to: 'return (GRAVITY * (t + kh * sech2)) / (2 * omega);',
  },
  'spectra-compared': { file: 'src/sim/waves/spectra/phillips.ts', from: 'export function phillips(', to: 'return ((PHILLIPS_ALPHA' },
  'slope-filtering': {
    file: 'src/sim/optics/resolvedSlopes.ts',
    from: 'export function resolvedShare(',
    to: 'return Math.max(SUN_DISC_SLOPE_VARIANCE, total - resolved);',
  },
  'light-units': {
    file: 'src/render/tone/wholeFrameToneCurve.ts',
    from: "const PLACEHOLDER = 'vec3 CustomToneMapping",
    to: 'return chunk.replace(PLACEHOLDER',
  },
  'water-colour': {
    file: 'shaders/subsurface.glsl',
    from: 'vec3 subsurfaceGlow(vec3 n, vec3 v) {',
    to: 'return uSunColor * SUN_IRRADIANCE * SUBSURFACE_SCATTER',
  },
  'fft-transform': {
    file: 'src/sim/waves/fft/spectralFields.ts',
    from: '// h₀(k) e^{iφ} + conj(h₀(−k)) e^{−iφ}; ω(−k) = ω(k).',
    to: 'const hi = ar * s',
  },
  'coast-dispersion': { file: 'src/sim/waves/dispersion.ts', from: 'export function waveNumber(', to: 'return k;' },
  'coast-refraction': {
    file: 'src/sim/coast/islandSwellField.ts',
    from: 'const a = Math.min(i > 0 ? phase[t - 1]',
    to: 'else next = 0.5 * (a + b + Math.sqrt(',
  },
  'coast-shoaling': {
    file: 'src/sim/coast/beachSwellField.ts',
    from: 'const k = fieldWaveNumber(model, omega, d);',
    to: 'amplitude[i] = amplitude0 * shoaling * refraction;',
  },
  'coast-breaking': {
    file: 'src/sim/coast/waveTransformation.ts',
    from: 'export function breakingFraction(',
    to: 'return t * t * (3 - 2 * t);',
  },
};
