// The side panel: what is shown (counts), how the cloud and hands are coloured, which hands
// are shown (by rejection reason, object and rank), and the hand last clicked.

import { categoryColour } from './colours.js';

function element(tag, attributes = {}, text = '') {
  const e = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) e.setAttribute(key, value);
  if (text) e.textContent = text;
  return e;
}

function select(parent, id, label, options) {
  const row = parent.appendChild(element('label', {}, label + ' '));
  const s = row.appendChild(element('select', { id }));
  for (const [value, text] of options) s.appendChild(element('option', { value }, text));
  return s;
}

// Checkboxes, one per category, each with its count and colour; returns the set of values
// ticked, kept up to date.
function checklist(parent, id, title, values, counts, onChange) {
  const box = parent.appendChild(element('fieldset', { id }));
  box.appendChild(element('legend', {}, title));
  const ticked = new Set(values);
  values.forEach((value, i) => {
    const row = box.appendChild(element('label', { class: 'check' }));
    const input = row.appendChild(element('input', { type: 'checkbox', 'data-value': value }));
    input.checked = true;
    input.addEventListener('change', () => {
      if (input.checked) ticked.add(value);
      else ticked.delete(value);
      onChange();
    });
    const swatch = row.appendChild(element('span', { class: 'swatch' }));
    swatch.style.background = '#' + categoryColour(i).getHexString();
    row.appendChild(document.createTextNode(` ${value} (${counts.get(value)})`));
  });
  return ticked;
}

function countsOf(values) {
  const counts = new Map();
  for (const v of values) counts.set(v, (counts.get(v) || 0) + 1);
  return counts;
}

const number = (v, digits = 4) => (typeof v === 'number' ? v.toFixed(digits) : String(v));
const vector = (v) => (Array.isArray(v) ? '[' + v.map((x) => number(x)).join(', ') + ']' : '-');

// One line per fact of `hand`.
function describe(hand, index) {
  const lines = [
    ['hand', String(index)],
    ['position_m', vector(hand.position_m)],
    ['quaternion_xyzw', vector(hand.quaternion_xyzw)],
    ['approach', vector(hand.approach)],
    ['width_m', number(hand.width_m)],
    ['score', number(hand.score)],
  ];
  if (hand.rank !== undefined) lines.push(['rank', String(hand.rank)]);
  if (hand.object !== undefined) lines.push(['object', String(hand.object)]);
  if (hand.label !== undefined) lines.push(['label', hand.label]);
  lines.push(['rejection', hand.rejection || 'none (accepted)']);
  return lines;
}

/**
 * Builds the panel into `root`; `draw` holds colourCloud(mode), colourHands(mode, reasons)
 * and showHands(visible(hand, i)). Returns {apply(), showHand(i)}.
 */
export function buildPanel(root, data, hands, reasonOf, draw) {
  root.appendChild(element('h1', {}, data.title || 'antipode view'));
  root.appendChild(
    element(
      'p',
      { id: 'summary' },
      `${data.cloud.count} points` +
        `, ${hands.length} hands, frame ${data.frame}` +
        (data.gripper.name ? `, ${data.gripper.name}` : ''),
    ),
  );
  const cloudMode = select(root, 'cloud-colour', 'cloud colour', [
    ['height', 'height'],
    ['grey', 'grey'],
  ]);
  const handMode = select(root, 'hand-colour', 'hand colour', [
    ['score', 'score'],
    ['reason', 'rejection reason'],
  ]);
  const rankRow = root.appendChild(element('label', {}, 'best hands shown '));
  const best = rankRow.appendChild(
    element('input', { id: 'best', type: 'number', min: 0, value: hands.length }),
  );

  const reasonCounts = countsOf(hands.map(reasonOf));
  const reasons = [...reasonCounts.keys()];
  const apply = () => {
    draw.colourHands(handMode.value, reasons);
    const limit = Number(best.value);
    draw.showHands(
      (hand, i) =>
        i < limit &&
        shownReasons.has(reasonOf(hand)) &&
        (!shownObjects || shownObjects.has(String(hand.object ?? 'none'))),
    );
  };
  const shownReasons = checklist(root, 'reasons', 'hands by rejection reason', reasons, reasonCounts, apply);
  let shownObjects = null;
  if (hands.some((h) => h.object !== undefined)) {
    const objectCounts = countsOf(hands.map((h) => String(h.object ?? 'none')));
    shownObjects = checklist(root, 'objects', 'hands by object', [...objectCounts.keys()], objectCounts, apply);
  }
  const info = root.appendChild(element('table', { id: 'hand-info' }));
  root.appendChild(element('p', { class: 'hint' }, 'Drag to turn, scroll to zoom, click a hand.'));

  cloudMode.addEventListener('change', () => draw.colourCloud(cloudMode.value));
  handMode.addEventListener('change', apply);
  best.addEventListener('change', apply);

  return {
    apply() {
      draw.colourCloud(cloudMode.value);
      apply();
    },
    showHand(index) {
      info.replaceChildren();
      if (index < 0) return;
      for (const [key, value] of describe(hands[index], index)) {
        const row = info.appendChild(element('tr', { 'data-key': key }));
        row.appendChild(element('th', {}, key));
        row.appendChild(element('td', {}, value));
      }
    },
  };
}
