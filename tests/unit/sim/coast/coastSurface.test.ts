import { describe, expect, it } from 'vitest';
import { CoastSurface, swellBound } from '../../../../src/sim/coast/coastSurface';
import { buildCoastField } from '../../../../src/sim/coast/coastSwellField';
import { coastSwellHeight } from '../../../../src/sim/coast/coastFieldSampling';
import { BEACH_SHORE_X, seaDepth, type SeaFloor } from '../../../../src/sim/coast/bathymetry';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import { GerstnerLiveModel } from '../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import type { LiveWaveModel } from '../../../../src/sim/waves/waveModel';
import { defaultParams } from '../../../../src/sim/params/params';
import { BREAKER_INDEX } from '../../../../src/sim/coast/windSeaDamping';
import { seededRandom } from '../../../../src/sim/noise/integerHash';

const floor: SeaFloor = { bathymetry: 'beach', beachSlope: 0.02, deepDepth: 1000 };
const field = buildCoastField({ ...floor, swellHeight: 1.5, swellPeriod: 10, swellDirection: 10, seed: 1 }, 128)!;
/** The seed's sea (sines and Perlin ripples) as the wind sea. */
const wind = (): LiveWaveModel => new SeedWaveModel(defaultParams());

describe('the CPU twin at the coast', () => {
  it('is the swell alone with the wind sea off', () => {
    const surface = new CoastSurface(wind(), field, floor, false);
    for (const [x, z, t] of [
      [0, 0, 3],
      [300, -40, 7.5],
      [380, 12, 100],
    ])
      expect(surface.sample(x, z, t).height).toBeCloseTo(coastSwellHeight(field, x, z, t), 12);
  });

  it('adds the whole wind sea where the water is deep, and none on land', () => {
    const model = wind();
    const surface = new CoastSurface(model, field, floor, true);
    const deep = [-2000, 30, 4] as const;
    expect(surface.height(...deep)).toBeCloseTo(model.height(...deep) + coastSwellHeight(field, ...deep), 12);
    const land = [BEACH_SHORE_X + 30, 0, 4] as const;
    expect(surface.height(...land)).toBeCloseTo(coastSwellHeight(field, ...land), 12);
  });

  it('limits the wind sea to γ h in the shallows', () => {
    const model = wind();
    const surface = new CoastSurface(model, field, floor, true);
    const height = 2 * model.bounds().vertical;
    const [x, z, t] = [BEACH_SHORE_X - 100, 0, 4];
    const factor = (BREAKER_INDEX * seaDepth(floor, x, z)) / height;
    expect(factor).toBeLessThan(1);
    expect(surface.height(x, z, t) - coastSwellHeight(field, x, z, t)).toBeCloseTo(factor * model.height(x, z, t), 12);
  });

  it('gives a unit normal that leans against the swell’s slope', () => {
    const surface = new CoastSurface(wind(), field, floor, false);
    const [x, z, t] = [100, 0, 2];
    const { normal } = surface.sample(x, z, t);
    expect(Math.hypot(...normal)).toBeCloseTo(1, 12);
    const slope = (coastSwellHeight(field, x + 0.01, z, t) - coastSwellHeight(field, x - 0.01, z, t)) / 0.02;
    expect(-normal[0] / normal[1]).toBeCloseTo(slope, 3);
  });

  it('grows the culling bounds by the swell’s largest height', () => {
    const model = wind();
    const surface = new CoastSurface(model, field, floor, true);
    expect(swellBound(field)).toBeGreaterThan(0.75);
    expect(surface.bounds().vertical).toBeCloseTo(model.bounds().vertical + swellBound(field), 12);
  });

  it('the swell’s bound holds: no |η| at 4000 seeded points and times over the beach exceeds it', () => {
    const random = seededRandom(4902);
    const span = field.spacing * (field.resolution - 1);
    let largest = 0;
    for (let s = 0; s < 4000; s++) {
      const x = field.originX - 0.1 * span + random() * 1.2 * span;
      const z = field.originZ + random() * span;
      largest = Math.max(largest, Math.abs(coastSwellHeight(field, x, z, random() * 1000)));
    }
    expect(largest).toBeLessThanOrEqual(swellBound(field));
    // Control: one component's largest amplitude, a regular train's bound, is no bound for their sum.
    let oneComponent = 0;
    for (const component of field.components)
      for (let t = 1; t < component.texels.length; t += 2) oneComponent = Math.max(oneComponent, component.texels[t]);
    expect(largest).toBeGreaterThan(oneComponent);
  });

  it('negative control: the wind sea on changes the answer where the water is deep', () => {
    const on = new CoastSurface(wind(), field, floor, true);
    const off = new CoastSurface(wind(), field, floor, false);
    expect(Math.abs(on.height(-2000, 30, 4) - off.height(-2000, 30, 4))).toBeGreaterThan(1e-3);
  });
});

describe('the wind sea’s sideways motion at the coast', () => {
  /** Gerstner's trochoids, whose points move sideways as much as up, as the wind sea. */
  const gerstner = (): LiveWaveModel => new GerstnerLiveModel({ ...defaultParams(), windSpeed: 14 });

  it('is calmed with its height: none on land, f D in the shallows (control: the model alone moves the sand)', () => {
    const model = gerstner();
    const surface = new CoastSurface(model, field, floor, true);
    const land = [BEACH_SHORE_X + 30, 5, 4] as const;
    expect(Math.hypot(model.displacement(...land)[0], model.displacement(...land)[2])).toBeGreaterThan(0.1);
    const [dx, , dz] = surface.displacement(...land);
    expect(Math.hypot(dx, dz)).toBe(0);
    const shallow = [BEACH_SHORE_X - 60, 5, 4] as const;
    const f = surface.windFactor(shallow[0], shallow[1]);
    expect(f).toBeGreaterThan(0);
    expect(f).toBeLessThan(1);
    expect(surface.displacement(...shallow)[0]).toBeCloseTo(f * model.displacement(...shallow)[0], 12);
  });

  it('the height above where a calmed grid point lands is that point’s height, in the shallows and offshore', () => {
    const surface = new CoastSurface(gerstner(), field, floor, true);
    const random = seededRandom(77);
    let worst = 0;
    for (let s = 0; s < 200; s++) {
      const [x, z, t] = [BEACH_SHORE_X - 5 - random() * 400, random() * 200, random() * 50];
      const [dx, dy, dz] = surface.displacement(x, z, t);
      worst = Math.max(worst, Math.abs(surface.height(x + dx, z + dz, t) - dy));
    }
    expect(worst).toBeLessThan(1e-3);
    // Control: the same question asked of the uncalmed landing point misses in the shallows.
    const [x, z, t] = [BEACH_SHORE_X - 40, 3, 6];
    const raw = gerstner().displacement(x, z, t);
    expect(Math.abs(surface.height(x + raw[0], z + raw[2], t) - surface.displacement(x, z, t)[1])).toBeGreaterThan(1e-3);
  });
});
