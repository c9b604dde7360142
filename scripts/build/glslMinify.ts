/**
 * The shader text the built page carries: GLSL with its comments, indentation and blank
 * lines removed. Our shaders explain themselves at length for the course (half their bytes
 * are comments); the browser's compiler needs none of it, so the build sends only the code.
 * Every directive keeps its own line (the preprocessor is line-based) and every other line
 * keeps its tokens in order, so the compiled program is the same.
 */
export function minifyGlsl(source: string): string {
  return source
    .replace(/\/\*[\s\S]*?\*\//g, ' ')
    .replace(/\/\/[^\n]*/g, '')
    .split('\n')
    .map((line) => line.trim())
    .filter((line) => line.length > 0)
    .join('\n');
}

/** Shader files imported as text (`?raw`) from shaders/: what the build minifies. */
export const SHADER_RAW_IMPORT = /[\\/]shaders[\\/].+\.(glsl|vert|frag)\?raw$/;
