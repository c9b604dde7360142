import type { OceanParams } from '../sim/params';
import type { CameraPose } from './cameraPose';

/** A named view for a course page: a few parameters changed from the defaults and a camera. */
export interface Preset {
  params: Partial<OceanParams>;
  camera: CameraPose;
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
  /** No swell, no ripples: the sea is a mirror, so what it shows is the reflected sky (and Fresnel). */
  'still-ocean': {
    params: { swellAmplitude: 0, rippleStrength: 0 },
    camera: { position: [0, 6, 40], target: [0, 2, -60] },
  },
} satisfies Record<string, Preset>;

export type PresetName = keyof typeof PRESETS;
export const presetNames = Object.keys(PRESETS) as PresetName[];

export function findPreset(name: string): Preset | null {
  return Object.prototype.hasOwnProperty.call(PRESETS, name) ? (PRESETS[name as PresetName] as Preset) : null;
}
