import { describe, expect, it } from 'vitest';
import {
  criticalAngle,
  fresnelClosedForm,
  fresnelReflectance,
  fresnelTable,
  schlickReflectance,
  WATER_IOR,
} from '../../../../src/sim/optics/fresnel';

const deg = (d: number) => (d * Math.PI) / 180;

describe('Fresnel reflectance, air to water', () => {
  it('is ((n1 − n2)/(n1 + n2))² ≈ 0.0204 at normal incidence', () => {
    expect(fresnelReflectance(1, 1, WATER_IOR)).toBeCloseTo(((1 - 1.333) / (1 + 1.333)) ** 2, 12);
    expect(fresnelReflectance(1, 1, WATER_IOR)).toBeCloseTo(0.0204, 4);
  });

  it('matches the exact s/p equations at several angles', () => {
    // Independent evaluation from the angles themselves (Fresnel's sine/tangent form).
    for (const angle of [10, 30, 45, 60, 75, 85]) {
      const i = deg(angle);
      const t = Math.asin(Math.sin(i) / WATER_IOR);
      const rs = (Math.sin(i - t) / Math.sin(i + t)) ** 2;
      const rp = (Math.tan(i - t) / Math.tan(i + t)) ** 2;
      expect(fresnelReflectance(Math.cos(i), 1, WATER_IOR)).toBeCloseTo((rs + rp) / 2, 10);
    }
  });

  it('has known values: ≈ 0.0279 at 45°, ≈ 0.0597 at 60° and → 1 at grazing', () => {
    expect(fresnelReflectance(Math.cos(deg(45)), 1, WATER_IOR)).toBeCloseTo(0.0279, 3);
    expect(fresnelReflectance(Math.cos(deg(60)), 1, WATER_IOR)).toBeCloseTo(0.0597, 3);
    expect(fresnelReflectance(Math.cos(deg(89.9)), 1, WATER_IOR)).toBeGreaterThan(0.98);
    expect(fresnelReflectance(Math.cos(deg(89.99)), 1, WATER_IOR)).toBeGreaterThan(0.998);
    expect(fresnelReflectance(0, 1, WATER_IOR)).toBe(1);
  });

  it('differs from Schlick in the middle but agrees at the ends', () => {
    expect(schlickReflectance(1, 1, WATER_IOR)).toBeCloseTo(fresnelReflectance(1, 1, WATER_IOR), 12);
    expect(schlickReflectance(0, 1, WATER_IOR)).toBeCloseTo(1, 12);
    expect(
      Math.abs(schlickReflectance(Math.cos(deg(80)), 1, WATER_IOR) - fresnelReflectance(Math.cos(deg(80)), 1, WATER_IOR)),
    ).toBeGreaterThan(0.001);
  });
});

describe("Cook & Torrance's closed form (the glint's facets)", () => {
  it('equals the s/p equations from air into water at every angle; control: n = 1.33 differs', () => {
    let worst = 0;
    let misprint = 0;
    for (let i = 0; i <= 1000; i++) {
      const c = i / 1000;
      worst = Math.max(worst, Math.abs(fresnelClosedForm(c, 1, WATER_IOR) - fresnelReflectance(c, 1, WATER_IOR)));
      misprint = Math.max(misprint, Math.abs(fresnelClosedForm(c, 1, 1.33) - fresnelReflectance(c, 1, WATER_IOR)));
    }
    expect(worst).toBeLessThan(1e-12);
    expect(misprint).toBeGreaterThan(1e-4);
  });
});

describe('Fresnel reflectance, water to air', () => {
  it('is total beyond the critical angle of about 48.6°', () => {
    expect((criticalAngle(WATER_IOR, 1) * 180) / Math.PI).toBeCloseTo(48.61, 2);
    expect(fresnelReflectance(Math.cos(deg(49)), WATER_IOR, 1)).toBe(1);
    expect(fresnelReflectance(Math.cos(deg(48)), WATER_IOR, 1)).toBeLessThan(1);
    expect(fresnelReflectance(1, WATER_IOR, 1)).toBeCloseTo(0.0204, 4);
  });
});

/**
 * Reference values written out independently of src/sim/optics/fresnel.ts: the Fresnel equations in
 * their sine–tangent form (Hecht, Optics, 5th ed., §4.6.2, eqs. 4.42–4.43),
 * Rs = sin²(θi − θt) / sin²(θi + θt), Rp = tan²(θi − θt) / tan²(θi + θt), R = (Rs + Rp) / 2,
 * with sin θt = (n1 / n2) sin θi, evaluated in Python (double precision) for n = 1.333 and
 * rounded to 7 digits. Entry i of a 256-entry table is at cos θ = i / 255.
 */
const FROM_ABOVE: [number, number][] = [
  [0, 1],
  [1, 0.9756162],
  [32, 0.4630947],
  [64, 0.2220939],
  [100, 0.1020273],
  [128, 0.0591519],
  [160, 0.0354576],
  [200, 0.0237266],
  [230, 0.0208973],
  [255, 0.0203732],
];

describe('known values of the exact equations (n = 1.333)', () => {
  it('normal incidence: ((1 − 1.333)/(1 + 1.333))² = 0.0203732', () => {
    expect(fresnelReflectance(1, 1, WATER_IOR)).toBeCloseTo(0.0203732, 7);
    expect(fresnelReflectance(1, WATER_IOR, 1)).toBeCloseTo(0.0203732, 7);
  });

  it("Brewster's angle, atan(1.333) = 53.123°: Rp = 0, so R = Rs / 2 = 0.0782710 / 2", () => {
    expect(fresnelReflectance(Math.cos(deg(53.1232258)), 1, WATER_IOR)).toBeCloseTo(0.0391355, 7);
    // Seen from below, Brewster's angle is atan(1/1.333) = 36.877°, with the same Rs.
    expect(fresnelReflectance(Math.cos(deg(36.8767742)), WATER_IOR, 1)).toBeCloseTo(0.0391355, 7);
  });

  it('critical angle from below, asin(1/1.333) = 48.607°: partial just inside, total just outside', () => {
    expect((criticalAngle(WATER_IOR, 1) * 180) / Math.PI).toBeCloseTo(48.6066, 4);
    expect(fresnelReflectance(Math.cos(deg(48.6)), WATER_IOR, 1)).toBeLessThan(1);
    expect(fresnelReflectance(Math.cos(deg(48.62)), WATER_IOR, 1)).toBe(1);
  });
});

describe('Fresnel table', () => {
  const table = fresnelTable(256);
  it('has 256 entries indexed by cos θ, grazing first, equal to the independently computed values', () => {
    expect(table.length).toBe(256);
    // float32 entries: 6 decimals is within their rounding for values ≤ 1.
    for (const [i, expected] of FROM_ABOVE) expect(table[i], `entry ${i}`).toBeCloseTo(expected, 6);
  });
  it('decreases monotonically from grazing to normal incidence', () => {
    for (let i = 1; i < table.length; i++) expect(table[i]).toBeLessThanOrEqual(table[i - 1]);
  });
});
