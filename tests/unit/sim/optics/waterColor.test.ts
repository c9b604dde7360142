import { describe, expect, it } from 'vitest';
import {
  bodyColor,
  deepWaterReflectance,
  molecularScattering,
  PURE_WATER_ABSORPTION,
  WAVELENGTHS,
} from '../../../../src/sim/optics/waterColor';

describe('water colour from optics', () => {
  it('takes pure-water absorption from Pope & Fry 1997: 0.34, 0.0325, 0.0114 m⁻¹ at 650, 510, 475 nm', () => {
    expect(WAVELENGTHS).toEqual([650, 510, 475]);
    expect(PURE_WATER_ABSORPTION).toEqual([0.34, 0.0325, 0.0114]);
  });

  // Control: λ⁻⁴ instead of λ⁻⁴·³ fails.
  it('has Morel’s molecular scattering: 0.00288 m⁻¹ at 500 nm, 0.000932 at 650 and 0.00359 at 475', () => {
    expect(molecularScattering(500)).toBeCloseTo(0.00288, 8);
    // Written out by hand: 0.00288 × 1.3^−4.3 and × 0.95^−4.3.
    expect(molecularScattering(650)).toBeCloseTo(0.000932, 6);
    expect(molecularScattering(475)).toBeCloseTo(0.003591, 6);
    const rayleigh = (w: number) => 0.00288 * Math.pow(w / 500, -4);
    expect(Math.abs(rayleigh(650) - 0.000932)).toBeGreaterThan(5e-5);
  });

  // Control: absorption and scattering swapped is not.
  it('is blue: R = 0.33 b_b/(a + b_b) is ≈ 0.0005 red, 0.013 green, 0.045 blue', () => {
    const [r, g, b] = bodyColor();
    expect(r).toBeCloseTo(0.000452, 5);
    expect(g).toBeCloseTo(0.0129, 4);
    expect(b).toBeCloseTo(0.0449, 4);
    expect(b).toBeGreaterThan(g);
    expect(g).toBeGreaterThan(r);
    const swapped = WAVELENGTHS.map((w, i) => deepWaterReflectance(molecularScattering(w), PURE_WATER_ABSORPTION[i]));
    expect(swapped[2]).toBeLessThan(swapped[0]);
  });
});
