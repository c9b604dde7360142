import { describe, expect, it } from 'vitest';
import { defaultParams, paramDefs, paramKeys, parseParamText, validateParam } from '../../../../src/sim/params/params';
import { isValidTime } from '../../../../src/sim/params/simulationTime';
import { formatUrlState, parseUrlState } from '../../../../src/app/url/urlState';

/**
 * The URL, the element's attributes and the API validate with one rule each, so a value
 * accepted in one place is not refused in another.
 */
describe('one validation for every entry point', () => {
  it('accepts a time in the API exactly when the URL accepts it', () => {
    for (const t of [-5, -0.001, 0, 12.5, 1e9, 1e9 + 1, 1e300, Infinity, NaN]) {
      expect(isValidTime(t), `t=${t}`).toBe(parseUrlState(`?t=${t}`).time !== null);
    }
    expect(isValidTime(-5)).toBe(false);
    expect(isValidTime(1e300)).toBe(false);
    expect(isValidTime('3')).toBe(false);
  });

  it('takes every parameter in its URL text form through setParams validation too', () => {
    const query = new URLSearchParams(
      formatUrlState({
        params: defaultParams(),
        time: 1,
        camera: { position: [0, 9, 40], target: [0, 0, -60] },
        language: 'en',
        sky: null,
        boat: null,
        embed: false,
      }),
    );
    for (const key of paramKeys) {
      const text = query.get(key)!;
      const { value, notice } = parseParamText(key, text);
      expect(notice).toBeUndefined();
      // The URL's text itself, where the API takes a string (colours, choices).
      const kind = paramDefs[key].kind;
      if (kind === 'color' || kind === 'choice') expect(validateParam(key, text)).toBe(value);
      else expect(validateParam(key, value)).toBe(value);
    }
    expect(validateParam('waterColor', '06283a')).toBe('#06283a');
    expect(validateParam('waterColor', '#06283A')).toBe('#06283a');
    for (const bad of ['06283', '#06283', 'blue', '##06283a', ''])
      expect(() => validateParam('waterColor', bad)).toThrow(/must be a colour/);
  });

  it('reads lang by its primary subtag: es-ES, es_MX and ES are Spanish, fr-FR is refused', () => {
    for (const tag of ['es', 'es-ES', 'es_MX', 'ES', 'en-GB']) {
      const state = parseUrlState(`?lang=${tag}`);
      expect(state.language, tag).toBe(tag.slice(0, 2).toLowerCase());
      expect(state.notices).toEqual([]);
    }
    for (const tag of ['fr-FR', 'e', 'spanish', '']) {
      expect(parseUrlState(`?lang=${tag}`).language, tag).toBeNull();
    }
  });
});

describe('boat state in a link', () => {
  it('writes the boat state so that it reads back bit for bit, and refuses a bad one with a notice', async () => {
    const { formatBoatState, parseBoatState } = await import('../../../../src/app/url/urlState');
    const b = {
      x: 6.36123456789,
      z: -5.3312345,
      heading: { value: 5.1, velocity: -0.01 },
      heave: { value: 1.0001, velocity: 0.3 },
      pitch: { value: 0.01, velocity: 1e-17 },
      roll: { value: -0.02, velocity: 0 },
    };
    expect(parseBoatState(formatBoatState(b))).toEqual(b);
    expect(parseUrlState(`?t=3&boatState=${formatBoatState(b)}`).boatState).toEqual(b);
    const bad = parseUrlState('?t=3&boatState=1,2,3');
    expect(bad.boatState).toBeNull();
    expect(bad.notices.map((n) => n.id)).toEqual(['boatStateInvalid']);
    expect(parseBoatState('3000,0,0,0,0,0,0,0,0,0')).toBeNull();
  });
});
