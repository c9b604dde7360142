import { describe, expect, it } from 'vitest';
import {
  beckmannSlopeDensity,
  complementaryErrorFunction,
  glintPerIrradiance,
  smithLambda,
  smithLambdaRational,
} from '../../../../src/sim/optics/beckmannGlint';

/** ∫∫ p(ζx, ζz) dζx dζz over a square of ±limit slopes, midpoint rule. */
function integrateDensity(density: (s2: number) => number, limit = 2, steps = 800): number {
  const h = (2 * limit) / steps;
  let sum = 0;
  for (let i = 0; i < steps; i++) {
    for (let j = 0; j < steps; j++) {
      const x = -limit + (i + 0.5) * h;
      const z = -limit + (j + 0.5) * h;
      sum += density(x * x + z * z);
    }
  }
  return sum * h * h;
}

describe('Beckmann slope density', () => {
  it('integrates to 1 and peaks at Cox–Munk’s 1/(2π σ_u σ_c) with σ_u² = σ_c² = σ²/2; control: 1/(2π σ²) fails', () => {
    for (const variance of [0.0286, 0.0542, 0.0798]) {
      expect(integrateDensity((s2) => beckmannSlopeDensity(s2, variance))).toBeCloseTo(1, 4);
      expect(beckmannSlopeDensity(0, variance)).toBeCloseTo(1 / (2 * Math.PI * (variance / 2)), 10);
      const wrong = (s2: number) => Math.exp(-s2 / variance) / (2 * Math.PI * variance);
      expect(Math.abs(integrateDensity(wrong) - 1)).toBeGreaterThan(0.4);
    }
  });

  it('has a standard deviation of slope √(σ²/2) along each axis', () => {
    const variance = 0.05;
    const limit = 2;
    const steps = 800;
    const h = (2 * limit) / steps;
    let second = 0;
    for (let i = 0; i < steps; i++) {
      for (let j = 0; j < steps; j++) {
        const x = -limit + (i + 0.5) * h;
        const z = -limit + (j + 0.5) * h;
        second += x * x * beckmannSlopeDensity(x * x + z * z, variance) * h * h;
      }
    }
    expect(second).toBeCloseTo(variance / 2, 5);
  });
});

describe('Smith shadowing of a Beckmann surface', () => {
  it('erfc has its tabulated values (A&S table 7.1)', () => {
    expect(complementaryErrorFunction(0)).toBeCloseTo(1, 6);
    expect(complementaryErrorFunction(0.5)).toBeCloseTo(0.4795001, 6);
    expect(complementaryErrorFunction(1)).toBeCloseTo(0.1572992, 6);
    expect(complementaryErrorFunction(2)).toBeCloseTo(0.004677735, 6);
  });

  // Control: ν without the √2 fails.
  it('Λ(ν = 1) = (e⁻¹/√π − erfc 1)/2 = 0.02513, vanishes seen from above, grows at grazing', () => {
    // ν = cot θ / √(2 σ²_dir) = 1 with σ²_dir = 0.02 and cot θ = 0.2.
    const cos = 0.2 / Math.sqrt(1 + 0.04);
    expect(smithLambda(cos, 0.02)).toBeCloseTo(0.02513, 4);
    expect(smithLambda(0.999, 0.02)).toBeLessThan(1e-12);
    expect(smithLambda(0.05, 0.02)).toBeGreaterThan(smithLambda(0.2, 0.02));
    const nu = 0.2 / Math.sqrt(0.02);
    const wrong = (Math.exp(-nu * nu) / (nu * Math.sqrt(Math.PI)) - complementaryErrorFunction(nu)) / 2;
    expect(wrong).not.toBeCloseTo(0.02513, 3);
  });
});

describe("Walter et al.'s rational Λ", () => {
  /** The largest difference of the shadowing factor 1 / (1 + Λ) from the exact one, ν from 0.01 to 5. */
  function worstShadowingError(lambda: (cosTheta: number, directionalVariance: number) => number): number {
    let worst = 0;
    for (let nu = 0.01; nu <= 5; nu += 0.001) {
      // ν = cot θ / √(2 σ²_dir) with σ²_dir = 0.5: cot θ = ν.
      const cos = nu / Math.sqrt(1 + nu * nu);
      worst = Math.max(worst, Math.abs(1 / (1 + lambda(cos, 0.5)) - 1 / (1 + smithLambda(cos, 0.5))));
    }
    return worst;
  }

  it('shadows within 0.004 of the exact Λ at every angle (measured 0.0031); control: 1.059 for 1.259 misses by 0.02', () => {
    expect(worstShadowingError(smithLambdaRational)).toBeLessThan(0.004);
    const misprint = (cosTheta: number, directionalVariance: number) => {
      const nu = cosTheta / Math.sqrt((1 - cosTheta * cosTheta) * 2 * directionalVariance);
      return nu < 1.6 ? (1 - 1.059 * nu + 0.396 * nu * nu) / (3.535 * nu + 2.181 * nu * nu) : 0;
    };
    expect(worstShadowingError(misprint)).toBeGreaterThan(0.02);
  });
});

describe('the glint', () => {
  const up = [0, 1, 0] as const;
  /** Directional–hemispherical reflectance per unit Fresnel: ∫ f cos θ_v dω_v, for a sun at `elevation`. */
  function albedo(elevationDeg: number, variance: number, glint = glintPerIrradiance): number {
    const e = (elevationDeg * Math.PI) / 180;
    const sun = [Math.cos(e), Math.sin(e), 0] as const;
    const steps = 600;
    let sum = 0;
    for (let i = 0; i < steps; i++) {
      const theta = ((i + 0.5) / steps) * (Math.PI / 2);
      for (let j = 0; j < steps; j++) {
        const phi = ((j + 0.5) / steps) * 2 * Math.PI;
        const view = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)] as const;
        // The BRDF is radiance per irradiance on the mean surface: cos θ_l E per unit E_sun normal to the sun.
        sum += (glint(sun, view, up, variance) / Math.sin(e)) * Math.cos(theta) * Math.sin(theta);
      }
    }
    return sum * (Math.PI / 2 / steps) * ((2 * Math.PI) / steps) * Math.sin(e);
  }

  it('reflects what it receives (∫ f cos θ dω ≈ 1 per unit F) for a high sun; control: without the 4 it reflects 4×', () => {
    const a = albedo(70, 0.03);
    expect(a).toBeGreaterThan(0.93);
    expect(a).toBeLessThan(1.02);
    const withoutFour = (
      l: readonly [number, number, number],
      v: readonly [number, number, number],
      n: readonly [number, number, number],
      s: number,
    ) => 4 * glintPerIrradiance(l, v, n, s);
    expect(albedo(70, 0.03, withoutFour)).toBeGreaterThan(3.5);
  });

  it('its width grows with σ: 15 m/s against 5 m/s is √(0.0798/0.0286) = 1.67 in slope, more in view angle', () => {
    // Seen from above with the sun overhead, the slope density falls to e⁻¹ where the half
    // vector's slope is σ: the view has turned by 2 arctan σ. The BRDF's 1/(cos θ_v cos⁴θ_h)
    // widens it a little more the wider it is: 1.85 instead of 1.67 in view angle.
    const halfWidth = (variance: number) => {
      const sun = [0, 1, 0] as const;
      const peak = glintPerIrradiance(sun, sun, up, variance);
      let lo = 0;
      let hi = 1;
      for (let i = 0; i < 60; i++) {
        const mid = (lo + hi) / 2;
        const view = [Math.sin(mid), Math.cos(mid), 0] as const;
        if (glintPerIrradiance(sun, view, up, variance) > peak / Math.E) lo = mid;
        else hi = mid;
      }
      return lo;
    };
    const ratio = halfWidth(0.0798) / halfWidth(0.0286);
    expect(ratio).toBeGreaterThan(1.67);
    expect(ratio).toBeLessThan(1.9);
    expect(halfWidth(0.0286)).toBeGreaterThan(2 * Math.atan(Math.sqrt(0.0286)));
    expect(halfWidth(0.0286)).toBeLessThan(1.1 * 2 * Math.atan(Math.sqrt(0.0286)));
  });
});
