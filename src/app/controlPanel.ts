import GUI, { type Controller } from 'lil-gui';
import { paramDefs, type OceanParams, type ParamDef, type ParamKey } from '../sim/params';

const FOLDERS: { title: string; keys: ParamKey[] }[] = [
  { title: 'Swell', keys: ['swellAmplitude', 'swellFrequency'] },
  { title: 'Ripples (Perlin)', keys: ['rippleStrength', 'rippleBlendSpeed', 'seed'] },
  { title: 'Light & water', keys: ['sunElevation', 'sunAzimuth', 'waterColor', 'fresnel'] },
  { title: 'Underwater', keys: ['blurStrength', 'fogDensity', 'seaBedDepth', 'caustics', 'causticsIntensity', 'godRays', 'godRaysIntensity'] },
  { title: 'View', keys: ['wireframe'] },
];

export interface ControlPanelHooks {
  onParam(key: ParamKey, value: OceanParams[ParamKey]): void;
  onPlayingChange(playing: boolean): void;
  onDive(): void;
  onSurface(): void;
}

/**
 * lil-gui panel built from the parameter definitions, so a new parameter gets its control
 * with its range and unit without touching this file beyond naming its folder.
 */
export class ControlPanel {
  readonly gui: GUI;
  private readonly model: OceanParams & { playing: boolean };
  private readonly controllers: Controller[] = [];

  constructor(container: HTMLElement, params: OceanParams, playing: boolean, hooks: ControlPanelHooks) {
    this.gui = new GUI({ container, title: 'Oceano' });
    this.model = { ...params, playing };
    for (const folder of FOLDERS) {
      const group = this.gui.addFolder(folder.title);
      for (const key of folder.keys) this.controllers.push(this.addControl(group, key, hooks));
    }
    this.controllers.push(
      this.gui.add(this.model, 'playing').name('Play').onChange((value: boolean) => hooks.onPlayingChange(value)),
    );
    const camera = { dive: () => hooks.onDive(), surface: () => hooks.onSurface() };
    this.gui.add(camera, 'dive').name('Dive under the surface');
    this.gui.add(camera, 'surface').name('Back to the surface view');
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

  dispose(): void {
    this.gui.destroy();
  }
}
