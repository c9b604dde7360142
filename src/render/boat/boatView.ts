import { Group, type Object3D, type Scene } from 'three';
import type { BoatPose } from '../../sim/boat/boatPose';

/** The boat in the scene: a group that carries the pose, holding the model once it is loaded. */
export class BoatView {
  private readonly group = new Group();

  constructor(scene: Scene) {
    this.group.name = 'Boat';
    // Yaw, then pitch about the beam, then roll about the keel: the order of boatPose.ts.
    this.group.rotation.order = 'YXZ';
    this.group.visible = false;
    scene.add(this.group);
  }

  setModel(model: Object3D): void {
    this.group.add(model);
    this.group.visible = true;
  }

  setPose(pose: BoatPose): void {
    // A paused view drawn again, or a boat at rest: the same pose leaves the group as it is
    // (setting the rotation remakes its quaternion). Object.is, so even a zero's sign stays.
    const { position: p, rotation: r } = this.group;
    if (
      Object.is(p.x, pose.x) &&
      Object.is(p.y, pose.y) &&
      Object.is(p.z, pose.z) &&
      Object.is(r.x, pose.pitch) &&
      Object.is(r.y, -pose.heading) &&
      Object.is(r.z, pose.roll)
    )
      return;
    this.group.position.set(pose.x, pose.y, pose.z);
    this.group.rotation.set(pose.pitch, -pose.heading, pose.roll);
  }
}
