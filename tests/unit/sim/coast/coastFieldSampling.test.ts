import { describe, expect, it } from 'vitest';
import { BEACH_SHORE_X, OFFSHORE_DEPTH } from '../../../../src/sim/coast/bathymetry';
import type { CoastField, CoastSetting } from '../../../../src/sim/coast/coastField';
import { coastSwellDisplacement, coastSwellHeight, coastSwellNormal, sampleCoastField } from '../../../../src/sim/coast/coastFieldSampling';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { waveNumber } from '../../../../src/sim/waves/dispersion';
import { regularSwell } from '../../../../src/sim/coast/swellSpectrum';
import { TEST_BEACH } from '../../../support/coastSurface';

const SETTING = TEST_BEACH;
const OMEGA = (2 * Math.PI) / SETTING.swellPeriod;
const THETA0 = (SETTING.swellDirection * Math.PI) / 180;

/** One regular wave train, whose phase and amplitude these tests read. */
const build = (setting: Partial<CoastSetting> = {}, resolution = 256): CoastField => {
  const full = { ...SETTING, ...setting };
  const field = buildCoastField(full, resolution, undefined, regularSwell(full));
  if (!field) throw new Error('a beach has a field');
  return field;
};
const FIELD = build();
const texel = (field: CoastField, i: number, j: number, channel: number): number =>
  field.components[0].texels[(j * field.resolution + i) * 2 + channel];
const centre = (field: CoastField, i: number, j: number): [number, number] => [
  field.originX + i * field.spacing,
  field.originZ + j * field.spacing,
];

describe('sampling reads the grid as a LINEAR-filtered texture does', () => {
  it('returns the texel at its centre, and the mean of four texels midway between their centres', () => {
    const [x, z] = centre(FIELD, 120, 40);
    expect(sampleCoastField(FIELD, x, z).phase).toBe(texel(FIELD, 120, 40, 0));
    const middle = sampleCoastField(FIELD, x + FIELD.spacing / 2, z + FIELD.spacing / 2);
    const mean = (texel(FIELD, 120, 40, 1) + texel(FIELD, 121, 40, 1) + texel(FIELD, 120, 41, 1) + texel(FIELD, 121, 41, 1)) / 4;
    expect(middle.amplitude).toBeCloseTo(mean, 6);
  });

  it('a sampler that puts texel centres on the corners (a half-texel shift) disagrees (negative control)', () => {
    const [x, z] = centre(FIELD, 120, 40);
    expect(Math.abs(sampleCoastField(FIELD, x - FIELD.spacing / 2, z).phase - texel(FIELD, 120, 40, 0))).toBeGreaterThan(0.1);
  });

  it('the deep sea has no field: buildCoastField returns null', () => {
    expect(buildCoastField({ ...SETTING, bathymetry: 'deep' })).toBeNull();
  });
});

describe('beyond the grid the offshore plane wave continues the edge', () => {
  const side = (FIELD.resolution - 1) * FIELD.spacing;
  const k0 = waveNumber(OMEGA, OFFSHORE_DEPTH);

  it('offshore of the grid the phase grows at k0 cos θ0 along x and k0 sin θ0 along z, amplitude unchanged', () => {
    const x = FIELD.originX - 500;
    const a = sampleCoastField(FIELD, x, 0);
    const b = sampleCoastField(FIELD, x + 10, 0);
    const c = sampleCoastField(FIELD, x, 10);
    expect((b.phase - a.phase) / 10).toBeCloseTo(k0 * Math.cos(THETA0), 5);
    expect((c.phase - a.phase) / 10).toBeCloseTo(k0 * Math.sin(THETA0), 5);
    expect(a.amplitude).toBeCloseTo(SETTING.swellHeight / 2, 5);
  });

  it('along the shore beyond the grid the beach goes on: phase continuous across the edge, k_z unchanged', () => {
    const x = BEACH_SHORE_X - 200;
    const edge = FIELD.originZ + side;
    const inside = sampleCoastField(FIELD, x, edge - 0.01);
    const outside = sampleCoastField(FIELD, x, edge + 0.01);
    expect(Math.abs(outside.phase - inside.phase)).toBeLessThan(0.01);
    const far = sampleCoastField(FIELD, x, edge + 3000);
    expect((far.phase - inside.phase) / 3000).toBeCloseTo(k0 * Math.sin(THETA0), 4);
    expect(far.amplitude).toBeCloseTo(inside.amplitude, 5);
  });

  it('a continuation that restarts the phase at 0 beyond the edge would jump (negative control)', () => {
    const edge = FIELD.originZ + side;
    expect(Math.abs(sampleCoastField(FIELD, BEACH_SHORE_X - 200, edge).phase)).toBeGreaterThan(1);
  });
});

/** ∫ k_x dx from x0 to x1 across the beach, by Simpson's rule on steps of at most 0.5 m. */
function phaseIntegral(x0: number, x1: number, slope: number): number {
  const kz = waveNumber(OMEGA, OFFSHORE_DEPTH) * Math.sin(THETA0);
  const kx = (at: number): number => {
    const k = waveNumber(OMEGA, Math.min(OFFSHORE_DEPTH, Math.max(0.1, (BEACH_SHORE_X - at) * slope)));
    return Math.sqrt(k * k - kz * kz);
  };
  const steps = 2 * Math.ceil((x1 - x0) / 1);
  const h = (x1 - x0) / steps;
  let sum = kx(x0) + kx(x1);
  for (let s = 1; s < steps; s++) sum += (s % 2 ? 4 : 2) * kx(x0 + s * h);
  return (sum * h) / 3;
}

/** The largest |S_bilinear − S_exact| at cell midpoints across the shore (z = 0), where the water is deeper than `shallowest`. */
function bilinearPhaseError(field: CoastField, slope: number, shallowest: number): number {
  let worst = 0;
  let x = field.originX;
  let exact = 0;
  for (let i = 0; i < field.resolution - 1; i++) {
    const next = field.originX + (i + 0.5) * field.spacing;
    if ((BEACH_SHORE_X - next) * slope < shallowest) break;
    exact += phaseIntegral(x, next, slope);
    x = next;
    worst = Math.max(worst, Math.abs(sampleCoastField(field, x, 0).phase - exact));
  }
  return worst;
}

describe("the bilinear error of the phase (S's curvature times spacing² / 8)", () => {
  it('stays under 0.05 rad deeper than 1 m, for slope 0.02 at 256² and slope 0.005 at 512²', () => {
    expect(bilinearPhaseError(FIELD, 0.02, 1)).toBeLessThan(0.05);
    expect(bilinearPhaseError(build({ beachSlope: 0.005 }, 512), 0.005, 1)).toBeLessThan(0.05);
  });

  it('a 64² grid on the gentle slope is too coarse and fails the bound (negative control)', () => {
    expect(bilinearPhaseError(build({ beachSlope: 0.005 }, 64), 0.005, 1)).toBeGreaterThan(0.05);
  });
});

describe('the surface of one component: a vertical swell η = a cos(S − ω t)', () => {
  const x = BEACH_SHORE_X - 300;

  it('the displacement is vertical, equals the height, and repeats after one period', () => {
    const [dx, dy, dz] = coastSwellDisplacement(FIELD, x, 7, 3.3);
    expect([dx, dz]).toEqual([0, 0]);
    expect(dy).toBe(coastSwellHeight(FIELD, x, 7, 3.3));
    expect(coastSwellHeight(FIELD, x, 7, 3.3 + SETTING.swellPeriod)).toBeCloseTo(dy, 9);
  });

  it('the normal leans against the slope: n ≈ (a k_x sin φ, 1, a k_z sin φ), normalised', () => {
    for (const time of [0, 2, 4.5]) {
      const sample = sampleCoastField(FIELD, x, 0);
      const phi = sample.phase - OMEGA * time;
      const k = waveNumber(OMEGA, sample.depth);
      const kz = waveNumber(OMEGA, OFFSHORE_DEPTH) * Math.sin(THETA0);
      const kx = Math.sqrt(k * k - kz * kz);
      const expected = [sample.amplitude * kx * Math.sin(phi), 1, sample.amplitude * kz * Math.sin(phi)];
      const length = Math.hypot(...expected);
      const normal = coastSwellNormal(FIELD, x, 0, time);
      for (let c = 0; c < 3; c++) expect(normal[c]).toBeCloseTo(expected[c] / length, 2);
    }
  });

  it('the normal a quarter period later differs (negative control)', () => {
    const now = coastSwellNormal(FIELD, x, 0, 1);
    const later = coastSwellNormal(FIELD, x, 0, 1 + SETTING.swellPeriod / 4);
    expect(Math.abs(now[0] - later[0])).toBeGreaterThan(0.01);
  });
});
