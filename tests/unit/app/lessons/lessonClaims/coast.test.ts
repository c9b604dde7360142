import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import type { OceanParams } from '../../../../../src/sim/params/params';
import { DEEP, GRAVITY, groupVelocity, waveNumber } from '../../../../../src/sim/waves/dispersion';
import { OFFSHORE_DEPTH, BEACH_SHORE_X, ISLAND_CENTER, ISLAND_RADIUS } from '../../../../../src/sim/coast/bathymetry';
import {
  MCCOWAN_BREAKER_INDEX,
  breakingDepth,
  breakingFraction,
  refractionCoefficient,
  shoalingCoefficient,
  snellAngle,
} from '../../../../../src/sim/coast/waveTransformation';
import { buildCoastField } from '../../../../../src/sim/coast/coastSwellField';
import { sampleCoastField } from '../../../../../src/sim/coast/coastFieldSampling';
import { LINEAR_THEORY, SHALLOWEST_DEPTH, type CoastWaveModel } from '../../../../../src/sim/coast/coastWaveModel';
import { MAX_REFRACTION_COEFFICIENT } from '../../../../../src/sim/coast/islandSwellField';
import type { CoastSetting } from '../../../../../src/sim/coast/coastField';
import { regularSwell, swellComponents } from '../../../../../src/sim/coast/swellSpectrum';

/**
 * Every number on the coast's cards (coast-dispersion, coast-refraction, coast-shoaling,
 * coast-breaking) that the code can compute, read out of the card's English and Spanish text
 * and recomputed from src/sim/coast/ and the dispersion relation it uses; each kind of check
 * has a planted fault that must fail.
 */

type Lang = 'en' | 'es';
const LANGS: Lang[] = ['en', 'es'];

/** The number that follows `before` (a regular expression source), as written, a Spanish decimal comma read as a point. */
function quotedAfter(text: string, before: string): string {
  const match = new RegExp(`${before}\\s*([0-9]+(?:[.,][0-9]+)?)`).exec(text);
  if (!match) throw new Error(`no number after /${before}/ in: ${text.slice(0, 80)}…`);
  return match[1].replace(',', '.');
}

/** Whether `computed` rounds to `quoted` at the quote's own number of decimals. */
function roundsTo(quoted: string, computed: number): boolean {
  const decimals = quoted.includes('.') ? quoted.split('.')[1].length : 0;
  return Math.abs(computed - Number(quoted)) <= 0.5 * 10 ** -decimals + 1e-12;
}

const viewParams = (id: string): OceanParams => lessonView(findLesson(id)!).params;
const omegaOf = (period: number) => (2 * Math.PI) / period;
const wavelength = (period: number, depth: number) => (2 * Math.PI) / waveNumber(omegaOf(period), depth);
const setting = (p: OceanParams): CoastSetting => ({
  bathymetry: p.bathymetry,
  beachSlope: p.beachSlope,
  deepDepth: p.depth,
  swellHeight: p.swellHeight,
  swellPeriod: p.swellPeriod,
  swellDirection: p.swellDirection,
  seed: p.seed,
});
/** The field of one regular wave train of the view's height and period: linear theory's, which the cards' single-wave figures speak of. */
const regularField = (p: OceanParams, resolution: number, model: CoastWaveModel = LINEAR_THEORY) =>
  buildCoastField(setting(p), resolution, model, regularSwell(setting(p)))!;

/**
 * The depth where a swell of offshore height H₀ (given at OFFSHORE_DEPTH), period T and
 * offshore angle θ₀ first reaches H = γ h on its way in, by bisection on H₀ Ks Kr − γ h,
 * which is negative offshore and positive near the shore.
 */
function breakingLine(height0: number, period: number, theta0: number, gamma = MCCOWAN_BREAKER_INDEX): { depth: number; height: number } {
  const omega = omegaOf(period);
  const shoaled = (h: number) =>
    height0 * shoalingCoefficient(omega, h, OFFSHORE_DEPTH) * refractionCoefficient(theta0, snellAngle(omega, theta0, h, OFFSHORE_DEPTH));
  let shallow = 0.05;
  let deep = OFFSHORE_DEPTH;
  for (let i = 0; i < 80; i++) {
    const mid = 0.5 * (shallow + deep);
    if (shoaled(mid) >= gamma * mid) shallow = mid;
    else deep = mid;
  }
  return { depth: shallow, height: shoaled(shallow) };
}

/**
 * The depth where a set's biggest wave, 2 Σ A_m (every component of the swell's spectrum at its
 * crest at once, each shoaled and refracted on its own), first reaches γ h, by bisection.
 */
function setBreakingLine(p: OceanParams, swellHeight = p.swellHeight, gamma = MCCOWAN_BREAKER_INDEX): { depth: number; height: number } {
  const theta0 = (p.swellDirection * Math.PI) / 180;
  const envelope = (h: number) =>
    2 *
    swellComponents({ ...setting(p), swellHeight }).reduce((sum, c) => {
      const omega = c.angularFrequency;
      const kr = refractionCoefficient(theta0, snellAngle(omega, theta0, h, OFFSHORE_DEPTH));
      return sum + c.amplitude * shoalingCoefficient(omega, h, OFFSHORE_DEPTH) * kr;
    }, 0);
  let shallow = 0.05;
  let deep = OFFSHORE_DEPTH;
  for (let i = 0; i < 80; i++) {
    const mid = 0.5 * (shallow + deep);
    if (envelope(mid) >= gamma * mid) shallow = mid;
    else deep = mid;
  }
  return { depth: shallow, height: envelope(shallow) };
}

describe('the coast’s views', () => {
  // Control: the deep sea has no coast field at all.
  it('open the beach (three cards) and the island (one), each with the 1.5 m, 10 s swell the cards speak of', () => {
    const floors = ['coast-dispersion', 'coast-refraction', 'coast-shoaling', 'coast-breaking'].map((id) => viewParams(id).bathymetry);
    expect(floors).toEqual(['beach', 'island', 'beach', 'beach']);
    for (const id of ['coast-dispersion', 'coast-shoaling', 'coast-breaking']) {
      const p = viewParams(id);
      expect([p.swellHeight, p.swellPeriod, p.swellDirection, p.beachSlope], id).toEqual([1.5, 10, 0, 0.02]);
      expect(buildCoastField(setting(p), 32), id).not.toBeNull();
    }
    expect(buildCoastField({ ...setting(viewParams('coast-breaking')), bathymetry: 'deep' }, 32)).toBeNull();
  });
});

describe('coast-dispersion: ω² = g k tanh(k h) shortens and slows the swell', () => {
  const text = (lang: Lang) => LESSON_TEXTS['coast-dispersion'].text[lang];

  // Control: deep water's g T²/2π, 156 m, is not the card's 154 m at 60 m.
  it('L = 154 m at 60 m, 92 m at 10 m, 44 m at 2 m, for the view’s 10 s period', () => {
    const { swellPeriod } = viewParams('coast-dispersion');
    for (const lang of LANGS) {
      expect(Number(quotedAfter(text(lang), ''))).toBe(swellPeriod);
      expect(roundsTo(quotedAfter(text(lang), 'L ='), wavelength(swellPeriod, OFFSHORE_DEPTH)), lang).toBe(true);
      const apart = /([0-9]+) m (?:apart at|a) 10 m[^0-9]+([0-9]+) m (?:apart at|a) 2 m/.exec(text(lang))!;
      expect(roundsTo(apart[1], wavelength(swellPeriod, 10)), lang).toBe(true);
      expect(roundsTo(apart[2], wavelength(swellPeriod, 2)), lang).toBe(true);
    }
    expect(roundsTo('154', wavelength(swellPeriod, DEEP))).toBe(false);
    expect(roundsTo('44', wavelength(swellPeriod, DEEP))).toBe(false);
  });

  // Control: the deep-water speed g/ω at 2 m is 15.6 m/s, far from 4.37.
  it('at 2 m c = ω/k = 4.37 m/s beside √(g h) = 4.43 m/s', () => {
    const omega = omegaOf(viewParams('coast-dispersion').swellPeriod);
    for (const lang of LANGS) {
      expect(roundsTo(quotedAfter(text(lang), 'c ='), omega / waveNumber(omega, 2)), lang).toBe(true);
      expect(roundsTo(quotedAfter(text(lang), '√\\(g h\\) ='), Math.sqrt(GRAVITY * 2)), lang).toBe(true);
    }
    expect(roundsTo('4.37', omega / waveNumber(omega, DEEP))).toBe(false);
  });

  // Control: deep water's L ∝ T² would give 99 m, not 66 m, at 15 s.
  it('the answer: at 2 m L grows from 44 m to 66 m when the period goes from 10 to 15 s', () => {
    for (const lang of LANGS) {
      const card = LESSON_TEXTS['coast-dispersion'];
      const [, from, to] = /(?:from|de) ([0-9]+) (?:to|a) ([0-9]+) s/.exec(card.question.ask[lang])!.map(Number);
      expect(from).toBe(viewParams('coast-dispersion').swellPeriod);
      const grows = /([0-9]+) m (?:to|a) ([0-9]+) m/.exec(card.question.answer[lang])!;
      expect(roundsTo(grows[1], wavelength(from, 2)), lang).toBe(true);
      expect(roundsTo(grows[2], wavelength(to, 2)), lang).toBe(true);
    }
    expect(roundsTo('66', wavelength(10, 2) * (15 / 10) ** 2)).toBe(false);
  });

  // Control: a depth of 0.2 m would not round to the choice line's 0.1.
  it('the choice line’s depth below which k is frozen is the code’s', () => {
    for (const lang of LANGS) {
      const choice = LESSON_TEXTS['coast-dispersion'].choice![lang];
      expect(roundsTo(quotedAfter(choice, '(?:below|bajo)'), SHALLOWEST_DEPTH), lang).toBe(true);
    }
    expect(roundsTo('0.1', 0.2)).toBe(false);
  });

  // Control: the periods of four evenly spaced frequencies across the band are not the card's.
  it('the choice line’s four periods are the swell spectrum’s components for the view’s 10 s peak', () => {
    const periods = swellComponents(setting(viewParams('coast-dispersion'))).map((c) => (2 * Math.PI) / c.angularFrequency);
    for (const lang of LANGS) {
      const choice = LESSON_TEXTS['coast-dispersion'].choice![lang];
      const quoted = /(?:periods|periodos),? ([0-9]+[.,][0-9])[,;] ([0-9]+[.,][0-9])[,;] ([0-9]+[.,][0-9]) (?:and|y) ([0-9]+[.,][0-9]) s/
        .exec(choice)!
        .slice(1)
        .map((q) => q.replace(',', '.'));
      quoted.forEach((q, m) => expect(roundsTo(q, periods[m]), `${lang} ${q}`).toBe(true));
    }
    const evenly = [0.8125, 1.4375, 2.0625, 2.6875].map((f) => 10 / f);
    expect(roundsTo('9.9', evenly[1])).toBe(false);
  });

  // Control: a field built with deep water's dispersion keeps 154 m crests all the way in.
  it('the field’s own crests across the beach stand 92 m apart at 10 m and 44 m at 2 m (within 3 %)', () => {
    const p = viewParams('coast-dispersion');
    const spacingAt = (depth: number, model: CoastWaveModel = LINEAR_THEORY) => {
      const field = regularField(p, 512, model);
      const x = BEACH_SHORE_X - depth / p.beachSlope;
      const dS = sampleCoastField(field, x + 5, 0).phase - sampleCoastField(field, x - 5, 0).phase;
      return (2 * Math.PI * 10) / dS;
    };
    expect(spacingAt(10) / 92).toBeCloseTo(1, 1);
    expect(Math.abs(spacingAt(10) / wavelength(10, 10) - 1)).toBeLessThan(0.03);
    expect(Math.abs(spacingAt(2) / wavelength(10, 2) - 1)).toBeLessThan(0.03);
    const deepWater: CoastWaveModel = { ...LINEAR_THEORY, waveNumber: (omega) => waveNumber(omega, DEEP) };
    expect(Math.abs(spacingAt(2, deepWater) / wavelength(10, 2) - 1)).toBeGreaterThan(0.03);
  });
});

describe('coast-refraction: Snell on the beach, the eikonal round the island', () => {
  // Control: without refraction (k the same at every depth) the swell would still be at 30°.
  it('a swell at 30° in 60 m of water turns to 17° at 10 m and to 8° at 2 m', () => {
    const omega = omegaOf(viewParams('coast-refraction').swellPeriod);
    const angle = (depth: number) => (snellAngle(omega, (30 * Math.PI) / 180, depth, OFFSHORE_DEPTH) * 180) / Math.PI;
    for (const lang of LANGS) {
      const text = LESSON_TEXTS['coast-refraction'].text[lang];
      const [, theta0, offshore, at10, at2] =
        /([0-9]+)° (?:in|en) ([0-9]+) m[^0-9]+([0-9]+)° a(?:t)? 10 m[^0-9]+([0-9]+)° a(?:t)? 2 m/.exec(text)!;
      expect(Number(theta0)).toBe(30);
      expect(Number(offshore)).toBe(OFFSHORE_DEPTH);
      expect(roundsTo(at10, angle(10)), lang).toBe(true);
      expect(roundsTo(at2, angle(2)), lang).toBe(true);
    }
    // k sin θ is kept: the same law written with the phase speed.
    const k = (h: number) => waveNumber(omega, h);
    expect(Math.sin((angle(2) * Math.PI) / 180) * k(2)).toBeCloseTo(Math.sin(Math.PI / 6) * k(OFFSHORE_DEPTH), 10);
    const noRefraction = (Math.asin((k(OFFSHORE_DEPTH) / k(OFFSHORE_DEPTH)) * Math.sin(Math.PI / 6)) * 180) / Math.PI;
    expect(roundsTo('17', noRefraction)).toBe(false);
  });

  // Control: just behind the shore, 50 m in the lee, the swell is far below 1 m, so the check can fail.
  it('the island’s lee is calm only in a strip behind the shore: 300 m behind it the swell is back above 1 m', () => {
    const p = viewParams('coast-refraction');
    const field = buildCoastField(setting(p), 256)!;
    // The swell's local significant height, 4 √m0 with m0 = Σ A_m² / 2 over its components.
    const behind = (metres: number) => {
      const x = ISLAND_CENTER[0] + ISLAND_RADIUS + metres;
      const m0 = field.components.reduce((sum, _, m) => sum + sampleCoastField(field, x, ISLAND_CENTER[1], m).amplitude ** 2 / 2, 0);
      return 4 * Math.sqrt(m0);
    };
    for (const lang of LANGS) {
      const answer = LESSON_TEXTS['coast-refraction'].question.answer[lang];
      const [, distance, height] = /([0-9]+) m (?:behind its shore|de su orilla)[^0-9]+([0-9]+) m/.exec(answer)!.map(Number);
      expect(behind(distance), lang).toBeGreaterThan(height);
      expect(behind(distance), lang).toBeLessThan(p.swellHeight);
    }
    expect(behind(50)).toBeLessThan(0.1 * p.swellHeight);
    expect(behind(50)).not.toBeGreaterThan(1);
  });

  // Control: another cap would not round to the card's.
  it('the choice line’s cap on Kr is the code’s', () => {
    for (const lang of LANGS)
      expect(roundsTo(quotedAfter(LESSON_TEXTS['coast-refraction'].choice![lang], '(?:at|a)'), MAX_REFRACTION_COEFFICIENT), lang).toBe(
        true,
      );
    expect(roundsTo('2.5', 2)).toBe(false);
  });
});

describe('coast-shoaling: H = H₀ Ks Kr, the energy flux kept', () => {
  const text = (lang: Lang) => LESSON_TEXTS['coast-shoaling'].text[lang];
  const omega = () => omegaOf(viewParams('coast-shoaling').swellPeriod);
  const cgAt = (h: number) => groupVelocity(waveNumber(omega(), h), h);
  const ks = (h: number) => shoalingCoefficient(omega(), h, OFFSHORE_DEPTH);
  /** The depth of Ks's least value, by a fine scan from 1 to 60 m. */
  const dip = () => {
    let best = { ks: Infinity, depth: 0 };
    for (let h = 1; h <= OFFSHORE_DEPTH; h += 0.01) if (ks(h) < best.ks) best = { ks: ks(h), depth: h };
    return best;
  };

  // Control: Ks referred to deep water (not to the 60 m where H₀ is given) dips to 0.91, not 0.94.
  it('c_g grows from 8.25 to 9.37 m/s near 25 m, where Ks = 0.94', () => {
    const least = dip();
    for (const lang of LANGS) {
      const t = text(lang);
      expect(roundsTo(quotedAfter(t, 'H₀ ='), viewParams('coast-shoaling').swellHeight), lang).toBe(true);
      const [, cg0, cgMax, near] = /([0-9]+[.,][0-9]+) m\/s [^0-9]+([0-9]+[.,][0-9]+) m\/s (?:near|cerca de) ([0-9]+) m/.exec(t)!;
      expect(roundsTo(cg0.replace(',', '.'), cgAt(OFFSHORE_DEPTH)), lang).toBe(true);
      expect(roundsTo(cgMax.replace(',', '.'), cgAt(least.depth)), lang).toBe(true);
      expect(roundsTo(near, least.depth), lang).toBe(true);
      expect(roundsTo(quotedAfter(t, 'K_s ='), least.ks), lang).toBe(true);
    }
    expect(roundsTo('0.94', Math.min(...[20, 25, 30].map((h) => shoalingCoefficient(omega(), h, DEEP))))).toBe(false);
  });

  // Control: H₀ / Ks instead of H₀ Ks gives 1.31 m, not 1.71.
  it('Ks = 1.14 at 5 m, where H = 1.71 m, and the beach’s field holds that height', () => {
    const p = viewParams('coast-shoaling');
    const field = regularField(p, 512);
    const x = BEACH_SHORE_X - 5 / p.beachSlope;
    const fieldHeight = 2 * sampleCoastField(field, x, 0).amplitude;
    for (const lang of LANGS) {
      const t = text(lang);
      const [, ks5, h5] = /K_s = ([0-9]+[.,][0-9]+) a(?:t)? 5 m[^=]+= ([0-9]+[.,][0-9]+) m/.exec(t)!;
      expect(roundsTo(ks5.replace(',', '.'), ks(5)), lang).toBe(true);
      expect(roundsTo(h5.replace(',', '.'), p.swellHeight * ks(5)), lang).toBe(true);
      expect(Math.abs(fieldHeight / Number(h5.replace(',', '.')) - 1), lang).toBeLessThan(0.01);
    }
    expect(roundsTo('1.71', p.swellHeight / ks(5))).toBe(false);
  });

  // Control: a field with deep water's group velocity (c_g = c/2 everywhere) does not shrink the swell at 25 m.
  it('the answer: from 60 to 25 m the swell shrinks by about 6 %, in the field too; Ks is back to 1 near 11 m', () => {
    const p = viewParams('coast-shoaling');
    const at25 = (model: CoastWaveModel = LINEAR_THEORY) =>
      (2 * sampleCoastField(regularField(p, 256, model), BEACH_SHORE_X - 25 / p.beachSlope, 0).amplitude) / p.swellHeight;
    for (const lang of LANGS) {
      const answer = LESSON_TEXTS['coast-shoaling'].question.answer[lang];
      const shrink = Number(/([0-9]+) %/.exec(answer)![1]) / 100;
      expect(roundsTo(String(shrink * 100), (1 - ks(25)) * 100), lang).toBe(true);
      expect(Math.abs(1 - at25() - shrink)).toBeLessThan(0.01);
      // Ks crosses 1 again at the depth the answer gives: above 1 half a metre shallower, below it half a metre deeper.
      const backToOne = Number(quotedAfter(answer, '(?:inside about|menos de unos)'));
      expect(ks(backToOne - 0.5), lang).toBeGreaterThan(1);
      expect(ks(backToOne + 0.5), lang).toBeLessThan(1);
    }
    // Control: a depth of 15 m, where Ks is still below 1, is not where it comes back.
    expect(ks(15 - 0.5)).toBeLessThan(1);
    const halfPhaseSpeed: CoastWaveModel = { ...LINEAR_THEORY, groupVelocity: (k, h) => 0.5 * Math.sqrt((GRAVITY / k) * Math.tanh(k * h)) };
    expect(at25(halfPhaseSpeed)).toBeGreaterThan(1);
  });
});

describe('coast-breaking: H_b = γ h, γ = 0.78, a set’s biggest waves first', () => {
  const p = () => viewParams('coast-breaking');

  // Control: another index does not round to the card's.
  it('γ = 0.78 is McCowan’s index in the code, and the slope 0.02 is the view’s', () => {
    for (const lang of LANGS) {
      const t = LESSON_TEXTS['coast-breaking'].text[lang];
      expect(roundsTo(quotedAfter(t, 'γ ='), MCCOWAN_BREAKER_INDEX), lang).toBe(true);
      expect(roundsTo(quotedAfter(t, '(?:slope|pendiente) s ='), p().beachSlope), lang).toBe(true);
    }
    expect(LESSON_TEXTS['coast-breaking'].math).toContain('<mi>γ</mi><mo>=</mo><mn>0.78</mn>');
    expect(roundsTo('0.78', 0.8)).toBe(false);
  });

  // Control: H₀/γ, the depth a wave that had not shoaled would break at, is 1.92 m, not 2.54.
  it('one 1.5 m, 10 s wave breaks at h = 2.54 m with H = 1.98 m, not at H₀/γ = 1.92 m', () => {
    const { swellHeight, swellPeriod } = p();
    const line = breakingLine(swellHeight, swellPeriod, 0);
    for (const lang of LANGS) {
      const t = LESSON_TEXTS['coast-breaking'].text[lang];
      expect(roundsTo(quotedAfter(t, 'H ='), line.height), lang).toBe(true);
      expect(roundsTo(quotedAfter(t, 'h ='), line.depth), lang).toBe(true);
      expect(roundsTo(quotedAfter(t, 'H₀/γ ='), breakingDepth(swellHeight)), lang).toBe(true);
    }
    expect(line.height).toBeCloseTo(MCCOWAN_BREAKER_INDEX * line.depth, 6);
    expect(roundsTo('2.54', breakingDepth(swellHeight))).toBe(false);
  });

  // Control: the single wave's 2.54 m and 127 m are not the set's.
  it('a set’s biggest waves, 2 Σ A of the four components, break first at 3.24 m; the surf zone is 162 m wide', () => {
    const set = setBreakingLine(p());
    for (const lang of LANGS) {
      const t = LESSON_TEXTS['coast-breaking'].text[lang];
      const first = /(?:break first, further out, at|rompen primero, más afuera, a) ([0-9]+[.,][0-9]+) m/.exec(t)![1].replace(',', '.');
      expect(roundsTo(first, set.depth), lang).toBe(true);
      expect(roundsTo(quotedAfter(t, '≈'), set.depth / p().beachSlope), lang).toBe(true);
    }
    expect(set.height).toBeCloseTo(MCCOWAN_BREAKER_INDEX * set.depth, 6);
    const single = breakingLine(p().swellHeight, p().swellPeriod, 0);
    expect(roundsTo('3.24', single.depth)).toBe(false);
    expect(roundsTo('162', single.depth / p().beachSlope)).toBe(false);
  });

  // Control: the field built with γ = 0.6 breaks further out, beyond the tolerance.
  it('the beach’s field starts to break at 0.9 γ h and is fully broken at the card’s breaking line (within a texel)', () => {
    const { swellHeight, swellPeriod } = p();
    const line = breakingLine(swellHeight, swellPeriod, 0);
    const fullyBroken = (model: CoastWaveModel = LINEAR_THEORY) => {
      const field = regularField(p(), 512, model);
      for (let i = 0; i < field.resolution; i++) {
        const at = sampleCoastField(field, field.originX + i * field.spacing, field.originZ);
        if (at.breaking >= 1) return { depth: at.depth, field };
      }
      throw new Error('never broken');
    };
    const { depth, field } = fullyBroken();
    const texelDepth = field.spacing * p().beachSlope;
    expect(Math.abs(depth - line.depth)).toBeLessThanOrEqual(texelDepth);
    expect(breakingFraction(0.9 * MCCOWAN_BREAKER_INDEX * 3, 3)).toBeCloseTo(0, 12);
    expect(breakingFraction(0.85 * MCCOWAN_BREAKER_INDEX * 3, 3)).toBe(0);
    expect(breakingFraction(MCCOWAN_BREAKER_INDEX * 3, 3)).toBe(1);
    const early = fullyBroken({ ...LINEAR_THEORY, breakerIndex: 0.6 });
    expect(Math.abs(early.depth - line.depth)).toBeGreaterThan(texelDepth);
  });

  // Control: a surf zone that doubled with the height would be 324 m, not 290.
  it('the answer: with Hs = 3 m a set’s biggest waves break at 5.80 m, a surf zone 290 m wide, 1.79 times as wide', () => {
    const { swellHeight, beachSlope } = p();
    const small = setBreakingLine(p());
    for (const lang of LANGS) {
      const card = LESSON_TEXTS['coast-breaking'].question;
      const [, from, to] = /(?:from|de) ([0-9]+[.,][0-9]+) (?:to|a) ([0-9]+) m/.exec(card.ask[lang])!;
      expect(Number(from.replace(',', '.'))).toBe(swellHeight);
      const big = setBreakingLine(p(), Number(to));
      const answer = card.answer[lang];
      expect(roundsTo(quotedAfter(answer, 'h ≈'), big.depth), lang).toBe(true);
      expect(roundsTo(quotedAfter(answer, '(?:about|unos)'), big.depth / beachSlope), lang).toBe(true);
      expect(roundsTo(/([0-9]+[.,][0-9]+) (?:times|veces)/.exec(answer)![1].replace(',', '.'), big.depth / small.depth), lang).toBe(true);
    }
    expect(roundsTo('290', (2 * small.depth) / beachSlope)).toBe(false);
  });
});
