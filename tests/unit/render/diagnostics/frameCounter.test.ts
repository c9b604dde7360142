import { describe, expect, it } from 'vitest';
import { countFrame } from '../../../../src/render/diagnostics/frameCounter';
import { texelBytes, texImage2DBytes } from '../../../../src/render/diagnostics/uploadBytes';

const GL = {
  FRAMEBUFFER: 0x8d40,
  READ_FRAMEBUFFER: 0x8ca8,
  DRAW_FRAMEBUFFER_BINDING: 0x8ca6,
  CURRENT_PROGRAM: 0x8b8d,
  TEXTURE_2D: 0x0de1,
  TEXTURE_3D: 0x806f,
  ARRAY_BUFFER: 0x8892,
  RGBA: 0x1908,
  RED: 0x1903,
  RGB: 0x1907,
  FLOAT: 0x1406,
  HALF_FLOAT: 0x140b,
  UNSIGNED_BYTE: 0x1401,
  UNSIGNED_SHORT_5_6_5: 0x8363,
  TRIANGLES: 4,
};

/** A stand-in for a WebGL2 context: the calls the counter wraps, each logged, so that the calls still reach it. */
function fakeContext() {
  const reached: string[] = [];
  const method =
    (name: string) =>
    (..._args: unknown[]) =>
      void reached.push(name);
  const gl = {
    getParameter: () => null,
    getSupportedExtensions: () => [],
    drawArrays: method('drawArrays'),
    drawElements: method('drawElements'),
    drawArraysInstanced: method('drawArraysInstanced'),
    drawElementsInstanced: method('drawElementsInstanced'),
    drawRangeElements: method('drawRangeElements'),
    bindFramebuffer: method('bindFramebuffer'),
    useProgram: method('useProgram'),
    texImage2D: method('texImage2D'),
    texSubImage2D: method('texSubImage2D'),
    texImage3D: method('texImage3D'),
    texSubImage3D: method('texSubImage3D'),
    bufferData: method('bufferData'),
    bufferSubData: method('bufferSubData'),
  };
  return { gl, reached, context: gl as unknown as WebGL2RenderingContext };
}

describe('the frame counter', () => {
  it('counts draws, the passes they fall in, program switches, and leaves the context as it was', () => {
    const { gl, reached, context } = fakeContext();
    const original = gl.drawArrays;
    const [a, b] = [{}, {}];
    const [p, q] = [{}, {}];
    const counts = countFrame(context, () => {
      gl.useProgram(p);
      gl.drawArrays(GL.TRIANGLES, 0, 3); // pass 1: the canvas
      gl.bindFramebuffer(GL.FRAMEBUFFER, a);
      gl.useProgram(p); // the same program: no switch
      gl.drawElements(GL.TRIANGLES, 6, 0, 0); // pass 2: a
      gl.bindFramebuffer(GL.FRAMEBUFFER, b);
      gl.bindFramebuffer(GL.FRAMEBUFFER, a); // bound and left without a draw: no pass
      gl.drawArraysInstanced(GL.TRIANGLES, 0, 3, 4); // still a
      gl.bindFramebuffer(GL.READ_FRAMEBUFFER, b); // a read target: not where draws go
      gl.useProgram(q);
      gl.drawRangeElements(GL.TRIANGLES, 0, 3, 3, 0, 0);
      gl.bindFramebuffer(GL.FRAMEBUFFER, null);
      gl.drawElementsInstanced(GL.TRIANGLES, 3, 0, 0, 2); // pass 3: the canvas again
    });
    expect(counts).toMatchObject({ drawCalls: 5, passes: 3, programSwitches: 2 });
    expect(reached.filter((name) => name.startsWith('draw'))).toHaveLength(5);
    expect(gl.drawArrays).toBe(original);
    expect(Object.hasOwn(gl, 'drawArrays')).toBe(true);
    // Calls after the frame are not counted.
    gl.drawArrays(GL.TRIANGLES, 0, 3);
    expect(counts.drawCalls).toBe(5);
  });

  it('one more render into a target of its own is one more pass', () => {
    const frame = (extra: boolean) => {
      const { gl, context } = fakeContext();
      return countFrame(context, () => {
        gl.drawArrays(GL.TRIANGLES, 0, 3);
        if (!extra) return;
        gl.bindFramebuffer(GL.FRAMEBUFFER, {});
        gl.drawArrays(GL.TRIANGLES, 0, 3);
      }).passes;
    };
    expect(frame(true)).toBe(frame(false) + 1);
  });

  it('counts the bytes each upload carries from the CPU, and none for an allocation or a buffer offset', () => {
    const { gl, context } = fakeContext();
    const counts = countFrame(context, () => {
      gl.texImage2D(GL.TEXTURE_2D, 0, GL.RGBA, 16, 8, 0, GL.RGBA, GL.FLOAT, new Float32Array(16 * 8 * 4)); // 2048 B
      gl.texImage2D(GL.TEXTURE_2D, 0, GL.RGBA, 16, 8, 0, GL.RGBA, GL.FLOAT, null); // allocation
      gl.texSubImage2D(GL.TEXTURE_2D, 0, 2, 2, 4, 4, GL.RED, GL.HALF_FLOAT, new Uint16Array(16)); // 32 B
      gl.texSubImage2D(GL.TEXTURE_2D, 0, 0, 0, 4, 4, GL.RGBA, GL.UNSIGNED_BYTE, 0); // from a bound pixel buffer
      gl.texImage2D(GL.TEXTURE_2D, 0, GL.RGBA, GL.RGBA, GL.UNSIGNED_BYTE, { width: 10, height: 5 }); // an image: 200 B
      gl.texImage3D(GL.TEXTURE_3D, 0, GL.RGBA, 4, 4, 2, 0, GL.RGBA, GL.UNSIGNED_BYTE, new Uint8Array(128)); // 128 B
      gl.texSubImage3D(GL.TEXTURE_3D, 0, 0, 0, 1, 4, 4, 1, GL.RGB, GL.UNSIGNED_SHORT_5_6_5, new Uint16Array(16)); // 32 B
      gl.bufferData(GL.ARRAY_BUFFER, new Float32Array(100), 0x88e4); // 400 B
      gl.bufferData(GL.ARRAY_BUFFER, 4096, 0x88e4); // allocation
      gl.bufferSubData(GL.ARRAY_BUFFER, 40, new Float32Array(100), 10, 30); // 30 floats: 120 B
      gl.bufferSubData(GL.ARRAY_BUFFER, 0, new Float32Array(100), 90); // its last 10: 40 B
    });
    expect(counts.bytesUploaded).toBe(2048 + 32 + 200 + 128 + 32 + 400 + 120 + 40);
    expect(counts.uploads).toBe(8);
  });

  it('knows a texel of each format it meets, and refuses a pair it does not know', () => {
    expect(texelBytes(GL.RGBA, GL.FLOAT)).toBe(16);
    expect(texelBytes(GL.RGB, GL.UNSIGNED_SHORT_5_6_5)).toBe(2);
    expect(() => texelBytes(0x1234, GL.FLOAT)).toThrow(/Unknown texel/);
    // A wrong reading of the arguments (the sub-image's offsets taken as its size) gives another figure.
    const args = [GL.TEXTURE_2D, 0, 2, 2, 4, 4, GL.RED, GL.FLOAT, new Float32Array(16)];
    expect(texImage2DBytes(args, true)).toBe(64);
    expect(texImage2DBytes(args, false)).not.toBe(64);
  });
});
