import { describe, expect, it } from 'vitest';
import { GLOSSARY, type GlossaryTerm } from '../../../../src/app/lessons/glossary';
import { firstTermOccurrences, sharedWordForms, termsMissingFrom } from '../../../../src/app/lessons/glossaryLinks';
import { LESSON_TEXTS } from '../../../../src/app/lessons/lessonTexts';

const LANGUAGES = ['en', 'es'] as const;
const cardTexts = (language: 'en' | 'es') => Object.values(LESSON_TEXTS).map((card) => card.text[language]);
const sentences = (text: string) => text.split(/[.!?](?:\s|$)/).filter((s) => s.trim() !== '').length;
const term = (en: string[], es: string[]): GlossaryTerm => ({
  words: { en, es },
  definition: { en: 'A planted term.', es: 'Un término plantado.' },
});

describe('the glossary', () => {
  it('has at least 30 terms, each with its words and a one-sentence definition in both languages', () => {
    expect(Object.keys(GLOSSARY).length).toBeGreaterThanOrEqual(30);
    for (const [key, entry] of Object.entries(GLOSSARY) as [string, GlossaryTerm][]) {
      for (const language of LANGUAGES) {
        expect(entry.words[language].length, `${key} ${language}`).toBeGreaterThan(0);
        for (const form of entry.words[language]) expect(form.trim(), `${key} ${language}`).toBe(form);
        const definition = entry.definition[language];
        expect(definition, `${key} ${language}`).toMatch(/^[A-ZÁÉÍÓÚÑσHFnLa-z].{20,}\.$/su);
        expect(sentences(definition), `${key} ${language}: one sentence`).toBe(1);
      }
      // The two languages are two texts, not one copied.
      expect(entry.definition.es, key).not.toBe(entry.definition.en);
    }
  });

  // Control: a planted term that occurs nowhere is reported.
  it('every term occurs in at least one card’s text in each language', () => {
    for (const language of LANGUAGES) expect(termsMissingFrom(cardTexts(language), language, GLOSSARY), language).toEqual([]);
    const planted = { ...GLOSSARY, plantedTerm: term(['bathysphere'], ['batisfera']) };
    for (const language of LANGUAGES) expect(termsMissingFrom(cardTexts(language), language, planted), language).toEqual(['plantedTerm']);
    // A term present in English only is missing in Spanish alone.
    const halfPlanted = { ...GLOSSARY, plantedTerm: term(['wireframe drawing', 'wireframe'], ['batisfera']) };
    expect(termsMissingFrom(cardTexts('en'), 'en', { plantedTerm: halfPlanted.plantedTerm })).toEqual([]);
    expect(termsMissingFrom(cardTexts('es'), 'es', halfPlanted)).toEqual(['plantedTerm']);
  });

  it('no two terms share a word form in one language, whatever its case (control: a planted duplicate is found)', () => {
    expect(sharedWordForms(GLOSSARY)).toEqual([]);
    expect(sharedWordForms({ ...GLOSSARY, planted: term(['Normals'], ['prueba']) })).toEqual(['en: Normals']);
  });
});

describe('linking the terms in a card', () => {
  it('links each term once, at its first occurrence, as a whole word; the longer term wins where two start together', () => {
    const text = 'The Kelvin wake trails the boat; its wake is a wedge. Wakeful normals, and normal incidence, and one normal.';
    const found = firstTermOccurrences(text, 'en', GLOSSARY).map(({ key, start, end }) => [key, text.slice(start, end)]);
    expect(found).toEqual([
      ['kelvinWake', 'Kelvin wake'],
      ['wake', 'wake'],
      ['normal', 'normals'],
      ['normalIncidence', 'normal incidence'],
    ]);
    // Control: "Wakeful" is no wake, and no occurrence is linked twice.
    expect(found.filter(([key]) => key === 'wake')).toHaveLength(1);
    expect(found.map(([, words]) => words)).not.toContain('Wake');
  });

  it('finds the Spanish forms, accents and plurals included, and not inside another word', () => {
    const text = 'Los vértices de la malla leen los mapas de alturas; una redonda no es una red.';
    const found = firstTermOccurrences(text, 'es', GLOSSARY).map(({ key, start, end }) => [key, text.slice(start, end)]);
    expect(found).toEqual([
      ['vertex', 'vértices'],
      ['mesh', 'malla'],
      ['heightmap', 'mapas de alturas'],
      ['lattice', 'red'],
    ]);
    expect(firstTermOccurrences('redonda', 'es', GLOSSARY)).toEqual([]);
  });

  it('leaves a form alone inside a phrase where it means something else (control: without that phrase it is linked)', () => {
    const text = 'Bright colours roll off towards white; the boat’s roll follows the slope.';
    const rolls = (glossary: Record<string, GlossaryTerm>) =>
      firstTermOccurrences(text, 'en', glossary)
        .filter((o) => o.key === 'roll')
        .map((o) => o.start);
    expect(rolls(GLOSSARY)).toEqual([text.indexOf('roll follows')]);
    expect(rolls({ roll: { ...GLOSSARY.roll, otherSenses: {} } })).toEqual([text.indexOf('roll off')]);
  });

  it('every card links at least one term in each language', () => {
    for (const [id, card] of Object.entries(LESSON_TEXTS)) {
      for (const language of LANGUAGES)
        expect(firstTermOccurrences(card.text[language], language, GLOSSARY).length, `${id} ${language}`).toBeGreaterThan(0);
    }
  });
});
