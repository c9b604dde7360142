import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { LESSONS } from '../../src/app/lessons/lessonCatalog';
import { LESSON_OUTLINE, SECTION_NAMES, type LessonSection } from '../../src/app/lessons/lessonOutline';
import { LESSON_QUOTE_SOURCES } from '../../src/app/lessons/lessonQuoteSources';

/** The doc this script writes, from the repository root. */
export const READING_PATH_DOC = 'docs/reading-the-code.md';

/**
 * The order a student reads the code in: the seed's sea in the shader, then the same sea on
 * the CPU, then the spectral sea, then the light; the grid and the water that answers last.
 * A course chapter no part names goes to the last part, so a new chapter is never dropped.
 */
const PARTS: { title: string; why: string; sections: LessonSection[] }[] = [
  {
    title: "The seed's sea, in the shader",
    why: 'A flat grid, displaced in the vertex shader by a swell and two heightmaps of value noise, with normals from fabricated neighbours.',
    sections: ['surface', 'motion', 'noise', 'normals'],
  },
  {
    title: 'The same sea on the CPU',
    why: 'The boat needs the height where the GPU draws it: a TypeScript twin of the shader, evaluated at the hull.',
    sections: ['boat'],
  },
  {
    title: 'The spectral sea (FFT), and the other wave models',
    why: 'A sea made from a measured spectrum and summed by FFT, then Gerstner waves, the models side by side, and the running sea measured against theory.',
    sections: ['spectral', 'gerstner', 'compare', 'physics'],
  },
  {
    title: 'The light',
    why: 'The sky as a cube map, reflection weighted by Fresnel, the sun on a rough sea, and what changes under the water.',
    sections: ['envmap', 'optics', 'underwater'],
  },
  {
    title: 'The grid to the horizon',
    why: 'Which chunks of the grid are drawn, at what detail, and how the sea reaches the horizon.',
    sections: ['lod', 'culling', 'horizon'],
  },
  {
    title: 'Water that answers',
    why: "The boat's Kelvin wake and the interactive waves.",
    sections: ['wake', 'interactive'],
  },
];

/** The reading path as Markdown: every lesson that quotes code, in the parts' order, then the course's. */
export function readingPathMarkdown(): string {
  const placed = new Set(PARTS.flatMap((part) => part.sections));
  const lastPart = PARTS[PARTS.length - 1];
  const sectionsOf = (part: (typeof PARTS)[number]) =>
    part === lastPart
      ? [...part.sections, ...(Object.keys(SECTION_NAMES) as LessonSection[]).filter((s) => !placed.has(s))]
      : part.sections;
  const lines = [
    '# Reading the code',
    '',
    "A path through the code in the order to read it: the seed's sea from the shader to its CPU twin,",
    'then the spectral sea, then the light. Each step is the code a lesson card quotes',
    '(`src/app/lessons/lessonQuoteSources.ts`): open the lesson (`?lesson=ID`) beside the file, and',
    'read from the line that starts the quote. The concept → file map is the',
    "[README's](../README.md#where-each-concept-lives).",
    '',
    'This file is written by `npx tsx scripts/build/readingPath.ts` from the quote sources;',
    '`tests/unit/repo/docs.test.ts` fails when it is out of date.',
  ];
  let step = 0;
  for (const [index, part] of PARTS.entries()) {
    lines.push('', `## ${index + 1}. ${part.title}`, '', part.why, '');
    for (const section of sectionsOf(part)) {
      const lessons = LESSONS.filter((lesson) => LESSON_OUTLINE[lesson.id]?.section === section && LESSON_QUOTE_SOURCES[lesson.id]);
      if (lessons.length === 0) continue;
      lines.push(`**${SECTION_NAMES[section].en}**`, '');
      for (const lesson of lessons) {
        const source = LESSON_QUOTE_SOURCES[lesson.id];
        step++;
        lines.push(
          `${step}. [\`${source.file}\`](../${source.file}), from \`${source.from.replace(/`/g, "'")}\` (lesson \`${lesson.id}\`)`,
        );
      }
      lines.push('');
    }
    if (lines[lines.length - 1] === '') lines.pop();
  }
  return `${lines.join('\n')}\n`;
}

if (process.argv[1] && import.meta.url === `file://${process.argv[1]}`) {
  writeFileSync(join(import.meta.dirname, '..', '..', READING_PATH_DOC), readingPathMarkdown());
}
