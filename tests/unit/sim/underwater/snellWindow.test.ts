import { describe, expect, it } from 'vitest';
import { AIR_IOR, fresnelReflectance, WATER_IOR } from '../../../../src/sim/optics/fresnel';
import {
  classifyNearPlane,
  fresnelTableFromBelow,
  refractDirection,
  refractedSunDirection,
  snellWindowHalfAngle,
} from '../../../../src/sim/underwater/snellWindow';
import { sunDirection } from '../../../../src/sim/optics/sun';

const deg = (d: number) => (d * Math.PI) / 180;
const toDeg = (r: number) => (r * 180) / Math.PI;

describe("Snell's window", () => {
  it('has a half-angle of asin(1/1.333) ≈ 48.6°', () => {
    expect(toDeg(snellWindowHalfAngle())).toBeCloseTo(48.61, 2);
    expect(Math.sin(snellWindowHalfAngle()) * WATER_IOR).toBeCloseTo(1, 12);
  });

  it('maps the whole sky into the window: a grazing ray from the air arrives at the critical angle', () => {
    const grazing = refractDirection([Math.sin(deg(89.999999)), -Math.cos(deg(89.999999)), 0], [0, 1, 0], AIR_IOR / WATER_IOR)!;
    expect(toDeg(Math.acos(-grazing[1]))).toBeCloseTo(toDeg(snellWindowHalfAngle()), 4);
  });

  it('refracts a ray leaving the water just inside the window and reflects one just outside', () => {
    const edge = snellWindowHalfAngle();
    const up = (angle: number): [number, number, number] => [Math.sin(angle), Math.cos(angle), 0];
    expect(refractDirection(up(edge - 1e-4), [0, -1, 0], WATER_IOR / AIR_IOR)).not.toBeNull();
    expect(refractDirection(up(edge + 1e-4), [0, -1, 0], WATER_IOR / AIR_IOR)).toBeNull();
  });
});

describe('Fresnel reflectance from below (water to air)', () => {
  it('equals ((n1 − n2)/(n1 + n2))² ≈ 0.0204 at normal incidence, the same as from above', () => {
    expect(fresnelReflectance(1, WATER_IOR, AIR_IOR)).toBeCloseTo(0.0204, 4);
    expect(fresnelReflectance(1, WATER_IOR, AIR_IOR)).toBeCloseTo(fresnelReflectance(1, AIR_IOR, WATER_IOR), 14);
  });

  it('equals the reflectance from above at the refracted angle (reciprocity) inside the window', () => {
    for (const angle of [10, 20, 30, 40, 45, 48]) {
      const inAir = Math.asin(Math.sin(deg(angle)) * WATER_IOR);
      expect(fresnelReflectance(Math.cos(deg(angle)), WATER_IOR, AIR_IOR)).toBeCloseTo(
        fresnelReflectance(Math.cos(inAir), AIR_IOR, WATER_IOR),
        12,
      );
    }
  });

  it('has known values: ≈ 0.0211 at 20°, ≈ 0.0335 at 35° and rises steeply towards the critical angle', () => {
    // Values of the s/p sine-tangent form at 20° and 35° in water, computed separately (Python, double precision).
    for (const [angle, expected] of [
      [20, 0.02105],
      [35, 0.03348],
    ] as const) {
      const i = deg(angle);
      const t = Math.asin(Math.sin(i) * WATER_IOR);
      const exact = ((Math.sin(i - t) / Math.sin(i + t)) ** 2 + (Math.tan(i - t) / Math.tan(i + t)) ** 2) / 2;
      expect(exact).toBeCloseTo(expected, 4);
      expect(fresnelReflectance(Math.cos(i), WATER_IOR, AIR_IOR)).toBeCloseTo(exact, 12);
    }
    expect(fresnelReflectance(Math.cos(deg(48.5)), WATER_IOR, AIR_IOR)).toBeGreaterThan(0.6);
  });

  it('is total (exactly 1) beyond the critical angle', () => {
    for (const angle of [48.7, 50, 60, 75, 89.9, 90]) {
      expect(fresnelReflectance(Math.cos(deg(angle)), WATER_IOR, AIR_IOR)).toBe(1);
    }
  });

  it('is tabulated by cos θ, total outside the window, equal to independently computed values inside it', () => {
    const table = fresnelTableFromBelow(256);
    // The window's edge, cos 48.607° = 0.66122, falls between entries 168 and 169 (× 255 = 168.61).
    for (let i = 0; i <= 168; i++) expect(table[i], `entry ${i}`).toBe(1);
    // Hecht's sine–tangent form (Optics, 5th ed., §4.6.2) with n1 = 1.333, n2 = 1, evaluated
    // in Python (double precision) at cos θ = i / 255, not with src/sim/optics/fresnel.ts.
    for (const [i, expected] of [
      [169, 0.6895744],
      [170, 0.4982109],
      [180, 0.1430512],
      [200, 0.045421],
      [230, 0.0225805],
      [255, 0.0203732],
    ] as const) {
      expect(table[i], `entry ${i}`).toBeCloseTo(expected, 6);
    }
  });
});

describe('sunlight under a flat sea', () => {
  it("obeys Snell's law: sin θ_air = 1.333 sin θ_water, heading kept", () => {
    for (const elevation of [5, 18, 45, 80]) {
      const sun = sunDirection(elevation, 30);
      const t = refractedSunDirection(sun)!;
      expect(Math.hypot(...t)).toBeCloseTo(1, 12);
      const sinAir = Math.hypot(sun[0], sun[2]);
      const sinWater = Math.hypot(t[0], t[2]);
      expect(sinAir).toBeCloseTo(WATER_IOR * sinWater, 12);
      expect(Math.atan2(-t[0], -t[2])).toBeCloseTo(Math.atan2(sun[0], sun[2]), 12);
      expect(t[1]).toBeLessThan(0);
    }
  });

  it('goes straight down for a sun at the zenith and is absent for a sun below the horizon', () => {
    const t = refractedSunDirection([0, 1, 0])!;
    expect(t[0]).toBeCloseTo(0, 15);
    expect(t[1]).toBeCloseTo(-1, 15);
    expect(refractedSunDirection(sunDirection(-5, 0))).toBeNull();
  });
});

describe('classifyNearPlane', () => {
  it('is above or below only when every point clears the surface by the margin on that side', () => {
    expect(
      classifyNearPlane(
        [
          { y: 1, surface: 0.5 },
          { y: 2, surface: 0 },
        ],
        0.25,
      ),
    ).toBe('above');
    expect(
      classifyNearPlane(
        [
          { y: -1, surface: 0.5 },
          { y: -2, surface: 0 },
        ],
        0.25,
      ),
    ).toBe('below');
    expect(
      classifyNearPlane(
        [
          { y: 1, surface: 0.9 },
          { y: 2, surface: 0 },
        ],
        0.25,
      ),
    ).toBe('straddling');
    expect(
      classifyNearPlane(
        [
          { y: 1, surface: 0 },
          { y: -1, surface: 0 },
        ],
        0.25,
      ),
    ).toBe('straddling');
    expect(() => classifyNearPlane([], 0.25)).toThrow(RangeError);
  });
});
