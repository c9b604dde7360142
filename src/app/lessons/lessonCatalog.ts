import { defaultParams, type OceanParams } from '../../sim/params/params';
import { DEFAULT_CAMERA, type CameraPose } from '../camera/cameraPose';
import { findPreset, type PresetName, type Stone } from '../url/presets';

/**
 * One lesson's view, in the course's order. Where it sits in the course, its title, words,
 * equations, controls and code quote are fetched after the first frame (lessonOutline.ts,
 * lessonTexts.ts, lessonQuoteSources.ts): the page's first script stays small.
 */
export interface Lesson {
  id: string;
  /** The figure it starts from; `params` and `camera` change it. */
  preset?: PresetName;
  params?: Partial<OceanParams>;
  camera?: CameraPose;
}

export const LESSONS: readonly Lesson[] = [
  { id: 'flat-plane', preset: 'flat-plane' },
  { id: 'displaced-plane', preset: 'displaced-plane' },
  { id: 'swell', preset: 'swell-normal' },
  { id: 'swell-maximum', preset: 'swell-maximum' },
  // Each step of the noise beside the one it starts from (src/sim/teaching/teachingFigures.ts).
  { id: 'perlin-hash', preset: 'perlin-heightmap', params: { view: 'noise-hash' } },
  { id: 'perlin-smoothing', preset: 'perlin-heightmap', params: { view: 'noise-smoothing' } },
  { id: 'perlin-octaves', preset: 'perlin-heightmap', params: { view: 'noise-octaves' } },
  {
    id: 'heightmap-blend',
    params: { swellAmplitude: 0, rippleStrength: 1.2, view: 'noise-blend' },
    camera: { position: [0, 8, 30], target: [0, 0, -30] },
  },
  { id: 'normals-wrong', preset: 'normals-wrong' },
  { id: 'normals-right', preset: 'normals-right' },
  {
    id: 'sky-cube',
    params: { view: 'sky-cube' },
    camera: { position: [0, 3, 40], target: [0, 40, -40] },
  },
  { id: 'reflection', preset: 'still-ocean' },
  { id: 'fresnel', preset: 'fresnel' },
  { id: 'fresnel-schlick', preset: 'fresnel', params: { fresnel: false } },
  // From 20 m up towards a 25° sun: the glitter's centre, 43 m ahead, in the middle of the view.
  {
    id: 'sun-glint',
    params: { waves: 'fft', windSpeed: 5, sunElevation: 25, sunAzimuth: 20 },
    camera: { position: [0, 20, 0], target: [14.7, 0, -40.4] },
  },
  {
    id: 'boat-twin',
    preset: 'boat-pitch',
    // Looking at the boat, so its sample points stay in sight on a phone held upright too.
    camera: { position: [18, 6, 14], target: [7, 0, -5] },
  },
  { id: 'boat-pitch', preset: 'boat-pitch' },
  { id: 'snell-window', preset: 'underwater' },
  {
    id: 'underwater-fog',
    params: { fogDensity: 0.06 },
    camera: { position: [0, -5, 20], target: [0, -6, -20] },
  },
  {
    id: 'caustics',
    params: { seaBedDepth: 10, godRays: false, sunElevation: 60 },
    camera: { position: [0, -3, 14], target: [0, -10, -6] },
  },
  {
    id: 'god-rays',
    params: { sunElevation: 40, sunAzimuth: 20 },
    camera: { position: [0, -10, 20], target: [0, -4, -20] },
  },
  { id: 'lod-bands', preset: 'lod-bands' },
  {
    id: 'lod-morph',
    params: { wireframe: true, lodColors: true, lodDistance: 40 },
    camera: { position: [0, 30, 50], target: [0, 0, -60] },
  },
  { id: 'frustum-culling', preset: 'frustum-culling' },
  { id: 'fft-calm', preset: 'calm' },
  { id: 'fft-fresh-breeze', preset: 'fresh-breeze' },
  { id: 'fft-short-fetch', preset: 'short-fetch' },
  { id: 'fft-gale', preset: 'gale' },
  { id: 'fft-normals', preset: 'fft-normals' },
  { id: 'gerstner-gentle', preset: 'gerstner-gentle' },
  { id: 'gerstner-steepness', preset: 'gerstner-steepness' },
  { id: 'compare-models', preset: 'compare-models' },
  { id: 'physics-panel', preset: 'fresh-breeze', params: { physics: true } },
  // The preset's view moved 35 m west: the boat stands clear of the card on the left.
  { id: 'kelvin-wake', preset: 'kelvin-wake', params: { wakeGuide: true }, camera: { position: [25, 60, 60], target: [25, 0, -10] } },
  { id: 'wake-turn', preset: 'wake-turn', params: { wakeGuide: true } },
  { id: 'waves-as-simulation', preset: 'stone', params: { waves: 'fft', windSpeed: 4, iwaveGuide: false } },
  { id: 'iwave-stone', preset: 'stone' },
  { id: 'iwave-compare', preset: 'stone-compare' },
  { id: 'iwave-boat', preset: 'boat-interactive' },
  {
    id: 'horizon',
    preset: 'lod-bands',
    camera: { position: [0, 120, 60], target: [0, 60, -1500] },
  },
  // The ideas under the models (conceptPath.ts walks them in the ideas' order).
  { id: 'airy-waves', preset: 'gerstner-gentle' },
  { id: 'group-velocity', preset: 'stone', params: { iwaveGuide: true } },
  { id: 'spectra-compared', preset: 'fresh-breeze', params: { spectrum: 'phillips' } },
  { id: 'fft-transform', preset: 'fresh-breeze', params: { physics: true } },
  // A low sun: its glitter runs far out, where a pixel spans metres of sea.
  { id: 'slope-filtering', preset: 'fresh-breeze', params: { sunElevation: 5 } },
  { id: 'light-units', preset: 'calm', params: { sunElevation: 10 } },
  { id: 'water-colour', preset: 'fresh-breeze' },
  // The coast (src/sim/coast/): the swell alone where its crests are to be seen, the wind sea on for the surf;
  // from the dune looking out to sea, the sun behind, so no glitter hides the crests.
  { id: 'coast-dispersion', preset: 'beach', params: { windSea: false }, camera: { position: [480, 70, 60], target: [200, 0, -20] } },
  { id: 'coast-refraction', preset: 'island', params: { windSea: false } },
  { id: 'coast-shoaling', preset: 'beach', params: { windSea: false } },
  { id: 'coast-breaking', preset: 'beach', camera: { position: [560, 150, 200], target: [250, 0, -40] } },
];

export const lessonIds = LESSONS.map((lesson) => lesson.id);

export function findLesson(id: string): Lesson | null {
  return LESSONS.find((lesson) => lesson.id === id) ?? null;
}

/** The view a lesson opens: the defaults, then its preset's parameters, then its own. */
export interface LessonView {
  params: OceanParams;
  camera: CameraPose;
  cullingCamera: CameraPose | null;
  /** Its preset's stones, their times counted from the lesson's opening. */
  stones: Stone[];
}

export function lessonView(lesson: Lesson): LessonView {
  const preset = lesson.preset ? findPreset(lesson.preset) : null;
  const camera = lesson.camera ?? preset?.camera ?? DEFAULT_CAMERA;
  return {
    params: { ...defaultParams(), ...preset?.params, ...lesson.params },
    camera: { position: [...camera.position], target: [...camera.target] },
    cullingCamera: preset?.cullingCamera
      ? { position: [...preset.cullingCamera.position], target: [...preset.cullingCamera.target] }
      : null,
    stones: [...(preset?.stones ?? [])],
  };
}
