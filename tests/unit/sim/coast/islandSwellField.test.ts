import { describe, expect, it } from 'vitest';
import { ISLAND_CENTER, ISLAND_RADIUS, OFFSHORE_DEPTH } from '../../../../src/sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../../../src/sim/coast/coastField';
import { sampleCoastField } from '../../../../src/sim/coast/coastFieldSampling';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { type CoastWaveModel, LINEAR_THEORY } from '../../../../src/sim/coast/coastWaveModel';
import { MCCOWAN_BREAKER_INDEX } from '../../../../src/sim/coast/waveTransformation';
import { GRAVITY, groupVelocity, waveNumber } from '../../../../src/sim/waves/dispersion';
import { regularSwell } from '../../../../src/sim/coast/swellSpectrum';
import { heightOverPeriod, phaseGradient } from '../../../support/coastSurface';

const SETTING: CoastSetting = {
  bathymetry: 'island',
  beachSlope: 0.05,
  deepDepth: OFFSHORE_DEPTH,
  swellHeight: 1,
  swellPeriod: 10,
  swellDirection: 0,
  seed: 1,
};
const OMEGA = (2 * Math.PI) / SETTING.swellPeriod;
const REACH = ISLAND_RADIUS + OFFSHORE_DEPTH / SETTING.beachSlope;

const DEEP_WATER_ONLY: CoastWaveModel = {
  waveNumber: (omega) => (omega * omega) / GRAVITY,
  groupVelocity: (k) => 0.5 * Math.sqrt(GRAVITY / k),
  breakerIndex: MCCOWAN_BREAKER_INDEX,
};

const build = (setting: Partial<CoastSetting> = {}, model: CoastWaveModel = LINEAR_THEORY): CoastField => {
  const full = { ...SETTING, ...setting };
  const field = buildCoastField(full, 256, model, regularSwell(full));
  if (!field) throw new Error('an island has a field');
  return field;
};
const FIELD = build();

/** Points on rings round the island, in water deeper than 3 m, outside the lee's sector (±30° downstream). */
function ringPoints(field: CoastField, directionDeg: number): [number, number][] {
  const points: [number, number][] = [];
  for (const radius of [200, 300, 600, 900, 1300]) {
    for (let angle = 0; angle < 360; angle += 10) {
      const fromDownstream = Math.abs(((angle - directionDeg + 540) % 360) - 180);
      if (fromDownstream < 30) continue;
      const x = ISLAND_CENTER[0] + radius * Math.cos((angle * Math.PI) / 180);
      const z = ISLAND_CENTER[1] + radius * Math.sin((angle * Math.PI) / 180);
      if (sampleCoastField(field, x, z).depth > 3) points.push([x, z]);
    }
  }
  return points;
}

/** |∇S| / k(h) − 1 at each point, ∇S by central differences of the sampled phase, one texel either side. */
const eikonalResiduals = (field: CoastField, points: [number, number][]): number[] =>
  points.map(
    ([x, z]) => Math.hypot(...phaseGradient(field, x, z, field.spacing)) / waveNumber(OMEGA, sampleCoastField(field, x, z).depth) - 1,
  );

describe('island: the phase solves the eikonal equation |∇S| = k(h)', () => {
  for (const direction of [0, 30]) {
    it(`the residual is under 2 % on average and 6 % at worst, outside the lee (swell at ${direction}°)`, () => {
      const field = direction === 0 ? FIELD : build({ swellDirection: direction });
      const residuals = eikonalResiduals(field, ringPoints(field, direction)).map(Math.abs);
      expect(residuals.length).toBeGreaterThan(100);
      expect(residuals.reduce((a, b) => a + b, 0) / residuals.length).toBeLessThan(0.02);
      expect(Math.max(...residuals)).toBeLessThan(0.06);
    });
  }

  it('a field built with deep-water dispersion fails the residual in the shallows (negative control)', () => {
    const field = build({}, DEEP_WATER_ONLY);
    const residuals = eikonalResiduals(field, ringPoints(field, 0)).map(Math.abs);
    expect(Math.max(...residuals)).toBeGreaterThan(0.06);
  });
});

describe('island: the waves wrap round it', () => {
  const LEE_X = ISLAND_CENTER[0] + ISLAND_RADIUS + 150;

  it('behind the island the surface rises and falls, over 40 % of the offshore height', () => {
    for (const z of [-60, 0, 60]) expect(heightOverPeriod(FIELD, LEE_X, z)).toBeGreaterThan(0.4 * SETTING.swellHeight);
  });

  /** The largest change of phase between samples 1 m apart across the lee, in units of k(h) · 1 m. */
  const largestPhaseStep = (field: CoastField): number => {
    let largest = 0;
    for (let z = -400; z < 400; z += 1) {
      const here = sampleCoastField(field, LEE_X, z);
      const step = Math.abs(sampleCoastField(field, LEE_X, z + 1).phase - here.phase);
      largest = Math.max(largest, step / waveNumber(OMEGA, Math.max(0.1, here.depth)));
    }
    return largest;
  };

  it('the phase across the lee is continuous: over 1 m it changes by at most 1.5 k(h) · 1 m', () => {
    expect(largestPhaseStep(FIELD)).toBeLessThan(1.5);
  });

  it('the same checks fail on land and on a field with a planted phase step (negative controls)', () => {
    expect(heightOverPeriod(FIELD, ISLAND_CENTER[0], ISLAND_CENTER[1])).toBe(0);
    const texels = FIELD.components[0].texels.slice();
    const stepped = { ...FIELD, components: [{ ...FIELD.components[0], texels }] };
    for (let t = 0; t < texels.length; t += 2) {
      const z = stepped.originZ + Math.floor(t / 2 / stepped.resolution) * stepped.spacing;
      if (z > 0) texels[t] += Math.PI;
    }
    expect(largestPhaseStep(stepped)).toBeGreaterThan(1.5);
  });
});

/**
 * Follows a ray tube of the drawn field: two orthogonal trajectories of the phase (along ∇S)
 * that start `width` metres apart upstream, the second kept on the first's crest. Returns the
 * energy flux a² c_g b along the tube, relative to its start, until the tube nears breaking or
 * passes the island's centre line; `fixedWidth` plants the fault of ignoring the tube's width.
 */
function tubeFluxes(field: CoastField, offset: number, fixedWidth = false): number[] {
  const width = 20;
  let a: [number, number] = [ISLAND_CENTER[0] - 1.05 * REACH, ISLAND_CENTER[1] + offset];
  let b: [number, number] = [a[0], a[1] + width];
  const along = (point: [number, number], distance: number): [number, number] => {
    const gradient = phaseGradient(field, point[0], point[1], 1);
    const length = Math.hypot(...gradient);
    return [point[0] + (distance * gradient[0]) / length, point[1] + (distance * gradient[1]) / length];
  };
  const fluxes: number[] = [];
  for (let s = 0; s < 2000; s++) {
    a = along(a, 2);
    const phase = sampleCoastField(field, a[0], a[1]).phase;
    for (let i = 0; i < 4; i++) {
      const gradient = Math.hypot(...phaseGradient(field, b[0], b[1], 1));
      b = along(b, (phase - sampleCoastField(field, b[0], b[1]).phase) / gradient);
    }
    const middle = sampleCoastField(field, 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
    if (middle.breaking > 0 || middle.depth < 1 || a[0] > ISLAND_CENTER[0]) break;
    const tube = fixedWidth ? width : Math.hypot(a[0] - b[0], a[1] - b[1]);
    fluxes.push(middle.amplitude ** 2 * groupVelocity(waveNumber(OMEGA, middle.depth), middle.depth) * tube);
  }
  return fluxes.map((flux) => flux / fluxes[0]);
}

describe('island: energy flux along a ray tube is kept before breaking', () => {
  const OFFSETS = [0.15, 0.3, 0.6, 0.9, -0.5].map((fraction) => fraction * REACH);

  it('a² c_g b stays within 15 % of its offshore value along five tubes', () => {
    for (const offset of OFFSETS) {
      const fluxes = tubeFluxes(FIELD, offset);
      expect(fluxes.length, `tube at ${offset.toFixed(0)} m`).toBeGreaterThan(100);
      for (const flux of fluxes) expect(Math.abs(flux - 1), `tube at ${offset.toFixed(0)} m`).toBeLessThan(0.15);
    }
  });

  it('ignoring the tube width (a planted fault) breaks the balance where rays bend (negative control)', () => {
    const worst = Math.max(...OFFSETS.flatMap((offset) => tubeFluxes(FIELD, offset, true).map((flux) => Math.abs(flux - 1))));
    expect(worst).toBeGreaterThan(0.15);
  });
});
