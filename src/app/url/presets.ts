import type { OceanParams } from '../../sim/params/params';
import { DEFAULT_CAMERA, type CameraPose } from '../camera/cameraPose';

import type { Stone } from '../../sim/iwave/iwaveGrid';

export type { Stone };

/** A named view for a course page: a few parameters changed from the defaults and a camera. */
export interface Preset {
  params: Partial<OceanParams>;
  camera: CameraPose;
  /** With freezeCulling: where the culling camera stood when the selection was frozen. */
  cullingCamera?: CameraPose;
  /** Stones dropped into the interactive waves: at their time from the page's start, or from when the preset is opened. */
  stones?: readonly Stone[];
}

/**
 * `?preset=NAME`. Parameters given in the URL as well override the preset's, so a page can
 * start from a figure and change one thing.
 */
export const PRESETS = {
  /** The seed's first figure: the bare grid before any displacement. */
  'flat-plane': {
    params: { swellAmplitude: 0, rippleStrength: 0, wireframe: true },
    camera: { position: [0, 45, 30], target: [0, 0, -10] },
  },
  /**
   * No swell, no ripples, no wind: the sea is a mirror (seaRoughness off: no slope below the
   * pixel but the sun's disc), so what it shows is the reflected sky (and Fresnel).
   */
  'still-ocean': {
    params: { swellAmplitude: 0, rippleStrength: 0, seaRoughness: false },
    camera: { position: [0, 6, 40], target: [0, 2, -60] },
  },
  /** "Texturas y heightmaps": the two Perlin heightmaps as the vertex shader receives them. */
  'perlin-heightmap': {
    params: { view: 'heightmap' },
    camera: DEFAULT_CAMERA,
  },
  /** The same grid as flat-plane, now displaced by swell and ripples. */
  'displaced-plane': {
    params: { wireframe: true },
    camera: { position: [0, 30, 30], target: [0, 0, -15] },
  },
  /** "Normales incorrectas": every vertex keeps the flat plane's normal, shown as a colour. */
  'normals-wrong': {
    params: { shading: 'normals', normals: 'flat', swellAmplitude: 2.5, swellFrequency: 0.08 },
    camera: { position: [0, 25, 40], target: [0, 0, -30] },
  },
  /** "Normales correctas": the fabricated-neighbour normals, shown as colours. */
  'normals-right': {
    params: { shading: 'normals', swellAmplitude: 2.5, swellFrequency: 0.08 },
    camera: { position: [0, 25, 40], target: [0, 0, -30] },
  },
  /** "Frecuencia y amplitud normales": the swell alone at its default frequency and amplitude, no wind on it (seaRoughness off). */
  'swell-normal': {
    params: { rippleStrength: 0, seaRoughness: false },
    camera: { position: [0, 12, 40], target: [0, 0, -60] },
  },
  /** "Máxima frecuencia y amplitud": the swell alone at the top of both ranges, no wind on it. */
  'swell-maximum': {
    params: { rippleStrength: 0, swellAmplitude: 4, swellFrequency: 0.2, seaRoughness: false },
    camera: { position: [0, 12, 40], target: [0, 0, -60] },
  },
  /** The Fresnel table the shader samples, plotted against Schlick's approximation, over the sea. */
  fresnel: {
    params: { fresnelPlot: true },
    camera: DEFAULT_CAMERA,
  },
  /** "Level of Detail": chunks tinted by distance band, seen from above. */
  'lod-bands': {
    params: { lodColors: true, wireframe: false },
    camera: { position: [0, 260, 220], target: [0, 0, -160] },
  },
  /** "Frustum culling": the selection frozen for the default camera, seen from far outside. */
  'frustum-culling': {
    params: { lodColors: true, freezeCulling: true },
    camera: { position: [-900, 1400, 1300], target: [0, 0, -500] },
    cullingCamera: DEFAULT_CAMERA,
  },
  /** "Quiero mover el bote": the boat pitching on a short, steep swell, seen from the side. */
  'boat-pitch': {
    params: { swellAmplitude: 1.6, swellFrequency: 0.12, rippleStrength: 0.15, boatHeading: 0 },
    camera: { position: [30, 3, -3], target: [7, 1, -5] },
  },
  /** "Bajo el agua": Snell's window overhead, god rays, fog and blur. */
  underwater: {
    params: {},
    camera: { position: [0, -8, 20], target: [0, 5, -20] },
  },
  // The spectral sea (waves=fft): the same seed and camera, only the wind and spectrum change.
  /** A gentle breeze (Beaufort 3), U = 4 m/s: short, low wind waves, no foam; the peak wavelength is about 14 m. */
  calm: {
    params: { waves: 'fft', windSpeed: 4 },
    camera: { position: [0, 9, 40], target: [0, 0, -60] },
  },
  /** Beaufort 5, U = 10 m/s on a fully developed Pierson–Moskowitz sea: Hs ≈ 2.2 m, peak ≈ 88 m. */
  'fresh-breeze': {
    params: { waves: 'fft', windSpeed: 10, spectrum: 'pierson-moskowitz' },
    camera: { position: [0, 9, 40], target: [0, 0, -60] },
  },
  /** Beaufort 8, U = 20 m/s: Hs ≈ 9 m, peak ≈ 350 m, choppy crests folding into foam (Jacobian < threshold). */
  gale: {
    params: { waves: 'fft', windSpeed: 20, foam: true },
    camera: { position: [0, 14, 40], target: [0, 2, -60] },
  },
  /** JONSWAP, 15 m/s blowing over only 20 km of water: a young, peaked sea, shorter and lower than PM's at that wind. */
  'short-fetch': {
    params: { waves: 'fft', windSpeed: 15, spectrum: 'jonswap', fetch: 20 },
    camera: { position: [0, 9, 40], target: [0, 0, -60] },
  },
  /**
   * Normals as colours on a fresh breeze: left, exact per pixel from the spectral slopes
   * (i k h); right, the seed's fabricated neighbours per vertex, interpolated.
   */
  'fft-normals': {
    params: { waves: 'fft', windSpeed: 10, shading: 'normals', normalsCompare: true },
    // Close over the water, away from the boat: the per-pixel detail of the left half shows.
    camera: { position: [-40, 7, 20], target: [-40, 0, -8] },
  },
  /**
   * A young wind sea (JONSWAP, 20 m/s over 20 km, long-crested) of 4 Gerstner trochoids at
   * Q = 1, the steepest the model allows (Qᵢ = 1 while Σ kᵢ Aᵢ ≤ 1, see limitSteepness): crests
   * sharpen towards cusps and troughs flatten. Four waves, because each then carries a quarter
   * of the sea's variance, so the shortest (3.9 m long, 0.28 m amplitude, kA = 0.46) is steep
   * enough for the trochoid's shape to show; with 64, each wave's kA is a few hundredths and
   * Q changes little the eye can see. The camera stands 1.2 m above the water, away from the
   * boat, looking across those short crests. Compare gerstner-gentle, the same sea and camera
   * at Q = 0.2 (tests/unit/sim/waves/gerstner/gerstnerSteepnessPreset.test.ts measures the crests' curvature
   * against the troughs': 1.5 times at Q = 0.2, 6.4 at Q = 1).
   */
  'gerstner-steepness': {
    params: { waves: 'gerstner', gerstnerSteepness: 1, gerstnerCount: 4, windSpeed: 20, spectrum: 'jonswap', fetch: 20, spreading: 32 },
    camera: { position: [-30, 1.2, 4], target: [-30, 0.3, -10] },
  },
  /** The same Gerstner sea at Q = 0.2: nearly sinusoidal, round crests. */
  'gerstner-gentle': {
    params: { waves: 'gerstner', gerstnerSteepness: 0.2, gerstnerCount: 4, windSpeed: 20, spectrum: 'jonswap', fetch: 20, spreading: 32 },
    camera: { position: [-30, 1.2, 4], target: [-30, 0.3, -10] },
  },
  /**
   * The three wave models side by side on one camera, wind (10 m/s, Pierson–Moskowitz) and
   * seed: left, the seed's sines and value-noise ripples; middle, 32 Gerstner trochoids drawn from
   * the wind spectrum; right, Tessendorf's FFT of the same spectrum.
   */
  'compare-models': {
    params: { compare: 'seed,gerstner,fft', compareSplit: 0.333, compareSplit2: 0.667, windSpeed: 10, spectrum: 'pierson-moskowitz' },
    // Shifted 35 m to the right: the boat, riding the first model, floats inside the seed's strip.
    camera: { position: [35, 9, 40], target: [35, 0, -60] },
  },
  /**
   * The Cuña de Kelvin: a boat at 4 m/s (Fr = 0.45 for its 8 m hull) on a calm, windless sea, seen from
   * 60 m up. The wake's sources lie along the boat's track (src/sim/wake/kelvinWake.ts); its largest
   * crests stand at about 18.3°, just inside the ±19.47° lines that `wakeGuide=1` draws over it. The foam marks the hull's
   * trail and the bow wave.
   */
  'kelvin-wake': {
    params: {
      swellAmplitude: 0,
      rippleStrength: 0.05,
      seaRoughness: false,
      wake: true,
      boatSpeed: 4,
      boatHeading: 270,
      sunElevation: 25,
      sunAzimuth: 300,
    },
    camera: { position: [60, 60, 60], target: [60, 0, -10] },
  },
  /** The same boat holding a 3 °/s turn to starboard (a 76 m radius): the wake follows the curved track, not a straight wedge. */
  'wake-turn': {
    params: {
      swellAmplitude: 0,
      rippleStrength: 0.05,
      seaRoughness: false,
      wake: true,
      boatSpeed: 4,
      boatHeading: 270,
      boatTurnRate: 3,
      sunElevation: 25,
      sunAzimuth: 300,
    },
    camera: { position: [50, 110, 70], target: [50, 0, -50] },
  },
  // Interactive waves (iWave, src/sim/iwave/): a height field stepped in time, where a stone or the boat makes waves.
  /**
   * A stone (a bump 2 m high, 1.2 m across) dropped at t = 0 on a calm, windless sea (seaRoughness off: the sun's disc alone glints), seen from above:
   * long waves run ahead, short ones trail. The yellow rings are Cauchy–Poisson's crests for
   * this instant, r = g t²/(8πn), those the grid carries (src/sim/iwave/cauchyPoissonRings.ts).
   */
  stone: {
    params: {
      swellAmplitude: 0,
      rippleStrength: 0,
      seaRoughness: false,
      interactiveWaves: true,
      iwaveGuide: true,
      sunElevation: 10,
      sunAzimuth: 0,
    },
    // Low, into the sun: its glint breaks on each crest. The field centres where the camera looks.
    camera: { position: [-20, 7, 16], target: [-20, 0, -20] },
    stones: [[0, -20, -20, 1.2, 2]],
  },
  /**
   * The same stone twice, 56 m apart: on the left deep water's equation (iWave, ω² = g k), on
   * the right the plain wave equation ∂²h/∂t² = c²∇²h (c = 2.56 m/s), a sponge between them
   * along the field's centre. One ring for the wave equation, a spreading train for the sea.
   */
  'stone-compare': {
    params: {
      swellAmplitude: 0,
      rippleStrength: 0,
      seaRoughness: false,
      interactiveWaves: true,
      iwaveEquation: 'side-by-side',
      iwaveGuide: true,
      sunElevation: 12,
      sunAzimuth: 345,
    },
    camera: { position: [-60, 20, 25], target: [-60, 0, -20] },
    stones: [
      [0, -88, -20, 1.2, 2],
      [0, -32, -20, 1.2, 2],
    ],
  },
  /**
   * The boat at 4 m/s in the interactive waves, the camera following: its hull a solid in the
   * field, its bow and stern pushing the near-field waves; past 16 m the analytic Kelvin wake
   * takes them over.
   */
  'boat-interactive': {
    params: {
      swellAmplitude: 0,
      rippleStrength: 0.05,
      seaRoughness: false,
      interactiveWaves: true,
      wake: true,
      boatSpeed: 4,
      boatHeading: 270,
      boatFollow: true,
      sunElevation: 22,
      sunAzimuth: 315,
    },
    camera: { position: [26, 16, 18], target: [1, 0, -5] },
  },
  /**
   * The beach seen from its sand: a 10 s swell from the open sea shortens and steepens over the
   * sloping bed (shoreline at x = 400 m), breaks in a line of surf, and the shallows show the
   * sand through turquoise water; the wind sea's seed waves are low, and calmed in the shallows.
   */
  beach: {
    params: { bathymetry: 'beach', swellAmplitude: 0.3, rippleStrength: 0.3, sunElevation: 35 },
    camera: { position: [440, 7, 60], target: [280, 0, -10] },
  },
  /** The island from above: the swell wraps round it, the surf rings its shore, the shelf shows through the water. */
  island: {
    params: { bathymetry: 'island', beachSlope: 0.05, swellAmplitude: 0.3, rippleStrength: 0.3, sunElevation: 50 },
    camera: { position: [380, 420, 260], target: [700, 0, 0] },
  },
} satisfies Record<string, Preset>;

export type PresetName = keyof typeof PRESETS;
export const presetNames = Object.keys(PRESETS) as PresetName[];

export function findPreset(name: string): Preset | null {
  return Object.prototype.hasOwnProperty.call(PRESETS, name) ? (PRESETS[name as PresetName] as Preset) : null;
}
