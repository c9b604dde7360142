import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import { paramDefs, type OceanParams } from '../../../../../src/sim/params/params';
import { orbitSemiAxes, waveEnergy, SEA_WATER_DENSITY } from '../../../../../src/sim/waves/airyWave';
import { GRAVITY, angularFrequency, groupVelocity } from '../../../../../src/sim/waves/dispersion';
import { gerstnerWavesFor } from '../../../../../src/sim/waves/gerstner/gerstnerLiveModel';
import { drawGerstnerWaves, limitSteepness } from '../../../../../src/sim/waves/gerstner/gerstnerSpectrum';
import { crestRadii } from '../../../../../src/sim/iwave/cauchyPoissonRings';
import { KELVIN_HALF_ANGLE } from '../../../../../src/sim/wake/kelvinGuide';
import { seaStateFromParams } from '../../../../../src/sim/waves/spectra/seaState';
import { frequencySpectrum, peakWavelength } from '../../../../../src/sim/waves/spectra/waveSpectrum';
import { PHILLIPS_ALPHA, phillips, phillipsPeak } from '../../../../../src/sim/waves/spectra/phillips';
import { PM_ALPHA, PM_BETA, windAt19_5 } from '../../../../../src/sim/waves/spectra/piersonMoskowitz';
import { JONSWAP_GAMMA, jonswapShape } from '../../../../../src/sim/waves/spectra/jonswap';
import { fftOceanSetup } from '../../../../../src/sim/waves/fft/fftOcean';
import { evolveSpectra } from '../../../../../src/sim/waves/fft/spectralFields';
import { stockhamInverse, stockhamRadices, stockhamStage } from '../../../../../src/sim/waves/fft/stockhamFft';
import { TILE_RATIOS, cascadeLayout } from '../../../../../src/sim/waves/fft/cascades';
import type { SpectralTile } from '../../../../../src/sim/waves/spectra/initialSpectrum';

/**
 * Every number and equation on the concept cards (airy-waves, group-velocity,
 * spectra-compared, fft-transform) that the code can compute, read out of the card's English
 * and Spanish text and checked against the code; each kind of check has a planted fault
 * that must fail.
 */

type Lang = 'en' | 'es';
const LANGS: Lang[] = ['en', 'es'];

function cardText(id: string, lang: Lang): string {
  const t = LESSON_TEXTS[id];
  return [t.text[lang], t.question?.ask[lang] ?? '', t.question?.answer[lang] ?? '', t.choice?.[lang] ?? ''].join(' ');
}

/** The number that follows `before` (a regular expression source), a Spanish decimal comma read as a point. */
function numberAfter(text: string, before: string): number {
  const match = new RegExp(`${before}\\s*([0-9]+(?:[.,][0-9]+)?)`).exec(text);
  if (!match) throw new Error(`no number after /${before}/ in: ${text.slice(0, 80)}…`);
  return Number(match[1].replace(',', '.'));
}

/** Whether a quoted value agrees with the computed one to within the quote's rounding (relative). */
function agrees(quoted: number, computed: number, relative: number): boolean {
  return Math.abs(quoted - computed) <= relative * Math.abs(computed);
}

const viewParams = (id: string): OceanParams => lessonView(findLesson(id)!).params;

describe('airy-waves: orbits shrink as e^{kz}, E = ½ ρ g a², and the view’s amplitudes', () => {
  it('the view is Gerstner’s sea at the least Q the control allows, 0.2, four waves from JONSWAP; at Q = 0 they would be Airy’s', () => {
    const p = viewParams('airy-waves');
    for (const lang of LANGS) expect(numberAfter(cardText('airy-waves', lang), 'Q =')).toBe(p.gerstnerSteepness);
    expect(p.gerstnerSteepness).toBe(paramDefs.gerstnerSteepness.min);
    expect(p.gerstnerCount).toBe(4);
    expect(p.spectrum).toBe('jonswap');
    // Sideways motion is at most Q = 0.2 of the height's; at Q = 0 none: the sum of Airy's cosines.
    expect(gerstnerWavesFor(p).every((w) => w.horizontal <= 0.2 * w.amplitude + 1e-12)).toBe(true);
    expect(limitSteepness(gerstnerWavesFor(p), 0).every((w) => w.horizontal === 0)).toBe(true);
  });

  it('half a wavelength down the orbit is e^{−π} ≈ 4 % of the surface’s, deep water and the finite-depth formula’s limit alike', () => {
    const k = 0.2;
    const deep = orbitSemiAxes(1, k, -Math.PI / k);
    const finite = orbitSemiAxes(1, k, -Math.PI / k, 150);
    expect(deep.vertical).toBeCloseTo(Math.exp(-Math.PI), 12);
    expect(finite.horizontal).toBeCloseTo(deep.horizontal, 9);
    for (const lang of LANGS) expect(agrees(numberAfter(cardText('airy-waves', lang), '≈'), 100 * deep.vertical, 0.1)).toBe(true);
    // In shallow water the vertical axis falls to 0 at the bed while the horizontal does not.
    const shallow = orbitSemiAxes(1, k, -2, 2);
    expect(shallow.vertical).toBeCloseTo(0, 12);
    expect(shallow.horizontal).toBeGreaterThan(0.5);
    // Control: a planted 14 % is not e^{−π}.
    expect(agrees(14, 100 * deep.vertical, 0.1)).toBe(false);
  });

  it('from 4 to 16 waves each falls from 0.28 m to 0.14 m and from about 400 to 100 J/m², the total ρ g m₀ᴮ ≈ 1.6 kJ/m² kept', () => {
    const p = viewParams('airy-waves');
    const four = gerstnerWavesFor(p);
    const sixteen = gerstnerWavesFor({ ...p, gerstnerCount: 16 });
    const total = (waves: typeof four) => waves.reduce((sum, w) => sum + waveEnergy(w.amplitude), 0);
    expect(total(sixteen)).toBeCloseTo(total(four), 6);
    expect(total(four)).toBeCloseTo(SEA_WATER_DENSITY * GRAVITY * four.reduce((s, w) => s + w.amplitude ** 2 / 2, 0), 6);
    for (const lang of LANGS) {
      const answer = LESSON_TEXTS['airy-waves'].question!.answer[lang];
      const [from, to] = [...answer.matchAll(/([0-9]+[.,][0-9]+) m\b/g)].map((m) => Number(m[1].replace(',', '.')));
      expect(agrees(from, four[0].amplitude, 0.02)).toBe(true);
      expect(agrees(to, sixteen[0].amplitude, 0.04)).toBe(true);
      const [perWaveAfter, perWaveBefore] = [...answer.matchAll(/\b([0-9]{3})\b/g)].map((m) => Number(m[1]));
      expect(agrees(perWaveBefore, waveEnergy(four[0].amplitude), 0.05)).toBe(true);
      expect(agrees(perWaveAfter, waveEnergy(sixteen[0].amplitude), 0.05)).toBe(true);
      expect(agrees(1000 * numberAfter(answer, 'm₀ᴮ ≈'), total(four), 0.05)).toBe(true);
    }
    // Control: without the ½, E = ρ g a² would give about 800 J/m², not the card's 400.
    expect(agrees(400, SEA_WATER_DENSITY * GRAVITY * four[0].amplitude ** 2, 0.05)).toBe(false);
  });

  it('the band the waves sample holds 98.9 % of the spectrum’s m₀ (control: a planted 99 % is not it)', () => {
    const p = viewParams('airy-waves');
    const sea = seaStateFromParams({ ...p, choppiness: 1, fftSize: '128' });
    const draw = (energyBand?: [number, number]) =>
      drawGerstnerWaves({
        count: p.gerstnerCount,
        seed: p.seed,
        spectrum: frequencySpectrum(sea).density,
        spreading: () => 1,
        windDirection: 0,
        steepness: p.gerstnerSteepness,
        energyBand,
      });
    const share = 100 * (draw()[0].amplitude / draw([0, 1])[0].amplitude) ** 2;
    // The band's amplitude is the live model's: these are the view's waves.
    expect(draw()[0].amplitude).toBeCloseTo(gerstnerWavesFor(p)[0].amplitude, 12);
    for (const lang of LANGS) {
      expect(
        agrees(numberAfter(LESSON_TEXTS['airy-waves'].text[lang], '(?:of the band they sample,|de su banda \\()'), share, 5e-4),
        lang,
      ).toBe(true);
    }
    expect(agrees(99, share, 5e-4)).toBe(false);
  });
});

describe('group-velocity: c_g = dω/dk is c/2 in deep water, and the rings and the wedge rest on it', () => {
  const phaseSpeed = (k: number, depth?: number) => angularFrequency(k, depth) / k;

  it('the question’s Speed 0.25 is one of the time scale’s options (control: 0.3 is not)', () => {
    const options = (paramDefs.timeScale as { options: readonly string[] }).options;
    for (const lang of LANGS) {
      const q = LESSON_TEXTS['group-velocity'].question!;
      const speed = numberAfter(q.ask[lang], '\\) (?:to|en)');
      expect(options).toContain(String(speed));
      expect(numberAfter(q.answer[lang], '(?:Speed to|velocidad en)')).toBe(speed);
    }
    expect(options).not.toContain('0.3');
  });

  it('the code’s group velocity is half the phase speed in deep water, and ½ c (1 + 2kh / sinh 2kh) at depth h', () => {
    for (const k of [0.01, 0.1, 1, 10]) expect(groupVelocity(k) / phaseSpeed(k)).toBeCloseTo(0.5, 12);
    const cardFormula = (k: number, h: number) => 0.5 * phaseSpeed(k, h) * (1 + (2 * k * h) / Math.sinh(2 * k * h));
    for (const kh of [0.05, 0.3, 1, 3, 10]) expect(groupVelocity(kh / 10, 10)).toBeCloseTo(cardFormula(kh / 10, 10), 10);
    // Shallow water: c_g rises to c.
    expect(groupVelocity(0.001, 10) / phaseSpeed(0.001, 10)).toBeGreaterThan(0.999);
    // Control: a formula without the 2 in 2kh is not the code's.
    expect(Math.abs(groupVelocity(0.1, 10) - 0.5 * phaseSpeed(0.1, 10) * (1 + (0.1 * 10) / Math.sinh(2))) > 1e-3).toBe(true);
  });

  it('each ring of the stone’s guide stands where its waves have run r = c_g t, not c t', () => {
    const t = 12;
    const radii = crestRadii(t, { kMin: 0, kMax: 10, maxRadius: 1e4 });
    expect(radii.length).toBeGreaterThan(5);
    for (const r of radii) {
      const n = Math.round((GRAVITY * t * t) / (8 * Math.PI * r));
      expect(r).toBeCloseTo((GRAVITY * t * t) / (8 * Math.PI * n), 9);
      const k = (GRAVITY * t * t) / (4 * r * r);
      expect(groupVelocity(k) * t).toBeCloseTo(r, 9);
      // Control: at the phase speed those waves would have run twice as far.
      expect(Math.abs(phaseSpeed(k) * t - r)).toBeGreaterThan(0.9 * r);
    }
    for (const lang of LANGS) {
      expect(LESSON_TEXTS['group-velocity'].question!.answer[lang]).toContain('r = g t²/(8πn)');
      expect(cardText('group-velocity', lang)).toContain('k = g t²/(4 r²)');
    }
  });

  it('Kelvin’s half-angle arcsin(1/3) ≈ 19.47° follows from the code’s c_g/c = ½; a non-dispersive ratio 1 would fill the whole half-plane', () => {
    // Waves at angle ψ to the track, emitted a time τ ago, carry their energy n c cos… : in the boat's frame
    // the point lies at (−1 + n cos²ψ, n cos ψ sin ψ)·Uτ, and the wedge is the largest angle it reaches.
    const wedge = (n: number) => {
      let best = 0;
      for (let i = 1; i < 20000; i++) {
        const psi = (i / 20000) * (Math.PI / 2);
        best = Math.max(best, Math.atan2(n * Math.cos(psi) * Math.sin(psi), 1 - n * Math.cos(psi) ** 2));
      }
      return best;
    };
    const k = 0.3;
    const n = groupVelocity(k) / phaseSpeed(k);
    expect(wedge(n)).toBeCloseTo(KELVIN_HALF_ANGLE, 6);
    for (const lang of LANGS)
      expect(agrees(numberAfter(cardText('group-velocity', lang), '≈'), (wedge(n) * 180) / Math.PI, 0.001)).toBe(true);
    // Control: c_g = c (n = 1) gives a wedge near 90°, not 19.47°.
    expect(wedge(1)).toBeGreaterThan(1.5);
  });
});

describe('spectra-compared: the three spectra’s Hs and peak wavelengths at the view’s 10 m/s', () => {
  const cases = [
    { spectrum: 'phillips', en: 'Phillips', es: 'Phillips' },
    { spectrum: 'pierson-moskowitz', en: 'Pierson–Moskowitz', es: 'Pierson–Moskowitz' },
    { spectrum: 'jonswap', en: 'JONSWAP over 100 km', es: 'JONSWAP con 100 km' },
  ] as const;
  const text = (lang: Lang) => LESSON_TEXTS['spectra-compared'].text[lang];
  const seaOf = (spectrum: OceanParams['spectrum']) => seaStateFromParams({ ...viewParams('spectra-compared'), spectrum });

  it('the view is Phillips at 10 m/s over the default 100 km fetch', () => {
    const p = viewParams('spectra-compared');
    expect(p.spectrum).toBe('phillips');
    for (const lang of LANGS) {
      expect(numberAfter(text(lang), lang === 'en' ? 'At' : 'A')).toBe(p.windSpeed);
      expect(numberAfter(text(lang), 'JONSWAP (?:over|con)')).toBe(p.fetch);
    }
  });

  it.each(cases)('$spectrum: Hs = 4√m₀ and the peak wavelength on the card are the code’s', ({ spectrum, ...names }) => {
    const sea = seaOf(spectrum);
    const s = frequencySpectrum(sea);
    for (const lang of LANGS) {
      const rest = text(lang).slice(text(lang).lastIndexOf('10 m/s'));
      const match = new RegExp(`${names[lang]} ([0-9]+[.,][0-9]+) m (?:and a |and |y pico de |y )([0-9]+) m`).exec(rest);
      expect(match, `${spectrum} ${lang}`).not.toBeNull();
      const [hs, peak] = [match![1], match![2]].map((v) => Number(v.replace(',', '.')));
      expect(agrees(hs, 4 * Math.sqrt(s.m0), 0.03), `${spectrum} ${lang} Hs`).toBe(true);
      expect(agrees(peak, peakWavelength(sea), 0.01), `${spectrum} ${lang} peak`).toBe(true);
    }
    // Control: the card's Phillips numbers do not fit Pierson–Moskowitz.
    if (spectrum === 'pierson-moskowitz') expect(agrees(1.8, 4 * Math.sqrt(s.m0), 0.03)).toBe(false);
  });

  it('m₀ is the area under S, the Phillips peak is the code’s maximum, and α, β, γ and U19.5 are the code’s constants', () => {
    for (const spectrum of ['phillips', 'pierson-moskowitz'] as const) {
      const s = frequencySpectrum(seaOf(spectrum));
      let area = 0;
      for (let w = 0.01; w < 40; w += 1e-3) area += s.density(w + 5e-4) * 1e-3;
      expect(area / s.m0).toBeCloseTo(1, 3);
    }
    let best = 0;
    for (let w = 0.3; w < 3; w += 1e-5) if (phillips(w, 10) > phillips(best, 10)) best = w;
    expect(best).toBeCloseTo(phillipsPeak(10), 4);
    expect(PHILLIPS_ALPHA).toBe(PM_ALPHA);
    for (const lang of LANGS) {
      const all = cardText('spectra-compared', lang);
      expect(numberAfter(all, 'α =') * 1e-3).toBeCloseTo(PHILLIPS_ALPHA, 12);
      expect(numberAfter(all, 'β =')).toBe(PM_BETA);
      expect(numberAfter(all, 'γ =')).toBe(JONSWAP_GAMMA);
      expect(agrees(numberAfter(all, '\\((?:un )?'), 100 * (windAt19_5(1) - 1), 0.01)).toBe(true);
    }
    // Control: a planted β = 1 is not the code's.
    expect(1).not.toBe(PM_BETA);
  });

  it('JONSWAP’s α is not Phillips’ 8.1·10⁻³: it comes from the fetch, ≈ 0.010 at 10 m/s over 100 km (control: Phillips’ α does not fit)', () => {
    const p = viewParams('spectra-compared');
    const { alpha } = jonswapShape(p.windSpeed, p.fetch * 1000);
    for (const lang of LANGS) expect(agrees(numberAfter(text(lang), 'α ≈'), alpha, 0.05), lang).toBe(true);
    expect(agrees(PHILLIPS_ALPHA, alpha, 0.05)).toBe(false);
  });
});

describe('fft-transform: Hermitian amplitudes, log₂N butterfly stages, tiles', () => {
  const p = viewParams('fft-transform');
  const sea = seaStateFromParams(p);

  /** h̃(k, t) of every mode of a tile, from the code's packed spectrum (choppiness 0: spectra[0] = i·h̃). */
  const heights = (tile: SpectralTile, t: number) => {
    const s0 = evolveSpectra(tile, t, 0)[0];
    return (i: number) => ({ re: s0[2 * i + 1], im: -s0[2 * i] });
  };
  const hermitianError = (tile: SpectralTile, h: (i: number) => { re: number; im: number }) => {
    const n = tile.n;
    let worst = 0;
    let scale = 0;
    for (let b = 0; b < n; b++) {
      for (let a = 0; a < n; a++) {
        const here = h(b * n + a);
        const there = h(((n - b) % n) * n + ((n - a) % n));
        worst = Math.max(worst, Math.hypot(here.re - there.re, here.im + there.im));
        scale = Math.max(scale, Math.hypot(here.re, here.im));
      }
    }
    return worst / scale;
  };

  it('h̃(−k, t) = h̃*(k, t) for every mode of every tile; the first term alone, h̃₀(k) e^{iωt}, is not (control)', () => {
    const { tiles } = fftOceanSetup(sea);
    for (const tile of tiles) expect(hermitianError(tile, heights(tile, 3.7))).toBeLessThan(1e-12);
    const tile = tiles[0];
    const firstTermOnly = (i: number) => {
      const [c, s] = [Math.cos(tile.omega[i] * 3.7), Math.sin(tile.omega[i] * 3.7)];
      return { re: tile.h0[2 * i] * c - tile.h0[2 * i + 1] * s, im: tile.h0[2 * i] * s + tile.h0[2 * i + 1] * c };
    };
    expect(hermitianError(tile, firstTermOnly)).toBeGreaterThan(0.1);
  });

  it('a Hermitian spectrum transforms to a real signal (control: a non-Hermitian one does not)', () => {
    const n = 16;
    const spectrum = new Float64Array(2 * n);
    for (let a = 1; a < n / 2; a++) {
      const [re, im] = [Math.sin(3 * a), Math.cos(5 * a)];
      spectrum.set([re, im], 2 * a);
      spectrum.set([re, -im], 2 * (n - a));
    }
    const largestImaginary = (x: Float64Array) => Math.max(...Array.from({ length: n }, (_, o) => Math.abs(x[2 * o + 1])));
    expect(largestImaginary(stockhamInverse(spectrum, n))).toBeLessThan(1e-12);
    spectrum[2 * 3 + 1] += 1;
    expect(largestImaginary(stockhamInverse(spectrum, n))).toBeGreaterThan(0.1);
  });

  it('log₂N butterfly stages give the inverse DFT: 7 for N = 128, done in 4 GPU passes of radices 2, 4, 4, 4 (control: 6 stages do not)', () => {
    const n = Number(p.fftSize);
    for (const lang of LANGS) {
      const text = LESSON_TEXTS['fft-transform'].text[lang];
      expect(numberAfter(text, 'N =')).toBe(n);
      expect(numberAfter(text, '(?:mariposas en x y luego en z:|butterflies along x, then z:)')).toBe(Math.log2(n));
      expect(text).toContain(`(${lang === 'en' ? 'radices' : 'radios'} ${stockhamRadices(n).join(', ')})`);
      expect(numberAfter(text, ', (?:in|en)')).toBe(stockhamRadices(n).length);
    }
    const m = 32;
    const input = Float64Array.from({ length: 2 * m }, (_, i) => Math.sin(1.3 * i) + 0.2 * i);
    const dft = (o: number) => {
      let [re, im] = [0, 0];
      for (let a = 0; a < m; a++) {
        const [c, s] = [Math.cos((2 * Math.PI * a * o) / m), Math.sin((2 * Math.PI * a * o) / m)];
        re += input[2 * a] * c - input[2 * a + 1] * s;
        im += input[2 * a] * s + input[2 * a + 1] * c;
      }
      return [re, im];
    };
    const stages = (count: number) => {
      let data: Float64Array = input;
      for (let s = 0, half = 1; s < count; s++, half *= 2) data = stockhamStage(data, m, half);
      return data;
    };
    const error = (x: Float64Array) =>
      Math.max(...Array.from({ length: m }, (_, o) => Math.hypot(x[2 * o] - dft(o)[0], x[2 * o + 1] - dft(o)[1])));
    expect(error(stages(Math.log2(m)))).toBeLessThan(1e-9);
    expect(error(stages(Math.log2(m) - 1))).toBeGreaterThan(1);
  });

  it('three tiles in size ratios 4.73 and 4.46 (control: a planted 4.5 is not one of them)', () => {
    const layout = cascadeLayout(peakWavelength(sea), sea.fftSize);
    expect(layout).toHaveLength(3);
    expect(layout[0].size / layout[1].size).toBeCloseTo(TILE_RATIOS[0], 12);
    expect(layout[1].size / layout[2].size).toBeCloseTo(TILE_RATIOS[1], 12);
    for (const lang of LANGS) {
      const all = cardText('fft-transform', lang);
      const [first, second] = [...all.matchAll(/4[.,][0-9]{2}/g)].slice(0, 2).map((m) => Number(m[0].replace(',', '.')));
      expect([first, second]).toEqual([...TILE_RATIOS]);
    }
    expect(TILE_RATIOS).not.toContain(4.5);
  });

  it('the seed moves the crests, not the height: Hs = 4√(Σ|h̃|²) from 2.15 m at seed 1 to 2.25 m at seed 2; the panel’s 4√m₀ prints 2.25 m whatever the seed', () => {
    const drawnHs = (seed: number) => {
      let variance = 0;
      for (const tile of fftOceanSetup({ ...sea, seed }).tiles) {
        const h = heights(tile, 0);
        for (let i = 0; i < tile.n * tile.n; i++) variance += h(i).re ** 2 + h(i).im ** 2;
      }
      return 4 * Math.sqrt(variance);
    };
    expect(p.seed).toBe(1);
    for (const lang of LANGS) {
      const answer = LESSON_TEXTS['fft-transform'].question!.answer[lang];
      const [one, two, spectrumHs] = [...answer.matchAll(/([0-9]+[.,][0-9]+) m\b/g)].map((m) => Number(m[1].replace(',', '.')));
      expect(agrees(one, drawnHs(1), 0.005)).toBe(true);
      expect(agrees(two, drawnHs(2), 0.005)).toBe(true);
      // The physics panel prints 4√m₀ with two decimals.
      expect(spectrumHs.toFixed(2)).toBe((4 * Math.sqrt(frequencySpectrum(sea).m0)).toFixed(2));
    }
    // Control: 2.24, 4√m₀ cut rather than rounded, is not what the panel prints.
    expect((2.24).toFixed(2)).not.toBe((4 * Math.sqrt(frequencySpectrum(sea).m0)).toFixed(2));
    // Control: the two seeds' seas do differ, crest by crest.
    const [a, b] = [fftOceanSetup({ ...sea, seed: 1 }).tiles[0].h0, fftOceanSetup({ ...sea, seed: 2 }).tiles[0].h0];
    expect(a.some((v, i) => Math.abs(v - b[i]) > 1e-6)).toBe(true);
  });
});
