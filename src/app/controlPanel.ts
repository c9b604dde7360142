import GUI, { type Controller } from 'lil-gui';
import { paramDefs, type OceanParams, type ParamDef, type ParamKey } from '../sim/params';

const FOLDERS: { title: string; keys: ParamKey[] }[] = [
  { title: 'Swell', keys: ['swellAmplitude', 'swellFrequency'] },
  { title: 'Ripples (Perlin)', keys: ['rippleStrength', 'rippleBlendSpeed', 'seed'] },
  { title: 'Light & water', keys: ['sunElevation', 'sunAzimuth', 'waterColor', 'fresnel'] },
  { title: 'LOD & culling', keys: ['lodDistance', 'lodBands', 'lodColors', 'freezeCulling', 'lodBruteForce'] },
  { title: 'View', keys: ['wireframe'] },
];

/** What the LOD debugger's read-only counters show. */
export interface LiveCounts {
  chunksVisible: number;
  chunksTotal: number;
  triangles: number;
  drawCalls: number;
  lodCounts: number[];
}

export interface ControlPanelHooks {
  onParam(key: ParamKey, value: OceanParams[ParamKey]): void;
  onPlayingChange(playing: boolean): void;
}

/**
 * lil-gui panel built from the parameter definitions, so a new parameter gets its control
 * with its range and unit without touching this file beyond naming its folder.
 */
export class ControlPanel {
  readonly gui: GUI;
  private readonly model: OceanParams & { playing: boolean };
  private readonly controllers: Controller[] = [];
  private readonly counts = { chunks: '', triangles: '', drawCalls: '', perBand: '' };
  private readonly countControllers: Controller[] = [];

  constructor(container: HTMLElement, params: OceanParams, playing: boolean, hooks: ControlPanelHooks) {
    this.gui = new GUI({ container, title: 'Oceano' });
    this.model = { ...params, playing };
    for (const folder of FOLDERS) {
      const group = this.gui.addFolder(folder.title);
      for (const key of folder.keys) this.controllers.push(this.addControl(group, key, hooks));
    }
    const live = this.gui.addFolder('LOD counts (live)');
    const labels: [keyof typeof this.counts, string][] = [
      ['chunks', 'Chunks visible / total'],
      ['triangles', 'Triangles'],
      ['drawCalls', 'Draw calls'],
      ['perBand', 'Chunks per band'],
    ];
    for (const [key, label] of labels) this.countControllers.push(live.add(this.counts, key).name(label).disable());
    this.controllers.push(
      this.gui.add(this.model, 'playing').name('Play').onChange((value: boolean) => hooks.onPlayingChange(value)),
    );
  }

  private addControl(group: GUI, key: ParamKey, hooks: ControlPanelHooks): Controller {
    const def: ParamDef = paramDefs[key];
    const emit = (value: OceanParams[ParamKey]) => hooks.onParam(key, value);
    if (def.kind === 'color') return group.addColor(this.model, key).name(def.label).onChange(emit);
    if (def.kind === 'boolean') return group.add(this.model, key).name(def.label).onChange(emit);
    const name = def.unit ? `${def.label} (${def.unit})` : def.label;
    const step = def.kind === 'integer' ? 1 : (def.step ?? (def.max - def.min) / 100);
    const controller = group.add(this.model, key, def.min, def.max, step).name(name);
    // A new seed regenerates both heightmaps: do it once when the user lets go, not per pixel dragged.
    return key === 'seed' ? controller.onFinishChange(emit) : controller.onChange(emit);
  }

  /** Shows values changed elsewhere (API, keyboard) without echoing them back. */
  sync(params: OceanParams, playing: boolean): void {
    Object.assign(this.model, params, { playing });
    for (const controller of this.controllers) controller.updateDisplay();
  }

  showCounts(counts: LiveCounts): void {
    this.counts.chunks = `${counts.chunksVisible} / ${counts.chunksTotal}`;
    this.counts.triangles = counts.triangles.toLocaleString('en-US');
    this.counts.drawCalls = String(counts.drawCalls);
    this.counts.perBand = counts.lodCounts.join(' ');
    for (const controller of this.countControllers) controller.updateDisplay();
  }

  dispose(): void {
    this.gui.destroy();
  }
}
