import { describe, expect, it } from 'vitest';
import { openOcean } from './harness';
import { useHarness } from './useHarness';

const harness = useHarness();

/**
 * The ocean's programs carry the boat wake's code only while the wake is on (OCEAN_WAKE, which
 * OceanMaterial sets as it draws, from the shared wake uniforms: a software rasterizer compiles
 * a program on its first draw, and the wake's loops are a large part of it). Turning the wake
 * on must compile it back into both ocean programs, so that the sea drawn shows the wake;
 * turning it off and on again must give the very same picture.
 *
 * Measured (320×180, SwiftShader): the wake moves 6.8 % of the pixels by more than 2 levels
 * (the boat's picture is the same: it floats on the waves alone, and the ±19.47° guide is
 * off); with the control (the code never compiled in) 0.05 % (the wake's bound grows the
 * culling boxes, which may pick other chunks).
 */
const QUERY = 'wake=0&wakeGuide=0&boatSpeed=4&boatHeading=270&boatTurnRate=3&t=10';
/** Share of pixels the wake must move by more than 2 levels: 1 %, between the control's 0.05 % and the measured 6.8 %. */
const WAKE_SHARE = 0.01;

describe('the wake compiled into the ocean only while it is on', () => {
  // The control (never compiled in) does not.
  it('shows the wake on the drawn sea once turned on, the same picture each time', async () => {
    const { page, consoleErrors } = await openOcean(harness, QUERY, 320, 180);
    try {
      const result = await page.evaluate(async () => {
        const o = window.oceano;
        const gl = o.three.renderer.getContext();
        // The wake's GLSL is fetched the first time the wake is on (src/render/wake/wakeChunk.ts): loaded() waits for it.
        const picture = async (wake: boolean) => {
          o.setParams({ wake });
          await o.loaded();
          o.renderFrame();
          const pixels = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
          gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
          return pixels;
        };
        const shareMoved = (a: Uint8Array, b: Uint8Array) => {
          let moved = 0;
          for (let i = 0; i < a.length; i += 4)
            if (Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) > 2) moved++;
          return moved / (a.length / 4);
        };
        const same = (a: Uint8Array, b: Uint8Array) => a.every((v, i) => v === b[i]);
        // Both ocean programs (the far bands' material and its near twin), by their uniforms.
        type Material = {
          defines: Record<string, string>;
          uniforms: Record<string, { value: unknown }>;
          onBeforeRender(...args: unknown[]): void;
          needsUpdate: boolean;
        };
        const materials = new Set<Material>();
        o.three.scene.traverse((object) => {
          const m = (object as unknown as { material?: Material }).material;
          if (m?.uniforms?.uWakeCount && m.uniforms.uFresnelTable) materials.add(m);
        });
        const compiledIn = () => [...materials].map((m) => 'OCEAN_WAKE' in m.defines);
        const off = await picture(false);
        const offDefines = compiledIn();
        const on = await picture(true);
        const onDefines = compiledIn();
        const offAgain = await picture(false);
        const onAgain = await picture(true);
        // The control: the wake's code taken out again after each material has compiled it in.
        const original = Object.getPrototypeOf([...materials][0]).onBeforeRender as (this: Material, ...args: unknown[]) => void;
        for (const m of materials)
          m.onBeforeRender = function (this: Material, ...args: unknown[]) {
            original.apply(this, args);
            if ('OCEAN_WAKE' in this.defines) {
              delete this.defines.OCEAN_WAKE;
              this.needsUpdate = true;
            }
          };
        await picture(false);
        const faulty = await picture(true);
        for (const m of materials) delete (m as Partial<Material>).onBeforeRender;
        return {
          materials: materials.size,
          offDefines,
          onDefines,
          moved: shareMoved(off, on),
          sameOff: same(off, offAgain),
          sameOn: same(on, onAgain),
          controlMoved: shareMoved(off, faulty),
        };
      });
      console.log(
        `[oceano] the wake on the drawn sea: ${(100 * result.moved).toFixed(2)} % of pixels moved by more than 2 levels; control (never compiled in) ${(100 * result.controlMoved).toFixed(2)} %`,
      );
      expect(result.materials).toBe(2);
      expect(result.offDefines).toEqual([false, false]);
      expect(result.onDefines).toEqual([true, true]);
      expect(result.moved).toBeGreaterThan(WAKE_SHARE);
      expect(result.sameOff).toBe(true);
      expect(result.sameOn).toBe(true);
      expect(result.controlMoved).toBeLessThan(WAKE_SHARE);
      expect(consoleErrors).toEqual([]);
    } finally {
      await page.close();
    }
  });
});
