import { buildBeachField } from './beachSwellField';
import type { CoastField, CoastSetting } from './coastField';
import { type CoastWaveModel, LINEAR_THEORY } from './coastWaveModel';
import { buildIslandField } from './islandSwellField';
import { swellComponents, type SwellComponentSpec } from './swellSpectrum';

/** Texels per side unless asked otherwise, and the most allowed (a 512² RGBA float texture is 4 MiB per layer). */
export const DEFAULT_COAST_RESOLUTION = 256;
export const MAX_COAST_RESOLUTION = 512;

/**
 * The swell's field over the coast for one setting (see coastField.ts), or null for `deep`:
 * the open sea has no bottom to feel, so the caller draws no coastal swell there.
 * `model` is linear theory; tests pass a planted wrong one to show their checks catch it.
 * `components` are the swell's spectrum (swellComponents) unless given: one component
 * (regularSwell) is linear theory's single wave train, which the tests measure.
 */
export function buildCoastField(
  setting: CoastSetting,
  resolution: number = DEFAULT_COAST_RESOLUTION,
  model: CoastWaveModel = LINEAR_THEORY,
  components: readonly SwellComponentSpec[] = swellComponents(setting),
): CoastField | null {
  const n = Math.round(Math.min(MAX_COAST_RESOLUTION, Math.max(8, resolution)));
  switch (setting.bathymetry) {
    case 'deep':
      return null;
    case 'beach':
      return buildBeachField(setting, n, model, components);
    case 'island':
      return buildIslandField(setting, n, model, components);
  }
}
