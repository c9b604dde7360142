import { cascadeLayout } from '../../waves/fft/cascades';
import { stockhamRadices, stockhamSource } from '../../waves/fft/stockhamFft';
import { seaStateFromParams, type SeaParams } from '../../waves/spectra/seaState';
import { peakWavelength } from '../../waves/spectra/waveSpectrum';
import type { Diagram, DiagramLine, DiagramMark } from './diagram';

/** Points of the small transform drawn; the sea's own is fftSize points per side. */
export const BUTTERFLY_POINTS = 8;

/**
 * The radix-2 Stockham stages of an 8-point inverse FFT, wired as stockhamSource reads them:
 * output o of a stage takes in[j] and in[j + n/2] (the second times ±e^{iπk/Ns}). Beside them,
 * what the sea runs: each cascade tile's side (cascadeLayout) and, for fftSize, the passes
 * per direction (stockhamRadices: radix 4 where it fits).
 */
export function butterflyDiagram(params: SeaParams): Diagram {
  const n = BUTTERFLY_POINTS;
  const lines: DiagramLine[] = [];
  const stages = Math.log2(n);
  for (let s = 0; s < stages; s++) {
    const half = 2 ** s;
    for (let o = 0; o < n; o++) {
      const { j, r } = stockhamSource(o, n, half);
      lines.push({ role: 'faint', points: [[s, -j], [s + 1, -o]] });
      lines.push({ role: r === 0 ? 'main' : 'second', points: [[s, -(j + n / 2)], [s + 1, -o]] });
    }
  }
  const sea = seaStateFromParams(params);
  const size = sea.fftSize;
  const tiles = cascadeLayout(peakWavelength(sea), size);
  const marks: DiagramMark[] = [
    ...Array.from({ length: stages }, (_, s): DiagramMark => ({ id: 'stage', x: s + 0.5, y: 0.7, value: 2 ** s, unit: '', index: s, bare: true })),
    { id: 'size', x: stages + 0.35, y: 0, value: size, unit: '', bare: true },
    { id: 'passes', x: stages + 0.35, y: -1.4, value: stockhamRadices(size).length, unit: '', bare: true },
    ...tiles.map((tile, index): DiagramMark => ({ id: 'tile', x: stages + 0.35, y: -2.8 - 1.4 * index, value: tile.size, unit: 'm', index, bare: true })),
  ];
  return { kind: 'butterflies', x: [-0.15, stages + 2.6], y: [-(n - 1) - 0.3, 1.1], equalScale: false, lines, marks, headline: 'size' };
}
