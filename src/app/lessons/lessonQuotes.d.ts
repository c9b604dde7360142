/** Built by scripts/build/lessonQuotes.ts from the files that lessonQuoteSources.ts names (Quote in quoteExtraction.ts). */
declare module 'virtual:oceano-lesson-quotes' {
  export const LESSON_QUOTES: Record<string, { file: string; firstLine: number; lastLine: number; text: string }>;
}
