// A scene's hands travel as columns (docs/viewer.md, "What is in the page"); the page works
// with one object per hand, made when the scene is first shown.

import { decodeFloat32 } from './base64.js';

/** The hands of `table` (or [] without one) as objects, in the file's order. */
export function handsOf(table) {
  if (!table || !table.count) return [];
  const position = decodeFloat32(table.position_m);
  const quaternion = decodeFloat32(table.quaternion_xyzw);
  const width = decodeFloat32(table.width_m);
  const open = decodeFloat32(table.open_width_m);
  const score = decodeFloat32(table.score);
  const hands = [];
  for (let i = 0; i < table.count; i++) {
    const hand = {
      position_m: Array.from(position.subarray(3 * i, 3 * i + 3)),
      quaternion_xyzw: Array.from(quaternion.subarray(4 * i, 4 * i + 4)),
      width_m: width[i],
      open_width_m: open[i],
      score: score[i],
    };
    if (table.rank[i] > 0) hand.rank = table.rank[i];
    if (table.object[i] >= 0) hand.object = table.object[i];
    if (table.label[i] >= 0) hand.label = table.labels[table.label[i]];
    if (table.rejection[i] >= 0) hand.rejection = table.reasons[table.rejection[i]];
    hands.push(hand);
  }
  return hands;
}

/** The hand's approach (its frame's x axis) in the data's frame. */
export function approachOf(hand) {
  const [x, y, z, w] = hand.quaternion_xyzw;
  return [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)];
}

/**
 * The hands within `radius_m` of hand `i`'s position, nearest first, each as {index,
 * distance_m, rejection} ("accepted" when no stage dropped it): the neighbours a person
 * compares a chosen grasp with.
 */
export function neighbours(hands, i, radius_m) {
  const [x, y, z] = hands[i].position_m;
  const near = [];
  hands.forEach((hand, j) => {
    if (j === i) return;
    const d = Math.hypot(hand.position_m[0] - x, hand.position_m[1] - y, hand.position_m[2] - z);
    if (d <= radius_m) near.push({ index: j, distance_m: d, rejection: hand.rejection || 'accepted' });
  });
  return near.sort((a, b) => a.distance_m - b.distance_m || a.index - b.index);
}
