/**
 * The negative control of the sine parity tests: shaders/sinTurns.glsl's exact sine replaced
 * by the driver's own `sin`, which GLSL only promises to about 2^-11. The replacement is made
 * in the shader's text, so the shipped shader carries no branch for it.
 */
export const SIN_TURNS_HEADER = 'float sinTurns(float turns) {';
export const NATIVE_SIN_TURNS = `${SIN_TURNS_HEADER}\n  return sin(6.283185307179586 * turns);\n}\nfloat sinTurnsExact(float turns) {`;

/** The source with sinTurns answering the driver's sine; throws where the source has no sinTurns to replace. */
export function withNativeSine(source: string): string {
  if (!source.includes(SIN_TURNS_HEADER)) throw new Error('No sinTurns in this shader: the native-sine control would test nothing.');
  return source.replace(SIN_TURNS_HEADER, NATIVE_SIN_TURNS);
}
