import { IWAVE_SPONGE, IWaveGrid, type Disturbance } from '../../src/sim/iwave/iwaveGrid';
import { fittedVerticalDerivativeKernel } from '../../src/sim/iwave/verticalDerivativeKernel';

/** What the iWave parity test plays on the GPU and on the CPU reference alike. */
export interface IWaveScript {
  n: number;
  spacing: number;
  dt: number;
  damping: number;
  /** 1 water, 0 solid, n × n row by row along z. */
  obstacle?: number[];
  actions: ({ kind: 'disturb'; disturbance: Disturbance } | { kind: 'step'; count: number } | { kind: 'recentre'; x: number; z: number })[];
}

/** The script on the CPU reference solver: the same kernel, sponge (IWAVE_SPONGE), damping and mask as GpuIWave's. */
export function playOnCpu(script: IWaveScript): IWaveGrid {
  const grid = new IWaveGrid({ n: script.n, spacing: script.spacing, kernel: fittedVerticalDerivativeKernel(), damping: script.damping, sponge: IWAVE_SPONGE });
  if (script.obstacle) grid.obstacle.set(script.obstacle);
  for (const action of script.actions) {
    if (action.kind === 'disturb') grid.disturb(action.disturbance);
    else if (action.kind === 'step') for (let s = 0; s < action.count; s++) grid.step(script.dt);
    else grid.recentre(action.x, action.z);
  }
  return grid;
}
