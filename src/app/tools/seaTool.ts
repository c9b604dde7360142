import type { PerspectiveCamera, Scene } from 'three';
import type { OceanParams } from '../../sim/params/params';
import type { CameraPose } from '../camera/cameraPose';
import type { Translator } from '../language/i18n';

/** A point on the sea, world metres (x, z); its height is the sea's there. */
export interface SeaXZ {
  x: number;
  z: number;
}

/** What the tools read of the running ocean and ask of it. */
export interface SeaToolContext {
  readonly tr: Translator;
  readonly scene: Scene;
  readonly camera: PerspectiveCamera;
  /** The canvas, at the container's top left: labels on the sea are placed over it. */
  readonly canvas: HTMLCanvasElement;
  /** Simulation time now, seconds. */
  time(): number;
  params(): OceanParams;
  pose(): CameraPose;
  /** Height of the sea as drawn at (x, z) now (waves, wake, interactive waves), metres. */
  height(x: number, z: number): number;
  /** Drops a stone into the interactive waves, turning them on (and waiting for their code) if they are off. */
  dropStone(point: SeaXZ): Promise<void>;
  notify(text: string): void;
  /** Asks for a frame, so a change shows on a paused view. */
  redraw(): void;
}

/**
 * One of the sea tools, as the toolbox drives it. The pointer and the keyboard's point both
 * end up here as points on the sea, so each tool is written once for both.
 */
export interface SeaTool {
  /** Its part of the toolbox card (figures, buttons); shown while it is chosen or holds a measurement. */
  readonly body: HTMLElement;
  /** Whether it has something on the sea to show (a probe, a ruler) even while another tool is chosen. */
  holdsMeasurement(): boolean;
  /** The pointer went down on the sea. */
  down(point: SeaXZ): void;
  /** The pointer, held down, moved over the sea. */
  drag(point: SeaXZ): void;
  /** Enter at the keyboard's point. */
  enter(point: SeaXZ): void;
  /** The keyboard's point moved (the ruler's loose end follows it). */
  cursorMoved(point: SeaXZ): void;
  /** Before each drawn frame: sample the sea, move the marks, refresh the figures. */
  frame(): void;
  /** After each drawn frame: labels placed from the camera's projection. */
  placeLabels(): void;
  /** Removes what it put on the sea. */
  clear(): void;
  dispose(): void;
}
