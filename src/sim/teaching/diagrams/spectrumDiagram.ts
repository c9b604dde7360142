import { seaStateFromParams, type SeaParams, type SpectrumName } from '../../waves/spectra/seaState';
import { frequencySpectrum, peakWavelength } from '../../waves/spectra/waveSpectrum';
import { sampled, type Diagram } from './diagram';

const SPECTRA: readonly SpectrumName[] = ['pierson-moskowitz', 'jonswap', 'phillips'];

/**
 * S(ω) of the spectrum the sea is drawn from, its peak ωp marked (as frequencySpectrum gives
 * it) with the peak's wavelength; the other two spectra for the same wind faint behind it.
 */
export function spectrumDiagram(params: SeaParams): Diagram {
  const sea = seaStateFromParams(params);
  const spectrum = frequencySpectrum(sea);
  const omegaMax = 3.5 * spectrum.peak;
  const curve = (name: SpectrumName) => {
    const density = frequencySpectrum({ ...sea, spectrum: name }).density;
    return sampled(0.2 * spectrum.peak, omegaMax, 160, (w) => [w, density(w)]);
  };
  const main = curve(sea.spectrum);
  const top = Math.max(...main.map(([, s]) => s)) * 1.25;
  return {
    kind: 'spectrum',
    x: [0, omegaMax],
    y: [0, top],
    equalScale: false,
    lines: [
      ...SPECTRA.filter((name) => name !== sea.spectrum).map((name) => ({ role: 'faint' as const, points: curve(name) })),
      { role: 'main', points: main },
      {
        role: 'guide',
        points: [
          [spectrum.peak, 0],
          [spectrum.peak, spectrum.density(spectrum.peak)],
        ],
      },
    ],
    marks: [
      { id: 'peak', x: spectrum.peak, y: spectrum.density(spectrum.peak), value: spectrum.peak, unit: 'rad/s' },
      { id: 'wavelength', x: spectrum.peak, y: 0, value: peakWavelength(sea), unit: 'm' },
    ],
    headline: 'peak',
  };
}
