import { describe, expect, it } from 'vitest';
import { LESSONS, lessonView, findLesson } from '../../../../../src/app/lessons/lessonCatalog';
import { diagramName, markLabel } from '../../../../../src/app/lessons/diagrams/diagramLabels';
import { DIAGRAM_WORDS } from '../../../../../src/app/lessons/diagrams/diagramWords';
import { defaultParams, type OceanParams } from '../../../../../src/sim/params/params';
import { crestRadii, stoneGuideReach } from '../../../../../src/sim/iwave/cauchyPoissonRings';
import { bandStart } from '../../../../../src/sim/lod/lodBands';
import { AIR_IOR, WATER_IOR, fresnelReflectance, schlickReflectance } from '../../../../../src/sim/optics/fresnel';
import { butterflyDiagram, BUTTERFLY_POINTS } from '../../../../../src/sim/teaching/diagrams/butterflyDiagram';
import { cauchyPoissonDiagram } from '../../../../../src/sim/teaching/diagrams/cauchyPoissonDiagram';
import { DEGREE, type Diagram, type DiagramMark, type Point } from '../../../../../src/sim/teaching/diagrams/diagram';
import { depthDispersionDiagram, seedDispersionDiagram } from '../../../../../src/sim/teaching/diagrams/dispersionDiagram';
import { fresnelDiagram } from '../../../../../src/sim/teaching/diagrams/fresnelDiagram';
import { kelvinDiagram } from '../../../../../src/sim/teaching/diagrams/kelvinDiagram';
import { LESSON_DIAGRAMS } from '../../../../../src/sim/teaching/diagrams/lessonDiagrams';
import { lodDiagram } from '../../../../../src/sim/teaching/diagrams/lodDiagram';
import { dominantGerstnerWave, orbitDiagram, ORBIT_DEPTHS } from '../../../../../src/sim/teaching/diagrams/orbitDiagram';
import { snellDiagram } from '../../../../../src/sim/teaching/diagrams/snellDiagram';
import { spectrumDiagram } from '../../../../../src/sim/teaching/diagrams/spectrumDiagram';
import { snellWindowHalfAngle } from '../../../../../src/sim/underwater/snellWindow';
import { KELVIN_HALF_ANGLE } from '../../../../../src/sim/wake/kelvinGuide';
import { angularFrequency, groupVelocity, waveNumber } from '../../../../../src/sim/waves/dispersion';
import { cascadeLayout } from '../../../../../src/sim/waves/fft/cascades';
import { stockhamRadices, stockhamSource } from '../../../../../src/sim/waves/fft/stockhamFft';
import { deepWaterAngularFrequency, surfaceStateAt } from '../../../../../src/sim/waves/seed/seedSurface';
import { seaStateFromParams } from '../../../../../src/sim/waves/spectra/seaState';
import { frequencySpectrum, peakWavelength } from '../../../../../src/sim/waves/spectra/waveSpectrum';

function lessonParams(id: string, change: Partial<OceanParams> = {}): OceanParams {
  const lesson = findLesson(id);
  if (!lesson) throw new Error(`no lesson ${id}`);
  return { ...lessonView(lesson).params, ...change };
}

function mark(diagram: Diagram, id: string, index?: number): DiagramMark {
  const found = diagram.marks.find((m) => m.id === id && (index === undefined || m.index === index));
  if (!found) throw new Error(`no mark ${id}`);
  return found;
}

const marks = (diagram: Diagram, id: string) => diagram.marks.filter((m) => m.id === id).map((m) => m.value);

/** Linear interpolation of a polyline sampled in increasing x. */
function valueAt(points: readonly Point[], x: number): number {
  for (let i = 1; i < points.length; i++) {
    const [x0, y0] = points[i - 1];
    const [x1, y1] = points[i];
    if (x >= x0 && x <= x1) return y0 + ((y1 - y0) * (x - x0)) / (x1 - x0);
  }
  throw new RangeError(`${x} outside the line`);
}

describe('every lesson diagram', () => {
  it('belongs to a lesson, is finite and has words in both languages for every mark', () => {
    expect(Object.keys(LESSON_DIAGRAMS).length).toBeGreaterThanOrEqual(8);
    const kinds = new Set<string>();
    for (const [id, draw] of Object.entries(LESSON_DIAGRAMS)) {
      expect(
        LESSONS.some((l) => l.id === id),
        id,
      ).toBe(true);
      const diagram = draw(lessonParams(id), 6);
      kinds.add(diagram.kind);
      for (const line of diagram.lines) for (const p of line.points) expect(p.every(Number.isFinite), `${id} line`).toBe(true);
      for (const m of diagram.marks) {
        expect(Number.isFinite(m.value) && Number.isFinite(m.x) && Number.isFinite(m.y), `${id} ${m.id}`).toBe(true);
        for (const language of ['en', 'es'] as const) expect(markLabel(diagram, m, language)).not.toMatch(/\{[vi]\}/);
      }
      expect(
        diagram.marks.some((m) => m.id === diagram.headline),
        id,
      ).toBe(true);
    }
    expect(kinds.size).toBeGreaterThanOrEqual(9);
  });

  it('names itself by its key value, written as each language writes numbers', () => {
    const snell = snellDiagram();
    expect(diagramName(snell, 'en')).toContain('critical angle 48.6°');
    expect(diagramName(snell, 'es')).toContain('ángulo crítico 48,6°');
    const lod = lodDiagram({ lodDistance: 40, lodBands: 6 });
    expect(diagramName(lod, 'en')).toBe('The distance bands: first ring at 40 m');
    expect(diagramName(lodDiagram({ lodDistance: 40, lodBands: 1 }), 'es')).toBe('Las bandas de distancia: una banda, vértices cada 2 m');
    // A planted wrong index of refraction names another angle.
    expect(diagramName(snellDiagram(1.5), 'en')).not.toContain('48.6°');
  });

  it('a mark without words is refused, not drawn blank', () => {
    const planted = { ...snellDiagram(), marks: [{ id: 'nonsense', x: 0, y: 0, value: 1, unit: '' }] };
    expect(() => markLabel(planted, planted.marks[0], 'en')).toThrow();
    expect(Object.keys(DIAGRAM_WORDS.snell.marks)).not.toContain('nonsense');
  });
});

describe('dispersion: the seed swell', () => {
  it('marks the two plane waves at the speeds the seed code’s phases give them', () => {
    const params = lessonParams('swell');
    const k = params.swellFrequency;
    // After one second the first product's phases are ω and 0.7ω (mod 2π), ω = √(g k).
    const omega = deepWaterAngularFrequency(k);
    const [px, pz] = surfaceStateAt(params, 1).swellPhase;
    expect(px).toBeCloseTo(omega % (2 * Math.PI), 9);
    expect(pz).toBeCloseTo((0.7 * omega) % (2 * Math.PI), 9);
    const d = seedDispersionDiagram(params);
    expect(mark(d, 'sum').value).toBeCloseTo((1.7 * omega) / (Math.SQRT2 * k), 6);
    expect(mark(d, 'difference').value).toBeCloseTo((0.3 * omega) / (Math.SQRT2 * k), 6);
    expect(mark(d, 'sum').x).toBeCloseTo(Math.SQRT2 * k, 12);
    // The curve's point is deep water's own speed at √2 k; the seed's waves are off it.
    expect(mark(d, 'curve').value).toBeCloseTo(angularFrequency(Math.SQRT2 * k) / (Math.SQRT2 * k), 9);
    expect(mark(d, 'sum').value / mark(d, 'curve').value).toBeCloseTo(1.7 * 2 ** -0.25, 6);
  });

  it('follows the frequency slider, and a speed taken at k instead of √2 k is not what it marks', () => {
    const params = lessonParams('swell');
    const d1 = seedDispersionDiagram(params);
    const d4 = seedDispersionDiagram({ ...params, swellFrequency: 4 * params.swellFrequency });
    // ω ∝ √k, so the speeds ω/k halve when k is four times larger.
    expect(mark(d4, 'sum').value).toBeCloseTo(mark(d1, 'sum').value / 2, 6);
    const omega = deepWaterAngularFrequency(params.swellFrequency);
    expect(mark(d1, 'sum').value).not.toBeCloseTo((1.7 * omega) / params.swellFrequency, 2);
  });
});

describe('dispersion: the depth', () => {
  it('marks the spectrum’s peak with its phase speed ω/k and group speed dω/dk at the current depth', () => {
    const params = lessonParams('fft-fresh-breeze', { depth: 8 });
    const sea = seaStateFromParams(params);
    const omegaPeak = frequencySpectrum(sea).peak;
    const kPeak = waveNumber(omegaPeak, 8);
    const d = depthDispersionDiagram(params);
    expect(mark(d, 'peak').x).toBeCloseTo(kPeak, 12);
    expect(mark(d, 'peak').y).toBeCloseTo(omegaPeak, 12);
    expect(mark(d, 'phase').value).toBeCloseTo(omegaPeak / kPeak, 9);
    expect(mark(d, 'group').value).toBeCloseTo(groupVelocity(kPeak, 8), 9);
    // The main curve is ω(k) at 8 m.
    const main = d.lines.find((l) => l.role === 'main')!;
    expect(valueAt(main.points, kPeak)).toBeCloseTo(omegaPeak, 3);
  });

  it('follows the depth slider: shallow water slows the peak towards √(g h); deep water does not', () => {
    const deep = depthDispersionDiagram(lessonParams('fft-fresh-breeze', { depth: 1000 }));
    const shallow = depthDispersionDiagram(lessonParams('fft-fresh-breeze', { depth: 2 }));
    expect(mark(shallow, 'phase').value).toBeLessThan(mark(deep, 'phase').value);
    expect(mark(shallow, 'phase').value).toBeLessThan(Math.sqrt(9.81 * 2) * 1.0001);
    expect(mark(deep, 'phase').value).not.toBeCloseTo(Math.sqrt(9.81 * 2), 1);
    // In deep water the group speed is half the phase speed.
    expect(mark(deep, 'group').value / mark(deep, 'phase').value).toBeCloseTo(0.5, 6);
  });
});

describe('orbits: Gerstner and Airy', () => {
  it('draws the tallest wave’s orbit QA across and A up, and Airy’s decay e^{kz} below', () => {
    const params = lessonParams('gerstner-gentle');
    const wave = dominantGerstnerWave(params);
    const d = orbitDiagram(params);
    const q = wave.horizontal / wave.amplitude;
    expect(mark(d, 'steepness').value).toBeCloseTo(q, 12);
    const scale = mark(d, 'exaggeration').value;
    // The Gerstner orbit is the 4th line; its extent, measured, is 2QA by 2A (exaggerated alike).
    const orbit = d.lines[3].points;
    const width = Math.max(...orbit.map((p) => p[0])) - Math.min(...orbit.map((p) => p[0]));
    const height = Math.max(...orbit.map((p) => p[1])) - Math.min(...orbit.map((p) => p[1]));
    expect(width / scale).toBeCloseTo(2 * wave.horizontal, 2);
    expect(height / scale).toBeCloseTo(2 * wave.amplitude, 2);
    const k = 2 * Math.PI * Math.hypot(wave.cx, wave.cz);
    ORBIT_DEPTHS.forEach((depth, i) =>
      expect(mark(d, 'decay', i).value).toBeCloseTo(100 * Math.exp(-k * depth * mark(d, 'wavelength').value), 9),
    );
    expect(mark(d, 'decay', 2).value).toBeCloseTo(100 * Math.exp(-Math.PI), 6);
  });

  it('follows the steepness slider; a gentle sea’s Q is not the steep one’s', () => {
    const gentle = orbitDiagram(lessonParams('gerstner-gentle'));
    const steep = orbitDiagram(lessonParams('gerstner-gentle', { gerstnerSteepness: 1 }));
    expect(mark(steep, 'steepness').value).toBeGreaterThan(mark(gentle, 'steepness').value);
    expect(mark(steep, 'steepness').value).toBeCloseTo(
      dominantGerstnerWave(lessonParams('gerstner-gentle', { gerstnerSteepness: 1 })).horizontal /
        dominantGerstnerWave(lessonParams('gerstner-gentle', { gerstnerSteepness: 1 })).amplitude,
      12,
    );
    expect(mark(gentle, 'steepness').value).not.toBeCloseTo(mark(steep, 'steepness').value, 2);
  });
});

describe('Snell’s window', () => {
  it('puts the window’s edge at the code’s critical angle', () => {
    const d = snellDiagram();
    expect(mark(d, 'critical').value).toBeCloseTo(snellWindowHalfAngle() / DEGREE, 12);
    expect(mark(d, 'critical').value).toBeCloseTo(48.6, 1);
    // The grazing ray (role second) meets the surface at tan θc from under the eye, one unit deep.
    const edges = d.lines.filter((l) => l.role === 'second');
    expect(edges).toHaveLength(2);
    for (const edge of edges) expect(Math.abs(edge.points[1][0])).toBeCloseTo(Math.tan(snellWindowHalfAngle()), 12);
  });

  it('follows the index of refraction; a planted 45° is not the edge', () => {
    expect(mark(snellDiagram(1.5), 'critical').value).toBeCloseTo(Math.asin(1 / 1.5) / DEGREE, 9);
    expect(mark(snellDiagram(), 'critical').value).not.toBeCloseTo(45, 1);
    // Every ray drawn leaving into the air left from inside the window.
    const inside = snellDiagram().lines.filter((l) => l.role === 'main' && l.points.length === 3);
    for (const ray of inside) expect(Math.abs(ray.points[1][0])).toBeLessThan(Math.tan(snellWindowHalfAngle()));
  });
});

describe('the wind spectrum', () => {
  it('marks the spectrum code’s peak, which is the drawn curve’s highest point', () => {
    for (const id of ['fft-calm', 'fft-short-fetch']) {
      const params = lessonParams(id);
      const sea = seaStateFromParams(params);
      const d = spectrumDiagram(params);
      expect(mark(d, 'peak').value).toBe(frequencySpectrum(sea).peak);
      expect(mark(d, 'wavelength').value).toBe(peakWavelength(sea));
      const main = d.lines.find((l) => l.role === 'main')!.points;
      const highest = main.reduce((a, b) => (b[1] > a[1] ? b : a));
      const spacing = main[1][0] - main[0][0];
      expect(Math.abs(highest[0] - mark(d, 'peak').value)).toBeLessThanOrEqual(spacing);
    }
  });

  it('follows the wind and the spectrum; a faint spectrum’s peak is not the one marked', () => {
    const params = lessonParams('fft-calm');
    const calm = spectrumDiagram(params);
    const windy = spectrumDiagram({ ...params, windSpeed: 2 * params.windSpeed });
    // Pierson–Moskowitz: ωp = 0.877 g / U₁₉.₅, so twice the wind halves it.
    expect(mark(windy, 'peak').value).toBeCloseTo(mark(calm, 'peak').value / 2, 9);
    const jonswap = spectrumDiagram({ ...params, spectrum: 'jonswap', fetch: 20 });
    expect(mark(jonswap, 'peak').value).toBe(frequencySpectrum(seaStateFromParams({ ...params, spectrum: 'jonswap', fetch: 20 })).peak);
    expect(mark(jonswap, 'peak').value).not.toBeCloseTo(mark(calm, 'peak').value, 2);
  });
});

describe('the FFT’s butterflies', () => {
  // And states the sea’s own size and cascades.
  it('wires each output to in[j] and in[j + n/2] as the Stockham stage reads them', () => {
    const params = lessonParams('fft-normals');
    const d = butterflyDiagram(params);
    const n = BUTTERFLY_POINTS;
    const stages = Math.log2(n);
    // The network's wires are two-point lines; the live row's strips below have fftSize points.
    expect(d.lines.filter((l) => l.points.length === 2)).toHaveLength(2 * n * stages);
    for (let s = 0; s < stages; s++) {
      for (let o = 0; o < n; o++) {
        const into = d.lines.filter((l) => l.points[1][0] === s + 1 && l.points[1][1] === -o);
        const { j } = stockhamSource(o, n, 2 ** s);
        expect(into.map((l) => -l.points[0][1]).sort((a, b) => a - b)).toEqual([j, j + n / 2]);
      }
    }
    const sea = seaStateFromParams(params);
    expect(mark(d, 'size').value).toBe(sea.fftSize);
    expect(mark(d, 'passes').value).toBe(stockhamRadices(sea.fftSize).length);
    expect(marks(d, 'tile')).toEqual(cascadeLayout(peakWavelength(sea), sea.fftSize).map((c) => c.size));
  });

  it('follows the FFT size; 64 points take 3 passes, not 128’s 4', () => {
    const params = lessonParams('fft-normals');
    const small = butterflyDiagram({ ...params, fftSize: '64' });
    expect(mark(small, 'size').value).toBe(64);
    expect(mark(small, 'passes').value).toBe(3);
    expect(mark(butterflyDiagram({ ...params, fftSize: '128' }), 'passes').value).not.toBe(3);
  });
});

describe('the LOD bands', () => {
  it('puts each ring where lodBands starts the band, one coloured stretch per band', () => {
    const params = lessonParams('lod-bands');
    const d = lodDiagram(params);
    expect(marks(d, 'ring')).toEqual(Array.from({ length: params.lodBands - 1 }, (_, i) => bandStart(i + 1, params.lodDistance)));
    expect(d.lines.filter((l) => l.color)).toHaveLength(params.lodBands);
  });

  it('follows L and the band count; a planted ring at 3L is not one of them', () => {
    const params = lessonParams('lod-bands', { lodDistance: 40, lodBands: 3 });
    const d = lodDiagram(params);
    expect(marks(d, 'ring')).toEqual([40, 80]);
    expect(marks(d, 'ring')).not.toContain(120);
    expect(marks(lodDiagram({ ...params, lodDistance: 80 }), 'ring')).toEqual([80, 160]);
  });
});

describe('the Kelvin wedge', () => {
  it('draws the wedge at the code’s Kelvin angle, and the crests it draws fold back at that angle', () => {
    const params = lessonParams('kelvin-wake');
    const d = kelvinDiagram(params);
    expect(mark(d, 'angle').value).toBeCloseTo(KELVIN_HALF_ANGLE / DEGREE, 12);
    for (const wedge of d.lines.filter((l) => l.role === 'second')) {
      const [x, y] = wedge.points[1];
      expect(Math.atan2(Math.abs(y), -x)).toBeCloseTo(KELVIN_HALF_ANGLE, 12);
    }
    const crestAngles = d.lines
      .filter((l) => l.role === 'main')
      .flatMap((l) => l.points.filter(([x]) => x < 0).map(([x, y]) => Math.atan2(Math.abs(y), -x)));
    expect(Math.max(...crestAngles)).toBeCloseTo(KELVIN_HALF_ANGLE, 3);
  });

  it('spaces the transverse crests 2πU²/g, the wavelength whose phase speed is the boat’s, and follows the speed', () => {
    const d = kelvinDiagram({ boatSpeed: 4 });
    const lambda = mark(d, 'transverse').value;
    const k = (2 * Math.PI) / lambda;
    expect(angularFrequency(k) / k).toBeCloseTo(4, 9);
    expect(mark(kelvinDiagram({ boatSpeed: 8 }), 'transverse').value).toBeCloseTo(4 * lambda, 9);
    expect(mark(kelvinDiagram({ boatSpeed: 8 }), 'transverse').value).not.toBeCloseTo(2 * lambda, 1);
    // At rest there is no wake to draw.
    const still = kelvinDiagram({ boatSpeed: 0 });
    expect(still.lines.filter((l) => l.role === 'main')).toHaveLength(0);
    expect(still.marks.some((m) => m.id === 'transverse')).toBe(false);
  });
});

describe('a stone’s crests', () => {
  it('marks the crests where crestRadii puts the rings on the sea, on crests of the drawn profile', () => {
    const d = cauchyPoissonDiagram(8);
    const radii = crestRadii(8, stoneGuideReach());
    expect(radii.length).toBeGreaterThan(2);
    expect(marks(d, 'crest')).toEqual(radii);
    const profile = d.lines.find((l) => l.role === 'main')!.points;
    for (const r of radii.filter((r) => r >= profile[0][0])) {
      expect(valueAt(profile, r)).toBeGreaterThan(0.95);
      // Half a local wavelength, π/k with k = g t²/(4r²), away lies a trough, not a crest.
      const trough = r + (Math.PI * 4 * r * r) / (9.81 * 64);
      if (trough <= profile[profile.length - 1][0]) expect(valueAt(profile, trough)).toBeLessThan(-0.8);
    }
    // r_n = g t²/(8πn): the outermost drawn crest is a whole n.
    const n = (9.81 * 64) / (8 * Math.PI * radii[0]);
    expect(n).toBeCloseTo(Math.round(n), 9);
  });

  it('moves with time, r ∝ t²; the crests of another moment are not these', () => {
    const early = marks(cauchyPoissonDiagram(8), 'crest');
    const later = marks(cauchyPoissonDiagram(8 * Math.SQRT2), 'crest');
    // Twice t² doubles every r_n; which n fall inside the field's band changes, so compare by n.
    const nOf = (r: number, t: number) => Math.round((9.81 * t * t) / (8 * Math.PI * r));
    const byN = new Map(later.map((r) => [nOf(r, 8 * Math.SQRT2), r]));
    for (const r of early) {
      const twin = byN.get(nOf(r, 8));
      if (twin !== undefined) expect(twin).toBeCloseTo(2 * r, 9);
    }
    expect(later).not.toEqual(early);
    expect(marks(cauchyPoissonDiagram(0), 'crest')).toEqual([]);
    // A second after the fall stationary phase holds nowhere in the field yet: no profile, no crest.
    const early1 = cauchyPoissonDiagram(1);
    expect(early1.lines.filter((l) => l.role === 'main')).toHaveLength(0);
    expect(marks(early1, 'crest')).toEqual([]);
  });
});

describe('Fresnel against Schlick', () => {
  it('marks the largest difference between the exact reflectance and Schlick’s', () => {
    const d = fresnelDiagram();
    let largest = 0;
    for (let a = 0; a <= 90; a += 0.01) {
      const c = Math.cos(a * DEGREE);
      largest = Math.max(largest, Math.abs(fresnelReflectance(c, AIR_IOR, WATER_IOR) - schlickReflectance(c, AIR_IOR, WATER_IOR)));
    }
    expect(mark(d, 'difference').value).toBeCloseTo(largest, 4);
    expect(mark(d, 'normal').value).toBeCloseTo(((WATER_IOR - 1) / (WATER_IOR + 1)) ** 2, 12);
  });

  it('follows the index; glass’s difference is not water’s', () => {
    const glass = fresnelDiagram(AIR_IOR, 1.5);
    expect(mark(glass, 'normal').value).toBeCloseTo(0.04, 9);
    expect(mark(glass, 'difference').value).not.toBeCloseTo(mark(fresnelDiagram(), 'difference').value, 4);
  });
});

describe('defaults stand in for lessons without a preset', () => {
  it('draws from the defaults too', () => {
    expect(() => LESSON_DIAGRAMS.swell(defaultParams(), 0)).not.toThrow();
  });
});
