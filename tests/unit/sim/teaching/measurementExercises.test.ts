import { describe, expect, it } from 'vitest';
import { findLesson, lessonView } from '../../../../src/app/lessons/lessonCatalog';
import { EXERCISE_LESSONS } from '../../../../src/app/lessons/lessonOutline';
import { exerciseFor, MEASUREMENT_EXERCISES, withinTolerance } from '../../../../src/sim/teaching/measurementExercises';
import type { OceanParams } from '../../../../src/sim/params/params';

/** A lesson's own parameters, with `change` over them. */
function paramsOf(lesson: string, change: Partial<OceanParams> = {}): OceanParams {
  return { ...lessonView(findLesson(lesson)!).params, ...change };
}
const expected = (lesson: string, change: Partial<OceanParams> = {}) => exerciseFor(lesson)!.expected(paramsOf(lesson, change));

// Independent published forms, written out by hand here.
const g = 9.81;
/** Pierson & Moskowitz (1964): Hs = 0.209 U19.5²/g, U19.5 = 1.026 U10 (Stewart 2008, §16.3). */
const pmHs = (u10: number) => (0.209 * (1.026 * u10) ** 2) / g;
/** Pierson & Moskowitz: ωp = 0.877 g/U19.5, Tp = 2π/ωp. */
const pmTp = (u10: number) => (2 * Math.PI * 1.026 * u10) / (0.877 * g);
/** Hasselmann et al. (1973), JONSWAP: fp = 3.5 (g/U10)(g F/U10²)^−0.33, Tp = 1/fp. */
const jonswapTp = (u10: number, fetchMetres: number) => 1 / (3.5 * (g / u10) * ((g * fetchMetres) / u10 ** 2) ** -0.33);

describe('measurement exercises: theory from the live parameters', () => {
  it('Hs against Pierson–Moskowitz’s 0.209 U19.5²/g, at the lesson’s wind and at another (within 1 %)', () => {
    expect(expected('fft-calm') / pmHs(4) - 1).toBeCloseTo(0, 2);
    expect(expected('fft-calm', { windSpeed: 7 }) / pmHs(7) - 1).toBeCloseTo(0, 2);
    expect(expected('physics-panel') / pmHs(10) - 1).toBeCloseTo(0, 2);
    expect(expected('physics-panel', { windSpeed: 15 }) / pmHs(15) - 1).toBeCloseTo(0, 2);
    // The gale preset's spectrum is the default, Pierson–Moskowitz: U = 20 m/s gives 8.97 m by hand.
    expect(pmHs(20)).toBeCloseTo(8.97, 2);
    expect(Math.abs(expected('fft-gale') / pmHs(20) - 1)).toBeLessThan(0.01);
    // Control: the wind changed, the value follows it (Hs ∝ U²), never a constant.
    expect(expected('fft-gale', { windSpeed: 10 }) / expected('fft-gale')).toBeCloseTo(0.25, 6);
  });

  it('Tp against Pierson–Moskowitz’s ωp = 0.877 g/U19.5 and JONSWAP’s fetch law (Hasselmann et al. 1973, within 3 %)', () => {
    expect(pmTp(10)).toBeCloseTo(7.49, 2);
    expect(Math.abs(expected('fft-fresh-breeze') / pmTp(10) - 1)).toBeLessThan(0.001);
    expect(Math.abs(expected('fft-fresh-breeze', { windSpeed: 6 }) / pmTp(6) - 1)).toBeLessThan(0.001);
    // 15 m/s over 20 km: 4.08 s by the published fit's exponent 0.33 (the code's 22 (g²/U F)^⅓ gives 4.17 s).
    expect(Math.abs(expected('fft-short-fetch') / jonswapTp(15, 20_000) - 1)).toBeLessThan(0.03);
    expect(Math.abs(expected('fft-short-fetch', { fetch: 50 }) / jonswapTp(15, 50_000) - 1)).toBeLessThan(0.03);
    expect(expected('fft-short-fetch', { fetch: 50 })).toBeGreaterThan(expected('fft-short-fetch') * 1.2);
  });

  it('the wake’s transverse wavelength is 2πU²/g: 10.25 m at 4 m/s, 23.06 m at 6 m/s', () => {
    expect(expected('kelvin-wake')).toBeCloseTo(10.25, 2);
    expect(expected('kelvin-wake', { boatSpeed: 6 })).toBeCloseTo(23.06, 2);
  });
});

describe('the tolerance check', () => {
  it('passes a value just inside and fails one just outside, on both sides (the negative control)', () => {
    for (const exercise of MEASUREMENT_EXERCISES) {
      // The stone's exercises are timed from its fall: 12 s after it.
      const theory = exercise.expected(paramsOf(exercise.lesson), { stoneAge: 12 });
      const t = exercise.tolerance;
      expect(withinTolerance(theory * (1 + 0.99 * t), theory, t), exercise.lesson).toBe(true);
      expect(withinTolerance(theory * (1 - 0.99 * t), theory, t), exercise.lesson).toBe(true);
      expect(withinTolerance(theory * (1 + 1.01 * t), theory, t), exercise.lesson).toBe(false);
      expect(withinTolerance(theory * (1 - 1.01 * t), theory, t), exercise.lesson).toBe(false);
    }
    expect(withinTolerance(Number.NaN, 1, 0.1)).toBe(false);
  });

  it('fails the usual slips: Tz typed for Tp, half a wavelength, twice Hs', () => {
    const tpExercise = exerciseFor('fft-fresh-breeze')!;
    // Pierson–Moskowitz's Tz/Tp = 0.710 (DNV-RP-C205).
    const tp = tpExercise.expected(paramsOf('fft-fresh-breeze'));
    expect(withinTolerance(0.71 * tp, tp, tpExercise.tolerance)).toBe(false);
    const wake = exerciseFor('kelvin-wake')!;
    const lambda = wake.expected(paramsOf('kelvin-wake'));
    expect(withinTolerance(lambda / 2, lambda, wake.tolerance)).toBe(false);
    const hs = exerciseFor('physics-panel')!;
    const h = hs.expected(paramsOf('physics-panel'));
    expect(withinTolerance(2 * h, h, hs.tolerance)).toBe(false);
  });

  it('every exercise is a lesson’s, one per lesson, and lessonOutline’s list of them says the same', () => {
    const ids = MEASUREMENT_EXERCISES.map((exercise) => exercise.lesson);
    for (const id of ids) expect(findLesson(id), id).not.toBeNull();
    expect(new Set(ids).size).toBe(ids.length);
    expect([...EXERCISE_LESSONS].sort()).toEqual([...ids].sort());
  });
});
