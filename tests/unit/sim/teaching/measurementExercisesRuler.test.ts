import { describe, expect, it } from 'vitest';
import { findLesson, lessonView } from '../../../../src/app/lessons/lessonCatalog';
import { EXERCISE_LESSONS } from '../../../../src/app/lessons/lessonOutline';
import { exerciseFor, withinTolerance, type ExerciseMoment } from '../../../../src/sim/teaching/measurementExercises';
import type { OceanParams } from '../../../../src/sim/params/params';

/** A lesson's own parameters, with `change` over them. */
function paramsOf(lesson: string, change: Partial<OceanParams> = {}): OceanParams {
  return { ...lessonView(findLesson(lesson)!).params, ...change };
}
const at = (stoneAge: number | null): ExerciseMoment => ({ stoneAge });
const expected = (lesson: string, moment: ExerciseMoment = at(null), change: Partial<OceanParams> = {}) =>
  exerciseFor(lesson)!.expected(paramsOf(lesson, change), moment);

const g = 9.81;
const RULER_LESSONS = ['wake-turn', 'iwave-compare', 'iwave-stone', 'group-velocity'];

describe('ruler exercises: theory from the live parameters and the live clock', () => {
  it('wake-turn: R = U/ω, by hand 4 / (3π/180) = 76.39 m; 6 m/s at 2°/s gives 171.89 m', () => {
    expect(expected('wake-turn')).toBeCloseTo(76.39, 2);
    expect(expected('wake-turn', at(null), { boatSpeed: 6, boatTurnRate: 2 })).toBeCloseTo(171.89, 2);
    // A turn to port is the same circle on the other side.
    expect(expected('wake-turn', at(null), { boatTurnRate: -3 })).toBeCloseTo(76.39, 2);
  });

  // c = √(g/1.5) = 2.557 m/s: by hand 25.57 m at 10 s, 15.34 m at 6 s; no stone, no theory.
  it('iwave-compare: the ring’s radius is r = c t', () => {
    const c = Math.sqrt(g / 1.5);
    expect(c).toBeCloseTo(2.557, 3);
    expect(expected('iwave-compare', at(10))).toBeCloseTo(25.57, 2);
    expect(expected('iwave-compare', at(6))).toBeCloseTo(15.34, 2);
    expect(expected('iwave-compare', at(null))).toBeNaN();
  });

  // At 12 s the outermost marked crests are n = 3 and 4 (n = 2 is longer than the grid carries):
  // Δr = g t²/(8π)(1/3 − 1/4) = 4.68 m; at 10 s n = 2 and 3, 6.51 m.
  it('iwave-stone: the outer crests’ spacing is Cauchy–Poisson’s', () => {
    // Hand computation: g t²/(8π) = 56.21 m at 12 s; k₂ = 16π²·4/(g t²) = 0.447 rad/m, below the band's 2π/10 = 0.63; k₃ = 1.006 inside it.
    const scale = (t: number) => (g * t * t) / (8 * Math.PI);
    expect(scale(12)).toBeCloseTo(56.21, 2);
    expect(expected('iwave-stone', at(12))).toBeCloseTo(scale(12) * (1 / 3 - 1 / 4), 2);
    expect(expected('iwave-stone', at(12))).toBeCloseTo(4.68, 2);
    // At 10 s, k₂ = 16π²·4/(g·100) = 0.644 rad/m: inside the band, so the outer pair is n = 2, 3.
    expect(expected('iwave-stone', at(10))).toBeCloseTo(scale(10) * (1 / 2 - 1 / 3), 2);
    expect(expected('iwave-stone', at(10))).toBeCloseTo(6.51, 2);
    expect(expected('iwave-stone', at(null))).toBeNaN();
  });
});

describe('ruler exercises: the tolerance check', () => {
  it('passes a value just inside and fails one just outside, on both sides (the negative control)', () => {
    for (const lesson of RULER_LESSONS) {
      const exercise = exerciseFor(lesson)!;
      const theory = exercise.expected(paramsOf(lesson), at(12));
      const t = exercise.tolerance;
      expect(withinTolerance(theory * (1 + 0.99 * t), theory, t), lesson).toBe(true);
      expect(withinTolerance(theory * (1 - 0.99 * t), theory, t), lesson).toBe(true);
      expect(withinTolerance(theory * (1 + 1.01 * t), theory, t), lesson).toBe(false);
      expect(withinTolerance(theory * (1 - 1.01 * t), theory, t), lesson).toBe(false);
    }
  });

  // The diameter for the radius, ω left in degrees, the ring read at the wrong moment, a crest’s radius or two spacings.
  it('fails the usual slips', () => {
    const turn = exerciseFor('wake-turn')!;
    const r = turn.expected(paramsOf('wake-turn'));
    expect(withinTolerance(2 * r, r, turn.tolerance)).toBe(false);
    expect(withinTolerance(4 / 3, r, turn.tolerance)).toBe(false);
    const ring = exerciseFor('iwave-compare')!;
    // A ring read at 10 s checked against 12 s: the clock matters.
    expect(
      withinTolerance(ring.expected(paramsOf('iwave-compare'), at(10)), ring.expected(paramsOf('iwave-compare'), at(12)), ring.tolerance),
    ).toBe(false);
    const stone = exerciseFor('iwave-stone')!;
    const spacing = stone.expected(paramsOf('iwave-stone'), at(12));
    expect(withinTolerance(2 * spacing, spacing, stone.tolerance)).toBe(false);
    expect(withinTolerance((g * 144) / (8 * Math.PI * 3), spacing, stone.tolerance)).toBe(false);
  });

  it('the four are listed as lessons with exercises, each with the ruler', () => {
    for (const lesson of RULER_LESSONS) {
      expect(EXERCISE_LESSONS).toContain(lesson);
      expect(exerciseFor(lesson)!.tool).toBe('ruler');
    }
    expect(exerciseFor('horizon')).toBeNull();
  });
});

describe('group-velocity: the outermost marked crest has run c_g t', () => {
  const group = (t: number | null) => exerciseFor('group-velocity')!.expected(paramsOf('group-velocity'), at(t));
  // 18.74 m at 12 s (n = 3), 19.52 m at 10 s (n = 2): the two theories agree.
  it('equals ½√(g/k)·t by hand, and Cauchy–Poisson’s r_n', () => {
    const k3 = (16 * Math.PI ** 2 * 9) / (g * 144);
    expect(k3).toBeCloseTo(1.006, 3);
    expect(group(12)).toBeCloseTo(0.5 * Math.sqrt(g / k3) * 12, 6);
    expect(group(12)).toBeCloseTo((g * 144) / (8 * Math.PI * 3), 6);
    expect(group(12)).toBeCloseTo(18.74, 2);
    const k2 = (16 * Math.PI ** 2 * 4) / (g * 100);
    expect(group(10)).toBeCloseTo(0.5 * Math.sqrt(g / k2) * 10, 6);
    expect(group(10)).toBeCloseTo(19.52, 2);
    expect(group(null)).toBeNaN();
  });

  it('fails the slip of the phase speed (c t, twice as far) and passes/fails at the tolerance’s edge', () => {
    const exercise = exerciseFor('group-velocity')!;
    const r = group(12);
    expect(withinTolerance(2 * r, r, exercise.tolerance)).toBe(false);
    expect(withinTolerance(r * (1 + 0.99 * exercise.tolerance), r, exercise.tolerance)).toBe(true);
    expect(withinTolerance(r * (1 - 1.01 * exercise.tolerance), r, exercise.tolerance)).toBe(false);
  });
});
