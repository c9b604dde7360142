import { BoatMotion, type BoatMotionState, type BoatSnapshot } from '../../sim/boat/boatMotion';
import type { HullSize } from '../../sim/boat/boatPose';
import type { OceanParams } from '../../sim/params/params';
import type { LiveWaveModel } from '../../sim/waves/waveModel';
import type { BoatView } from '../../render/boat/boatView';
import type { BoatModel } from '../../render/boat/boatModel';
import type { OceanView } from '../../render/ocean/oceanView';
import type { BoatInField, InteractiveWaves } from '../../render/iwave/interactiveWaves';
import type { SurfaceSample } from '../../sim/waves/waveModel';
import { addWake, BoatWake, WAKE_HULL, wakeHeightBound } from '../../sim/wake/boatWake';
import type { WakeTrack } from '../../sim/wake/wakeTrack';
import type { SailLimit } from '../../sim/coast/aground';

/** Hull used to float the boat until (or unless) its model gives the real size: the shipped model's. */
const NOMINAL_HULL: HullSize = { length: 8, beam: 2.6 };
const DEG = Math.PI / 180;

export interface BoatInfo {
  /** Centre of the hull at the waterline, metres. */
  position: [number, number, number];
  /** Radians; the conventions of src/sim/boat/boatPose.ts: heading clockwise from −z, pitch > 0 bow up, roll > 0 starboard up. */
  heading: number;
  pitch: number;
  roll: number;
  /**
   * The undamped pose on the surface at this instant. Equal to the above after a jump in
   * time or on a link without a boat state; a paused view keeps the damped pose, not this.
   */
  target: { position: [number, number, number]; pitch: number; roll: number };
  /** The hull the surface is sampled under, metres: bow and stern lie length/2, port and starboard beam/2 from the centre. */
  hull: HullSize;
  model: 'loading' | 'loaded' | 'failed';
}

/**
 * The boat's motion on the active waves and, when the camera follows it, the camera's:
 * `carryCamera(dx, dz)` moves the eye and the orbit target together by the boat's step.
 */
export class BoatController {
  private readonly motion = new BoatMotion();
  private state?: BoatMotionState;
  private hull: HullSize = NOMINAL_HULL;
  private modelState: BoatInfo['model'] = 'loading';
  /** The wake the boat leaves, recorded every frame (src/sim/wake/boatWake.ts). */
  private readonly wake = new BoatWake();

  /** `opened`: a share link's boat state, restored at its time (the link's `t`); without both the boat starts afresh. */
  constructor(
    private readonly view: BoatView,
    private readonly carryCamera: (dx: number, dz: number) => void,
    opened: { boatState: BoatSnapshot | null; wakeTrack?: WakeTrack | null; time: number | null } = { boatState: null, time: null },
    /** Called once each time the boat runs aground (it stops where the water is shallower than its draft). */
    private readonly onAground: () => void = () => {},
  ) {
    if (opened.boatState && opened.time !== null) this.motion.restore(opened.boatState, opened.time);
    if (opened.wakeTrack && opened.time !== null) this.wake.restore(opened.wakeTrack);
  }

  setModel(model: BoatModel | null): void {
    this.modelState = model ? 'loaded' : 'failed';
    if (!model) return;
    this.hull = model.hull;
    this.view.setModel(model.object);
  }

  /**
   * Floats the boat at `time` on the waves (not on its analytic wake; on the interactive
   * waves, `field`, where they are on, its own near-field waves included); with the camera
   * following, carries the camera along. Then records the boat into its wake and hands the
   * wake and the hull for this frame to `view`.
   */
  update(
    time: number,
    params: OceanParams,
    waves: LiveWaveModel,
    view: Pick<OceanView, 'setWake'>,
    ocean?: {
      setBoat(boat: BoatInField | null): void;
      readonly interactiveWaves: InteractiveWaves | null;
      readonly sailLimit: SailLimit | null;
    },
  ): void {
    const previous = this.state?.pose;
    const model = (x: number, z: number) => waves.height(x, z, time);
    const field = ocean?.interactiveWaves;
    const wasAground = this.motion.aground;
    this.motion.limit = ocean?.sailLimit ?? null;
    this.state = this.motion.update(
      time,
      { heading: params.boatHeading * DEG, speed: params.boatSpeed, response: params.boatResponse },
      this.hull,
      model,
      waves,
      // With the interactive waves on, the boat rides them too, as they stand beside its hull.
      field
        ? (x, z, heading) => {
            const beside = field.beside({ x, z, heading, ...WAKE_HULL });
            return (px, pz) => model(px, pz) + beside(px, pz);
          }
        : undefined,
    );
    if (this.motion.aground && !wasAground) this.onAground();
    const pose = this.state.pose;
    this.view.setPose(pose);
    if (params.boatFollow && previous) this.carryCamera(pose.x - previous.x, pose.z - previous.z);
    this.wake.record(time, { x: pose.x, z: pose.z, heading: pose.heading, speed: params.boatSpeed, turnRate: params.boatTurnRate * DEG });
    const data = this.wake.uniforms(time, { enabled: params.wake, strength: params.wakeStrength });
    view.setWake(data, wakeHeightBound(data), {
      visible: params.wake && params.wakeGuide,
      x: pose.x,
      y: 0.05,
      z: pose.z,
      heading: pose.heading,
    });
    ocean?.setBoat({
      hull: { x: pose.x, z: pose.z, heading: pose.heading, speed: params.boatSpeed, ...WAKE_HULL, strength: params.wakeStrength },
      turnRate: params.boatTurnRate * DEG,
      time,
      wake: params.wake,
    });
  }

  /**
   * The waves' sample at world (x, z) with the boat's wake added there, as drawn (times
   * `weight`: the hand-over to the interactive waves near the boat): what a second boat would feel.
   */
  withWake(sample: SurfaceSample, x: number, z: number, time: number, params: OceanParams, weight = 1): SurfaceSample {
    if (!params.wake) return sample;
    const [h, dx, dz] = this.wake.at(x, z, time, { enabled: params.wake, strength: params.wakeStrength });
    return addWake(sample, [weight * h, weight * dx, weight * dz]);
  }

  /** Following starts by looking at the boat from where the camera stands relative to its target. */
  startFollowing(target: { x: number; z: number }): void {
    if (!this.state) return;
    const { x, z } = this.state.pose;
    this.carryCamera(x - target.x, z - target.z);
  }

  /** The wake's track for a share link made at `time`; null if it was last recorded at another time. */
  wakeText(time: number): string | null {
    return this.wake.track.fine.latest()?.time === time ? this.wake.track.serialize() : null;
  }

  /** The motion at `time` for a share link; null if the boat was last floated at another time. */
  snapshot(time: number): BoatSnapshot | null {
    return this.motion.snapshot(time);
  }

  info(): BoatInfo {
    if (!this.state) throw new Error('The boat has not been floated yet: wait for oceano.ready.');
    const { pose, target } = this.state;
    return {
      position: [pose.x, pose.y, pose.z],
      heading: pose.heading,
      pitch: pose.pitch,
      roll: pose.roll,
      target: { position: [target.x, target.y, target.z], pitch: target.pitch, roll: target.roll },
      hull: { ...this.hull },
      model: this.modelState,
    };
  }
}
