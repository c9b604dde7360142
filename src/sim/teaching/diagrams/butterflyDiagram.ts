import { cascadeLayout } from '../../waves/fft/cascades';
import { liveRowStages } from '../../waves/fft/rowStages';
import { stockhamRadices, stockhamSource } from '../../waves/fft/stockhamFft';
import { seaStateFromParams, type SeaParams } from '../../waves/spectra/seaState';
import { peakWavelength } from '../../waves/spectra/waveSpectrum';
import type { Diagram, DiagramLine, DiagramMark } from './diagram';

/** Points of the small transform drawn; the sea's own is fftSize points per side. */
export const BUTTERFLY_POINTS = 8;

/** Height of one strip of the live row, in the diagram's rows (the network's outputs are 1 apart). */
const STRIP = 1.5;
/** Where the first strip's top sits, below the network's last output (−7). */
const STRIPS_TOP = -7.9;

/**
 * The radix-2 Stockham stages of an 8-point inverse FFT, wired as stockhamSource reads them:
 * output o of a stage takes in[j] and in[j + n/2] (the second times ±e^{iπk/Ns}). Beside them,
 * what the sea runs: each cascade tile's side (cascadeLayout) and, for fftSize, the passes
 * per direction (stockhamRadices: radix 4 where it fits). Below them, the live sea: the row
 * z = 0 of cascade 0 at `time` (liveRowStages), a strip for its spectrum and one after each
 * stage the sea runs, each |value| scaled to its own largest; the last is the row of heights
 * (the real part, signed), the very heights the sea draws there.
 */
export function butterflyDiagram(params: SeaParams, time = 0): Diagram {
  const n = BUTTERFLY_POINTS;
  const lines: DiagramLine[] = [];
  const stages = Math.log2(n);
  for (let s = 0; s < stages; s++) {
    const half = 2 ** s;
    for (let o = 0; o < n; o++) {
      const { j, r } = stockhamSource(o, n, half);
      lines.push({
        role: 'faint',
        points: [
          [s, -j],
          [s + 1, -o],
        ],
      });
      lines.push({
        role: r === 0 ? 'main' : 'second',
        points: [
          [s, -(j + n / 2)],
          [s + 1, -o],
        ],
      });
    }
  }
  const sea = seaStateFromParams(params);
  const size = sea.fftSize;
  const live = liveRowStages(sea, time);
  const right = stages + 2.4;
  const last = live.stages.length - 1;
  const stripMarks: DiagramMark[] = [];
  live.stages.forEach((data, s) => {
    const top = STRIPS_TOP - s * STRIP;
    const heights = s === last;
    const value = (p: number) => (heights ? data[2 * p] : Math.hypot(data[2 * p], data[2 * p + 1]));
    const largest = Math.max(1e-30, ...Array.from({ length: live.n }, (_, p) => Math.abs(value(p))));
    // Magnitudes stand on the strip's floor; the signed heights about its middle.
    const base = heights ? top - STRIP / 2 : top - STRIP + 0.15;
    // Below the strip's label, which stands at its top.
    const reach = heights ? 0.3 * STRIP : 0.55 * STRIP;
    lines.push({
      role: heights ? 'main' : 'second',
      points: Array.from({ length: live.n }, (_, p) => [(right * p) / (live.n - 1), base + (reach * value(p)) / largest] as const),
    });
    if (s === 0) stripMarks.push({ id: 'rowSpectrum', x: 0, y: top, value: live.n, unit: '', bare: true });
    else if (heights) stripMarks.push({ id: 'heights', x: 0, y: top, value: largest, unit: 'm', bare: true });
    else stripMarks.push({ id: 'liveStage', x: 0, y: top, value: live.radices[s - 1], unit: '', index: s - 1, bare: true });
  });
  const tiles = cascadeLayout(peakWavelength(sea), size);
  const marks: DiagramMark[] = [
    ...Array.from({ length: stages }, (_, s): DiagramMark => ({
      id: 'stage',
      x: s + 0.5,
      y: 0.7,
      value: 2 ** s,
      unit: '',
      index: s,
      bare: true,
    })),
    { id: 'size', x: stages + 0.35, y: 0, value: size, unit: '', bare: true },
    { id: 'passes', x: stages + 0.35, y: -1.4, value: stockhamRadices(size).length, unit: '', bare: true },
    ...tiles.map((tile, index): DiagramMark => ({
      id: 'tile',
      x: stages + 0.35,
      y: -2.8 - 1.4 * index,
      value: tile.size,
      unit: 'm',
      index,
      bare: true,
    })),
    ...stripMarks,
  ];
  const bottom = STRIPS_TOP - live.stages.length * STRIP - 0.1;
  return {
    kind: 'butterflies',
    x: [-0.15, stages + 2.6],
    y: [bottom, 1.1],
    equalScale: false,
    lines,
    marks,
    headline: 'size',
    graphHeight: 330,
  };
}
