import wake from '../../../shaders/wake.glsl?raw';

/**
 * The wake's GLSL (chunk `oceano_wake`, src/render/shaders/lateChunks.ts), fetched the first
 * time the wake or the interactive waves are switched on, or the GPU probe runs: most views never
 * draw a wake, and its loops are a large part of the page's shader text.
 */
export const wakeChunk = wake;
