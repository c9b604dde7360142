import type { OceanParams } from '../../params/params';
import { butterflyDiagram } from './butterflyDiagram';
import { cauchyPoissonDiagram } from './cauchyPoissonDiagram';
import type { Diagram } from './diagram';
import { depthDispersionDiagram, seedDispersionDiagram } from './dispersionDiagram';
import { fresnelDiagram } from './fresnelDiagram';
import { kelvinDiagram } from './kelvinDiagram';
import { lodDiagram } from './lodDiagram';
import { orbitDiagram } from './orbitDiagram';
import { snellDiagram } from './snellDiagram';
import { spectrumDiagram } from './spectrumDiagram';

/** A lesson's diagram from the parameters on screen, the seconds since the lesson opened and the sea's clock (s). */
export type DiagramOf = (params: OceanParams, age: number, clock?: number) => Diagram;

/** The lessons whose card shows a flat diagram beside the sea, and which. */
export const LESSON_DIAGRAMS: Readonly<Record<string, DiagramOf>> = {
  swell: (p) => seedDispersionDiagram(p),
  'fft-fresh-breeze': (p) => depthDispersionDiagram(p),
  'gerstner-gentle': (p) => orbitDiagram(p),
  'gerstner-steepness': (p) => orbitDiagram(p),
  'snell-window': () => snellDiagram(),
  'fft-calm': (p) => spectrumDiagram(p),
  'fft-short-fetch': (p) => spectrumDiagram(p),
  'fft-normals': (p, _, clock) => butterflyDiagram(p, clock),
  'lod-bands': (p) => lodDiagram(p),
  'lod-morph': (p) => lodDiagram(p),
  'kelvin-wake': (p) => kelvinDiagram(p),
  // The stone falls as the lesson opens (oceanApp.ts): its age is the lesson's.
  'iwave-stone': (_, age) => cauchyPoissonDiagram(age),
  'fresnel-schlick': () => fresnelDiagram(),
};

/** The diagrams that change with time as well as with the parameters: redrawn as the clock runs. */
export const MOVING_DIAGRAMS: ReadonlySet<string> = new Set(['iwave-stone', 'fft-normals']);
