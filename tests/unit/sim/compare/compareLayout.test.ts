import { describe, expect, it } from 'vitest';
import {
  COMPARE_OFF,
  compareModelNames,
  compareOrderings,
  compareStrips,
  dividerPositions,
} from '../../../../src/sim/compare/compareLayout';
import { paramDefs, validateParam, ParamError } from '../../../../src/sim/params/params';
import { parseSettings } from '../../../../src/app/url/urlState';
import { Translator } from '../../../../src/app/language/i18n';

describe('compare: which models, in which order', () => {
  it('lists every ordered pair and triple of distinct models, and nothing else', () => {
    const options = compareOrderings(['seed', 'fft', 'gerstner']);
    expect(options).toHaveLength(6 + 6);
    expect(new Set(options).size).toBe(options.length);
    for (const option of options) {
      const names = option.split(',');
      expect(names.length === 2 || names.length === 3).toBe(true);
      expect(new Set(names).size).toBe(names.length);
    }
    expect(options).toContain('gerstner,seed');
    expect(options).toContain('seed,gerstner,fft');
    expect(paramDefs.compare.options).toEqual([COMPARE_OFF, ...options]);
  });

  it('reads the models back in order; off is none', () => {
    expect(compareModelNames('fft,seed')).toEqual(['fft', 'seed']);
    expect(compareModelNames(COMPARE_OFF)).toEqual([]);
  });

  it('the API refuses a model twice, an unknown model and one model alone, naming the key', () => {
    for (const bad of ['seed,seed', 'seed,waves', 'seed', 'seed,gerstner,fft,seed', 'seed, gerstner']) {
      expect(() => validateParam('compare', bad), bad).toThrow(ParamError);
      expect(() => validateParam('compare', bad), bad).toThrow(/"compare" must be one of off, seed,fft/);
    }
    expect(validateParam('compare', 'fft,gerstner')).toBe('fft,gerstner');
  });

  it('a bad compare= in the URL gives a notice and no split; compareSplit out of range is clamped with a notice', () => {
    const state = parseSettings([
      ['compare', 'seed,seed'],
      ['compareSplit', '1.5'],
    ]);
    expect(state.params.compare).toBe(COMPARE_OFF);
    expect(state.params.compareSplit).toBe(1);
    const text = state.notices.map((m) => new Translator('en').message(m));
    expect(text[0]).toMatch(/^"compare=seed,seed" is not one of off, seed,fft, .*; using off\.$/);
    expect(text[1]).toMatch(/compareSplit/);
    expect(parseSettings([['compare', 'gerstner,fft,seed']]).notices).toEqual([]);
  });
});

describe('compare: the strips each model draws', () => {
  it('tiles the width without gap or overlap, with each divider on round(f · width)', () => {
    for (const width of [1, 7, 320, 1281]) {
      for (const [count, a, b] of [
        [2, 0.5, 0.75],
        [2, 0, 0],
        [2, 1, 1],
        [3, 0.3, 0.65],
        [3, 0.9, 0.2],
        [3, 0.3333, 0.6667],
      ] as const) {
        const strips = compareStrips(count, a, b, width);
        expect(strips).toHaveLength(count);
        expect(strips[0].x0).toBe(0);
        expect(strips.at(-1)!.x1).toBe(width);
        for (let i = 0; i + 1 < strips.length; i++) expect(strips[i].x1).toBe(strips[i + 1].x0);
        for (const s of strips) expect(s.x1).toBeGreaterThanOrEqual(s.x0);
        expect(strips[0].x1).toBe(Math.round(a * width));
      }
    }
    expect(compareStrips(2, 0.4, 0.75, 320)).toEqual([
      { x0: 0, x1: 128 },
      { x0: 128, x1: 320 },
    ]);
  });

  it('puts the dividers in the free columns [from, to) while the outer strips still reach the edges', () => {
    // A 1366-px view whose lessons drawer ends at 284 and panel begins at 1109.
    const strips = compareStrips(3, 1 / 3, 2 / 3, 1366, 284, 1109);
    expect(strips).toEqual([
      { x0: 0, x1: 559 },
      { x0: 559, x1: 834 },
      { x0: 834, x1: 1366 },
    ]);
    for (const edge of [strips[0].x1, strips[1].x1]) expect(edge > 284 && edge < 1109).toBe(true);
    // Control: laid over the whole width, the third model's divider falls under the panel.
    expect(compareStrips(3, 1 / 3, 0.85, 1366)[1].x1).toBeGreaterThan(1109);
  });

  it('keeps the second divider right of the first; ignores it with two models', () => {
    expect(dividerPositions(3, 0.9, 0.2)).toEqual([0.9, 0.9]);
    expect(dividerPositions(3, 0.3, 0.65)).toEqual([0.3, 0.65]);
    expect(dividerPositions(2, 0.3, 0.1)).toEqual([0.3]);
    expect(dividerPositions(1, 0.3, 0.1)).toEqual([]);
  });
});
