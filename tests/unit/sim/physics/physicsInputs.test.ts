import { describe, expect, it } from 'vitest';
import { defaultParams, type OceanParams } from '../../../../src/sim/params/params';
import { physicsInputs } from '../../../../src/sim/physics/physicsInputs';

const base = (): OceanParams => ({ ...defaultParams(), waves: 'fft' });
const changed = (change: Partial<OceanParams>) => physicsInputs({ ...base(), ...change }) !== physicsInputs(base());

describe('physicsInputs: when the physics panel must measure again', () => {
  it('changes with every parameter the models’ heights or the glint’s roughness are drawn from', () => {
    const changes: Partial<OceanParams>[] = [
      { waves: 'gerstner' },
      { windSpeed: 15 },
      { windDirection: 90 },
      { spectrum: 'phillips' },
      { fetch: 20 },
      { depth: 10 },
      { spreading: 20 },
      { spreadingModel: 'hasselmann' },
      { choppiness: 0.5 },
      { fftSize: '256' },
      { seed: 7 },
      { gerstnerCount: 8 },
      { gerstnerSteepness: 0.9 },
      { swellAmplitude: 2 },
      { swellFrequency: 0.1 },
      { rippleStrength: 1 },
      { rippleBlendSpeed: 1 },
      { seaRoughness: false },
    ];
    for (const change of changes) expect(changed(change), JSON.stringify(change)).toBe(true);
  });

  it('stays put for the sun, the exposure, the camera’s tools and the panel’s own switch (the control)', () => {
    for (const change of [
      { sunElevation: 5 },
      { exposure: 1 },
      { physics: true },
      { wireframe: true },
      { foam: false },
    ] as Partial<OceanParams>[]) {
      expect(changed(change), JSON.stringify(change)).toBe(false);
    }
  });

  it('with the side-by-side split on, the first model named is the one measured', () => {
    expect(physicsInputs({ ...base(), waves: 'seed', compare: 'fft,seed' })).toBe(physicsInputs({ ...base(), waves: 'fft' }));
    expect(physicsInputs({ ...base(), waves: 'fft', compare: 'gerstner,fft' })).not.toBe(physicsInputs({ ...base(), waves: 'fft' }));
  });
});
