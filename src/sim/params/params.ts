import { message, type Message } from './message';
import { COMPARE_OFF, compareOrderings } from '../compare/compareLayout';
import { FOAM_FADE_SECONDS } from '../waves/fft/whitecaps';

/** The wave models, in the order the `waves` parameter lists them (src/render/waves/waveViewRegistry.ts). */
const WAVE_MODEL_NAMES = ['seed', 'fft', 'gerstner'] as const;

/**
 * Every tunable of the ocean in one typed place: default, range and unit. The GUI, the
 * URL and the automation API all read these definitions, so a value that passes here is
 * safe to hand to a shader.
 */
interface NumberDef {
  kind: 'number' | 'integer';
  default: number;
  min: number;
  max: number;
  step?: number;
  unit: string;
}
interface BooleanDef {
  kind: 'boolean';
  default: boolean;
}
interface ColorDef {
  kind: 'color';
  default: string;
}
interface ChoiceDef {
  kind: 'choice';
  default: string;
  options: readonly string[];
}
export type ParamDef = NumberDef | BooleanDef | ColorDef | ChoiceDef;

export const paramDefs = {
  // The wave model (src/render/waves/waveViewRegistry.ts): 'seed' is the seed report's sines and Perlin ripples,
  // 'fft' the spectral sea (Tessendorf's FFT of a wind spectrum, src/sim/waves/fft/fftOcean.ts),
  // 'gerstner' a sum of trochoids drawn from the same wind spectrum (src/sim/waves/gerstner/gerstnerLiveModel.ts).
  waves: { kind: 'choice', default: 'seed', options: WAVE_MODEL_NAMES },
  // Side by side (src/sim/compare/compareLayout.ts): two or three models, left to right, on the same
  // camera, wind and seed, each drawing only its own strip of the screen. The first replaces
  // `waves` while the split is on: the boat, the underwater view and the physics panel use it.
  compare: {
    kind: 'choice',
    default: COMPARE_OFF,
    options: [COMPARE_OFF, ...compareOrderings(WAVE_MODEL_NAMES)],
  },
  // Where the dividers stand, as fractions of the view's width (the second only with three models).
  compareSplit: { kind: 'number', default: 0.5, min: 0, max: 1, step: 0.001, unit: '' },
  compareSplit2: { kind: 'number', default: 0.75, min: 0, max: 1, step: 0.001, unit: '' },
  // The spectral sea's wind and spectrum (read only with waves=fft; see src/sim/waves/spectra/seaState.ts).
  windSpeed: { kind: 'number', default: 10, min: 1, max: 30, step: 0.5, unit: 'm/s' },
  windDirection: { kind: 'number', default: 20, min: 0, max: 360, step: 1, unit: '°' },
  spectrum: { kind: 'choice', default: 'pierson-moskowitz', options: ['pierson-moskowitz', 'jonswap', 'phillips'] },
  fetch: { kind: 'number', default: 100, min: 1, max: 1000, step: 1, unit: 'km' },
  // At 1000 m every wave the cascades carry is a deep-water wave (k h > 3), so 1000 means deep.
  depth: { kind: 'number', default: 1000, min: 1, max: 1000, step: 1, unit: 'm' },
  spreading: { kind: 'number', default: 8, min: 1, max: 40, step: 0.5, unit: '' },
  // cos-2s with the s above at every frequency, or Hasselmann et al. (1980)'s s(ω/ωp) measured in JONSWAP.
  spreadingModel: { kind: 'choice', default: 'cos-2s', options: ['cos-2s', 'hasselmann'] },
  choppiness: { kind: 'number', default: 1, min: 0, max: 2, step: 0.05, unit: '' },
  fftSize: { kind: 'choice', default: '128', options: ['64', '128', '256'] },
  foam: { kind: 'boolean', default: true },
  // Added to the Jacobian threshold that gives Monahan's whitecap coverage for the wind (src/sim/waves/fft/whitecaps.ts).
  foamThreshold: { kind: 'number', default: 0, min: -0.5, max: 0.5, step: 0.01, unit: '' },
  // e-folding time of the foam left behind (Callaghan et al. 2012: 0.5–8 s; src/sim/waves/fft/foamMemory.ts).
  foamFade: { kind: 'number', default: FOAM_FADE_SECONDS, min: 0.5, max: 8, step: 0.1, unit: 's' },
  // Foam drawn as foam (bubbles, feathered edges, streaks, lit with its own normal) or as flat white paint, for the lesson.
  foamTexture: { kind: 'boolean', default: true },
  // Wave groups: a field that never repeats decides where waves break and, far away, which copy of the shorter tiles shows (src/sim/waves/fft/foamBreakup.ts, shaders/waves/fft.glsl); off, the lesson shows the tiles' repeat.
  waveGroups: { kind: 'boolean', default: true },
  // Windrows: from Beaufort 7 (13.9 m/s) the foam left behind lies in streaks along the wind (src/sim/waves/fft/windrows.ts); off, for the lesson, it lies where it was laid.
  windrows: { kind: 'boolean', default: true },
  // Thin sunlit crests glowing green when the sun is behind them (shaders/subsurface.glsl).
  subsurface: { kind: 'boolean', default: true },
  seed: { kind: 'integer', default: 1, min: 0, max: 2147483647, unit: '' },
  swellAmplitude: { kind: 'number', default: 1.4, min: 0, max: 4, step: 0.05, unit: 'm' },
  swellFrequency: { kind: 'number', default: 0.05, min: 0.005, max: 0.2, step: 0.001, unit: 'rad/m' },
  rippleStrength: { kind: 'number', default: 0.6, min: 0, max: 2, step: 0.05, unit: 'm' },
  rippleBlendSpeed: { kind: 'number', default: 0.25, min: 0, max: 3, step: 0.01, unit: 'rad/s' },
  sunElevation: { kind: 'number', default: 18, min: -10, max: 90, step: 0.5, unit: '°' },
  sunAzimuth: { kind: 'number', default: 20, min: 0, max: 360, step: 1, unit: '°' },
  waterColor: { kind: 'color', default: '#06283a' },
  // The water's colour comes from its optics (absorption and scattering, docs/light.md) on
  // every wave model; the picked colour above is an artistic override, used only when this is on.
  waterColorPicked: { kind: 'boolean', default: false },
  fresnel: { kind: 'boolean', default: true },
  // The slopes the picture does not show (Cox & Munk's σ² for the wind less the model's own)
  // as the roughness of the sun's glint and the sky's reflection (docs/light.md); off, a mirror
  // but for the sun's disc, as the seed's lessons of a windless sea show it.
  seaRoughness: { kind: 'boolean', default: true },
  // The sky's reflection blurred by that roughness (a mip level of the sky cube, shaders/skyCube.glsl), or read as from a mirror while the glint stays rough.
  skyBlur: { kind: 'boolean', default: true },
  // How far a dark object can be told from the horizon (Koschmieder's 2 % contrast): the haze
  // between the eye and the sea (src/sim/optics/haze.ts). 20 km: a clear day at sea.
  visibility: { kind: 'number', default: 20, min: 1, max: 60, step: 0.5, unit: 'km' },
  // A camera's exposure, in stops: the frame's light is multiplied by 2^exposure before the
  // tone curve (src/render/tone/wholeFrameToneCurve.ts), so −1 halves it and the glint's core
  // stays white while the sea beside it darkens.
  exposure: { kind: 'number', default: 0, min: -3, max: 3, step: 0.1, unit: 'EV' },
  wireframe: { kind: 'boolean', default: false },
  boatSpeed: { kind: 'number', default: 0, min: -3, max: 12, step: 0.1, unit: 'm/s' },
  boatHeading: { kind: 'number', default: 290, min: 0, max: 360, step: 1, unit: '°' },
  boatResponse: { kind: 'number', default: 0.25, min: 0.02, max: 2, step: 0.01, unit: 's' },
  boatFollow: { kind: 'boolean', default: false },
  // A held rudder: the heading turns by this much every second of play (positive to starboard),
  // as the A/D keys do; the wake-turn preset uses it.
  boatTurnRate: { kind: 'number', default: 0, min: -20, max: 20, step: 0.5, unit: '°/s' },
  // The boat's Kelvin wake (src/sim/wake/boatWake.ts, shaders/wake.glsl), added to whichever wave
  // model is active. Off by default, so the default picture stays what it was.
  wake: { kind: 'boolean', default: false },
  wakeStrength: { kind: 'number', default: 1, min: 0, max: 3, step: 0.05, unit: '' },
  // Teaching overlay: the ±19.47° lines from theory, drawn behind the boat.
  wakeGuide: { kind: 'boolean', default: false },
  // Tessendorf's iWave (src/sim/iwave/): a height field stepped in time around the camera's focus,
  // added to whichever wave model is active; stones dropped with disturb() make waves that obey
  // ω² = g k. Off, none of its passes run and none of its code is compiled in.
  interactiveWaves: { kind: 'boolean', default: false },
  // What the field solves: deep water (iWave), the plain wave equation, or the two side by side
  // about the field's centre (src/sim/iwave/interactiveField.ts); and the teaching rings drawn
  // round each stone where theory puts its crests.
  iwaveEquation: {
    kind: 'choice',
    default: 'dispersive',
    options: ['dispersive', 'non-dispersive', 'side-by-side'],
  },
  iwaveGuide: { kind: 'boolean', default: false },
  // Teaching views of the seed's figures.
  shading: { kind: 'choice', default: 'water', options: ['water', 'normals'] },
  normals: { kind: 'choice', default: 'fabricated', options: ['fabricated', 'flat'] },
  // waves=fft teaching view: left half of the screen the exact slope normals per pixel, right
  // half the seed's fabricated-neighbour normals per vertex, on the same sea.
  normalsCompare: { kind: 'boolean', default: false },
  // What the canvas shows: the sea, or a teaching figure in its place (src/sim/teaching/teachingFigures.ts):
  // the heightmaps, the Perlin noise's steps, the sky's cube map unfolded.
  view: {
    kind: 'choice',
    default: 'ocean',
    options: ['ocean', 'heightmap', 'noise-hash', 'noise-smoothing', 'noise-octaves', 'noise-blend', 'sky-cube'],
  },
  fresnelPlot: { kind: 'boolean', default: false },
  // Slow motion for teaching: simulated seconds per second of the frame loop (and per Step of 1/60 s).
  timeScale: { kind: 'choice', default: '1', options: ['1', '0.5', '0.25', '0.1'] },
  // The physics panel (src/app/physics/physicsPanel.ts): the running sea measured against theory.
  physics: { kind: 'boolean', default: false },
  lodDistance: { kind: 'number', default: 100, min: 10, max: 1000, step: 5, unit: 'm' },
  lodBands: { kind: 'integer', default: 6, min: 1, max: 6, unit: '' },
  lodColors: { kind: 'boolean', default: false },
  // CDLOD geomorphing (src/sim/lod/lodMorph.ts); off shows the pops it removes.
  lodMorph: { kind: 'boolean', default: true },
  freezeCulling: { kind: 'boolean', default: false },
  lodBruteForce: { kind: 'boolean', default: false },
  blurStrength: { kind: 'number', default: 1.5, min: 0, max: 8, step: 0.1, unit: 'px' },
  // The water's beam attenuation at 510 nm (green), 1/m; the default is pure water's (src/sim/underwater/waterFog.ts).
  fogDensity: { kind: 'number', default: 0.035, min: 0, max: 0.3, step: 0.001, unit: '1/m' },
  // The coast (src/sim/coast/): the sea floor's shape, and a long-crested swell from far away that feels it
  // (shoaling, refraction, breaking). 'deep' is today's sea, and none of the coast's code is fetched for it.
  // The values of Bathymetry (src/sim/coast/bathymetry.ts), written out so the page's first script does not carry that module.
  bathymetry: { kind: 'choice', default: 'deep', options: ['deep', 'beach', 'island'] },
  beachSlope: { kind: 'number', default: 0.02, min: 0.005, max: 0.1, step: 0.005, unit: '' },
  // The swell's significant height Hs = 4 √m0 and peak period Tp: a JONSWAP spectrum sampled at four frequencies (src/sim/coast/swellSpectrum.ts).
  swellHeight: { kind: 'number', default: 1.5, min: 0, max: 6, step: 0.1, unit: 'm' },
  swellPeriod: { kind: 'number', default: 10, min: 4, max: 20, step: 0.5, unit: 's' },
  // 0 heads straight for the beach's shore (+x); positive turns it towards +z.
  swellDirection: { kind: 'number', default: 0, min: -60, max: 60, step: 1, unit: '°' },
  // The wave model's own waves (the wind sea) on top of the swell, calmed where the water is too shallow to hold them.
  windSea: { kind: 'boolean', default: true },
  seaBedDepth: { kind: 'number', default: 20, min: 2, max: 200, step: 0.5, unit: 'm' },
  caustics: { kind: 'boolean', default: true },
  causticsIntensity: { kind: 'number', default: 1, min: 0, max: 3, step: 0.05, unit: '' },
  godRays: { kind: 'boolean', default: true },
  godRaysIntensity: { kind: 'number', default: 1, min: 0, max: 3, step: 0.05, unit: '' },
  // Gerstner waves (waves=gerstner): how many trochoids are drawn from the wind spectrum, and
  // Q, the share of the looping limit Σ Qᵢ kᵢ Aᵢ ≤ 1 they may use (src/sim/waves/gerstner/gerstnerSpectrum.ts).
  gerstnerCount: { kind: 'integer', default: 32, min: 4, max: 64, unit: '' },
  gerstnerSteepness: { kind: 'number', default: 0.6, min: 0.2, max: 1, step: 0.05, unit: '' },
} as const satisfies Record<string, ParamDef>;

export type ParamKey = keyof typeof paramDefs;
type ValueOf<D> = D extends { kind: 'boolean' }
  ? boolean
  : D extends { kind: 'choice'; options: readonly (infer O)[] }
    ? O
    : D extends { kind: 'color' }
      ? string
      : number;
export type OceanParams = { -readonly [K in ParamKey]: ValueOf<(typeof paramDefs)[K]> };

export const paramKeys = Object.keys(paramDefs) as ParamKey[];

export function defaultParams(): OceanParams {
  const params = {} as Record<ParamKey, unknown>;
  for (const key of paramKeys) params[key] = paramDefs[key].default;
  return params as OceanParams;
}

export class ParamError extends Error {
  constructor(
    readonly key: string,
    message: string,
  ) {
    super(message);
    this.name = 'ParamError';
  }
}

export function isParamKey(key: string): key is ParamKey {
  return Object.prototype.hasOwnProperty.call(paramDefs, key);
}

const COLOR_PATTERN = /^#[0-9a-fA-F]{6}$/;

/** Checks one value against its definition; throws a ParamError naming the key. */
export function validateParam(key: string, value: unknown): OceanParams[ParamKey] {
  if (!isParamKey(key)) {
    throw new ParamError(key, `Unknown parameter "${key}". Known parameters: ${paramKeys.join(', ')}.`);
  }
  const def: ParamDef = paramDefs[key];
  switch (def.kind) {
    case 'boolean':
      if (typeof value !== 'boolean') throw new ParamError(key, `"${key}" must be true or false, got ${describe(value)}.`);
      return value;
    case 'choice':
      if (typeof value !== 'string' || !def.options.includes(value)) {
        throw new ParamError(key, `"${key}" must be one of ${def.options.join(', ')}, got ${describe(value)}.`);
      }
      return value as OceanParams[ParamKey];
    case 'color': {
      // With or without the '#': the URL, the GUI's share links and this API take the same text.
      const hex = typeof value === 'string' && !value.startsWith('#') ? `#${value}` : value;
      if (typeof hex !== 'string' || !COLOR_PATTERN.test(hex)) {
        throw new ParamError(key, `"${key}" must be a colour like #12ab9f or 12ab9f, got ${describe(value)}.`);
      }
      return hex.toLowerCase();
    }
    default: {
      if (typeof value !== 'number' || !Number.isFinite(value)) {
        throw new ParamError(key, `"${key}" must be a finite number, got ${describe(value)}.`);
      }
      if (def.kind === 'integer' && !Number.isInteger(value)) {
        throw new ParamError(key, `"${key}" must be an integer, got ${value}.`);
      }
      if (value < def.min || value > def.max) {
        throw new ParamError(key, `"${key}" must lie in [${def.min}, ${def.max}]${def.unit ? ' ' + def.unit : ''}, got ${value}.`);
      }
      return value;
    }
  }
}

/** Validates a whole partial update first, so a bad key never half-applies an update. */
export function validateParams(partial: unknown): Partial<OceanParams> {
  if (typeof partial !== 'object' || partial === null || Array.isArray(partial)) {
    throw new ParamError('', `Parameters must be an object, got ${describe(partial)}.`);
  }
  const result: Record<string, unknown> = {};
  for (const [key, value] of Object.entries(partial)) result[key] = validateParam(key, value);
  return result as Partial<OceanParams>;
}

function describe(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number' || typeof value === 'boolean' || value === null || value === undefined) return String(value);
  return typeof value;
}

/**
 * Reads a parameter from URL text. A malformed value falls back to the default and an
 * out-of-range number is clamped; either way a notice says what happened.
 */
export function parseParamText(key: ParamKey, text: string): { value: OceanParams[ParamKey]; notice?: Message } {
  const def: ParamDef = paramDefs[key];
  if (def.kind === 'boolean') {
    if (['1', 'true', 'on', 'yes'].includes(text)) return { value: true };
    if (['0', 'false', 'off', 'no'].includes(text)) return { value: false };
    return { value: def.default, notice: message('paramNotBoolean', { key, text, fallback: def.default }) };
  }
  if (def.kind === 'choice') {
    if (def.options.includes(text)) return { value: text as OceanParams[ParamKey] };
    return {
      value: def.default as OceanParams[ParamKey],
      notice: message('paramNotChoice', { key, text, options: def.options.join(', '), fallback: def.default }),
    };
  }
  if (def.kind === 'color') {
    const hex = text.startsWith('#') ? text : `#${text}`;
    if (COLOR_PATTERN.test(hex)) return { value: hex.toLowerCase() };
    return { value: def.default, notice: message('paramNotColour', { key, text, fallback: def.default }) };
  }
  const number = text.trim() === '' ? NaN : Number(text);
  if (!Number.isFinite(number) || (def.kind === 'integer' && !Number.isInteger(number))) {
    const id = def.kind === 'integer' ? 'paramNotInteger' : 'paramNotNumber';
    return { value: def.default, notice: message(id, { key, text, fallback: def.default }) };
  }
  if (number < def.min || number > def.max) {
    const clamped = Math.min(def.max, Math.max(def.min, number));
    return { value: clamped, notice: message('paramClamped', { key, text, min: def.min, max: def.max, unit: def.unit, clamped }) };
  }
  return { value: number };
}
