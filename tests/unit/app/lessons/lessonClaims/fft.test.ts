import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import type { OceanParams } from '../../../../../src/sim/params/params';
import { seaStateFromParams, type SeaState } from '../../../../../src/sim/waves/spectra/seaState';
import { frequencySpectrum, peakWavelength } from '../../../../../src/sim/waves/spectra/waveSpectrum';
import { spectralTheory } from '../../../../../src/sim/tools/probeTheory';
import { PM_ALPHA, PM_BETA, windAt19_5 } from '../../../../../src/sim/waves/spectra/piersonMoskowitz';
import { JONSWAP_GAMMA, JONSWAP_SIGMA_ABOVE, JONSWAP_SIGMA_BELOW, jonswapShape } from '../../../../../src/sim/waves/spectra/jonswap';
import { GRAVITY, quantiseFrequency, waveNumber } from '../../../../../src/sim/waves/dispersion';
import { REPEAT_PERIOD } from '../../../../../src/sim/waves/spectra/initialSpectrum';
import { FOAM_FADE_SECONDS, foamRemaining, whitecapCoverage } from '../../../../../src/sim/waves/fft/whitecaps';
import { WIND_DRIFT_SHARE } from '../../../../../src/sim/waves/fft/foamDrift';
import { BEAUFORT_7_FROM } from '../../../../../src/sim/waves/fft/windrows';
import { BAND_STEPS, BASE_STEP, bandStart, CHUNK_SIZE, MAX_LOD_BANDS } from '../../../../../src/sim/lod/lodBands';
import { CHUNK_REACH, MORPH_SAFETY, morphZone } from '../../../../../src/sim/lod/lodMorph';
import { gerstnerWavesFor } from '../../../../../src/sim/waves/gerstner/gerstnerLiveModel';

/**
 * Every number on the fft group's cards (lod-bands … gerstner-steepness) that the code can
 * compute, read out of the card's English and Spanish text and checked against the code, so
 * that editing a card without the code (or the code without the card) fails here.
 */

type Lang = 'en' | 'es';
const LANGS: Lang[] = ['en', 'es'];

/** The card's text, question and answer in one language. */
function cardText(id: string, lang: Lang): string {
  const t = LESSON_TEXTS[id];
  return [t.text[lang], t.question?.ask[lang] ?? '', t.question?.answer[lang] ?? '', t.choice?.[lang] ?? ''].join(' ');
}

/** The number that follows `before` (a regular expression source), with a Spanish decimal comma read as a point. */
function numberAfter(text: string, before: string): number {
  const match = new RegExp(`${before}\\s*([0-9]+(?:[.,][0-9]+)?)`).exec(text);
  if (!match) throw new Error(`no number after /${before}/ in: ${text.slice(0, 80)}…`);
  return Number(match[1].replace(',', '.'));
}

/** Whether a quoted value agrees with the code's to within the quote's rounding (a relative tolerance). */
function agrees(quoted: number, computed: number, relative: number): boolean {
  return Math.abs(quoted - computed) <= relative * Math.abs(computed);
}

function viewParams(id: string): OceanParams {
  return lessonView(findLesson(id)!).params;
}
function viewSea(id: string): SeaState {
  return seaStateFromParams(viewParams(id));
}
function hs(sea: SeaState): number {
  return (spectralTheory(frequencySpectrum(sea)) as { height: number }).height;
}

describe('each FFT card’s Hs and peak wavelength come from the spectrum code at its view', () => {
  // Card, then per language the words before Hs and before the peak wavelength.
  const cases: { id: string; hs: Record<Lang, string>; peak: Record<Lang, string> }[] = [
    { id: 'fft-calm', hs: { en: 'only about', es: 'solo de unos' }, peak: { en: 'peak wavelength is about', es: 'pico es de unos' } },
    {
      id: 'fft-fresh-breeze',
      hs: { en: 'significant height about', es: 'altura significativa de unos' },
      peak: { en: 'peak wavelength about', es: 'del pico de unos' },
    },
    {
      id: 'fft-short-fetch',
      hs: { en: 'Hs is about', es: 'Hs es de unos' },
      peak: { en: 'peak wavelength about', es: 'del pico de unos' },
    },
    { id: 'fft-gale', hs: { en: 'Hs about', es: 'Hs de unos' }, peak: { en: 'peak wavelength about', es: 'del pico de unos' } },
  ];
  it.each(cases)('$id', ({ id, hs: hsBefore, peak }) => {
    const sea = viewSea(id);
    for (const lang of LANGS) {
      const text = LESSON_TEXTS[id].text[lang];
      expect(agrees(numberAfter(text, hsBefore[lang]), hs(sea), 0.03), `${lang} Hs`).toBe(true);
      expect(agrees(numberAfter(text, peak[lang]), peakWavelength(sea), 0.05), `${lang} λp`).toBe(true);
    }
  });
  it('control: a planted Hs of 8 m for the gale (the preset comment’s) and a 90 m fresh-breeze peak at 5 % fail', () => {
    expect(agrees(8, hs(viewSea('fft-gale')), 0.05)).toBe(false);
    expect(agrees(90, peakWavelength(viewSea('fft-fresh-breeze')), 0.02)).toBe(false);
  });
});

describe('fft-calm', () => {
  it('states the view’s wind, Pierson–Moskowitz’s α, β and 1.026, and the Beaufort force', () => {
    const p = viewParams('fft-calm');
    expect(p.spectrum).toBe('pierson-moskowitz');
    for (const lang of LANGS) {
      const t = cardText('fft-calm', lang);
      expect(numberAfter(t, 'U₁₀ =')).toBe(p.windSpeed);
      expect(numberAfter(t, 'α =')).toBe(8.1);
      expect(PM_ALPHA).toBe(8.1e-3);
      expect(numberAfter(t, 'β =')).toBe(PM_BETA);
      expect(numberAfter(t, 'U₁₉.₅ =')).toBeCloseTo(windAt19_5(1), 12);
      // Beaufort 3 is 3.4–5.4 m/s (WMO); light air, force 1, ends at 1.5 m/s.
      expect(numberAfter(t, 'Beaufort')).toBe(3);
      expect(p.windSpeed).toBeGreaterThanOrEqual(3.4);
      expect(p.windSpeed).toBeLessThan(5.5);
    }
  });
  it('doubling the wind quadruples λp and Hs, to the answer’s 56 m and 1.4 m', () => {
    const sea = viewSea('fft-calm');
    const doubled = { ...sea, windSpeed: 2 * sea.windSpeed };
    expect(peakWavelength(doubled) / peakWavelength(sea)).toBeCloseTo(4, 9);
    expect(hs(doubled) / hs(sea)).toBeCloseTo(4, 6);
    for (const lang of LANGS) {
      const a = LESSON_TEXTS['fft-calm'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'to about' : 'hasta unos'), peakWavelength(doubled), 0.02)).toBe(true);
      expect(agrees(numberAfter(a, lang === 'en' ? 'Hs grows as U², to about' : 'Hs crece como U², hasta unos'), hs(doubled), 0.05)).toBe(
        true,
      );
    }
    // Control: a linear growth (twice) would be wrong.
    expect(agrees(2 * peakWavelength(sea), peakWavelength(doubled), 0.1)).toBe(false);
  });
});

describe('fft-fresh-breeze', () => {
  it('at 10 m depth the peak wave shortens and slows as the answer says; the sea repeats after 1000 s', () => {
    const sea = viewSea('fft-fresh-breeze');
    const shallow = { ...sea, depth: 10 };
    const wp = frequencySpectrum(sea).peak;
    const speed = (depth: number) => wp / waveNumber(wp, depth);
    for (const lang of LANGS) {
      const a = LESSON_TEXTS['fft-fresh-breeze'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'about 88 m to about' : 'unos 88 m a unos'), peakWavelength(shallow), 0.02)).toBe(true);
      expect(agrees(numberAfter(a, lang === 'en' ? 'drops from about' : 'baja de unos'), speed(Infinity), 0.01)).toBe(true);
      expect(agrees(numberAfter(a, lang === 'en' ? '11.7 to' : '11,7 a'), speed(10), 0.01)).toBe(true);
      expect(numberAfter(cardText('fft-fresh-breeze', lang), lang === 'en' ? 'after' : 'a los')).toBe(REPEAT_PERIOD);
    }
    // Control: the deep-water length is not the shallow one.
    expect(agrees(88, peakWavelength(shallow), 0.05)).toBe(false);
  });
  it('names the view’s wind’s Beaufort force and rounds ω down to a multiple of 2π/1000 s, as the choice says', () => {
    const p = viewParams('fft-fresh-breeze');
    // Beaufort 5 is 8.0–10.7 m/s (WMO).
    const force5 = (u: number) => u >= 8.0 && u < 10.8;
    for (const lang of LANGS) {
      const t = cardText('fft-fresh-breeze', lang);
      expect(numberAfter(t, 'U₁₀ =')).toBe(p.windSpeed);
      expect(numberAfter(t, 'Beaufort')).toBe(5);
      expect(numberAfter(t, '2π/')).toBe(REPEAT_PERIOD);
    }
    expect(force5(p.windSpeed)).toBe(true);
    const step = (2 * Math.PI) / REPEAT_PERIOD;
    const wp = frequencySpectrum(viewSea('fft-fresh-breeze')).peak;
    const q = quantiseFrequency(wp, REPEAT_PERIOD);
    expect(q).toBeLessThanOrEqual(wp);
    expect(wp - q).toBeLessThan(step);
    expect((q / step) % 1).toBeCloseTo(0, 9);
    // Controls: the gale's 20 m/s is no Beaufort 5; rounding to nearest would sometimes go up.
    expect(force5(viewParams('fft-gale').windSpeed)).toBe(false);
    expect(quantiseFrequency(step * 2.9, REPEAT_PERIOD)).not.toBeCloseTo(step * 3, 9);
  });
});

describe('fft-short-fetch', () => {
  it('quotes the view’s fetch and wind, JONSWAP’s γ and σ, and the fully developed sea’s Hs and λp', () => {
    const sea = viewSea('fft-short-fetch');
    expect(sea.spectrum).toBe('jonswap');
    const developed: SeaState = { ...sea, spectrum: 'pierson-moskowitz' };
    for (const lang of LANGS) {
      const t = cardText('fft-short-fetch', lang);
      expect(numberAfter(t, '(?:aquí|here)')).toBe(sea.fetch / 1000);
      expect(numberAfter(t, 'U₁₀ =')).toBe(sea.windSpeed);
      expect(numberAfter(t, 'γ =')).toBe(JONSWAP_GAMMA);
      expect(numberAfter(t, 'σ =')).toBe(JONSWAP_SIGMA_BELOW);
      expect(t).toContain(lang === 'en' ? '0.09 above' : '0,09 encima');
      expect(JONSWAP_SIGMA_ABOVE).toBe(0.09);
      expect(agrees(numberAfter(t, lang === 'en' ? 'against' : 'frente a'), hs(developed), 0.02)).toBe(true);
      expect(agrees(numberAfter(t, lang === 'en' ? 'm and' : 'm y'), peakWavelength(developed), 0.01)).toBe(true);
    }
  });
  it('the card’s ωp = 22 (g²/(U₁₀F))^⅓ and α = 0.076 (gF/U₁₀²)^−0.22 are the code’s at the view', () => {
    const sea = viewSea('fft-short-fetch');
    const shape = jonswapShape(sea.windSpeed, sea.fetch);
    for (const lang of LANGS) {
      const t = cardText('fft-short-fetch', lang);
      const a = numberAfter(t, 'ωp =');
      const b = numberAfter(t, 'α =');
      const e = numberAfter(t, '\\^−');
      const peak = a * ((GRAVITY * GRAVITY) / (sea.windSpeed * sea.fetch)) ** (1 / 3);
      const alpha = b * ((GRAVITY * sea.fetch) / sea.windSpeed ** 2) ** -e;
      expect(peak).toBeCloseTo(shape.peak, 12);
      expect(alpha).toBeCloseTo(shape.alpha, 12);
      // Control: a planted exponent of 0.33 (the peak's) for α fails.
      expect(b * ((GRAVITY * sea.fetch) / sea.windSpeed ** 2) ** -0.33).not.toBeCloseTo(shape.alpha, 4);
    }
  });
  it('eight times the fetch gives the answer’s fourfold, 109 m peak wave', () => {
    const sea = viewSea('fft-short-fetch');
    const longer = { ...sea, fetch: 8 * sea.fetch };
    expect(peakWavelength(longer) / peakWavelength(sea)).toBeCloseTo(4, 6);
    for (const lang of LANGS) {
      const a = LESSON_TEXTS['fft-short-fetch'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'to about' : 'hasta unos'), peakWavelength(longer), 0.01)).toBe(true);
    }
    // Control: a fetch that reaches the developed peak would not quadruple it.
    const huge = { ...sea, fetch: 1000 * sea.fetch };
    expect(peakWavelength(huge) / peakWavelength(sea)).not.toBeCloseTo(1000 ** (2 / 3), 0);
  });
});

describe('fft-gale', () => {
  it('quotes τ, the drift share, Beaufort 7, Monahan’s 10 % at the view’s wind, and e^{−5/τ}', () => {
    const p = viewParams('fft-gale');
    for (const lang of LANGS) {
      const t = cardText('fft-gale', lang);
      expect(numberAfter(t, 'U₁₀ =')).toBe(p.windSpeed);
      expect(numberAfter(t, 'τ =')).toBe(FOAM_FADE_SECONDS);
      expect(p.foamFade).toBe(FOAM_FADE_SECONDS);
      expect(numberAfter(t, lang === 'en' ? 'drifts at' : 'deriva al') / 100).toBe(WIND_DRIFT_SHARE);
      expect(numberAfter(t, 'Beaufort')).toBe(8);
      expect(t).toContain('Beaufort 7');
      expect(agrees(numberAfter(t, lang === 'en' ? 'so that about' : 'rompa un') / 100, whitecapCoverage(p.windSpeed), 0.1)).toBe(true);
      const a = LESSON_TEXTS['fft-gale'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'leaves about' : 'deja un') / 100, foamRemaining(5, 2.5), 0.05)).toBe(true);
      expect(agrees(numberAfter(a, lang === 'en' ? 'and about' : 'y un') / 100, foamRemaining(5, 8), 0.02)).toBe(true);
    }
    // 20 m/s lies in Beaufort 8 (17.2–20.7 m/s), above force 7's lower bound.
    expect(p.windSpeed).toBeGreaterThanOrEqual(17.2);
    expect(p.windSpeed).toBeGreaterThan(BEAUFORT_7_FROM);
    // Control: a planted 30 % left at τ = 2.5 s fails.
    expect(agrees(0.3, foamRemaining(5, 2.5), 0.05)).toBe(false);
  });
});

describe('lod-bands', () => {
  it('the bands’ starts and steps are the code’s', () => {
    expect(BAND_STEPS).toEqual([1, 2, 3, 6, 12, 24]);
    expect(MAX_LOD_BANDS).toBe(6);
    for (let b = 1; b < MAX_LOD_BANDS; b++) expect(bandStart(b, 100)).toBe(100 * 2 ** (b - 1));
    expect(bandStart(0, 100)).toBe(0);
    const math = LESSON_TEXTS['lod-bands'].math;
    expect(math).toContain(BAND_STEPS.map((s) => `<mn>${s}</mn>`).join('<mo>,</mo>'));
    for (const lang of LANGS) {
      const t = cardText('lod-bands', lang);
      expect(numberAfter(t, lang === 'en' ? 'chunks' : 'parcelas cuadradas de')).toBe(CHUNK_SIZE);
      expect(numberAfter(t, lang === 'en' ? '\\(' : '\\(a')).toBe(BASE_STEP);
    }
    // Control: the card's old "every sixth and beyond" from 2L would be band 3 starting at 2L.
    expect(bandStart(3, 100)).not.toBe(200);
  });
  it('from the view’s camera the bottom of the picture lies past 2L, so the nearest band is 2 (yellow); L ≈ 300 m brings red', () => {
    const view = lessonView(findLesson('lod-bands')!);
    const [x, y, z] = view.camera.position;
    const [tx, ty, tz] = view.camera.target;
    const pitch = Math.atan2(y - ty, Math.hypot(tx - x, tz - z));
    const fov = (55 * Math.PI) / 180; // oceanView.ts's PerspectiveCamera
    const bottom = y / Math.sin(pitch + fov / 2);
    const L = view.params.lodDistance;
    for (const lang of LANGS) {
      const t = cardText('lod-bands', lang);
      expect(numberAfter(t, lang === 'en' ? 'camera is' : 'Cámara a')).toBe(y);
      expect(numberAfter(t, 'L =')).toBe(L);
      expect(
        agrees(
          numberAfter(LESSON_TEXTS['lod-bands'].question!.answer[lang], lang === 'en' ? 'picture is about' : 'imagen está a unos'),
          bottom,
          0.05,
        ),
      ).toBe(true);
    }
    expect(bottom).toBeGreaterThan(bandStart(2, L));
    expect(bottom).toBeLessThan(bandStart(3, L));
    for (const lang of LANGS) {
      const raised = numberAfter(LESSON_TEXTS['lod-bands'].question!.answer[lang], lang === 'en' ? 'L to about' : 'L hasta unos');
      expect(bottom).toBeLessThan(raised);
      expect(bottom).toBeGreaterThan(raised - 25);
    }
    // Control: with the camera at 60 m the nearest band would be 0.
    expect(60 / Math.sin(pitch + fov / 2)).toBeLessThan(bandStart(1, L));
  });
});

describe('lod-morph', () => {
  it('at the view’s L = 40 m band 1 has no zone; the 69 m is a chunk’s diagonal plus a metre; L = 100 m gives 30 m', () => {
    const L = lessonView(findLesson('lod-morph')!).params.lodDistance;
    expect(morphZone(1, L, MAX_LOD_BANDS).start).toBe(Infinity);
    expect(Number.isFinite(morphZone(0, L, MAX_LOD_BANDS).start)).toBe(true);
    const z100 = morphZone(1, 100, MAX_LOD_BANDS);
    for (const lang of LANGS) {
      const t = cardText('lod-morph', lang);
      expect(numberAfter(t, 'L =')).toBe(L);
      expect(Math.round(numberAfter(t, lang === 'en' ? 'first' : 'primeros'))).toBe(Math.round(CHUNK_REACH + MORPH_SAFETY));
      expect(
        agrees(
          numberAfter(LESSON_TEXTS['lod-morph'].question!.answer[lang], lang === 'en' ? 'zone' : 'zona de'),
          1 / z100.inverseWidth,
          0.02,
        ),
      ).toBe(true);
    }
    for (const lang of LANGS) {
      const a = LESSON_TEXTS['lod-morph'].question!.answer[lang];
      expect(numberAfter(a, lang === 'en' ? 'only from' : 'solo de')).toBe(bandStart(1, L));
      expect(numberAfter(a, lang === 'en' ? `from ${L} to` : `de ${L} a`)).toBe(bandStart(2, L));
      expect(numberAfter(a, lang === 'en' ? 'chunk’s diagonal,' : 'parcela,')).toBe(CHUNK_SIZE);
    }
    expect(CHUNK_REACH).toBeCloseTo(CHUNK_SIZE * Math.SQRT2, 12);
    // Control: band 0 is exempt from the 69 m rule (the card's "past band 0"), so at L = 40 m its zone is half the band.
    expect(1 / morphZone(0, L, MAX_LOD_BANDS).inverseWidth).toBeCloseTo(L / 2, 9);
    expect(CHUNK_REACH + MORPH_SAFETY).toBeGreaterThan(L);
    // Control: at L = 100 m band 1 does have a zone.
    expect(Number.isFinite(z100.start)).toBe(true);
  });
});

describe('gerstner-gentle and gerstner-steepness', () => {
  const waves = (id: string, over: Partial<OceanParams> = {}) => gerstnerWavesFor({ ...viewParams(id), ...over });
  const kA = (w: ReturnType<typeof gerstnerWavesFor>[number]) => 2 * Math.PI * Math.hypot(w.cx, w.cz) * w.amplitude;
  it('four waves of 0.28 m, three 25–38 m long and one 3.9 m, from JONSWAP at 20 m/s over 20 km; QᵢAᵢ = 0.057 m at Q = 0.2', () => {
    const p = viewParams('gerstner-gentle');
    const w = waves('gerstner-gentle');
    expect(w.length).toBe(4);
    const lengths = w.map((x) => 1 / Math.hypot(x.cx, x.cz)).sort((a, b) => a - b);
    for (const lang of LANGS) {
      const t = cardText('gerstner-gentle', lang);
      for (const x of w) expect(agrees(numberAfter(t, lang === 'en' ? 'each' : 'de'), x.amplitude, 0.02)).toBe(true);
      expect(agrees(numberAfter(t, lang === 'en' ? 'one of' : 'una de'), lengths[0], 0.02)).toBe(true);
      expect(numberAfter(t, 'Q =')).toBe(p.gerstnerSteepness);
      expect(numberAfter(t, '\\(')).toBe(p.windSpeed);
      const a = LESSON_TEXTS['gerstner-gentle'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'from' : 'de'), w[0].horizontal, 0.02)).toBe(true);
    }
    for (const lang of LANGS) {
      const t = cardText('gerstner-gentle', lang);
      const shortest = numberAfter(t, lang === 'en' ? 'three of' : 'tres de');
      const longest = numberAfter(t, lang === 'en' ? `three of ${shortest} to` : `tres de ${shortest} a`);
      expect(Math.round(lengths[1])).toBeGreaterThanOrEqual(shortest);
      expect(Math.round(lengths[3])).toBeLessThanOrEqual(longest);
      expect(Math.round(lengths[1])).toBe(shortest);
      expect(Math.round(lengths[3])).toBe(longest);
    }
    // Control: the shortest wave is not among the three.
    expect(lengths[0]).toBeLessThan(25);
    expect(p.spectrum).toBe('jonswap');
    expect(p.fetch).toBe(20);
    // Control: at Q = 0.2 the orbit is no circle.
    expect(w[0].horizontal).not.toBeCloseTo(w[0].amplitude, 3);
  });
  it('Σ kᵢAᵢ ≈ 0.64 leaves Qᵢ = 1 at Q = 1; with 64 waves it is ≈ 1.28 and Qᵢ ≈ 0.78', () => {
    const four = waves('gerstner-steepness');
    const sum4 = four.reduce((s, w) => s + kA(w), 0);
    const many = waves('gerstner-steepness', { gerstnerCount: 64 });
    const sum64 = many.reduce((s, w) => s + kA(w), 0);
    for (const lang of LANGS) {
      const t = cardText('gerstner-steepness', lang);
      expect(agrees(numberAfter(t, lang === 'en' ? 'is about' : 'vale unos'), sum4, 0.01)).toBe(true);
      const a = LESSON_TEXTS['gerstner-steepness'].question!.answer[lang];
      expect(agrees(numberAfter(a, lang === 'en' ? 'grows to about' : 'sube a unos'), sum64, 0.01)).toBe(true);
      expect(agrees(numberAfter(a, lang === 'en' ? 'cut to about' : 'recorta a unos'), many[0].horizontal / many[0].amplitude, 0.01)).toBe(
        true,
      );
      expect(agrees(numberAfter(a, lang === 'en' ? 'falls to about' : 'baja a unos'), many[0].amplitude, 0.05)).toBe(true);
    }
    for (const w of four) expect(w.horizontal).toBe(w.amplitude);
    expect(many.reduce((s, w) => s + (w.horizontal / w.amplitude) * kA(w), 0)).toBeCloseTo(1, 9);
    // Control: a planted Σ kA of 1.28 for four waves fails.
    expect(agrees(1.28, sum4, 0.05)).toBe(false);
  });
});

describe('frustum-culling and fft-normals', () => {
  it('the drawn step is a chunk; the normals view is the 10 m/s sea with vertices 2 m apart, so ripples under 4 m are lost', () => {
    for (const lang of LANGS) {
      const f = LESSON_TEXTS['frustum-culling'].question!.answer[lang];
      expect(numberAfter(f, lang === 'en' ? 'whole,' : 'entera, de')).toBe(CHUNK_SIZE);
      const t = cardText('fft-normals', lang);
      expect(numberAfter(t, lang === 'en' ? 'sea at' : 'mar a')).toBe(viewParams('fft-normals').windSpeed);
      expect(numberAfter(t, lang === 'en' ? 'vertex,' : 'vértice, a')).toBe(BASE_STEP);
      expect(numberAfter(t, lang === 'en' ? 'shorter than about' : 'de menos de unos')).toBe(2 * BASE_STEP);
    }
    expect(viewParams('fft-normals').waves).toBe('fft');
    // Control: the nearest band's vertices are not 1 m apart.
    expect(BAND_STEPS[0] * BASE_STEP).not.toBe(1);
  });
});
