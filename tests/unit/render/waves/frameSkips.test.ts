import { describe, expect, it, vi } from 'vitest';
import {
  ACESFilmicToneMapping,
  BackSide,
  CubeTexture,
  CustomToneMapping,
  DoubleSide,
  FrontSide,
  Group,
  NoToneMapping,
  PerspectiveCamera,
  Scene,
  Texture,
  type IUniform,
} from 'three';
import { createWakeUniforms } from '../../../../src/render/wake/wakeUniforms';
import { createFoamUniforms } from '../../../../src/render/foam/foamUniforms';
import { OceanMaterial } from '../../../../src/render/ocean/oceanMaterial';
import { BoatView } from '../../../../src/render/boat/boatView';
import { WaveBinding } from '../../../../src/render/waves/waveBinding';
import type { WaveModelView } from '../../../../src/render/waves/waveModelView';
import type { Submersion } from '../../../../src/sim/underwater/snellWindow';
import type { BoatPose } from '../../../../src/sim/boat/boatPose';
import { SeedWaveView } from '../../../../src/render/waves/seed/seedWaveView';
import { SeedWaveModel } from '../../../../src/sim/waves/seed/seedWaveModel';
import { defaultParams } from '../../../../src/sim/params/params';

/**
 * The update step's setters that skip a frame's repeat of the last frame's values
 * (stats().cpuMs): skipping must leave the same state as setting.
 */

function material(wakeCodeArrived = true): OceanMaterial {
  const view = {
    name: 'seed',
    chunkName: 'oceano_waves_test',
    chunk: '',
    uniforms: {},
    model: { bounds: () => ({ vertical: 1, horizontal: 0 }) },
  } as unknown as WaveModelView;
  const shared = { uSunColor: { value: null }, ...createWakeUniforms(), ...createFoamUniforms() } as unknown as ConstructorParameters<
    typeof OceanMaterial
  >[3];
  const binding = new WaveBinding(view);
  // The wake's GLSL is fetched with the wake (lateChunks.ts); the define waits for it.
  if (wakeCodeArrived) binding.late.provide('oceano_wake', '// the wake');
  return new OceanMaterial(binding, { fromAbove: new Texture(), fromBelow: new Texture() }, new CubeTexture(), shared);
}

/** What onBeforeRender reads of a renderer: a scene's renderer with no tone curve, three.js's default. */
const plainRenderer = { toneMapping: NoToneMapping };

/** What setSeenFromBelow decides, for both programs. */
function seen(m: OceanMaterial) {
  const defines = (x: OceanMaterial) => Object.keys(x.defines).sort().join();
  return {
    side: m.side,
    nearSide: m.near.side,
    defines: defines(m),
    nearDefines: defines(m.near),
    marks: (m.uniforms.uMarkSides as IUniform<boolean>).value,
  };
}

describe('OceanMaterial.setSeenFromBelow: the same answer again changes nothing', () => {
  it('walks every change between the three answers and leaves each as a fresh material set once would', () => {
    const walk: Submersion[] = [
      'above',
      'above',
      'straddling',
      'straddling',
      'below',
      'below',
      'above',
      'below',
      'straddling',
      'above',
      'straddling',
      'below',
      'below',
    ];
    const m = material();
    let previous: Submersion | null = null;
    for (const where of walk) {
      const versions = [m.version, m.near.version];
      m.setSeenFromBelow(where);
      const fresh = material();
      fresh.setSeenFromBelow(where);
      expect(seen(m)).toEqual(seen(fresh));
      expect(m.side).toBe(where === 'below' ? BackSide : where === 'above' ? FrontSide : DoubleSide);
      // A repeat recompiles nothing (needsUpdate bumps the version).
      if (where === previous) expect([m.version, m.near.version]).toEqual(versions);
      previous = where;
    }
  });
});

// The wake's shared uniforms.
describe('OceanMaterial: the wake compiled in only while its uniforms hold a track; a repeat recompiles nothing', () => {
  it('follows every change of uWakeCount at the next draw of each program, and leaves the versions alone on a repeat', () => {
    const m = material();
    const camera = new PerspectiveCamera();
    // Nothing drawn yet: no track, no wake code.
    expect('OCEAN_WAKE' in m.defines || 'OCEAN_WAKE' in m.near.defines).toBe(false);
    // The first draw compiles in what the renderer asks for (its tone curve): not what is counted here.
    m.onBeforeRender(plainRenderer, null, camera);
    m.near.onBeforeRender(plainRenderer, null, camera);
    let previous = false;
    for (const count of [0, 1, 2, 40, 0, 64, 1, 0]) {
      const on = count >= 2;
      const versions = [m.version, m.near.version];
      // The count is shared by every ocean material of a view (compare strips too); each program
      // reads it as it is drawn.
      (m.uniforms.uWakeCount as IUniform<number>).value = count;
      m.onBeforeRender(plainRenderer, null, camera);
      m.near.onBeforeRender(plainRenderer, null, camera);
      expect('OCEAN_WAKE' in m.defines).toBe(on);
      expect('OCEAN_WAKE' in m.near.defines).toBe(on);
      // Drawn every frame: a repeat must not rebuild the programs.
      if (on === previous) expect([m.version, m.near.version]).toEqual(versions);
      else expect([m.version, m.near.version]).toEqual([versions[0] + 1, versions[1] + 1]);
      previous = on;
    }
  });

  it('leaves the wake out while its GLSL has not arrived, whatever the track', () => {
    const m = material(false);
    (m.uniforms.uWakeCount as IUniform<number>).value = 40;
    m.onBeforeRender(plainRenderer, null, new PerspectiveCamera());
    expect('OCEAN_WAKE' in m.defines).toBe(false);
  });
});

describe('OceanMaterial: the sea rolls its own highlights off only under a renderer with no tone curve', () => {
  // Out for the app's curve or a scene's own (ACES).
  it('compiles the roll-off in for NoToneMapping and out for any curve; a repeat recompiles nothing', () => {
    const m = material();
    const camera = new PerspectiveCamera();
    for (const [toneMapping, own] of [
      [NoToneMapping, true],
      [NoToneMapping, true],
      [CustomToneMapping, false],
      [ACESFilmicToneMapping, false],
      [NoToneMapping, true],
    ] as const) {
      m.onBeforeRender({ toneMapping }, null, camera);
      expect('OCEAN_OWN_ROLL_OFF' in m.defines).toBe(own);
    }
    // Drawn twice under the same renderer: the second draw leaves the program as it was.
    const before = m.version;
    m.onBeforeRender({ toneMapping: NoToneMapping }, null, camera);
    expect(m.version).toBe(before);
    // The define is what ocean.frag rolls the highlights off by.
    expect(m.fragmentShader).toMatch(/#ifdef OCEAN_OWN_ROLL_OFF\s+color = rollOffHighlights\(color\);\s+#endif/);
  });
});

// The LOD tint, the normal as colour and the normals comparison.
describe('OceanMaterial teaching and debug views are compiled in only while shown', () => {
  it('puts each define in both programs and takes it out again; a repeat recompiles nothing', () => {
    const m = material();
    // Each view's define, in the material and in its near-band twin.
    const defines = () =>
      ['OCEAN_LOD_COLORS', 'OCEAN_SHOW_NORMALS', 'OCEAN_NORMALS_COMPARE'].map((name) => [name in m.defines, name in m.near.defines]);
    const show = (on: boolean) => {
      m.setLodColors(on);
      m.setTeachingViews(!on, on);
      m.setNormalsCompare(on);
    };
    expect(defines()).toEqual([
      [false, false],
      [false, false],
      [false, false],
    ]);
    show(true);
    expect(defines()).toEqual([
      [true, true],
      [true, true],
      [true, true],
    ]);
    const versions = [m.version, m.near.version];
    show(true);
    expect([m.version, m.near.version]).toEqual(versions);
    show(false);
    expect(defines()).toEqual([
      [false, false],
      [false, false],
      [false, false],
    ]);
  });
});

describe('BoatView.setPose: the same pose again leaves the group as it is', () => {
  const pose = (p: Partial<BoatPose>): BoatPose => ({ x: 7, y: 0.3, z: -5, heading: 0.4, pitch: 0.02, roll: -0.05, ...p });
  const group = (scene: Scene) => scene.getObjectByName('Boat') as Group;

  it('does not set a repeated pose, and sets any one coordinate that changed as a fresh view would', () => {
    const scene = new Scene();
    const view = new BoatView(scene);
    view.setPose(pose({}));
    const rotationSet = vi.spyOn(group(scene).rotation, 'set');
    const positionSet = vi.spyOn(group(scene).position, 'set');
    view.setPose(pose({}));
    expect(rotationSet).not.toHaveBeenCalled();
    expect(positionSet).not.toHaveBeenCalled();
    for (const change of [
      { x: 7.001 },
      { y: 0.31 },
      { z: -5.2 },
      { heading: 0.41 },
      { pitch: 0.03 },
      { roll: -0.04 },
      { heading: -0 },
      { heading: 0 },
    ]) {
      view.setPose(pose(change));
      const freshScene = new Scene();
      new BoatView(freshScene).setPose(pose(change));
      const a = group(scene);
      const b = group(freshScene);
      expect(a.position.toArray()).toEqual(b.position.toArray());
      expect(a.quaternion.toArray()).toEqual(b.quaternion.toArray());
      expect(a.rotation.toArray()).toEqual(b.rotation.toArray());
      expect(Object.is(a.rotation.y, b.rotation.y)).toBe(true);
    }
  });
});

describe('SeedWaveView.update: the state already applied is not applied again', () => {
  /** The per-frame uniforms' values, as plain numbers (vectors as arrays; the heightmap textures left out). */
  const values = (view: SeedWaveView) =>
    Object.fromEntries(
      Object.entries(view.uniforms)
        .filter(([, u]) => !(u.value instanceof Texture))
        .map(([k, u]) => [
          k,
          u.value && typeof u.value === 'object' && 'toArray' in u.value ? (u.value as { toArray(): number[] }).toArray() : u.value,
        ]),
    );

  it("repeats set nothing; a new time or new parameters at the same time give a fresh view's uniforms", () => {
    const params = defaultParams();
    const view = new SeedWaveView(new SeedWaveModel(params));
    view.update(10);
    const offset = vi.spyOn(view.uniforms.uRippleOffset.value as { fromArray(a: number[]): unknown }, 'fromArray');
    view.update(10);
    expect(offset).not.toHaveBeenCalled();
    const steps: [number, Partial<typeof params>][] = [
      [10, { swellAmplitude: 0.9 }],
      [10, { rippleStrength: 0.2 }],
      [10.5, {}],
      [10.5, {}],
      [10.5, { rippleBlendSpeed: 0.3 }],
    ];
    let current = params;
    for (const [time, change] of steps) {
      current = { ...current, ...change };
      view.setParams(current);
      view.update(time);
      const fresh = new SeedWaveView(new SeedWaveModel(current));
      fresh.update(time);
      expect(values(view)).toEqual(values(fresh));
    }
  });
});
