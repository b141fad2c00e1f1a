// A hand as the gripper file describes it (docs/pose-convention.md, "The hand in its own
// frame"): two fingers d long, w thick and h tall on either side of the closing region, a
// palm t thick behind it. Each part is a unit box scaled and placed by one matrix.

import * as THREE from 'three';

/**
 * The matrices of the finger at -y, the finger at +y and the palm of `hand` (position_m,
 * quaternion_xyzw, open_width_m) in the data's frame, for a gripper with finger_width_m,
 * depth_m, height_m, palm_thickness_m, outer_diameter_m and max_aperture_m.
 */
export function handMatrices(hand, gripper) {
  const a = hand.open_width_m || gripper.max_aperture_m;
  const w = gripper.finger_width_m;
  const d = gripper.depth_m;
  const h = gripper.height_m;
  const t = gripper.palm_thickness_m;
  const palmWidth = 2 * Math.max(gripper.outer_diameter_m / 2, a / 2 + w);
  const pose = new THREE.Matrix4().compose(
    new THREE.Vector3().fromArray(hand.position_m),
    new THREE.Quaternion().fromArray(hand.quaternion_xyzw),
    new THREE.Vector3(1, 1, 1),
  );
  const box = (cx, cy, sx, sy) =>
    new THREE.Matrix4().multiplyMatrices(
      pose,
      new THREE.Matrix4().compose(
        new THREE.Vector3(cx, cy, 0),
        new THREE.Quaternion(),
        new THREE.Vector3(sx, sy, h),
      ),
    );
  return [
    box(d / 2, -(a / 2 + w / 2), d, w),
    box(d / 2, a / 2 + w / 2, d, w),
    box(-t / 2, 0, t, palmWidth),
  ];
}
