import { gerstnerWavesFor, type GerstnerSeaParams } from '../../waves/gerstner/gerstnerLiveModel';
import { gerstnerDisplacementAt, gerstnerTimePhases, type GerstnerWave } from '../../waves/gerstner/gerstnerWaves';
import { sampled, type Diagram, type Point } from './diagram';

/** The Gerstner sea's tallest wave: the one whose orbit the diagram draws. */
export function dominantGerstnerWave(params: GerstnerSeaParams): GerstnerWave {
  return gerstnerWavesFor(params).reduce((a, b) => (b.amplitude > a.amplitude ? b : a));
}

/** Depths of the orbits drawn below the surface, in wavelengths. */
export const ORBIT_DEPTHS = [0.125, 0.25, 0.5] as const;

/**
 * One wavelength of the tallest wave in profile: Gerstner's trochoid and Airy's sine, the
 * orbit a surface particle runs under each (Gerstner's ellipse, QA across and A up, from
 * gerstnerDisplacementAt over one period; Airy's circle of radius A), and Airy's orbits
 * below, radius A e^{kz}. The heights are exaggerated by `exaggeration` so that a 50 m wave
 * 1 m high is seen; the depths are not.
 */
export function orbitDiagram(params: GerstnerSeaParams): Diagram {
  const wave = dominantGerstnerWave(params);
  const turnsPerMetre = Math.hypot(wave.cx, wave.cz);
  const k = 2 * Math.PI * turnsPerMetre;
  const wavelength = 1 / turnsPerMetre;
  const [ux, uz] = [wave.cx / turnsPerMetre, wave.cz / turnsPerMetre];
  const exaggeration = (0.08 * wavelength) / wave.amplitude;
  // Grid point s metres along the wave's direction, displaced, in (along, up), heights exaggerated.
  const displaced = (s: number, time: number): Point => {
    const [dx, dy, dz] = gerstnerDisplacementAt([wave], gerstnerTimePhases([wave], time), s * ux, s * uz);
    return [s + exaggeration * (dx * ux + dz * uz), exaggeration * dy];
  };
  const period = (2 * Math.PI) / wave.omega;
  const centre = wavelength / 2;
  const trochoid = sampled(0, wavelength, 120, (s) => displaced(s, 0));
  const airyPhase = (s: number) => 2 * Math.PI * (wave.cx * s * ux + wave.cz * s * uz + wave.phase);
  const sine = sampled(0, wavelength, 120, (s) => [s, exaggeration * wave.amplitude * Math.cos(airyPhase(s))]);
  const gerstnerOrbit = sampled(0, period, 72, (t) => {
    const [x, y] = displaced(centre, t);
    return [x, y];
  });
  const circle = (cy: number, r: number) => sampled(0, 2 * Math.PI, 72, (a) => [centre + r * Math.cos(a), cy + r * Math.sin(a)]);
  const airyRadius = (depth: number) => wave.amplitude * Math.exp(-k * depth);
  const deepest = ORBIT_DEPTHS[ORBIT_DEPTHS.length - 1] * wavelength;
  const top = exaggeration * wave.amplitude * 1.6;
  return {
    kind: 'orbit',
    x: [0, wavelength],
    y: [-deepest - exaggeration * wave.amplitude * 1.3, top],
    equalScale: true,
    lines: [
      { role: 'second', points: sine },
      { role: 'main', points: trochoid },
      { role: 'second', points: circle(0, exaggeration * wave.amplitude) },
      { role: 'main', points: gerstnerOrbit },
      ...ORBIT_DEPTHS.map((d) => ({ role: 'faint' as const, points: circle(-d * wavelength, exaggeration * airyRadius(d * wavelength)) })),
    ],
    marks: [
      { id: 'steepness', x: centre + exaggeration * wave.horizontal, y: 0, value: wave.horizontal / wave.amplitude, unit: '' },
      { id: 'wavelength', x: 0.02 * wavelength, y: top * 0.55, value: wavelength, unit: 'm', bare: true },
      { id: 'amplitude', x: centre, y: exaggeration * wave.amplitude, value: wave.amplitude, unit: 'm' },
      ...ORBIT_DEPTHS.map((d, index) => ({
        id: 'decay',
        x: centre,
        y: -d * wavelength,
        value: (100 * airyRadius(d * wavelength)) / wave.amplitude,
        unit: '%',
        index,
      })),
      {
        id: 'exaggeration',
        x: 0.02 * wavelength,
        y: -deepest - exaggeration * wave.amplitude * 0.9,
        value: exaggeration,
        unit: '×',
        bare: true,
      },
    ],
    headline: 'steepness',
  };
}
