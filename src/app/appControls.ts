import type { OceanParams } from '../sim/params';
import { BoatSteering } from './boatSteering';
import { ControlPanel, type ControlPanelHooks, type LiveCounts } from './controlPanel';
import { FresnelPlot } from './fresnelPlot';
import type { Translator } from './i18n';

/** How often the GUI's live LOD counts are refreshed (frames). */
const COUNTS_EVERY = 10;

/**
 * What the user steers the ocean with besides the canvas: the lil-gui panel (full page
 * only), the keyboard's boat steering and the Fresnel plot, kept in step with the parameters.
 */
export class AppControls {
  private readonly panel?: ControlPanel;
  private readonly steering: BoatSteering;
  private fresnelPlot?: FresnelPlot;

  constructor(
    private readonly container: HTMLElement,
    private readonly fresnelData: Float32Array,
    state: { showPanel: boolean; params: OceanParams; playing: boolean; tr: Translator },
    hooks: ControlPanelHooks & { setParams(change: Partial<OceanParams>): void; params(): OceanParams },
  ) {
    if (state.showPanel) this.panel = new ControlPanel(container, state.params, state.playing, hooks, state.tr);
    // The full page steers from anywhere; an embedded figure only when it has the focus.
    this.steering = new BoatSteering(state.showPanel ? window : container, (change) => hooks.setParams(change), () => hooks.params());
    this.sync(state.params, state.playing);
  }

  /** Applies held steering keys for `seconds` of the loop. */
  steer(seconds: number): void {
    this.steering.apply(seconds);
  }

  sync(params: OceanParams, playing: boolean): void {
    // The plot is made the first time it is asked for: most figures never show it.
    if (params.fresnelPlot) this.fresnelPlot ??= new FresnelPlot(this.container, this.fresnelData);
    this.fresnelPlot?.setVisible(params.fresnelPlot);
    this.panel?.sync(params, playing);
  }

  /** The panel's live LOD counts, refreshed every COUNTS_EVERY frames. */
  showCounts(frame: number, counts: () => LiveCounts): void {
    if (this.panel && frame % COUNTS_EVERY === 0) this.panel.showCounts(counts());
  }

  dispose(): void {
    this.steering.dispose();
    this.panel?.dispose();
    this.fresnelPlot?.dispose();
  }
}
