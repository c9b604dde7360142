import { describe, expect, it } from 'vitest';
import { paramKeys } from '../../src/sim/params';
import { message, type MessageId } from '../../src/sim/message';
import { preferredLanguage, SPANISH_PARAM_LABELS, Translator } from '../../src/app/i18n';
import { parseUrlState } from '../../src/app/urlState';

describe('language', () => {
  it('follows the first browser language we speak, else English', () => {
    expect(preferredLanguage(['es-AR', 'en'])).toBe('es');
    expect(preferredLanguage(['fr-FR', 'ES'])).toBe('es');
    expect(preferredLanguage(['de', 'fr'])).toBe('en');
    expect(preferredLanguage([])).toBe('en');
  });

  it('has a Spanish label for every parameter, different from the English one where words differ', () => {
    const es = new Translator('es');
    const en = new Translator('en');
    for (const key of paramKeys) {
      expect(SPANISH_PARAM_LABELS[key], key).toBeTruthy();
      expect(es.paramLabel(key)).toBe(SPANISH_PARAM_LABELS[key]);
    }
    expect(es.paramLabel('swellAmplitude')).not.toBe(en.paramLabel('swellAmplitude'));
  });

  it('renders every notice of a bad URL in both languages, with its values in it', () => {
    const state = parseUrlState('?t=abc&seed=-1.5&swellAmplitude=1e9&bogus=1&fresnel=maybe&waterColor=red&sky=//x&cam=1&lang=fr&embed=2&preset=nope');
    expect(state.notices).toHaveLength(11);
    const es = state.notices.map((m) => new Translator('es').message(m));
    const en = state.notices.map((m) => new Translator('en').message(m));
    es.forEach((text, i) => expect(text).not.toBe(en[i]));
    expect(es.join('\n')).toContain('"swellAmplitude=1e9" está fuera de [0, 4] m; se limita a 4.');
    expect(en.join('\n')).toContain('"swellAmplitude=1e9" is outside [0, 4] m; clamped to 4.');
  });

  it('has both languages for every message id', () => {
    const ids: MessageId[] = ['skyLoadFailed', 'contextLost', 'shareCopied', 'shareFallback', 'webgl2Missing', 'startFailed'];
    for (const id of ids) {
      const m = message(id, { base: 'sky', url: 'http://x/?a', error: 'boom' });
      expect(new Translator('es').message(m)).not.toBe(new Translator('en').message(m));
    }
  });
});
