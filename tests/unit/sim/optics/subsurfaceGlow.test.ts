import { describe, expect, it } from 'vitest';
import { crestScattering, henyeyGreenstein, particleScattering, PARTICLE_MEAN_COSINE } from '../../../../src/sim/optics/subsurfaceGlow';
import { bodyColor } from '../../../../src/sim/optics/waterColor';

describe('the glow of a sunlit crest, in single scattering (Morel 1988, Mobley 1994, Pope & Fry 1997)', () => {
  // 0.1952 m⁻¹ at 0.5 mg m⁻³, 0.30 at 1 (control: the exponent 0.62 read as 0.26 gives 0.25 at 0.5).
  it('particles scatter b_p(550) = 0.30 C^0.62, varying as 550/λ', () => {
    expect(particleScattering(550, 0.5)).toBeCloseTo(0.1952, 4);
    expect(particleScattering(550, 1)).toBeCloseTo(0.3, 12);
    expect(particleScattering(475, 1) / particleScattering(650, 1)).toBeCloseTo(650 / 475, 12);
    expect(Math.abs(0.3 * Math.pow(0.5, 0.26) - 0.1953)).toBeGreaterThan(0.04);
  });

  // Over the sphere (control: without its 4π it integrates to 4π).
  it('the Henyey–Greenstein phase function integrates to 1 and has mean cosine g = 0.924', () => {
    let total = 0;
    let meanCosine = 0;
    const steps = 200_000;
    for (let i = 0; i < steps; i++) {
      const mu = -1 + (2 * (i + 0.5)) / steps;
      const weight = (2 * Math.PI * 2) / steps;
      total += henyeyGreenstein(mu) * weight;
      meanCosine += mu * henyeyGreenstein(mu) * weight;
    }
    expect(total).toBeCloseTo(1, 4);
    expect(meanCosine).toBeCloseTo(PARTICLE_MEAN_COSINE, 3);
    expect(total * 4 * Math.PI).not.toBeCloseTo(1, 1);
    // Forward: 60 times stronger at 10° than at 60° (the glow only looking into the sun).
    expect(henyeyGreenstein(Math.cos((10 * Math.PI) / 180)) / henyeyGreenstein(Math.cos((60 * Math.PI) / 180))).toBeGreaterThan(30);
  });

  // Green over blue 0.93 against 0.29 (control: unabsorbed, red would be 0.78 of green, a paler cyan).
  it("through 1 m of crest the light is green-blue, greener than the deep water's own colour", () => {
    const [r, g, b] = crestScattering();
    const [wr, wg, wb] = bodyColor();
    expect(g / b).toBeGreaterThan(0.85);
    expect(g / b).toBeGreaterThan(2 * (wg / wb));
    expect(r / g).toBeLessThan(0.7);
    expect(wr / wg).toBeLessThan(0.1);
    const unabsorbed = [650, 510, 475].map((l) => particleScattering(l));
    expect(unabsorbed[1] / unabsorbed[2]).toBeCloseTo(475 / 510, 12);
    expect(unabsorbed[0] / unabsorbed[1]).toBeGreaterThan(0.7);
  });
});
