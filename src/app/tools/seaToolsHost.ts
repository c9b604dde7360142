import type { OceanParams } from '../../sim/params/params';
import type { OceanView } from '../../render/ocean/oceanView';
import type { Translator } from '../language/i18n';
import type { Notices } from '../boot/notices';
import type { OceanAppOptions } from '../boot/appOptions';
import type { CameraPose } from '../camera/cameraPose';
import type { BoatController } from '../boat/boatController';

/**
 * What the sea tools use of the app (OceanApp has it all). Named here rather than imported as
 * OceanApp so that the app, its panel and the tools' chunk do not import each other in a ring.
 */
export interface SeaToolsHost {
  readonly tr: Translator;
  readonly canvas: HTMLCanvasElement;
  readonly container: HTMLElement;
  readonly options: OceanAppOptions;
  readonly notices: Notices;
  readonly clock: { readonly time: number };
  readonly loop: { requestRender(): void };
  readonly view: OceanView;
  readonly boatMotion: BoatController;
  getParams(): OceanParams;
  setParams(partial: unknown): OceanParams;
  camera(): CameraPose;
  whenPartsLoaded(): Promise<void>;
  disturb(x: number, z: number, options?: { radius?: number; height?: number }): string[];
}
