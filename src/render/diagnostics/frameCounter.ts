import { bufferDataBytes, bufferSubDataBytes, texImage2DBytes, texImage3DBytes } from './uploadBytes';

/** What one frame asks of the GPU, counted from its WebGL calls; the same on every machine. */
export interface FrameCounts {
  /** drawArrays, drawElements, their instanced and ranged forms, and each multi-draw call (one submission each). */
  drawCalls: number;
  /** Draws into a framebuffer other than the previous draw's (the first draw of the frame starts one). */
  passes: number;
  /** useProgram with a program other than the one bound. */
  programSwitches: number;
  /** Bytes carried from the CPU by texture and buffer uploads (allocations and copies between GPU buffers carry none). */
  bytesUploaded: number;
  /** Upload calls that carried bytes. */
  uploads: number;
}

type Method = (...args: unknown[]) => unknown;

const DRAWS = ['drawArrays', 'drawElements', 'drawArraysInstanced', 'drawElementsInstanced', 'drawRangeElements'] as const;
const MULTI_DRAWS = [
  'multiDrawArraysWEBGL',
  'multiDrawElementsWEBGL',
  'multiDrawArraysInstancedWEBGL',
  'multiDrawElementsInstancedWEBGL',
] as const;
const UPLOADS: Record<string, (args: readonly unknown[]) => number> = {
  texImage2D: (args) => texImage2DBytes(args, false),
  texSubImage2D: (args) => texImage2DBytes(args, true),
  texImage3D: (args) => texImage3DBytes(args, false),
  texSubImage3D: (args) => texImage3DBytes(args, true),
  bufferData: bufferDataBytes,
  bufferSubData: bufferSubDataBytes,
};
const FRAMEBUFFER = 0x8d40;
const DRAW_FRAMEBUFFER = 0x8ca9;
const DRAW_FRAMEBUFFER_BINDING = 0x8ca6;
const CURRENT_PROGRAM = 0x8b8d;

/**
 * Runs `body` (one frame) with `gl`'s calls counted, and answers the counts. The counting
 * wrappers are own properties of the context object (and of its multi-draw extension, which
 * three.js keeps), shadowing the prototype's methods, and are removed afterwards: a context
 * that is not being counted runs untouched.
 */
export function countFrame(gl: WebGL2RenderingContext, body: () => void): FrameCounts {
  const counts: FrameCounts = { drawCalls: 0, passes: 0, programSwitches: 0, bytesUploaded: 0, uploads: 0 };
  let framebuffer = gl.getParameter(DRAW_FRAMEBUFFER_BINDING) as unknown;
  let program = gl.getParameter(CURRENT_PROGRAM) as unknown;
  let drawnInto: unknown = undefined; // no draw yet this frame: the first one starts a pass
  const draw = () => {
    counts.drawCalls++;
    if (framebuffer !== drawnInto) counts.passes++;
    drawnInto = framebuffer;
  };
  const wrapped: [object, string, PropertyDescriptor | undefined][] = [];
  const wrap = (target: object, name: string, before: (args: unknown[]) => void) => {
    const original = (target as Record<string, Method>)[name];
    if (typeof original !== 'function') return;
    wrapped.push([target, name, Object.getOwnPropertyDescriptor(target, name)]);
    Object.defineProperty(target, name, {
      configurable: true,
      writable: true,
      value: (...args: unknown[]) => {
        before(args);
        return original.apply(target, args);
      },
    });
  };
  for (const name of DRAWS) wrap(gl, name, draw);
  const multiDraw = gl.getSupportedExtensions()?.includes('WEBGL_multi_draw') ? gl.getExtension('WEBGL_multi_draw') : null;
  if (multiDraw) for (const name of MULTI_DRAWS) wrap(multiDraw, name, draw);
  wrap(gl, 'bindFramebuffer', ([target, bound]) => {
    if (target === FRAMEBUFFER || target === DRAW_FRAMEBUFFER) framebuffer = bound;
  });
  wrap(gl, 'useProgram', ([bound]) => {
    if (bound !== program) counts.programSwitches++;
    program = bound;
  });
  for (const [name, bytesOf] of Object.entries(UPLOADS))
    wrap(gl, name, (args) => {
      const bytes = bytesOf(args);
      if (bytes === 0) return;
      counts.bytesUploaded += bytes;
      counts.uploads++;
    });
  try {
    body();
  } finally {
    for (const [target, name, own] of wrapped.reverse()) {
      if (own) Object.defineProperty(target, name, own);
      else delete (target as Record<string, unknown>)[name];
    }
  }
  return counts;
}
