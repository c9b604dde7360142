import { describe, expect, it } from 'vitest';
import { FOAM_WATER_PATH, foamReflectance, foamReflectanceAt, WATER_ABSORPTION_850NM } from '../../../../src/sim/optics/foamReflectance';
import { foamMaterialChunk } from '../../../../src/render/foam/foamDetail';

describe("foam's reflectance (Whitlock et al. 1982, Frouin et al. 1996, Pope & Fry 1997)", () => {
  // At every wavelength (control: the albedo drawn before, 0.72–0.80, is above it).
  it("is 0.55 over the visible, within Whitlock et al.'s 0.5–0.6 for fresh foam", () => {
    for (const r of foamReflectance()) {
      expect(r).toBeGreaterThanOrEqual(0.5);
      expect(r).toBeLessThanOrEqual(0.6);
    }
    expect(Math.min(0.72, 0.77, 0.8)).toBeGreaterThan(0.6);
  });

  // Control: no path keeps it 1.
  it("falls to Frouin et al.'s 0.6 of the visible at 850 nm, along about 12 cm of water", () => {
    expect(foamReflectanceAt(WATER_ABSORPTION_850NM) / foamReflectanceAt(0)).toBeCloseTo(0.6, 12);
    expect(FOAM_WATER_PATH).toBeCloseTo(0.1188, 4);
    expect(Math.exp(-WATER_ABSORPTION_850NM * 0)).toBe(1);
  });

  // Red 3.8 % below blue, green 0.3 % below it (control: 850 nm's absorption in the red would
  // make it 40 % lower).
  it("is almost grey on screen, in the order Pope & Fry's absorption gives", () => {
    const [r, g, b] = foamReflectance();
    expect(r / b).toBeCloseTo(0.9617, 4);
    expect(g / b).toBeCloseTo(0.9975, 4);
    expect(r).toBeLessThan(g);
    expect(g).toBeLessThan(b);
    expect(foamReflectanceAt(WATER_ABSORPTION_850NM) / b).toBeLessThan(0.61);
  });

  it('reaches the foam material as FOAM_REFLECTANCE, from these values', () => {
    const [r, g, b] = foamReflectance();
    expect(foamMaterialChunk.startsWith(`#define FOAM_REFLECTANCE vec3(${r}, ${g}, ${b})\n`)).toBe(true);
    expect(foamMaterialChunk).toContain('vec3 foam = FOAM_REFLECTANCE *');
  });
});
