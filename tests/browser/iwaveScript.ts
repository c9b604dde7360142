import { IWAVE_SPONGE, IWaveGrid, type Disturbance } from '../../src/sim/iwave/iwaveGrid';
import { equationKernels, type IWaveEquation } from '../../src/sim/iwave/interactiveField';
import type { MovingHull } from '../../src/sim/iwave/movingHull';

/** What the iWave parity test plays on the GPU and on the CPU reference alike. */
export interface IWaveScript {
  n: number;
  spacing: number;
  dt: number;
  damping: number;
  /** 1 water, 0 solid, n × n row by row along z. */
  obstacle?: number[];
  /** Which equation (equationKernels); dispersive by default. */
  equation?: IWaveEquation;
  actions: (
    | { kind: 'disturb'; disturbance: Disturbance }
    | { kind: 'step'; count: number }
    | { kind: 'recentre'; x: number; z: number }
    | { kind: 'hull'; hull: MovingHull | null }
  )[];
}

/** The script on the CPU reference solver: the same kernels, sponge (IWAVE_SPONGE), damping, mask and hull as GpuIWave's. */
export function playOnCpu(script: IWaveScript): IWaveGrid {
  const grid = new IWaveGrid({
    n: script.n,
    spacing: script.spacing,
    ...equationKernels(script.equation ?? 'dispersive', script.spacing),
    damping: script.damping,
    sponge: IWAVE_SPONGE,
  });
  if (script.obstacle) grid.obstacle.set(script.obstacle);
  for (const action of script.actions) {
    if (action.kind === 'disturb') grid.disturb(action.disturbance);
    else if (action.kind === 'step') for (let s = 0; s < action.count; s++) grid.step(script.dt);
    else if (action.kind === 'hull') grid.hull = action.hull;
    else grid.recentre(action.x, action.z);
  }
  return grid;
}
