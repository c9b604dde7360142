import { describe, expect, it } from 'vitest';
import { ShaderMaterial, type IUniform } from 'three';
import { defaultParams } from '../../../../../src/sim/params/params';
import { SeedWaveModel } from '../../../../../src/sim/waves/seed/seedWaveModel';
import type { LiveWaveModel } from '../../../../../src/sim/waves/waveModel';
import { maxDisplacement, surfaceHeight, surfaceNormal, surfaceStateAt } from '../../../../../src/sim/waves/seed/seedSurface';
import { WaveBinding } from '../../../../../src/render/waves/waveBinding';
import type { WaveModelView } from '../../../../../src/render/waves/waveModelView';

describe('the seed sea as a WaveModel', () => {
  const params = defaultParams();
  const points: [number, number, number][] = [
    [3, -7, 10],
    [1000.5, -2000.25, 1e5],
    [-17.3, 41.9, 0],
  ];

  it('displaces only vertically, by the seed surface M(x, z), and samples the same surface', () => {
    const model = new SeedWaveModel(params);
    for (const [x, z, t] of points) {
      const state = surfaceStateAt(params, t);
      const h = surfaceHeight(state, model.heightmaps, x, z);
      expect(model.displacement(x, z, t)).toEqual([0, h, 0]);
      expect(model.height(x, z, t)).toBe(h);
      expect(model.sample(x, z, t)).toEqual({ height: h, normal: surfaceNormal(state, model.heightmaps, x, z) });
    }
    expect(model.bounds()).toEqual({ vertical: maxDisplacement(params), horizontal: 0 });
  });

  it('forgets its cached state when the parameters change (a stale cache would keep the old swell)', () => {
    const model = new SeedWaveModel(params);
    const before = model.height(3, -7, 10);
    model.setParams({ ...params, swellAmplitude: 0, rippleStrength: 0 });
    expect(before).not.toBe(0);
    expect(model.height(3, -7, 10)).toBe(0);
    expect(model.bounds().vertical).toBe(0);
  });

  it('regenerates its heightmaps only when the noise seed changes', () => {
    const model = new SeedWaveModel(params);
    const maps = model.heightmaps;
    expect(model.setParams({ ...params, swellAmplitude: 2 })).toBe(false);
    expect(model.heightmaps).toBe(maps);
    expect(model.setParams({ ...params, seed: 2 })).toBe(true);
    expect(model.heightmaps[0].data).not.toEqual(maps[0].data);
  });
});

function fakeView(name: string, uniforms: Record<string, IUniform>): WaveModelView {
  return {
    name: 'seed',
    model: null as unknown as LiveWaveModel,
    chunkName: `oceano_waves_${name}`,
    chunk: `float wave_${name};`,
    lensPeriod: null,
    uniforms,
    setParams() {},
    update() {},
    dispose() {},
  };
}

describe('WaveBinding', () => {
  it("points each material's <oceano_waves> at the active model's chunk and gives it that model's uniforms", () => {
    const a = fakeView('a', { uA: { value: 1 } });
    const b = fakeView('b', { uB: { value: 2 } });
    const binding = new WaveBinding(a);
    const material = binding.attach(
      new ShaderMaterial({
        vertexShader: '#include <oceano_waves>\nvoid main() {}',
        fragmentShader: 'void main() {}',
        uniforms: { uOwn: { value: 0 } },
      }),
    );
    expect(material.vertexShader).toBe('float wave_a;\nvoid main() {}');
    expect(Object.keys(material.uniforms).sort()).toEqual(['uA', 'uOwn']);
    expect(material.uniforms.uA).toBe(a.uniforms.uA);
    const version = material.version;
    binding.setModel(b);
    expect(material.vertexShader).toBe('float wave_b;\nvoid main() {}');
    expect(Object.keys(material.uniforms).sort()).toEqual(['uB', 'uOwn']);
    expect(material.version).toBeGreaterThan(version);
    expect(binding.resolve('x\n#include <oceano_waves>\ny')).toBe('x\nfloat wave_b;\ny');
  });
});
